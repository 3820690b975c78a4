"""Worm efficiency: an independent mpmath implementation (SDP/SI's cos/cot form, not ours), the published
Niemann-Winter III Beispiel 3 figures (tests/data/worm_efficiency_examples.md), properties, bad input."""
import math

import mpmath as mp
import numpy as np
import pytest

from geardesign.errors import GearDesignError
from geardesign.gears.worm import efficiency as eff

mp.mp.dps = 40


def mp_eta(gamma_deg, mu, alpha_deg):
    """SDP/SI eq. (16-21): (cos α_n − μ tan γ)/(cos α_n + μ cot γ)."""
    g, a, m = mp.radians(mp.mpf(gamma_deg)), mp.radians(mp.mpf(alpha_deg)), mp.mpf(mu)
    return (mp.cos(a) - m * mp.tan(g)) / (mp.cos(a) + m * mp.cot(g))


def mp_eta_reverse(gamma_deg, mu, alpha_deg):
    """Wheel driving in the same form: (cos α_n − μ cot γ)/(cos α_n + μ tan γ)."""
    g, a, m = mp.radians(mp.mpf(gamma_deg)), mp.radians(mp.mpf(alpha_deg)), mp.mpf(mu)
    return (mp.cos(a) - m * mp.cot(g)) / (mp.cos(a) + m * mp.tan(g))


def designs(n=300, seed=14521):
    rng = np.random.default_rng(seed)
    return rng.uniform(0.5, 40.0, n), rng.uniform(0.0, 0.2, n), rng.uniform(0.0, 30.0, n)


def test_efficiencies_match_an_independent_mpmath_form_on_random_designs():
    gamma, mu, alpha = designs()
    eta = eff.efficiency_worm_driving(gamma, mu, alpha)
    eta_r = eff.efficiency_wheel_driving(gamma, mu, alpha)
    for i in range(len(gamma)):
        want = float(mp_eta(gamma[i], mu[i], alpha[i]))
        want_r = float(mp_eta_reverse(gamma[i], mu[i], alpha[i]))
        assert eta[i] == pytest.approx(want, rel=1e-12, abs=1e-13)
        assert eta_r[i] == pytest.approx(want_r, rel=1e-12, abs=1e-12)


def test_sliding_speed_matches_mpmath():
    rng = np.random.default_rng(3)
    d, n, g = rng.uniform(10, 300, 50), rng.uniform(10, 6000, 50), rng.uniform(1, 40, 50)
    got = eff.sliding_speed(d, n, g)
    for i in range(50):
        want = mp.mpf(d[i]) * mp.mpf(n[i]) * mp.pi / (60000 * mp.cos(mp.radians(mp.mpf(g[i]))))
        assert got[i] == pytest.approx(float(want), rel=1e-13)


# Niemann-Winter III Beispiel 3 as the DSoftCon report prints it (tests/data/worm_efficiency_examples.md)
NW_GAMMA = math.degrees(math.atan(10.42 / 83.2))     # d2/z2 = 416.8/40 = 10.42 mm, d1 = 83.2 mm, z1 = 1


def test_niemann_winter_example_3_friction_angles():
    assert float(eff.friction_angle_deg(0.120)) == pytest.approx(6.8428, abs=5e-5)     # printed ρ_zA
    # printed ρ_z = 1.4954° belongs to μ_z = 0.0261 (printed rounded to 0.026): arctan of it to 4 decimals
    assert float(eff.friction_angle_deg(0.0261)) == pytest.approx(1.4954, abs=5e-4)


def test_niemann_winter_example_3_efficiencies():
    mu = math.tan(math.radians(1.4954))                  # from the printed friction angle
    assert round(float(eff.efficiency_worm_driving(NW_GAMMA, mu)), 2) == 0.82
    assert round(float(eff.efficiency_wheel_driving(NW_GAMMA, mu)), 2) == 0.79
    assert round(float(eff.efficiency_worm_driving(NW_GAMMA, 0.120)), 3) == 0.503   # static, from rest
    assert not eff.self_locking(NW_GAMMA, mu)            # γ_m 7.14° > ρ_z 1.50°
    assert not eff.self_locking(NW_GAMMA, 0.120)         # γ_m 7.14° > ρ_zA 6.84°: not even at rest


def test_a_larger_lead_angle_raises_efficiency_below_the_optimum():
    # η = tan γ/tan(γ + ρ) rises with γ up to γ = 45° − ρ/2 (its maximum), then falls
    for mu, alpha in ((0.02, 0.0), (0.05, 20.0), (0.1, 14.5)):
        rho = float(eff.friction_angle_deg(mu, alpha))
        g = np.linspace(0.5, 45.0 - rho / 2, 400)
        assert np.all(np.diff(eff.efficiency_worm_driving(g, mu, alpha)) > 0)
        best = 45.0 - rho / 2
        assert eff.efficiency_worm_driving(best, mu, alpha) >= eff.efficiency_worm_driving(
            [best - 1e-3, best + 1e-3], mu, alpha).max()


