"""Kinetostatics of the slider-crank: the force plans' torque against virtual power (1e-9), both against an exact
closed form written here (Lagrange's energy form, differentiated by mpmath), the joints' equilibrium, and seed 003's
two-cylinder case at φ1 = 45° (F_y 2073 N by kinetostatics, 2080 N by Zhukovsky's lever)."""
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
from geardesign.mechanism.kinetostatics import joint_forces, piston_force_torque, virtual_power_torque
from geardesign.mechanism.slider_crank import SliderCrank

DATA = Path(__file__).resolve().parents[1] / "data" / "seed_engine_mechanism.csv"
mp.mp.dps = 40


def _energy_torque(mech, phi_deg, n_rpm, fg, g, tilt_deg):
    """The driving torque by Lagrange at constant ω, written from the positions alone:

        M(φ) = F_g·s'(φ) − ½·ω²·I'(φ) − V'(φ),

    I(φ) = m_p·y_B'² + m_r·|S'|² + J_S·β'² (the reduced moment of inertia; the crank's is constant), V(φ) the
    potential of the weights, ' = d/dφ (mpmath, 40 digits)."""
    r, l_, e, cg, rc = (mp.mpf(x) / 1000 for x in (mech.crank_radius_mm, mech.rod_length_mm, mech.offset_mm,
                                                    mech.rod_cg_mm, mech.crank_cg_mm))
    mp_, mr, js, mc = (mp.mpf(x) for x in (mech.piston_mass_kg, mech.rod_mass_kg, mech.rod_inertia_kg_m2,
                                           mech.crank_mass_kg))
    w = mp.pi * mp.mpf(n_rpm) / 30
    tau = mp.radians(mp.mpf(tilt_deg))
    gx, gy = -mp.mpf(g) * mp.sin(tau), -mp.mpf(g) * mp.cos(tau)

    def beta(p):
        return mp.asin((r * mp.sin(p) - e) / l_)

    def yb(p):
        return r * mp.cos(p) + l_ * mp.cos(beta(p))

    def s_xy(p):
        return -r * mp.sin(p) + cg * mp.sin(beta(p)), r * mp.cos(p) + cg * mp.cos(beta(p))

    def inertia(p):
        sx = mp.diff(lambda q: s_xy(q)[0], p)
        sy = mp.diff(lambda q: s_xy(q)[1], p)
        return mp_ * mp.diff(yb, p) ** 2 + mr * (sx ** 2 + sy ** 2) + js * mp.diff(beta, p) ** 2

    def potential(p):     # −(work of the weights): V = −Σ m·g·position
        sx, sy = s_xy(p)
        return -(mp_ * (gx * (-e) + gy * yb(p)) + mr * (gx * sx + gy * sy)
                 + mc * rc * (gx * (-mp.sin(p)) + gy * mp.cos(p)))

    p = mp.radians(mp.mpf(phi_deg))
    return float(-mp.mpf(fg) * mp.diff(yb, p) - w ** 2 / 2 * mp.diff(inertia, p) - mp.diff(potential, p))


MECHS = [SliderCrank(70, 250, rod_cg_mm=75, piston_mass_kg=2.1, rod_mass_kg=4.7, rod_inertia_kg_m2=0.031,
                     crank_mass_kg=10.5, crank_cg_mm=25),
         SliderCrank(44, 176, rod_cg_mm=58.7, offset_mm=6, piston_mass_kg=0.69, rod_mass_kg=0.85,
                     rod_inertia_kg_m2=0.0058, crank_mass_kg=3.0, crank_cg_mm=-20)]


