"""Worm load capacity: forces against SDP/SI's normal-force form in mpmath, the power balance, the beam
deflection, the closed-form load capacity against a numerical inversion of the rating, the checks a rating
leaves out and says so, self-locking flags, bad input by name."""
import json
import math

import mpmath as mp
import numpy as np
import pytest
from scipy.optimize import brentq

from geardesign.errors import GearDesignError
from geardesign.gears.worm import efficiency as eff
from geardesign.gears.worm import rating as rt
from geardesign.gears.worm.temperature import housing_area_estimate

mp.mp.dps = 40


def test_forces_match_sdp_si_normal_force_form_in_mpmath():
    rng = np.random.default_rng(16)
    for _ in range(200):
        T2, d2 = rng.uniform(1, 5000), rng.uniform(20, 800)
        g, a, mu = rng.uniform(1, 40), rng.uniform(10, 30), rng.uniform(0, 0.15)
        rho = float(eff.friction_angle_deg(mu, a))
        F_t2, F_t1, F_r = rt.mesh_forces(T2, d2, g, a, rho)
        # SDP/SI eq. (16-20), worm driving: F_u2 = F_a1 = F_n (cos α_n cos γ − μ sin γ)
        G, A, M = mp.radians(mp.mpf(g)), mp.radians(mp.mpf(a)), mp.mpf(mu)
        Ft2 = 2000 * mp.mpf(T2) / mp.mpf(d2)
        Fn = Ft2 / (mp.cos(A) * mp.cos(G) - M * mp.sin(G))
        assert F_t2 == pytest.approx(float(Ft2), rel=1e-14)
        assert F_t1 == pytest.approx(float(Fn * (mp.cos(A) * mp.sin(G) + M * mp.cos(G))), rel=1e-12)
        assert F_r == pytest.approx(float(Fn * mp.sin(A)), rel=1e-12)


def test_power_balance_of_the_forces():
    # T1·u·η_z = T2: the worm torque from F_t1 at d_m1 against the wheel torque, for q·m_x and z2·m_x
    m_x, z1, z2, q, mu, alpha = 5.0, 2, 41, 9.0, 0.04, 20.0
    g = float(rt.mean_lead_angle_deg(z1, q))
    rho = float(eff.friction_angle_deg(mu, alpha))
    F_t2, F_t1, _ = rt.mesh_forces(800.0, float(rt.wheel_reference_diameter(m_x, z2)), g, alpha, rho)
    T1 = F_t1 * float(rt.worm_reference_diameter(m_x, q)) / 2000.0
    assert T1 * (z2 / z1) * float(eff.efficiency_worm_driving(g, mu, alpha)) == pytest.approx(800.0, rel=1e-13)


def test_worm_deflection_is_the_mid_span_beam_formula():
    F_t1, F_r, l, d, E = 1200.0, 3500.0, 280.0, 42.5, 210000.0
    I = mp.pi * mp.mpf(d) ** 4 / 64
    want = mp.sqrt(mp.mpf(F_t1) ** 2 + mp.mpf(F_r) ** 2) * mp.mpf(l) ** 3 / (48 * mp.mpf(E) * I)
    assert float(rt.worm_deflection(F_t1, F_r, l, d, E)) == pytest.approx(float(want), rel=1e-14)
    assert float(rt.deflection_limit(8.0)) == pytest.approx(0.032)            # Autodesk: 0.004·m hardened
    assert float(rt.deflection_limit(8.0, hardened=False)) == pytest.approx(0.08)


def test_mean_contact_stress_grows_with_the_root_of_the_torque():
    s = rt.mean_contact_stress(np.array([100.0, 400.0]), 125.0, 0.9, 150000.0)
    assert s[1] / s[0] == pytest.approx(2.0, rel=1e-14)
    want = 4 / mp.pi * mp.sqrt(mp.mpf("0.9") * 100 * 1000 * 150000 / mp.mpf(125) ** 3)
    assert s[0] == pytest.approx(float(want), rel=1e-14)
    assert float(rt.reduced_modulus(206000, 0.3, 206000, 0.3)) == pytest.approx(206000 / (1 - 0.09), rel=1e-14)


