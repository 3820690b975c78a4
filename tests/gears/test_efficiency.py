"""Mesh power loss (geardesign.gears.efficiency): the FZG gears' printed gear loss factors (tests/data/
efficiency_examples.md), an oil data sheet's viscosities, and independent implementations of the viscosity
line and of H_V (the sliding integrated over the path of contact with scipy's quad)."""
from __future__ import annotations

import itertools
import math
from pathlib import Path

import mpmath
import numpy as np
import pandas as pd
import pytest
from scipy.integrate import quad

from geardesign.errors import GearDesignError
from geardesign.gears.efficiency import (
    Lubricant,
    dynamic_viscosity,
    gear_loss_factor_integrated,
    gear_loss_factor_ohlendorf,
    kinematic_viscosity,
    mean_friction_coefficient,
    mesh_loss,
    oil_density,
    tip_contact_ratios,
    walther_constants,
)
from geardesign.gears.pair import GearPair

DATA = Path(__file__).resolve().parents[1] / "data"
CASES = pd.read_csv(DATA / "efficiency_examples.csv")


def _pair(row):
    return GearPair(row.m_n_mm, int(row.z1), int(row.z2), row.x1, row.x2, beta_deg=row.beta_deg,
                    face_width_mm=row.b_mm)


@pytest.mark.parametrize("row", list(CASES.itertuples()), ids=list(CASES["case"]))
def test_fzg_gears_geometry_as_printed(row):
    g = _pair(row).geometry()
    assert g.a_w == pytest.approx(row.a_w_mm, abs=5e-4)
    assert g.da1 / 2 == pytest.approx(row.tip_radius1_mm, abs=1e-3)
    assert g.da2 / 2 == pytest.approx(row.tip_radius2_mm, abs=1e-3)
    assert g.eps_alpha == pytest.approx(row.eps_alpha, abs=0.005)
    assert g.eps_beta == pytest.approx(row.eps_beta, abs=0.005)


@pytest.mark.parametrize("row", list(CASES.itertuples()), ids=list(CASES["case"]))
def test_fzg_gear_loss_factors_as_printed(row):
    loss = mesh_loss(_pair(row), 200.0, 1500.0, 46.23)
    assert loss.H_V_ohlendorf == pytest.approx(row.H_V_ohlendorf, abs=5e-5)
    assert loss.H_V == pytest.approx(row.H_V_integrated, abs=row.H_V_integrated_tol)


def test_nrel_stage3_gear_power_loss_is_niemanns_with_ohlendorfs_h_v():
    """A helical stage's printed mesh loss (issue 37 proof): the KISSsoft report of the NREL 5 MW stage 3
    (tests/data/iso6336_nrel_stage3_kisssoft.md, "Mesh power loss") prints μ_m = 0.030 (3 decimals) and
    P_VZ = 15.635 kW at 5000 kW. P_VZ = P·μ_m·H_V with our Ohlendorf H_V gives back a μ_m that rounds to the
    printed one; the efficiency is 1 − P_VZ/P as printed."""
    printed = pd.read_csv(DATA / "efficiency_nrel_stage3_kisssoft.csv").set_index("quantity")["value"]
    pair = GearPair(14.0, 24, 95, 0.48, 0.6691, beta_deg=10.0, face_width_mm=360.0)
    beta_b = math.degrees(math.asin(math.sin(math.radians(10.0)) * math.cos(math.radians(20.0))))
    e1, e2 = tip_contact_ratios(pair.geometry())
    H_V = float(gear_loss_factor_ohlendorf(24, 95 / 24, beta_b, e1, e2))
    mu = printed["P_VZ"] / (printed["P"] * H_V)
    assert round(mu, 3) == printed["mu_m"]
    assert round(100 * (1 - printed["P_VZ"] / printed["P"]), 3) == printed["eta_z"]
    # the integrated H_V is another quantity: with it the printed loss would need μ_m ≈ 0.025
    H_int = float(gear_loss_factor_integrated(24, 95 / 24, beta_b, e1, e2, eps_beta=float(pair.geometry().eps_beta)))
    assert round(printed["P_VZ"] / (printed["P"] * H_int), 3) != printed["mu_m"]


def _n_contacts(x, x_a, x_e):
    """Tooth pairs in contact when one of them is at x (positions x + k, base pitch 1)."""
    k = np.arange(-5, 6)
    pos = x + k
    return int(np.sum((pos >= x_a - 1e-15) & (pos <= x_e + 1e-15)))