def test_efficiency_falls_as_friction_rises():
    mu = np.linspace(0.0, 0.3, 301)
    for g in (2.0, 10.0, 30.0):
        e = eff.efficiency_worm_driving(g, mu, 20.0)
        assert e[0] == 1.0 and np.all(np.diff(e) < 0)
        assert np.all(np.diff(eff.efficiency_wheel_driving(g, mu, 20.0)) < 0)


def test_self_locking_iff_lead_angle_below_friction_angle():
    gamma, mu, alpha = designs(2000, seed=7)
    rho = eff.friction_angle_deg(mu, alpha)
    lock = eff.self_locking(gamma, mu, alpha)
    assert np.array_equal(lock, gamma <= rho)
    eta_r = eff.efficiency_wheel_driving(gamma, mu, alpha)
    assert np.all(eta_r[lock] <= 1e-15) and np.all(eta_r[~lock] > 0)
    assert lock.any() and (~lock).any()


def test_agma_friction_coefficient_against_the_printed_formula():
    v = np.array([0.0, 0.02, 0.05, 0.5, 2.0, 10.0, 25.0])
    got = eff.friction_coefficient_agma(v)
    for vi, fi in zip(v, got):
        vs = mp.mpf(vi) * 60 / mp.mpf("0.3048")          # m/s -> ft/min
        if vi == 0:
            want = mp.mpf("0.15")
        elif vs <= 10:
            want = mp.mpf("0.124") * mp.exp(mp.mpf("-0.074") * vs ** mp.mpf("0.645"))
        else:
            want = mp.mpf("0.103") * mp.exp(mp.mpf("-0.110") * vs ** mp.mpf("0.450")) + mp.mpf("0.012")
        assert fi == pytest.approx(float(want), rel=1e-13)
    assert np.all(np.diff(got) < 0)                      # friction falls as the sliding speed rises


def test_tooth_friction_iso_is_the_product_of_its_factors():
    assert float(eff.tooth_friction_iso(0.02)) == 0.02   # the reference gear: every factor 1
    assert float(eff.tooth_friction_iso(0.02, 1.1, 0.9, 1.2, 1.05)) == pytest.approx(0.02 * 1.1 * 0.9 * 1.2 * 1.05)
    with pytest.raises(GearDesignError, match="Y_W"):
        eff.tooth_friction_iso(0.02, Y_W=0.0)


def test_total_efficiency_is_output_over_input():
    P2, eta, p0, pl, pd = 3000.0, 0.85, 40.0, 25.0, 10.0
    P1 = P2 / eta + p0 + pl + pd                         # what the worm shaft takes in
    assert float(eff.total_efficiency(P2, eta, p0, pl, pd)) == pytest.approx(P2 / P1, rel=1e-14)
    assert float(eff.total_efficiency(P2, eta)) == pytest.approx(eta, rel=1e-15)
    assert float(eff.mesh_power_loss(P2, eta)) == pytest.approx(P2 / eta - P2, rel=1e-14)


@pytest.mark.parametrize("call, name", [
    (lambda: eff.efficiency_worm_driving(0.0, 0.05), "gamma_m_deg"),
    (lambda: eff.efficiency_worm_driving(50.0, 0.05), "gamma_m_deg"),
    (lambda: eff.efficiency_worm_driving(10.0, -0.01), "mu"),
    (lambda: eff.efficiency_worm_driving(10.0, float("nan")), "mu"),
    (lambda: eff.efficiency_worm_driving(10.0, 0.05, 50.0), "alpha_n_deg"),
    (lambda: eff.efficiency_worm_driving(45.0, 1.0), "gamma_m_deg"),
    (lambda: eff.sliding_speed(0.0, 1500, 5.0), "d_m1"),
    (lambda: eff.sliding_speed(50.0, -1, 5.0), "n1"),
    (lambda: eff.friction_coefficient_agma(-1.0), "v_g"),
    (lambda: eff.total_efficiency(0.0, 0.9), "P2"),
    (lambda: eff.total_efficiency(100.0, 0.9, P_V0=-1.0), "P_V0"),
    (lambda: eff.mesh_power_loss(100.0, 0.0), "eta_z"),
])
def test_bad_input_is_refused_by_name(call, name):
    with pytest.raises(GearDesignError, match=name):
        call()


def test_efficiency_at_speed_is_its_parts_over_arrays():
    d, n, g = np.array([40.0, 80.0, 120.0]), np.array([300.0, 1500.0, 3000.0]), np.array([3.0, 11.3, 21.8])
    v, mu, eta = eff.efficiency_at_speed(d, n, g, 20.0)
    assert np.array_equal(v, eff.sliding_speed(d, n, g))
    assert np.array_equal(mu, eff.friction_coefficient_agma(v))
    assert np.array_equal(eta, eff.efficiency_worm_driving(g, mu, 20.0))
    v2, mu2, eta2 = eff.efficiency_at_speed(d, n, g, 0.0, mu=0.03)
    assert mu2.shape == (3,) and np.all(mu2 == 0.03)
    assert np.array_equal(eta2, eff.efficiency_worm_driving(g, 0.03, 0.0))
