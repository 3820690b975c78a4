"""Accuracy grade -> deviations (geardesign.gears.strength.accuracy): the ISO 1328-1:1995 clause 6.3 formulas,
written out here, and the grade step 2^((Q-5)/2) of clause 6.2."""
import math

import numpy as np
import pytest

from geardesign.gears.strength import accuracy as acc


def _step(q):
    return 2.0 ** ((q - 5) / 2)


@pytest.mark.parametrize("grade", range(0, 13))
def test_each_grade_is_the_grade_5_value_times_sqrt2_per_grade(grade):
    m, d, b = 8.0, 141.34, 100.0        # ISO/TR 6336-30 example 1's pinion: m_n 8 mm, d 141.34 mm, b 100 mm
    assert acc.grade_step(grade) == pytest.approx(_step(grade), rel=1e-15)
    assert acc.single_pitch_deviation(m, d, grade) == pytest.approx((0.3 * (m + 0.4 * math.sqrt(d)) + 4) * _step(grade),
                                                                    rel=1e-14)
    assert acc.profile_form_deviation(m, d, grade) == pytest.approx(
        (2.5 * math.sqrt(m) + 0.17 * math.sqrt(d) + 0.5) * _step(grade), rel=1e-14)
    assert acc.helix_deviation_total(d, b, grade) == pytest.approx(
        (0.1 * math.sqrt(d) + 0.63 * math.sqrt(b) + 4.2) * _step(grade), rel=1e-14)
    assert acc.helix_slope_deviation(d, b, grade) == pytest.approx(
        (0.07 * math.sqrt(d) + 0.45 * math.sqrt(b) + 3.0) * _step(grade), rel=1e-14)


def test_floats_and_arrays_agree():
    m, d, b = np.array([2.0, 5.0, 12.0]), np.array([40.0, 200.0, 900.0]), np.array([20.0, 60.0, 300.0])
    for grade in (3, 7.0, 11):
        for f, args in ((acc.single_pitch_deviation, (m, d)), (acc.profile_form_deviation, (m, d)),
                        (acc.helix_deviation_total, (d, b)), (acc.helix_slope_deviation, (d, b))):
            many = f(*args, grade)
            one = [f(float(a0), float(a1), float(grade)) for a0, a1 in zip(*args)]
            assert np.allclose(many, one, rtol=1e-14, atol=0)