def _h_v_quad(z1, u, eps1, eps2):
    """H_V = (u+1)/(u r_b1) (1/p) ∫ |x| / N(x) dx over the path (p = 1, r_b1 = z1/2π), by quad between the
    points where N changes: the load shared equally between the pairs in contact (Ohlendorf's assumption)."""
    x_a, x_e = -eps2, eps1
    pts = sorted({float(v) for v in np.clip([x_a, x_e, 0.0, x_a + 1, x_e - 1, x_a + 2, x_e - 2], x_a, x_e)})
    f = lambda x: abs(x) / _n_contacts(x, x_a, x_e)
    total = sum(quad(f, a, b, epsabs=1e-14, epsrel=1e-13)[0] for a, b in itertools.pairwise(pts) if b > a)
    return (u + 1) / (u * z1 / (2 * math.pi)) * total


def test_ohlendorf_is_the_integral_of_the_sliding_over_the_path():
    rng = np.random.default_rng(37)
    for _ in range(40):
        z1, u = int(rng.integers(8, 80)), float(rng.uniform(1.0, 6.0))
        eps_alpha = rng.uniform(1.05, 1.95)
        eps1 = rng.uniform(eps_alpha - 1.0 + 0.02, 0.98)
        eps2 = eps_alpha - eps1
        if not 0 < eps2 < 1:
            continue
        closed = float(gear_loss_factor_ohlendorf(z1, u, 0.0, eps1, eps2))
        assert _h_v_quad(z1, u, eps1, eps2) == pytest.approx(closed, rel=1e-9)
        assert gear_loss_factor_integrated(z1, u, 0.0, eps1, eps2) == pytest.approx(closed, rel=1e-12)


def _h_v_grid(z1, u, beta_b_deg, eps1, eps2, eps_beta, n_phase=1500, n_face=300):
    """Independent brute force: points on the lines of contact on a phase × face grid (midpoints), the load
    spread evenly over the contact length, mean |x| averaged over the phase."""
    s = (np.arange(n_phase) + 0.5) / n_phase
    y = (np.arange(n_face) + 0.5) / n_face * eps_beta
    k = np.arange(-6, 7)
    x = s[:, None, None] + k[None, :, None] + y[None, None, :]
    inside = (x >= -eps2) & (x <= eps1)
    mean = np.sum(np.where(inside, np.abs(x), 0.0), axis=(1, 2)) / np.sum(inside, axis=(1, 2))
    return (u + 1) / (u * z1 / (2 * math.pi) * math.cos(math.radians(beta_b_deg))) * mean.mean()


@pytest.mark.parametrize("eps1, eps2, eps_beta", [(0.7, 0.75, 0.54), (0.45, 0.48, 1.0), (0.8, 0.9, 2.3),
                                                   (0.6, 0.5, 0.1)])
def test_integrated_h_v_of_helical_pairs_against_a_brute_force_grid(eps1, eps2, eps_beta):
    exact = gear_loss_factor_integrated(20, 1.5, 14.0, eps1, eps2, eps_beta)
    assert _h_v_grid(20, 1.5, 14.0, eps1, eps2, eps_beta) == pytest.approx(exact, rel=2e-3)


def test_integrated_h_v_with_a_whole_overlap_is_the_mean_sliding_over_the_path():
    # ε_β a whole number: the contact length in mesh is constant, the load uniform over the whole path,
    # H_V = (u+1)/(u r_b1 cos β_b) · mean |x| over [−ε2, ε1] = ... (ε1² + ε2²)/(2 ε_α)
    e1, e2, z1, u = 0.8, 0.6, 25, 2.0
    expect = (u + 1) / (u * z1 / (2 * math.pi)) * (e1 ** 2 + e2 ** 2) / (2 * (e1 + e2))
    assert gear_loss_factor_integrated(z1, u, 0.0, e1, e2, 1.0) == pytest.approx(expect, rel=1e-12)
    assert gear_loss_factor_integrated(z1, u, 0.0, e1, e2, 2.0) == pytest.approx(expect, rel=1e-12)


