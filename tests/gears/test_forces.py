"""Mesh forces (geardesign.gears.forces): NTN's printed gear loads (tests/data/gear_force_examples.csv), the two
conventions against each other and against the line-of-action force written out here, helical and internal
pairs, each mesh of a planetary set, and the vectorised function."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import geardesign as gd
from geardesign.errors import GearDesignError
from geardesign.gears import forces as f

DATA = Path(__file__).resolve().parents[1] / "data"


def test_ntn_example_4_gear_loads():
    """NTN CAT. 2203/E Example 4: Dp = 150 mm, α = 20°, 150 kW at 2 000 min⁻¹: Kt 9.55, Ks 3.48, Kr 10.16 kN."""
    r = pd.read_csv(DATA / "gear_force_examples.csv").set_index("case").loc["ntn_example_4"]
    torque = r.power_kw * 1e3 / (r.n_rpm * math.pi / 30)
    m = f.mesh_forces(torque, r.pitch_diameter_mm, r.alpha_deg, r.beta_deg)
    assert round(float(m["F_t_n"]) / 1000, 2) == r.printed_Kt_kn
    assert round(float(m["F_r_n"]) / 1000, 2) == r.printed_Ks_kn
    assert round(math.hypot(m["F_t_n"], m["F_r_n"]) / 1000, 2) == r.printed_Kr_kn
    # the same through a pair with d1 = 150 mm (m = 5, z1 = 30), both conventions (no shift: they agree)
    pair = gd.GearPair(5, 30, 60)
    for circle in ("operating", "reference"):
        pf = pair.forces(torque, circle=circle)
        assert round(pf.F_t_n / 1000, 2) == r.printed_Kt_kn and round(pf.F_r_n / 1000, 2) == r.printed_Ks_kn


@settings(max_examples=60, deadline=None)
@given(st.integers(12, 60), st.integers(20, 120), st.floats(-0.4, 0.8), st.floats(-0.4, 0.8),
       st.sampled_from([0.0, 8.0, 15.0, 30.0]), st.floats(1.0, 5000.0))
def test_conventions_are_components_of_the_line_of_action_force(z1, z2, x1, x2, beta, torque):
    """On the operating circle, F_t and F_r are the components of F_bt = 2000 T/d_b1 along and across the line of
    centres; the reference F_t is 2000 T/d1; the axial force is F_bt·tan β_b in both (written out here)."""
    try:
        pair = gd.GearPair(3, z1, z2, x1, x2, beta_deg=beta)
    except GearDesignError:
        return
    g = pair.geometry()
    op, ref = pair.forces(torque), pair.forces(torque, circle="reference")
    alpha_n = math.radians(20.0)
    alpha_t = math.atan(math.tan(alpha_n) / math.cos(math.radians(beta)))
    d1 = 3 * z1 / math.cos(math.radians(beta))
    db1 = d1 * math.cos(alpha_t)
    F_bt = 2000 * torque / db1
    alpha_wt = math.acos(db1 / g.dw1)
    assert op.F_t_n == pytest.approx(F_bt * math.cos(alpha_wt), rel=1e-9)
    assert op.F_r_n == pytest.approx(F_bt * math.sin(alpha_wt), rel=1e-9)
    assert ref.F_t_n == pytest.approx(2000 * torque / d1, rel=1e-12)
    assert ref.F_r_n == pytest.approx(ref.F_t_n * math.tan(alpha_n) / math.cos(math.radians(beta)), rel=1e-9)
    beta_b = math.atan(math.tan(math.radians(beta)) * math.cos(alpha_t))
    assert op.F_a_n == pytest.approx(F_bt * math.tan(beta_b), rel=1e-9, abs=1e-9)
    assert ref.F_a_n == pytest.approx(op.F_a_n, rel=1e-12, abs=1e-9)
    assert op.r1_mm == pytest.approx(g.dw1 / 2, rel=1e-12) and ref.r1_mm == pytest.approx(d1 / 2, rel=1e-12)
    assert op.torque2_nm == pytest.approx(torque * z2 / z1, rel=1e-12)
    # the torque about each axis: F_t times the radius it acts at
    assert op.F_t_n * op.r1_mm / 1000 == pytest.approx(torque, rel=1e-9)
    assert op.F_t_n * op.r2_mm / 1000 == pytest.approx(torque * z2 / z1, rel=1e-9)


def test_load_on_gear_2_and_axial_moment():
    pair = gd.GearPair(3, 20, 60, 0.3, 0.1, beta_deg=15)
    by_load = pair.forces(gd.Load(torque_nm=900, n_rpm=100, on_gear=2), circle="reference")
    by_torque = pair.forces(300.0, circle="reference")
    assert by_load.F_t_n == pytest.approx(by_torque.F_t_n, rel=1e-12)
    assert by_load.axial_moment1_nm == pytest.approx(by_load.F_a_n * by_load.r1_mm / 1000, rel=1e-12)
    assert by_load.axial_moment2_nm == pytest.approx(by_load.F_a_n * by_load.r2_mm / 1000, rel=1e-12)


def test_internal_pair_and_bad_inputs():
    ring = gd.GearPair(2, 20, 60, 0.3, 0.3, internal=True)     # x2 − x1 = 0: runs on the reference circles
    fo = ring.forces(100.0)
    assert fo.internal and fo.F_t_n == pytest.approx(2000 * 100 / 40, rel=1e-12)
    assert fo.F_r_n == pytest.approx(fo.F_t_n * math.tan(math.radians(20)), rel=1e-12)
    for bad in (-1.0, 0.0, float("nan"), "100", True):
        with pytest.raises(GearDesignError, match="load"):
            ring.forces(bad)
    with pytest.raises(GearDesignError, match="circle"):
        ring.forces(100.0, circle="base")


def test_planetary_meshes_balance_the_planet():
    """Each mesh carries T_sun/N; on the planet the two tangential forces balance its torque (F_t·r on both
    pitch circles), and its bearing load is their vector sum, written out here."""
    s = gd.PlanetarySet.coaxial(2, 20, 31, 82, 3, 0.3, 0.1)
    out = f.planetary_forces(s, gd.Load(torque_nm=300, n_rpm=1000))
    sp, pr = out["sun-planet"], out["planet-ring"]
    assert sp.F_t_n * sp.r1_mm / 1000 == pytest.approx(100.0, rel=1e-9)         # T_sun/N on the sun
    assert sp.F_t_n * sp.r2_mm == pytest.approx(pr.F_t_n * pr.r1_mm, rel=1e-9)   # the planet idles
    assert out["planet_bearing_n"] == pytest.approx(math.hypot(sp.F_t_n + pr.F_t_n, sp.F_r_n - pr.F_r_n), rel=1e-12)
    ref = f.planetary_forces(s, 300.0, circle="reference")
    assert ref["sun-planet"].F_t_n == pytest.approx(2000 * 100 / 40, rel=1e-12)
    assert ref["planet-ring"].F_t_n == pytest.approx(2000 * 100 / 40, rel=1e-12)
    with pytest.raises(GearDesignError, match="sun"):
        f.planetary_forces(s, gd.Load(torque_nm=300, n_rpm=1000, on_gear=2))


def test_mesh_forces_vectorised_equals_one_by_one():
    rng = np.random.default_rng(6336)
    T, d, a, bb = rng.uniform(1, 1e4, 200), rng.uniform(10, 1000, 200), rng.uniform(14, 30, 200), rng.uniform(0, 40, 200)
    arr = f.mesh_forces(T, d, a, bb)
    for i in range(0, 200, 17):
        one = f.mesh_forces(T[i], d[i], a[i], bb[i])
        for k in arr:
            assert arr[k][i] == float(one[k])
    assert np.allclose(arr["F_n"], f.normal_force_n(arr["F_t_n"], np.degrees(np.arctan(
        np.tan(np.radians(a)) * np.cos(np.radians(bb)))), bb), rtol=1e-12)
