"""Planetary sets of given shifts: coaxiality, the ring shift that gives it, kinematics, assembly,
neighbours, and the chain rule that carries the planet-ring mesh's gradients to (x_sun, x_planet).

Sources: LECAD, University of Ljubljana, "Analysis of Planetary Transmissions", test run of the pg
program (tests/data/internal_helical_examples.csv, rows P1_planetary_21_43_108); the 50-digit
involute relations of ISO 21771:2007 eq. (62) written again here with mpmath.
"""
import math

import mpmath as mp
import numpy as np
import pytest
from hypothesis import example, given, settings, strategies as st

import geardesign as gd
from geardesign.gears import planetary as pl
from geardesign.shifts.planetary import PlanetaryProblem

mp.mp.dps = 50


def mp_ring_shift(m, z_s, z_p, z_r, x_s, x_p, alpha_deg=20):
    """x_r of the coaxial set and the common a_w, in 50 digits (external sun-planet mesh, internal
    planet-ring mesh, GOST 19274-73 sign of the ring's shift)."""
    a = mp.radians(alpha_deg)
    inv = lambda t: mp.tan(t) - t   # noqa: E731
    inv_w = inv(a) + 2 * (mp.mpf(x_s) + mp.mpf(x_p)) * mp.tan(a) / (z_s + z_p)
    if inv_w <= 0:   # no sun-planet mesh: inv α_w must be > 0 (findroot would return a negative angle)
        return None, None
    aw_a = mp.findroot(lambda t: inv(t) - inv_w, mp.mpf("0.5"))
    a_w = mp.mpf(m) * (z_s + z_p) * mp.cos(a) / (2 * mp.cos(aw_a))
    cos_b = mp.mpf(m) * (z_r - z_p) * mp.cos(a) / (2 * a_w)
    if cos_b >= 1:   # the planet-ring mesh cannot reach this a_w
        return None, a_w
    aw_b = mp.acos(cos_b)
    return mp.mpf(x_p) + (z_r - z_p) * (inv(aw_b) - inv(a)) / (2 * mp.tan(a)), a_w


def test_lecad_set_is_coaxial_to_its_printed_precision():
    # printed: m 1.75, z 21/43/108, 3 planets, x 0.4380/0.0426/0.0000 (4 decimals), a = 56.8 mm (0.1 mm),
    # ratio 6.14286; the shifts' rounding (±5e-5 each) moves each mesh's a_w by at most
    # m·(|∂a_w/∂x_Σ| ≈ 1)·1e-4: the meshes agree within 2·1.75e-4 mm
    s = gd.PlanetarySet(1.75, 21, 43, 108, 3, 0.4380, 0.0426, 0.0)
    assert abs(s.a_w - 56.8) <= 0.05 and abs(s.a_w_planet_ring - 56.8) <= 0.05
    assert abs(s.a_w - s.a_w_planet_ring) <= 2 * 1.75e-4 * 1.1
    table = s.checks(coaxiality_tol_mm=2 * 1.75e-4 * 1.1).set_index("check")
    assert table.loc["set:coaxiality", "ok"]
    assert round(s.ratio, 5) == 6.14286
    assert table.loc["set:assembly", "ok"] and table.loc["set:assembly", "value"] == 43.0   # 129/3
    # the default tolerance 1e-3·m holds too; a planet one tooth bigger is not coaxial
    assert s.checks().set_index("check").loc["set:coaxiality", "ok"]
    assert not gd.PlanetarySet(1.75, 21, 44, 108, 3, 0.4380, 0.0426, 0.0).checks().set_index(
        "check").loc["set:coaxiality", "ok"]


def test_lecad_neighbours_value():
    # 2 a_w sin(π/3) − d_a,planet with d_a,p = m(z_p + 2 h_a* + 2 x_p) (tips not shortened in a set)
    s = gd.PlanetarySet(1.75, 21, 43, 108, 3, 0.4380, 0.0426, 0.0)
    row = s.checks().set_index("check").loc["set:neighbours"]
    expect = 2 * s.a_w * math.sin(math.pi / 3) - 1.75 * (43 + 2 + 2 * 0.0426)
    assert row["value"] * 1.75 == pytest.approx(expect, rel=1e-13)
    assert row["limit"] == 0.5 and row["ok"]


@settings(max_examples=40, deadline=None)
@given(z_s=st.integers(12, 120), z_p=st.integers(12, 120), m=st.sampled_from([0.5, 1.0, 2.5, 8.0]))
def test_standard_set_is_coaxial_exactly(z_s, z_p, m):
    s = gd.PlanetarySet(m, z_s, z_p, z_s + 2 * z_p, 1)
    assert s.a_w == pytest.approx(m * (z_s + z_p) / 2, rel=1e-14)
    assert abs(s.a_w - s.a_w_planet_ring) <= 1e-12 * s.a_w
    c = gd.PlanetarySet.coaxial(m, z_s, z_p, z_s + 2 * z_p, 1)
    assert abs(c.x_ring) < 1e-12