@pytest.mark.parametrize("mech", MECHS)
@pytest.mark.parametrize("phi", [0.0, 17.0, 95.0, 181.0, 300.0, 333.3])
def test_torque_against_the_energy_form(mech, phi):
    n, fg, g, tilt = 4200.0, 12345.0, 9.81, 25.0
    exact = _energy_torque(mech, phi, n, fg, g, tilt)
    scale = fg * mech.crank_radius_mm / 1000 + mech.rod_mass_kg * (math.pi * n / 30) ** 2 * (mech.crank_radius_mm
                                                                                              / 1000) ** 2
    plans = float(joint_forces(mech, phi, n, fg, gravity_m_s2=g, axis_tilt_deg=tilt).torque_nm)
    power = float(virtual_power_torque(mech, phi, n, fg, gravity_m_s2=g, axis_tilt_deg=tilt))
    assert plans == pytest.approx(exact, abs=1e-9 * scale)
    assert power == pytest.approx(exact, abs=1e-9 * scale)


@settings(max_examples=40, deadline=None)
@given(phi=st.floats(0, 720), lam=st.floats(0.1, 0.9), cg=st.floats(0, 1), e=st.floats(-0.5, 0.5),
       mp_=st.floats(0, 50), mr=st.floats(0, 50), js=st.floats(0, 2), mc=st.floats(0, 50), rc=st.floats(-1.5, 1.5),
       fg=st.floats(-1e5, 1e6), n=st.floats(10, 20000), tilt=st.floats(-180, 180))
def test_force_plans_and_virtual_power_agree(phi, lam, cg, e, mp_, mr, js, mc, rc, fg, n, tilt):
    r = 60.0
    l_ = r / lam
    mech = SliderCrank(r, l_, rod_cg_mm=cg * l_, offset_mm=e * (l_ - r), piston_mass_kg=mp_, rod_mass_kg=mr,
                       rod_inertia_kg_m2=js, crank_mass_kg=mc, crank_cg_mm=rc * r)
    a = float(joint_forces(mech, phi, n, fg, axis_tilt_deg=tilt).torque_nm)
    b = float(virtual_power_torque(mech, phi, n, fg, axis_tilt_deg=tilt))
    w = math.pi * n / 30
    scale = (abs(fg) + (mp_ + mr + js / (r / 1000) ** 2 + mc) * w * w * r / 1000 / lam + 1.0) * r / 1000
    assert a == pytest.approx(b, abs=1e-9 * scale)


def test_every_joint_holds_its_links_in_equilibrium():
    """Each link's forces (with the inertia forces) sum to zero: the piston along x and y, the rod, the crank, and
    the whole mechanism (frame forces R03 + R01 against everything applied)."""
    mech = MECHS[0]
    phi = np.linspace(0, 360, 37)
    n, g = 3000.0, 9.80665
    fg = 5000 + 20000 * np.cos(np.radians(phi))
    f = joint_forces(mech, phi, n, fg)
    a = k.piston_acceleration(phi, 70, 250, n)
    # the piston: R23 + R03 + (0, −F_g) + (0, −m g) + (0, m a) = 0
    np.testing.assert_allclose(f.piston_pin_x_n + f.wall_n, 0, atol=1e-9)
    np.testing.assert_allclose(f.piston_pin_y_n - fg - mech.piston_mass_kg * g + mech.piston_mass_kg * a, 0,
                               atol=1e-8)
    # the rod: R12 − R23 + G + Φ = 0
    np.testing.assert_allclose(f.crank_pin_x_n - f.piston_pin_x_n + f.rod_inertia_x_n, 0, atol=1e-8)
    np.testing.assert_allclose(f.crank_pin_y_n - f.piston_pin_y_n - mech.rod_mass_kg * g + f.rod_inertia_y_n, 0,
                               atol=1e-8)
    # a massless rod is a two-force member: R23 lies along B − A = l·(sin β, cos β), so the wall's normal force
    # balances its x part, R03 = −R23_y·tan β
    f0 = joint_forces(mech, phi, n, fg, gravity_m_s2=0.0)
    m0 = SliderCrank(70, 250, piston_mass_kg=2.1)        # a massless rod: the rod force lies along the rod
    f1 = joint_forces(m0, phi, n, fg, gravity_m_s2=0.0)
    tan_b = np.tan(np.radians(k.rod_angle_deg(phi, 70, 250)))
    np.testing.assert_allclose(f1.wall_n, -f1.piston_pin_y_n * tan_b, atol=1e-8)
    assert np.all(np.isfinite(f0.main_bearing_x_n))