def full_rating(T2=600.0, **over):
    kw = dict(n1=1500.0, m_x=6.3, z1=2, z2=41, q=10.0, b_2=55.0, l_1=260.0, p_m_star=0.9,
              E_red=float(rt.reduced_modulus(206000, 0.3, 98000, 0.35)), sigma_HG=400.0, Y_root=1.2, tau_FG=90.0,
              k_heat=18.0, A_housing=float(housing_area_estimate(160.0)), P_V0=60.0)
    kw.update(over)
    return rt.worm_rating(T2, **kw)


def test_a_full_rating_is_consistent_with_its_parts():
    r = full_rating()
    g = float(rt.mean_lead_angle_deg(2, 10.0))
    assert r.v_g == pytest.approx(float(eff.sliding_speed(63.0, 1500.0, g)), rel=1e-15)
    assert r.mu == pytest.approx(float(eff.friction_coefficient_agma(r.v_g)), rel=1e-15)
    assert r.eta_z == pytest.approx(float(eff.efficiency_worm_driving(g, r.mu, 20.0)), rel=1e-15)
    P2 = 600.0 * 1500.0 / 20.5 * math.pi / 30.0
    assert r.P_V == pytest.approx(P2 / r.eta_z - P2 + 60.0, rel=1e-13)
    assert r.eta_total == pytest.approx(P2 / (P2 + r.P_V), rel=1e-13)
    assert r.S_H == pytest.approx(400.0 / r.sigma_Hm) and r.S_F == pytest.approx(90.0 / r.tau_F)
    assert r.S_delta == pytest.approx(0.004 * 6.3 / r.delta_m)
    assert math.isnan(r.S_W) and "S_W" not in r.margins
    assert set(r.factors["symbol"]) >= {"v_g", "mu", "eta_z", "sigma_Hm", "tau_F", "delta_m", "theta_S", "S_T"}
    assert r.factors["method"].str.len().min() > 5           # every row says where it comes from
    json.dumps(r.to_dict())
    assert len(repr(r).splitlines()) <= 15


def test_load_capacity_matches_a_numerical_inversion_of_the_rating():
    r = full_rating(P_V0=60.0)
    cap = rt.load_capacity(r, P_const=60.0)
    for check in ("S_H", "S_F", "S_delta", "S_T"):
        def excess(T2, check=check):
            return getattr(full_rating(T2), check) / r.minimums[check] - 1.0
        assert cap[check] == pytest.approx(brentq(excess, 1.0, 1e6, xtol=1e-10, rtol=1e-14), rel=1e-9)
    assert cap["T2_max"] == min(cap[k] for k in ("S_H", "S_F", "S_delta", "S_T"))
    at_max = full_rating(cap["T2_max"])
    assert at_max.governing[0] == cap["governing"] and at_max.governing[1] == pytest.approx(0.0, abs=1e-9)


def test_checks_without_inputs_are_not_computed_and_say_why():
    r = rt.worm_rating(300.0, 1000.0, 4.0, 1, 30, 10.0)
    assert all(math.isnan(getattr(r, k)) for k in ("S_H", "S_F", "S_delta", "S_T", "S_W"))
    assert not r.ok and r.governing == ("", r.governing[1])
    text = " ".join(r.notes)
    for k in ("S_H", "S_F", "S_delta", "S_T", "S_W"):
        assert f"{k} not computed" in text or f"{k} (wear) not computed" in text
    with pytest.raises(GearDesignError, match="no computed check"):
        rt.load_capacity(r)
    assert r.eta_z > 0 and r.friction_method.startswith("AGMA")


def test_static_and_dynamic_self_locking():
    # z1 = 1, q = 20: γ_m = 2.86°; at rest μ = 0.15 (AGMA) gives ρ' = 9.07° with α_n = 20°: locks
    fast = rt.worm_rating(50.0, 3000.0, 2.0, 1, 40, 20.0)
    assert fast.self_locking_static and not fast.self_locking_dynamic and fast.eta_z_reverse > 0
    creeping = rt.worm_rating(50.0, 5.0, 2.0, 1, 40, 20.0)          # v_g ≈ 0.01 m/s: friction near rest
    assert creeping.self_locking_dynamic and creeping.eta_z_reverse <= 0
    assert any("self-locking" in n for n in creeping.notes)
    steep = rt.worm_rating(50.0, 3000.0, 2.0, 4, 40, 8.0)           # γ_m = 26.6°: never locks
    assert not steep.self_locking_static and not steep.self_locking_dynamic
    given = rt.worm_rating(50.0, 3000.0, 2.0, 1, 40, 20.0, mu=0.06, mu_static=0.02)
    assert given.friction_method == "given" and given.mu == 0.06 and not given.self_locking_static