@settings(max_examples=30, deadline=None)
@given(z_s=st.integers(12, 60), z_p=st.integers(12, 60), d=st.integers(-2, 2),
       x_s=st.floats(-0.3, 0.8), x_p=st.floats(-0.3, 0.8))
@example(z_s=12, z_p=12, d=0, x_s=-0.25, x_p=-0.25)   # x_Σ below the sun-planet mesh's existence: NaN
def test_ring_shift_against_mpmath(z_s, z_p, d, x_s, x_p):
    z_r = z_s + 2 * z_p + d
    x_r, a_w = mp_ring_shift(2.0, z_s, z_p, z_r, x_s, x_p)
    geo = pl.set_geometry(pl.PlanetaryMeshes(z_s, z_p, z_r, 1), 2.0, float(x_s), float(x_p))
    if x_r is None:
        assert math.isnan(geo["x_ring"])
        assert a_w is not None or math.isnan(geo["a_w"])
        return
    assert abs(geo["x_ring"] - float(x_r)) < 1e-11
    assert abs(geo["a_w"] - float(a_w)) < 1e-11 * float(a_w)
    assert abs(geo["a_w_pr"] - float(a_w)) < 1e-11 * float(a_w)
    # and the array path gives the same
    arr = pl.set_geometry(pl.PlanetaryMeshes(z_s, z_p, z_r, 1), 2.0, np.array([x_s]), np.array([x_p]))
    assert abs(arr["x_ring"][0] - float(x_r)) < 1e-11


@pytest.mark.parametrize("sizes", [(21, 43, 108, 3), (11, 12, 37, 3), (18, 27, 72, 3), (30, 20, 72, 4)])
def test_set_gradients_are_the_chain_rule(sizes):
    """Every check's and objective piece's gradient in (x_sun, x_planet), including the planet-ring
    mesh's carried through x_ring(x_sun, x_planet), against central differences of the margins."""
    meshes = pl.PlanetaryMeshes(*sizes)
    for objective in ("max_eps_alpha", "balanced_sliding", "min_specific_pressure"):
        prob = PlanetaryProblem(meshes, 2.0, objective=objective)
        v, h = (0.21, 0.37), 1e-6
        P, M, GP, GM = prob.evaluate_point(v)
        for k in range(2):
            vp, vm = list(v), list(v)
            vp[k] += h
            vm[k] -= h
            Pp, Mp, _, _ = prob.evaluate_point(vp)
            Pm, Mm, _, _ = prob.evaluate_point(vm)
            np.testing.assert_allclose(GM[:, k], (Mp - Mm) / (2 * h), rtol=1e-5, atol=1e-6)
            np.testing.assert_allclose(GP[:, k], (Pp - Pm) / (2 * h), rtol=1e-5, atol=1e-6)


def test_ratio_and_assembly():
    # Willis: ring fixed 1 + z_r/z_s; carrier fixed −z_r/z_s; sun fixed 1 + z_s/z_r
    assert pl.planetary_ratio(24, 72) == 4.0
    assert pl.planetary_ratio(24, 72, "carrier_fixed") == -3.0
    assert pl.planetary_ratio(24, 72, "sun_fixed") == pytest.approx(4 / 3, rel=1e-15)
    assert pl.assembly_value(24, 72, 4) == 0.0 and pl.assembly_value(24, 72, 5) == pytest.approx(0.2)
    # unequal spacing: planets where (z_s + z_r)·θ/360 is whole; 129 teeth: steps of 360/129 deg
    ok = pl.PlanetaryMeshes(21, 43, 108, 3, planet_angles_deg=(0, 360 * 43 / 129, 360 * 87 / 129))
    assert pl.Assembly(meshes=ok).margin({"a": 0.0}) == 0.0
    bad = pl.PlanetaryMeshes(21, 43, 108, 3, planet_angles_deg=(0, 100, 220))
    assert pl.Assembly(meshes=bad).margin({"a": 0.0}) < 0


@pytest.mark.parametrize("args, words", [
    ((2, 20, 30, 30, 3), "z_ring must exceed z_planet"),
    ((2, 20, 30, 80, 0), "n_planets"),
    ((2, 20, 30, 80, 65), "n_planets"),
    ((2, 20, 2, 80, 3), "z_planet"),
])
def test_bad_sets_are_refused_by_name(args, words):
    with pytest.raises(gd.GearDesignError, match=words):
        gd.PlanetarySet(*args)


def test_bad_arrangement_and_angles():
    with pytest.raises(gd.GearDesignError, match="arrangement"):
        gd.PlanetarySet(2, 20, 30, 80, 2, arrangement="sun_in")
    with pytest.raises(gd.GearDesignError, match="planet_angles_deg"):
        gd.PlanetarySet(2, 20, 30, 80, 2, planet_angles_deg=(0, 400))