def test_internal_pair_slides_at_the_difference_of_the_speeds():
    e1, e2 = 0.7, 0.8
    ext = float(gear_loss_factor_ohlendorf(20, 3.0, 0.0, e1, e2))
    internal = float(gear_loss_factor_ohlendorf(20, 3.0, 0.0, e1, e2, internal=True))
    assert internal / ext == pytest.approx((3.0 - 1.0) / (3.0 + 1.0), rel=1e-14)
    assert gear_loss_factor_integrated(20, 3.0, 0.0, e1, e2, internal=True) == pytest.approx(internal, rel=1e-12)


def test_tip_contact_ratios_add_up_to_eps_alpha_for_internal_pairs():
    g = GearPair(2.0, 20, 60, 0.2, 0.3, internal=True).geometry()
    e1, e2 = tip_contact_ratios(g, internal=True)
    assert float(e1) > 0 and float(e2) > 0
    assert float(e1 + e2) == pytest.approx(g.eps_alpha, rel=1e-14)


def test_viscosity_reproduces_the_oil_data_sheet():
    # LIQUI MOLY SAE 75W: ν40 30.8, ν100 5.9; printed ν80 9.12, ν90 7.25 mm²/s (tests/data/efficiency_examples.md)
    din = kinematic_viscosity(30.8, 5.9, np.array([80.0, 90.0]), c=0.8)
    assert np.round(din, 2).tolist() == [9.12, 7.25]
    astm = kinematic_viscosity(30.8, 5.9, np.array([80.0, 90.0]))
    assert astm == pytest.approx([9.12, 7.25], rel=0.005)


def test_viscosity_against_an_independent_high_precision_line():
    mpmath.mp.dps = 40
    rng = np.random.default_rng(3)
    for _ in range(50):
        nu40 = float(rng.uniform(10, 1500))
        nu100 = float(nu40 / rng.uniform(3, 25))
        if nu100 < 2.0:
            continue
        t = float(rng.uniform(-20, 150))
        lg = lambda v: mpmath.log10(mpmath.log10(mpmath.mpf(v) + mpmath.mpf("0.7")))
        x = lambda tc: mpmath.log10(mpmath.mpf(tc) + mpmath.mpf("273.15"))
        w = lg(nu40) + (lg(nu100) - lg(nu40)) * (x(t) - x(40)) / (x(100) - x(40))
        ref = float(mpmath.power(10, mpmath.power(10, w)) - mpmath.mpf("0.7"))
        assert float(kinematic_viscosity(nu40, nu100, t)) == pytest.approx(ref, rel=1e-9)
    # and the line passes through its two points
    assert float(kinematic_viscosity(220.0, 19.0, 40.0)) == pytest.approx(220.0, rel=1e-12)
    assert float(kinematic_viscosity(220.0, 19.0, 100.0)) == pytest.approx(19.0, rel=1e-12)


def test_walther_constants_of_the_gearpie_m320_oil():
    # GEARpie's M320 line: A = 9.0658, B = 3.4730; at 75 °C ν = 53.10 mm²/s, η = 46.23 mPa·s with ρ15 = 902
    nu = lambda t: 10 ** 10 ** (9.0658 - 3.4730 * math.log10(t + 273.15)) - 0.7
    A, B = walther_constants(nu(40), 40, nu(100), 100)
    assert (float(A), float(B)) == pytest.approx((9.0658, 3.4730), rel=1e-12)
    oil = Lubricant(nu(40), nu(100), 902.0)
    assert round(float(oil.viscosity_mm2s(75.0)), 2) == 53.10
    assert round(float(oil.dynamic_viscosity_mpas(75.0)), 2) == 46.23
    assert float(dynamic_viscosity(53.10, oil_density(902.0, 75.0))) == pytest.approx(46.23, abs=0.005)


def test_mean_friction_coefficient_follows_its_exponents():
    base = float(mean_friction_coefficient(400.0, 4.0, 8.0, 40.0, 0.5, 1.0))
    ref = 0.048 * (400.0 / (4.0 * 8.0)) ** 0.2 * 40.0 ** -0.05 * 0.5 ** 0.25
    assert base == pytest.approx(ref, rel=1e-14)
    assert float(mean_friction_coefficient(800.0, 4.0, 8.0, 40.0, 0.5)) / base == pytest.approx(2 ** 0.2, rel=1e-14)
    assert float(mean_friction_coefficient(400.0, 4.0, 8.0, 80.0, 0.5)) / base == pytest.approx(2 ** -0.05, rel=1e-14)
    assert float(mean_friction_coefficient(400.0, 4.0, 8.0, 40.0, 1.0)) / base == pytest.approx(2 ** 0.25, rel=1e-14)