def test_balancing_torque_is_the_driving_torques_negative():
    f = joint_forces(MECHS[0], [30.0, 200.0], 1700, 1e4)
    np.testing.assert_array_equal(f.balancing_torque_nm, -f.torque_nm)
    assert list(f.table().columns)[-1] == "balancing_torque_nm" and len(f.table()) == 2
    assert "JointForces(2 crank angles" in repr(f)


def test_gas_torque_closed_form():
    """A massless mechanism: the gas force's torque is F·r·sin(φ + β)/cos β (Kolchin & Demidov §10.1), written
    here with the exact β."""
    mech = SliderCrank(70, 250)
    phi = np.linspace(0, 360, 73)
    beta = np.arcsin(0.28 * np.sin(np.radians(phi)))
    closed = 1e4 * 0.07 * np.sin(np.radians(phi) + beta) / np.cos(beta)
    np.testing.assert_allclose(joint_forces(mech, phi, 1700, 1e4, gravity_m_s2=0).torque_nm, closed, rtol=0,
                               atol=1e-9 * 700)
    np.testing.assert_allclose(piston_force_torque(1e4, phi, 70, 250), closed, rtol=0, atol=1e-9 * 700)


def test_inertia_torque_averages_to_zero_over_a_turn():
    """The inertia forces and the weights are conservative at constant ω: their torque does no work over a turn."""
    mech = MECHS[1]
    phi = np.arange(720) * 0.5
    m = joint_forces(mech, phi, 6000, 0.0).torque_nm
    assert abs(m.mean()) < 1e-10 * np.abs(m).max()
    assert np.abs(m).max() > 1.0


def _seed003():
    with open(DATA, encoding="utf-8") as fh:
        return {row["symbol"]: float(row["seed_value"]) for row in csv.DictReader(fh) if row["seed"] == "003"}


def seed003_mechanism():
    """Seed 003's slider-crank reconstructed from its own figures (see the test below): (mechanism, n_rpm, seed's
    figures). r/l from the lever's pb/pa, the speed, the rod's centre of gravity and inertia from Φ_S3, Φ_S2, M_S2."""
    from scipy.optimize import brentq

    s = _seed003()
    g = 9.81
    r, l_ = 44.0, 176.0
    m_piston, m_rod = s["G3"] / g, s["G2"] / g
    w2 = s["Phi_S3"] / (m_piston * float(k.piston_acceleration(45, r, l_, 30 / math.pi)))
    n = math.sqrt(w2) * 30 / math.pi

    def a_s(cg, phi):
        return math.hypot(*(float(x) for x in k.rod_cg_acceleration(phi, r, l_, cg, n)))

    cg = brentq(lambda c: m_rod * a_s(c, 45) - s["Phi_S2"], 0, l_)
    j = s["M_S2"] / abs(float(k.rod_angular_acceleration(45, r, l_, n)))
    mech = SliderCrank(r, l_, rod_cg_mm=cg, piston_mass_kg=m_piston, rod_mass_kg=m_rod, rod_inertia_kg_m2=j)
    return mech, n, s


