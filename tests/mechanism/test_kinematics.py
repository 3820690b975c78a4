"""Slider-crank kinematics against an independent high-precision reference (the positions written here from the
geometry, differentiated numerically by mpmath at 40 digits) and against seed 000's velocity plan."""
import csv
import math
from pathlib import Path

import mpmath as mp
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from geardesign.errors import GearDesignError
from geardesign.mechanism import kinematics as k

DATA = Path(__file__).resolve().parents[1] / "data" / "seed_engine_mechanism.csv"

mp.mp.dps = 40


def _reference(phi_deg, r, l_, e, n_rpm, cg):
    """Exact positions as functions of time (ω constant), differentiated by mpmath: (s, v, a, β, β̇, β̈, a_Sx, a_Sy)
    in mm, m/s, m/s², rad, rad/s, rad/s²."""
    w = mp.pi * mp.mpf(n_rpm) / 30
    phi0 = mp.radians(mp.mpf(phi_deg))
    r, l_, e, cg = (mp.mpf(x) / 1000 for x in (r, l_, e, cg))      # m

    def beta(t):
        return mp.asin((r * mp.sin(phi0 + w * t) - e) / l_)

    def yb(t):      # the piston pin, from the crank axis along the cylinder
        return r * mp.cos(phi0 + w * t) + mp.sqrt(l_ ** 2 - (r * mp.sin(phi0 + w * t) - e) ** 2)

    def sx(t):      # the rod's centre of gravity: A + cg·(sin β, cos β)
        return -r * mp.sin(phi0 + w * t) + cg * mp.sin(beta(t))

    def sy(t):
        return r * mp.cos(phi0 + w * t) + cg * mp.cos(beta(t))

    top = mp.sqrt((l_ + r) ** 2 - e ** 2)
    return (1000 * (top - yb(0)), -mp.diff(yb, 0), -mp.diff(yb, 0, 2), beta(0), mp.diff(beta, 0),
            mp.diff(beta, 0, 2), mp.diff(sx, 0, 2), mp.diff(sy, 0, 2))


CASES = [(0.0, 70, 250, 0, 1700, 75), (300.0, 70, 250, 0, 1700, 75), (33.3, 44, 176, 0, 2400, 58.7),
         (123.4, 50, 160, 12, 6000, 40), (251.0, 50, 160, -12, 6000, 100), (359.99, 95, 190, 30, 800, 0),
         (90.0, 60, 61, 0, 3000, 61), (185.0, 60, 70, 9.5, 3000, 20)]


@pytest.mark.parametrize("phi, r, l_, e, n, cg", CASES)
def test_every_quantity_against_mpmath(phi, r, l_, e, n, cg):
    s, v, a, beta, bd, bdd, asx, asy = (float(x) for x in _reference(phi, r, l_, e, n, cg))
    w2r = (math.pi * n / 30) ** 2 * r / 1000          # the scale of the accelerations
    assert k.piston_displacement(phi, r, l_, e) == pytest.approx(s, abs=1e-9 * r)
    assert k.piston_velocity(phi, r, l_, n, e) == pytest.approx(v, abs=1e-10 * math.sqrt(w2r * r / 1000))
    assert k.piston_acceleration(phi, r, l_, n, e) == pytest.approx(a, abs=1e-10 * w2r)
    assert math.radians(float(k.rod_angle_deg(phi, r, l_, e))) == pytest.approx(beta, abs=1e-13)
    assert k.rod_angular_velocity(phi, r, l_, n, e) == pytest.approx(bd, abs=1e-10 * math.pi * n / 30)
    assert k.rod_angular_acceleration(phi, r, l_, n, e) == pytest.approx(bdd, abs=1e-10 * (math.pi * n / 30) ** 2)
    ax, ay = k.rod_cg_acceleration(phi, r, l_, cg, n, e)
    assert (float(ax), float(ay)) == pytest.approx((asx, asy), abs=1e-10 * w2r)


def test_vectorised_over_the_crank_angle_equals_one_at_a_time():
    phi = np.linspace(0, 720, 97)
    many = k.piston_acceleration(phi, 50, 160, 4000, 5)
    one = [float(k.piston_acceleration(p, 50, 160, 4000, 5)) for p in phi]
    np.testing.assert_array_equal(many, one)
    assert k.piston_velocity(phi.reshape(1, -1), 50, 160, 4000).shape == (1, 97)


def _seed():
    with open(DATA, encoding="utf-8") as fh:
        return {row["symbol"]: row for row in csv.DictReader(fh) if row["seed"] == "000"}