@pytest.mark.parametrize("kw, name", [
    (dict(T2=0.0), "T2"), (dict(T2=[1.0, 2.0]), "T2"), (dict(n1=-5.0), "n1"), (dict(z1=0), "z1"),
    (dict(q=1.0), "q"), (dict(mu=-0.1), "mu"), (dict(minimums={"S_X": 1.0}), "minimums"),
    (dict(minimums={"S_H": 0.0}), "minimums"), (dict(l_1=-3.0), "l_1"), (dict(sigma_HG=0.0), "sigma_HG"),
    (dict(k_heat=-1.0), "k_heat"), (dict(x2=5.0), "x2"),
])
def test_bad_input_is_refused_by_name(kw, name):
    args = dict(T2=300.0, n1=1000.0, m_x=4.0, z1=1, z2=30, q=10.0, b_2=40.0, Y_root=1.0, tau_FG=80.0,
                p_m_star=0.9, E_red=150000.0, sigma_HG=400.0, l_1=200.0, k_heat=15.0, A_housing=0.4)
    args.update(kw)
    T2, n1, m_x, z1, z2, q = (args.pop(k) for k in ("T2", "n1", "m_x", "z1", "z2", "q"))
    with pytest.raises(GearDesignError, match=name):
        rt.worm_rating(T2, n1, m_x, z1, z2, q, **args)


def test_worm_pair_rates_on_its_own_geometry():
    import geardesign as gd
    # ZN: the rack's α is the normal one, so the pair's α_n, d_f1 are worm_rating's defaults (c* = 0.25)
    pair = gd.WormPair(6.3, 2, 41, 10.0, flank_form="ZN")
    kw = dict(l_1=260.0, k_heat=28.0, A_housing=1.1, P_V0=60.0)
    a = pair.rating(600.0, 1500.0, **kw)
    b = rt.worm_rating(600.0, 1500.0, 6.3, 2, 41, 10.0, **kw)
    for k in ("v_g", "mu", "rho_deg", "eta_z", "eta_z_reverse", "F_t1", "F_r", "delta_m", "S_delta", "S_T"):
        assert getattr(a, k) == pytest.approx(getattr(b, k), rel=1e-13), k
    assert set(a.factors.set_index("symbol").loc[["d_m1", "a", "d_f1"], "method"]) == {"WormPair geometry (DIN 3975)"}
    e = pair.efficiency(1500.0)
    assert e["eta_z"] == pytest.approx(a.eta_z, rel=1e-15) and e["self_locking_static"] == a.self_locking_static
    # ZA: α is axial, the pair's α_n = arctan(tan 20° cos γ_m) goes into the friction angle and the forces
    za = gd.WormPair(6.3, 2, 41, 10.0, flank_form="ZA").efficiency(1500.0, mu=0.05)
    g = math.atan(0.2)
    alpha_n = math.degrees(math.atan(math.tan(math.radians(20.0)) * math.cos(g)))
    assert za["eta_z"] == pytest.approx(float(eff.efficiency_worm_driving(math.degrees(g), 0.05, alpha_n)), rel=1e-14)


def test_an_unknown_rating_option_is_refused_by_name():
    import geardesign as gd
    with pytest.raises(GearDesignError, match="unknown rating option 'k_heta'.*k_heat"):
        rt.worm_rating(300.0, 1000.0, 4.0, 1, 30, 10.0, k_heta=15.0)
    with pytest.raises(GearDesignError, match="unknown rating option 'b_2'"):
        gd.WormPair(4.0, 1, 30, 10.0).rating(300.0, 1000.0, b_2=40.0)     # the pair's width is face_width_mm
    # the list of options is rate_geometry's keywords
    import inspect
    assert rt._RATE_OPTIONS == tuple(p for p in inspect.signature(rt.rate_geometry).parameters
                                     if p not in ("T2", "n1", "geo"))


def test_html_view_says_which_checks_were_not_computed():
    r = rt.worm_rating(300.0, 1000.0, 4.0, 1, 30, 10.0, l_1=200.0)
    html = r._repr_html_()
    assert "not computed" in html and "nan" not in html and f"{r.S_delta:.3f}" in html