def test_mesh_loss_of_the_fzg_c_gear_by_hand():
    pair = GearPair(4.5, 16, 24, 0.1817, 0.1715, face_width_mm=14)
    loss = mesh_loss(pair, 200.0, 1500.0, 46.23, 0.6, 0.846)
    g = pair.geometry()
    aw = math.radians(g.alpha_w_deg)
    v_t = 1500 * math.pi / 30 * g.dw1 / 2000
    F_bt = 2000 * 200 / g.db1
    assert F_bt == pytest.approx(5912.1, abs=0.05)         # GEARpie C14: "Base circle load F_bt: 5912.1 N"
    rho = g.dw1 / 2 * math.sin(aw) * 1.5 / 2.5
    mu = 0.048 * (F_bt / 14 / (2 * v_t * math.sin(aw) * rho)) ** 0.2 * 46.23 ** -0.05 * 0.6 ** 0.25 * 0.846
    assert loss.mu_mz == pytest.approx(mu, rel=1e-12)
    assert loss.power_w == pytest.approx(31415.9, abs=0.05)  # GEARpie C14: "Pin: 31415.9 W"
    assert loss.loss_w == pytest.approx(loss.power_w * mu * loss.H_V, rel=1e-12)


def test_bad_inputs_name_themselves():
    pair = GearPair(4.5, 16, 24, 0.1817, 0.1715)
    with pytest.raises(GearDesignError, match="face_width_mm"):
        mesh_loss(pair, 200.0, 1500.0, 46.23)
    with pytest.raises(GearDesignError, match="Ra_um"):
        mesh_loss(pair, 200.0, 1500.0, 46.23, Ra_um=-1, face_width_mm=14)
    with pytest.raises(GearDesignError, match="method"):
        mesh_loss(pair, 200.0, 1500.0, 46.23, face_width_mm=14, method="fast")
    with pytest.raises(GearDesignError, match="nu100"):
        Lubricant(100.0, 120.0)
    with pytest.raises(GearDesignError, match="temperature_c"):
        kinematic_viscosity(100.0, 11.0, float("nan"))
    with pytest.raises(GearDesignError, match="nu40"):
        kinematic_viscosity(1.0, 0.5, 40.0)


def test_integrated_h_v_of_high_contact_ratio_spur_pairs_against_quad():
    # ε_α > 2: two or three pairs share the load; Ohlendorf's form does not apply, the integral does
    rng = np.random.default_rng(11)
    for _ in range(20):
        eps_alpha = rng.uniform(2.05, 2.9)
        eps1 = rng.uniform(0.3, eps_alpha - 0.3)
        z1, u = int(rng.integers(20, 60)), float(rng.uniform(1.0, 4.0))
        expect = _h_v_quad(z1, u, eps1, eps_alpha - eps1)
        assert gear_loss_factor_integrated(z1, u, 0.0, eps1, eps_alpha - eps1) == pytest.approx(expect, rel=1e-9)


def test_internal_pair_mesh_loss():
    pair = GearPair(2.0, 20, 60, 0.2, 0.3, internal=True, face_width_mm=20)
    loss = mesh_loss(pair, 50.0, 1500.0, 30.0)
    assert loss.H_V == pytest.approx(loss.H_V_ohlendorf, rel=1e-12)
    g = pair.geometry()
    rho1 = g.dw1 / 2 * math.sin(math.radians(g.alpha_w_deg))
    rho2 = g.dw2 / 2 * math.sin(math.radians(g.alpha_w_deg))
    assert loss.rho_red_c_mm == pytest.approx(rho1 * rho2 / (rho2 - rho1), rel=1e-12)   # concave ring flank


def test_iso_vg_grades():
    assert Lubricant.iso_vg(320, 24.0).nu40 == 320.0
    with pytest.raises(GearDesignError, match="ISO 3448"):
        Lubricant.iso_vg(300, 24.0)