def test_seed003_two_cylinder_balancing_force():
    """Seed 003 §2.7 (an 80° V-twin, rods of 176 mm on one crank pin, φ1 = 45°). Its dimensions are on pages not
    included; they follow from the lever's own figures: pb/pa = 0.834 gives λ = 0.25 (r = 44 mm), the weights' arms
    ph/pb = pn/pc = cos 40° the 80° V. The speed, the rods' centre of gravity and inertia are fitted to Φ_S3, Φ_S2 and
    M_S2; Φ_S5, Φ_S4 and M_S4 are then predictions (0.3 %), and the balancing force F_y = M/r of the two cylinders
    reproduces the lever's 2080 N (0.1 %) and the force plans' 2073 N (0.4 %)."""
    mech, n, s = seed003_mechanism()
    g = 9.81
    r, l_, cg, j = mech.crank_radius_mm, mech.rod_length_mm, mech.rod_cg_mm, mech.rod_inertia_kg_m2
    assert s["M_S2"] / s["M_S2/l_AB"] == pytest.approx(0.176, abs=5e-4)     # l_AB = M_S2/F'_и2
    assert float(k.piston_velocity(45, r, l_, 30 / math.pi)) / (r / 1000) == pytest.approx(s["pb"] / 100, abs=1e-3)
    assert abs(float(k.piston_velocity(-35, r, l_, 30 / math.pi))) / (r / 1000) == pytest.approx(s["pc"] / 100,
                                                                                                  abs=1e-3)
    assert s["ph"] / s["pb"] == pytest.approx(math.cos(math.radians(40)), abs=2e-3)
    assert s["pn"] / s["pc"] == pytest.approx(math.cos(math.radians(40)), abs=2e-3)
    assert n == pytest.approx(2396, abs=1)
    assert mech.piston_mass_kg * float(k.piston_acceleration(-35, r, l_, n)) == pytest.approx(s["Phi_S5"], rel=3e-3)
    assert cg == pytest.approx(l_ / 3, rel=0.03)                  # the usual l/3
    a_s4 = math.hypot(*(float(x) for x in k.rod_cg_acceleration(-35, r, l_, cg, n)))
    assert mech.rod_mass_kg * a_s4 == pytest.approx(s["Phi_S4"], rel=3e-3)
    assert j * abs(float(k.rod_angular_acceleration(-35, r, l_, n))) == pytest.approx(s["M_S4"], rel=3e-3)

    # cylinder 1 tilted 40° against the rotation, cylinder 2 (80° later) 40° with it; P3 on piston 1, P5 = 0
    m1 = joint_forces(mech, 45.0, n, s["P3"], gravity_m_s2=g, axis_tilt_deg=-40).torque_nm
    m2 = joint_forces(mech, -35.0, n, s["P5"], gravity_m_s2=g, axis_tilt_deg=40).torque_nm
    lever = virtual_power_torque(mech, 45.0, n, s["P3"], gravity_m_s2=g, axis_tilt_deg=-40) + \
        virtual_power_torque(mech, -35.0, n, s["P5"], gravity_m_s2=g, axis_tilt_deg=40)
    f_y = float(m1 + m2) / (r / 1000)
    assert float(lever) / (r / 1000) == pytest.approx(f_y, rel=1e-12)
    assert f_y == pytest.approx(s["F_y_lever"], rel=1e-3)
    assert f_y == pytest.approx(s["F_y_plans"], rel=5e-3)
    # the seed's own lever sum, recomputed from its printed terms (line 58-60)
    terms = [-290 * 72.8, 364 * 57.1, 8.29 * 26.9, -1998 * 35.8, -1351 * 83.4, 2376 * 83.4, 6.73 * 63.9, 364 * 14.7,
             1725 * 69.2, -290 * 9.9, -6.73 * 53, -0, -8.29 * 11.6, 2184 * 33.1]
    assert sum(terms) / 100 == pytest.approx(s["F_y_lever"], abs=0.5)


def test_bad_inputs_are_refused_by_name():
    mech = MECHS[0]
    with pytest.raises(GearDesignError, match="gas_force_n must be finite"):
        joint_forces(mech, [0, 1], 1000, [0, float("nan")])
    with pytest.raises(GearDesignError, match="gravity_m_s2 must be in"):
        joint_forces(mech, 0, 1000, 0, gravity_m_s2=-1)
    with pytest.raises(GearDesignError, match="mechanism must be a SliderCrank"):
        virtual_power_torque("crank", 0, 1000)


