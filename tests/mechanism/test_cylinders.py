"""Several cylinders: firing phases, seed 004's journal and crank-pin torques (written here as its loops), the
unevenness, the excess work of a sinusoid (closed form) and the torque reversals."""
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp

from geardesign.errors import GearDesignError
from geardesign.mechanism.cylinders import (crank_pin_torques, even_phases, excess_work, firing_phases,
                                            fluctuation_coefficient, journal_torques, reversal_angles, unevenness)


def test_firing_phases_of_common_engines():
    # in-line six firing 1-5-3-6-2-4 every 120°: cylinder 1's angle at each cylinder's top dead centre
    six = firing_phases((0, 120, 240, 240, 120, 0), (1, 5, 3, 6, 2, 4), 720)
    assert six.tolist() == [0.0, 480.0, 240.0, 600.0, 120.0, 360.0]
    # a 180° twin and a parallel twin (360°)
    assert firing_phases((0, 180), (1, 2), 720).tolist() == [0.0, 180.0]
    assert firing_phases((0, 0), (1, 2), 720).tolist() == [0.0, 360.0]
    # two-stroke: each cylinder fires at its throw
    assert firing_phases((0, 120, 240), (1, 2, 3), 360).tolist() == [0.0, 120.0, 240.0]
    # a firing order written from another cylinder is the same cycle
    assert firing_phases((0, 180, 180, 0), (3, 4, 2, 1), 720).tolist() == [0.0, 540.0, 180.0, 360.0]
    assert even_phases(3, 360).tolist() == [0.0, 120.0, 240.0]


@pytest.mark.parametrize("order, match", [((1, 2, 2, 4), "each cylinder 1..4 once"), ((1, 2, 3), "each cylinder"),
                                          ("abc", "cylinder numbers")])
def test_bad_firing_orders_are_refused(order, match):
    with pytest.raises(GearDesignError, match=match):
        firing_phases((0, 180, 180, 0), order, 720)


def test_journal_and_crank_pin_torques_are_seed004s_sums():
    """Seed 004: M_z1 = 0 (the timing-gear end), M_zi = Σ_{k<i} M_k, the last journal the resultant; crank pin
    M_qi = M_zi + 0.5·M_i."""
    rng = np.random.default_rng(4)
    m = rng.normal(size=(5, 33))
    mz = journal_torques(m)
    mq = crank_pin_torques(m)
    for i in range(6):
        expected = sum((m[k] for k in range(i)), np.zeros(33))
        np.testing.assert_allclose(mz[i], expected, rtol=0, atol=1e-14)
    for i in range(5):
        np.testing.assert_allclose(mq[i], mz[i] + 0.5 * m[i], rtol=0, atol=1e-14)
    np.testing.assert_allclose(mz[-1], m.sum(axis=0), atol=1e-14)
    assert crank_pin_torques(m[:1]).tolist() == (0.5 * m[:1]).tolist()      # one cylinder: M_q = M/2


def test_unevenness():
    phi = np.radians(np.arange(720) * 0.5)
    assert unevenness(100 + 50 * np.sin(phi)) == pytest.approx(1.0, abs=1e-12)
    with pytest.raises(GearDesignError, match="positive mean"):
        unevenness(np.sin(phi))


@pytest.mark.parametrize("order", [1, 2, 3, 6])
def test_excess_work_of_a_sinusoid(order):
    """M = M0 + A·sin(kφ): E(φ) = (A/k)(1 − cos kφ), a swing of 2A/k (J); the trapezoids converge to it."""
    n = 3600
    phi = np.arange(n) * (360.0 / n)
    e, swing = excess_work(300 + 80 * np.sin(order * np.radians(phi)), 360)
    assert swing == pytest.approx(2 * 80 / order, rel=1e-5)
    assert fluctuation_coefficient(swing, 2.0, 3000) == pytest.approx(swing / (2.0 * (100 * math.pi) ** 2))


def test_reversal_angles_of_a_sinusoid():
    phi = np.arange(720) * 0.5
    rev = reversal_angles(phi, np.sin(np.radians(2 * phi - 10)), 360)
    np.testing.assert_allclose(rev, [5, 95, 185, 275], atol=1e-3)
    assert reversal_angles(phi, 1 + np.sin(np.radians(phi))).size == 0       # touches zero, never reverses


@settings(max_examples=50, deadline=None)
@given(m=hnp.arrays(float, st.tuples(st.integers(1, 6), st.integers(2, 40)),
                    elements=st.floats(-1e4, 1e4, allow_subnormal=False)))
def test_the_last_journal_carries_the_resultant(m):
    mz = journal_torques(m)
    assert mz.shape == (m.shape[0] + 1, m.shape[1])
    np.testing.assert_allclose(mz[-1], m.sum(axis=0), rtol=1e-12, atol=1e-9)
    assert np.all(mz[0] == 0)


def test_a_speed_too_low_for_any_flywheel_is_refused_by_name():
    """Fuzzing found a ZeroDivisionError from Engine.analyse at n_rpm = 5e-324 (a 1 µm crank in a 2 m bore: ω²
    underflows in δ = ΔE/(J·ω²)); a δ that overflows is refused by name, a slow but finite one answers."""
    with pytest.raises(GearDesignError, match="n_rpm = 4.94066e-324 rpm is too slow for a fluctuation coefficient"):
        fluctuation_coefficient(1000.0, 1e-6, 5e-324)
    # ω = π/30·(30/π) = 1 rad/s: δ = ΔE/J
    assert fluctuation_coefficient(1000.0, 2.0, 30 / math.pi) == pytest.approx(500.0, rel=1e-15)
