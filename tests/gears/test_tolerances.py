"""ISO 1328-1:2013 flank tolerances (geardesign.gears.tolerances); sources in tests/data/iso1328_2013.md."""
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from geardesign.errors import GearDesignError
from geardesign.gears import tolerances as tol
from geardesign.gears.tolerances import flank_tolerances, round_iso1328


def test_public_worked_value_class_6():
    """m_n 3 mm, z 40, b 30 mm, class 6: f_pT 8.94 µm unrounded, 9.0 µm rounded (tests/data/iso1328_2013.md)."""
    assert round(float(tol.single_pitch_tolerance_um(120.0, 3.0, 6)), 2) == 8.94
    assert flank_tolerances(3, 40, 6, face_width_mm=30).f_pT == 9.0


@settings(max_examples=100, deadline=None)
@given(st.floats(0.5, 70), st.floats(5, 15000), st.floats(4, 1200), st.integers(1, 9))
def test_two_classes_double_every_unrounded_tolerance(m, d, b, a):
    for fun, args in ((tol.single_pitch_tolerance_um, (d, m)), (tol.cumulative_pitch_tolerance_um, (d, m)),
                      (tol.profile_slope_tolerance_um, (d, m)), (tol.profile_form_tolerance_um, (m,)),
                      (tol.profile_total_tolerance_um, (d, m)), (tol.helix_slope_tolerance_um, (d, b)),
                      (tol.helix_form_tolerance_um, (d, b)), (tol.helix_total_tolerance_um, (d, b))):
        assert float(fun(*args, a + 2)) == pytest.approx(2.0 * float(fun(*args, a)), rel=1e-13)


@settings(max_examples=200, deadline=None)
@given(st.floats(0.05, 500))
def test_rounding_bands(v):
    r = round_iso1328(v)
    step = 1.0 if v > 10 else (0.5 if v >= 5 else 0.1)
    assert abs(r - v) <= step / 2 + 1e-9
    assert abs(r / step - round(r / step)) < 1e-9


def test_totals_come_from_the_unrounded_parts():
    t = flank_tolerances(3, 40, 6, face_width_mm=30)
    raw = math.hypot(float(tol.profile_slope_tolerance_um(120, 3, 6)), float(tol.profile_form_tolerance_um(3, 6)))
    assert t.F_alphaT == round_iso1328(raw)
    assert t.F_betaT is not None and flank_tolerances(3, 40, 6).F_betaT is None


def test_grow_with_size_and_class_and_broadcast():
    t = flank_tolerances(np.array([1, 2, 4]), np.array([[20], [80]]), 7, face_width_mm=20)
    assert np.shape(t.F_pT) == (2, 3) and np.all(np.diff(t.F_pT, axis=1) >= 0) and np.all(np.diff(t.F_pT, axis=0) > 0)
    classes = flank_tolerances(3, 40, np.arange(1, 12)).F_pT
    assert np.all(np.diff(classes) > 0)
    assert len(repr(flank_tolerances(3, 40, 6, face_width_mm=30)).splitlines()) <= 15


@pytest.mark.parametrize("kwargs, word", [
    (dict(m=3, z=40, accuracy_class=0), "accuracy_class"), (dict(m=3, z=40, accuracy_class=12), "accuracy_class"),
    (dict(m=0.3, z=40, accuracy_class=6), "m"), (dict(m=80, z=40, accuracy_class=6), "m"),
    (dict(m=3, z=4, accuracy_class=6), "z"), (dict(m=3, z=1001, accuracy_class=6), "z"),
    (dict(m=3, z=40, accuracy_class=6, face_width_mm=2), "face_width_mm"),
    (dict(m=3, z=40, accuracy_class=6, beta_deg=50), "beta_deg"),
    (dict(m=0.5, z=5, accuracy_class=6, d_mm=2.0), "d_mm"), (dict(m=70, z=1000, accuracy_class=6), "d_mm"),
    (dict(m=3, z=40, accuracy_class=6.5), "accuracy_class"),
])
def test_outside_the_standard_is_one_clear_error(kwargs, word):
    with pytest.raises(GearDesignError, match=word):
        flank_tolerances(**kwargs)