def test_seed000_velocity_plan():
    """Seed 000 §5.3.3 (r = 70 mm, l = 250 mm, L_CS = 75 mm, e_k = 25 mm, 1700 rpm, φ = 300°): the plan's speeds,
    read to ±0.5 mm at μ_v = 0.1779 (m/s)/mm, with the seed's ω = 177.9 rad/s (π = 3.14)."""
    rows = _seed()
    n = 177.9 * 30 / math.pi                         # the seed's ω
    assert float(k.crank_speed(1700)) == pytest.approx(float(rows["omega"]["seed_value"]), rel=1e-3)
    plan = 0.5 * 0.1779                              # half a millimetre on the plan, m/s
    v_c = float(k.crank_speed(n)) * 0.070
    assert v_c == pytest.approx(float(rows["v_C"]["seed_value"]), abs=0.01)
    v_cb = float(k.rod_angular_velocity(300, 70, 250, n)) * 0.250
    assert v_cb == pytest.approx(float(rows["v_CB"]["seed_value"]), abs=plan)
    assert v_cb * 75 / 250 == pytest.approx(float(rows["v_SC"]["seed_value"]), abs=plan)
    assert v_c * 25 / 70 == pytest.approx(float(rows["v_Sk"]["seed_value"]), abs=plan)
    # the seed's piston speed is a slip: the plan's own (cb) = 36 mm closes the triangle at -12.35 m/s
    v_b = float(k.piston_velocity(300, 70, 250, n))
    assert v_b == pytest.approx(-12.34, abs=0.01)
    assert abs(v_b - float(rows["v_B"]["seed_value"])) > 5 * plan
    # and so is the crank's centre-of-gravity acceleration: ω²·e_k
    ax, ay = k.crank_pin_acceleration(300, 25, n)
    assert math.hypot(ax, ay) == pytest.approx(177.9 ** 2 * 0.025, rel=1e-12)
    assert math.hypot(ax, ay) > 1.3 * float(rows["a_Sk"]["seed_value"])


def test_the_stroke_and_the_dead_centres():
    r, l_, e = 50.0, 160.0, 10.0
    top_phi = math.degrees(math.asin(e / (l_ + r)))            # the true top dead centre of an offset mechanism
    bottom_phi = 180 + math.degrees(math.asin(e / (l_ - r)))
    assert k.piston_displacement(top_phi, r, l_, e) == pytest.approx(0.0, abs=1e-12)
    stroke = math.sqrt((l_ + r) ** 2 - e * e) - math.sqrt((l_ - r) ** 2 - e * e)
    assert k.piston_displacement(bottom_phi, r, l_, e) == pytest.approx(stroke, abs=1e-12)
    assert k.piston_velocity([top_phi, bottom_phi], r, l_, 3000, e) == pytest.approx([0, 0], abs=1e-12)


@settings(max_examples=60, deadline=None)
@given(phi=st.floats(-720, 720), lam=st.floats(0.05, 0.95), e_frac=st.floats(-0.9, 0.9))
def test_displacement_stays_inside_the_stroke(phi, lam, e_frac):
    r = 50.0
    l_ = r / lam
    e = e_frac * (l_ - r)
    s = float(k.piston_displacement(phi, r, l_, e))
    stroke = math.sqrt((l_ + r) ** 2 - e * e) - math.sqrt((l_ - r) ** 2 - e * e)
    assert -1e-9 <= s <= stroke + 1e-9


@pytest.mark.parametrize("kw, match", [
    (dict(crank_radius_mm=70, rod_length_mm=70), "rod_length_mm must exceed"),
    (dict(crank_radius_mm=70, rod_length_mm=100, offset_mm=31), "crank_radius_mm \\+ \\|offset_mm\\| = 101"),
    (dict(crank_radius_mm=-1, rod_length_mm=100), r"crank_radius_mm must be in \[0.001, 100000\] mm, got -1"),
    (dict(crank_radius_mm=70, rod_length_mm=float("nan")), "rod_length_mm must be finite"),
])
def test_bad_lengths_are_refused_by_name(kw, match):
    with pytest.raises(GearDesignError, match=match):
        k.piston_displacement(0.0, **kw)


def test_bad_angles_and_speeds_are_refused_by_name():
    with pytest.raises(GearDesignError, match="crank_angle_deg must be finite"):
        k.piston_velocity([0, float("inf")], 70, 250, 1000)
    with pytest.raises(GearDesignError, match=r"n_rpm must be in \(0, 100000\] rpm"):
        k.piston_velocity(0, 70, 250, 0)
    with pytest.raises(GearDesignError, match="rod_cg_mm must be in \\[0, 250\\]"):
        k.rod_cg_acceleration(0, 70, 250, 260, 1000)


def test_lengths_beyond_their_range_are_refused_by_name():
    """Fuzzing found a RuntimeWarning (0/0) escaping IndicatorDiagram.otto for a rod of 1e38 mm (np.float32's
    largest): the stroke rounds to 0 against it. Crank and rod lengths are checked against [0.001, 100000] mm."""
    import warnings
    from geardesign.mechanism.pressure import IndicatorDiagram
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(GearDesignError,
                           match=r"rod_length_mm must be in \[0.001, 100000\] mm, got 9.99999968\d*e\+37"):
            IndicatorDiagram.otto(45.0, np.float32(1e38), 25.0, peak_pressure_mpa=30.0)
        with pytest.raises(GearDesignError, match=r"crank_radius_mm must be in \[0.001, 100000\] mm, got 5e-324"):
            k.piston_velocity(90.0, 5e-324, 250, 1000)
        with pytest.raises(GearDesignError, match=r"offset_mm must be in \[-100000, 100000\] mm"):
            k.check_lengths(70, 250, 1e300)