def test_one_angle_with_several_gas_forces_broadcasts():
    """Fuzzing found 'ValueError: cannot broadcast a non-scalar to a scalar array' for one crank angle with several
    gas forces; they broadcast together (as the docstring says), each the same as its own call, and shapes that do
    not broadcast are refused by name."""
    mech = MECHS[0]
    gas = [0.0, 1e3, 5e4]
    f = joint_forces(mech, 30.0, 1700, gas)
    assert f.torque_nm.shape == (3,)
    for i, g in enumerate(gas):
        one = joint_forces(mech, [30.0], 1700, g)
        assert f.torque_nm[i] == pytest.approx(one.torque_nm[0], rel=1e-12, abs=1e-9)
        assert f.crank_pin_x_n[i] == pytest.approx(one.crank_pin_x_n[0], rel=1e-12, abs=1e-9)
    with pytest.raises(GearDesignError, match="do not broadcast"):
        joint_forces(mech, [0.0, 30.0], 1700, gas)


@pytest.mark.parametrize("n_rpm", [1e308, 1e6, float("inf"), 0.0])
def test_a_speed_beyond_the_range_is_refused_by_name(n_rpm):
    """Fuzzing found NaN torques from virtual_power_torque at n_rpm = 1e308 (ω² overflows): the crank's speed is
    checked against (0, 100000] rpm, the engine's range, by every kinematic function."""
    for fn in (joint_forces, virtual_power_torque):
        with pytest.raises(GearDesignError, match=r"n_rpm must be (in \(0, 100000\] rpm|finite)"):
            fn(MECHS[0], [0.0, 90.0], n_rpm)
    with pytest.raises(GearDesignError, match=r"n_rpm must be (in \(0, 100000\] rpm|finite)"):
        k.piston_velocity(90.0, 70, 250, n_rpm)


def test_one_axis_tilt_as_a_list_is_refused_by_name():
    """Fuzzing found 'TypeError: only 0-dimensional arrays can be converted' for axis_tilt_deg=np.array([1.0])."""
    with pytest.raises(GearDesignError, match="axis_tilt_deg must be one number"):
        virtual_power_torque(MECHS[0], [0.0, 90.0], 1700, axis_tilt_deg=np.array([1.0]))
    with pytest.raises(GearDesignError, match="gravity_m_s2 must be one number"):
        joint_forces(MECHS[0], [0.0, 90.0], 1700, gravity_m_s2=[9.81, 0.0])


def test_a_gas_force_beyond_any_engine_is_refused_by_name_near_the_dead_point():
    """Fuzzing found NaN joint forces at l/r = 1.0000001 with gas_force_n = 1e308: near the dead point the forces grow
    as F_g/cos β_max and overflowed (inf − inf). Every l/r > 1 is a mechanism whose forces are finite; the gas force
    is bounded instead, |F_g| <= 1e10 N (24 MN is a 1 m bore at 30 MPa)."""
    mech = SliderCrank(45.0, 45.0000045, rod_cg_mm=0.0, piston_mass_kg=1000.0, crank_mass_kg=10.5, crank_cg_mm=450.0)
    phi = np.linspace(0.0, 720.0, 37)
    for fn in (joint_forces, virtual_power_torque):
        for gas in (1e308, -1e308, [1e4, 2e10]):
            with pytest.raises(GearDesignError, match=r"gas_force_n must be in \[-1e\+10, 1e\+10\] N"):
                fn(mech, phi if np.ndim(gas) == 0 else [0.0, 90.0], 1700.0, gas)
    f = joint_forces(mech, phi, 1700.0, 1e10)
    assert all(np.all(np.isfinite(getattr(f, name))) for name in f.__dataclass_fields__ if name != "success")