def test_gearpie_c14_mesh_loss():
    """GEARpie's report C14 (commit 40fc512e, tests/data/efficiency_examples.md): the whole load-dependent loss
    of the FZG type C pair at 200 N·m, 1 500 rpm, M32 oil at 60 °C, with the tolerances that note explains."""
    row = next(pd.read_csv(DATA / "efficiency_loss_examples.csv").itertuples())
    pair = GearPair(row.m_n_mm, int(row.z1), int(row.z2), row.x1, row.x2, beta_deg=row.beta_deg,
                    face_width_mm=row.b_mm, tip_shortening=bool(row.tip_shortening))
    loss = mesh_loss(pair, row.torque1_nm, row.n1_rpm, row.eta_mpas, (row.Ra1_um + row.Ra2_um) / 2,
                     row.lubricant_factor)
    assert round(loss.power_w, 1) == row.printed_P_in_w
    assert round(loss.v_t_m_s, 2) == row.printed_v_t_m_s
    assert round(loss.F_bt_n, 1) == row.printed_F_bt_n
    assert round(loss.H_V_ohlendorf, 4) == row.printed_H_V_ohlendorf
    assert loss.H_V == pytest.approx(loss.H_V_ohlendorf, rel=1e-9)      # spur: the integral is Ohlendorf's
    # GEARpie's own arithmetic: P_VZP = P_in·μ_mZ·H_VL from its printed factors (μ printed to 3 digits)
    assert row.printed_P_in_w * row.printed_mu_mz * row.printed_H_V_grid == pytest.approx(row.printed_P_VZP_w,
                                                                                         rel=0.002)
    assert loss.mu_mz == pytest.approx(row.printed_mu_mz, rel=0.005)
    assert loss.loss_w == pytest.approx(row.printed_P_VZP_w, rel=0.03)
    eta_printed = 1 - row.printed_P_VZP_w / row.printed_P_in_w
    assert 1 - loss.loss_w / loss.power_w == pytest.approx(eta_printed, abs=3e-4)


def test_a_vanishing_helix_or_width_gives_a_number_or_one_line():
    # fuzzing: β = 1e-300 gave a NaN mesh loss (0/0 in the overlap's integration), a face width of 5e-324 mm an
    # infinite line load and NaN μ; a vanishing helix is a spur pair (H_V to 1e-9), a sub-micrometre width refused
    import math

    from geardesign.errors import GearDesignError
    from geardesign.gears.efficiency import gear_loss_factor_integrated, mesh_loss
    from geardesign.gears.pair import GearPair

    assert gear_loss_factor_integrated(21, 26 / 21, 0.0, 0.7, 0.8, 1e-302) == \
        gear_loss_factor_integrated(21, 26 / 21, 0.0, 0.7, 0.8, 0.0)
    spur = mesh_loss(GearPair(10, 21, 26, 0.3, 0.2, face_width_mm=40), 100.0, 1450, 50.0)
    tiny = mesh_loss(GearPair(10, 21, 26, 0.3, 0.2, beta_deg=1e-300, face_width_mm=40), 100.0, 1450, 50.0)
    assert math.isfinite(tiny.loss_w) and tiny.loss_w == pytest.approx(spur.loss_w, rel=1e-12)
    with pytest.raises(GearDesignError, match="face_width_mm must be in"):
        mesh_loss(GearPair(10, 21, 26, 0.3, 0.2, face_width_mm=5e-324), 100.0, 1450, 50.0)


@pytest.mark.parametrize("args, kwargs, missing", [((), {}, ("nu40", "nu100")), ((320.0,), {}, ("nu100",)),
                                                    ((), {"nu100": 24.0}, ("nu40",)),
                                                    ((), {"density15_kg_m3": 880.0}, ("nu40", "nu100"))])
def test_a_lubricant_without_its_viscosities_is_refused_by_name(args, kwargs, missing):
    """Lubricant() raised Python's own TypeError ('missing 2 required positional arguments'): now one
    GearDesignError naming each missing viscosity with its unit and range (as gd.Load(torque=100) hints)."""
    with pytest.raises(GearDesignError) as e:
        Lubricant(*args, **kwargs)
    text = str(e.value)
    assert text.startswith(f"Lubricant needs {', '.join(missing)} (missing)")
    for name in missing:
        assert f"{name}: the kinematic viscosity at {name[2:]} °C" in text and "mm²/s, in [2, 1e6]" in text
    with pytest.raises(GearDesignError, match=r"Lubricant.iso_vg\(220, nu100\)"):
        Lubricant(grade=220)
    assert Lubricant(nu100=24.0, nu40=320.0) == Lubricant(320.0, 24.0)