@pytest.mark.parametrize("excess", [1e-7, 1e-12])
def test_forces_at_the_dead_point_match_an_exact_computation(excess):
    """l/r = 1 + ε, φ = 90°: the rod stands at sin β = r/l, and with massless links the piston pin carries F·tan β
    across the cylinder and the crank F·r (Kolchin & Demidov §10.1: T = F·sin(φ + β)/cos β). cos β = √(1 − (r/l)²)
    in 40 digits (mpmath): 1 − r/l computed after r/l was rounded lost 2.5e-5 of it at ε = 1e-12; it is
    (l − r)(l + r)/l² now, to 1e-13."""
    r = 70.0
    l_ = r * (1.0 + excess)
    mech = SliderCrank(r, l_, rod_cg_mm=0.0)
    F = 1e4
    f = joint_forces(mech, [90.0], 1700.0, F, gravity_m_s2=0.0)
    phi = mp.mpf(float(np.radians(90.0)))         # the double the function turns 90° into: cos φ = 6e-17, not 0
    s = mp.mpf(r) * mp.sin(phi) / mp.mpf(l_)
    tan_beta = s / mp.sqrt((1 - s) * (1 + s))
    assert float(f.piston_pin_x_n[0]) == pytest.approx(float(F * tan_beta), rel=1e-12)
    # M = F·r·sin(φ + β)/cos β = F·r·(sin φ + cos φ·tan β)
    exact = F * mp.mpf(r) / 1000 * (mp.sin(phi) + mp.cos(phi) * tan_beta)
    assert float(f.torque_nm[0]) == pytest.approx(float(exact), rel=1e-12)
    cb = k.state(np.array([float(phi)]), r, l_, 0.0, 1.0).cos_beta[0]
    assert float(cb) == pytest.approx(float(mp.sqrt((1 - s) * (1 + s))), rel=1e-13)


def test_a_vanishing_speed_gives_the_static_torque_and_a_list_of_speeds_is_refused():
    """Fuzzing found a NaN torque from virtual_power_torque at n_rpm = 5e-324 (ω underflows to 0: the power over ω
    was 0/0; the velocities per unit ω are used now) and a broadcasting ValueError for n_rpm = [1, 2] (one speed a
    cycle). At φ = 90° with massless links the static torque is F·r."""
    mech = SliderCrank(70.0, 250.0, rod_cg_mm=0.0)
    for fn in (joint_forces, virtual_power_torque):
        t = fn(mech, [90.0], 5e-324, 1e4, gravity_m_s2=0.0)
        t = t.torque_nm if hasattr(t, "torque_nm") else t
        assert float(t[0]) == pytest.approx(700.0, rel=1e-12)
        for speeds in ([1.0, 2.0], (), np.array([1700.0])):
            with pytest.raises(GearDesignError, match="n_rpm must be"):
                fn(mech, np.linspace(0.0, 720.0, 37), speeds, 1e4)


def test_the_fuzz_case_of_a_micrometre_crank_in_a_2000_mm_bore():
    """The reproducer reported as 'r = 0.001 mm on a 2000 mm bore' (a crank of radius 1 µm in a 2 m cylinder at
    n = 5e-324 rpm): virtual_power_torque gave NaN (0/0); both routes now agree on a finite torque."""
    mech = SliderCrank(crank_radius_mm=0.001, rod_length_mm=0.0035, rod_cg_mm=0.0, piston_mass_kg=0.6,
                       rod_mass_kg=0.7, rod_inertia_kg_m2=0.0617, cylinder_bore_mm=2000.0, offset_mm=0.00099)
    phi = np.linspace(0.0, 720.0, 37)
    t = virtual_power_torque(mech, phi, 5e-324, 1e7)
    f = joint_forces(mech, phi, 5e-324, 1e7)
    assert np.all(np.isfinite(t)) and np.allclose(t, f.torque_nm, rtol=1e-12, atol=1e-12 * np.abs(t).max())
