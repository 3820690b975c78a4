"""Issue 38 §4: the damage checks reach every consumer of the check registry (a pair's checks, optimize_shifts,
feasible_region, tooth searches), with the value pair_life gives for that design (computed here independently);
several spectra are several load cases, each of which must hold."""
from __future__ import annotations

import numpy as np
import pytest

import geardesign as gd
from geardesign.errors import GearDesignError
from geardesign.gears.checks import PittingDamage, RootDamage, make_checks
from geardesign.gears.strength.service_life import pair_life

SPEC = gd.LoadSpectrum.from_bins(np.linspace(2.5, 120.0, 48), 1000, share=np.full(48, 1 / 48), duration_h=20000)
CASE = {"spectrum": SPEC, "material": "42CrMo4", "face_width_mm": 40.0}


def _d(x1, x2, spec=SPEC, **kw):
    return pair_life(np.float64(4.0), 20, 60, x1, x2, spectrum=spec, material1="42CrMo4", face_width_mm=40.0, **kw)


def test_a_pairs_checks_carry_the_damage_sums():
    pair = gd.GearPair(4, 20, 60, 0.3, 0.1, face_width_mm=40)
    t = pair.checks(**CASE).set_index("check")
    out = _d(0.3, 0.1)
    for name, mode in (("pitting_damage1", "H1"), ("pitting_damage2", "H2"), ("root_damage1", "F1"),
                       ("root_damage2", "F2")):
        assert float(t.loc[name, "value"]) == pytest.approx(out["D_" + mode], rel=1e-9, abs=1e-300)
        assert float(t.loc[name, "margin"]) == pytest.approx(1.0 - out["D_" + mode], rel=1e-9)
    # a tighter limit D_max: margin 1 − D/D_max
    t = pair.checks(damage_max=0.5, **CASE).set_index("check")
    assert float(t.loc["pitting_damage1", "margin"]) == pytest.approx(1.0 - out["D_H1"] / 0.5, rel=1e-9)


def test_no_spectrum_no_damage_checks_and_bad_context_refused():
    names = [c.name for c in make_checks()]
    assert not any("damage" in n for n in names)
    with pytest.raises(GearDesignError, match="without a spectrum"):
        make_checks(life_h=1000.0)
    with pytest.raises(GearDesignError, match="spectrum must be a geardesign LoadSpectrum"):
        make_checks(spectrum=[1, 2], material="42CrMo4")
    with pytest.raises(GearDesignError, match="need material"):
        make_checks(spectrum=SPEC)
    rev = gd.LoadSpectrum.from_bins([100.0, -100.0], 1000, time_h=[1.0, 1.0])
    with pytest.raises(GearDesignError, match="mean_stress_factor"):
        make_checks(spectrum=rev, material="42CrMo4")
    assert len(make_checks(spectrum=rev, material="42CrMo4", mean_stress_factor=0.7)) > 4


def test_gradients_are_central_differences_of_the_damage():
    pair = gd.GearPair(4, 20, 60, 0.3, 0.1, face_width_mm=40)
    geo = pair._geo
    chk = next(c for c in make_checks(**CASE) if c.name == "pitting_damage1")
    g1, g2 = chk.gradient(dict(geo))
    h = 1e-5
    d = [_d(0.3 + a, 0.1 + b)["D_H1"] for a, b in ((h, 0), (-h, 0), (0, h), (0, -h))]
    assert g1 == pytest.approx(-(d[0] - d[1]) / (2 * h), rel=1e-4)
    assert g2 == pytest.approx(-(d[2] - d[3]) / (2 * h), rel=1e-4)


def test_optimize_shifts_stops_on_the_damage_boundary():
    """max_x_sum with the damage checks: the pinion's pitting damage is active, and pair_life at the optimum says
    D_H1 = 1 (the boundary), the strength of the single-load checks not consulted."""
    r = gd.optimize_shifts(20, 60, m=4, checks=CASE, objective="max_x_sum")
    assert r.success and "pitting_damage1" in r.active
    assert _d(r.x1, r.x2)["D_H1"] == pytest.approx(1.0, abs=1e-6)


def test_feasible_region_and_tooth_search_carry_the_damage_checks():
    region = gd.feasible_region(20, 60, m=4, checks=CASE, n=15)
    assert {"pitting_damage1", "pitting_damage2", "root_damage1", "root_damage2"} <= set(region.checks)
    sel = gd.select_teeth(3.0, 0.02, m=4, z1_range=(20, 21), checks={**CASE, "face_width_mm": 40.0})
    rows = sel.table[sel.table["feasible"]]
    assert len(rows)
    best = rows.iloc[0]
    d = pair_life(np.float64(4.0), int(best["z1"]), int(best["z2"]), float(best["x1"]), float(best["x2"]),
                  spectrum=SPEC, material1="42CrMo4", face_width_mm=40.0)
    assert d["D_H1"] <= 1.0 + 1e-6 and d["D_H2"] <= 1.0 + 1e-6


def test_several_spectra_are_several_load_cases():
    light = gd.LoadSpectrum.from_bins([60.0], 1000, time_h=[20000.0])
    checks = make_checks(spectrum=[SPEC, light], material="42CrMo4", face_width_mm=40.0)
    names = [c.name for c in checks]
    assert "pitting_damage1" in names and "case2_pitting_damage1" in names and "case2_root_damage2" in names
    pair = gd.GearPair(4, 20, 60, 0.3, 0.1, face_width_mm=40)
    t = pair.checks(spectrum=[SPEC, light], material="42CrMo4", face_width_mm=40.0).set_index("check")
    assert float(t.loc["case2_pitting_damage1", "value"]) == pytest.approx(_d(0.3, 0.1, light)["D_H1"], rel=1e-9)


def test_a_per_tooth_spectrum_is_for_its_pair_only():
    phi = np.linspace(0.0, 720.0, 721)
    spec = gd.LoadSpectrum.from_curve(100 + 50 * np.cos(np.radians(phi)), angle_deg=phi, n_rpm=1000, teeth=(20, 60))
    assert spec.teeth == (20, 60)
    _d(0.3, 0.1, spec)
    with pytest.raises(GearDesignError, match="counted per tooth for teeth"):
        pair_life(np.float64(4.0), 21, 60, 0.3, 0.1, spectrum=spec, material1="42CrMo4", face_width_mm=40.0)


def test_the_classes_are_registered_with_one_option():
    assert PittingDamage.option is RootDamage.option
    assert PittingDamage.option.name == "damage_max" and PittingDamage.option.default == 1.0


def test_an_atlas_carries_the_damage_margins():
    """shift_atlas works per unit module (m = 1, face width b/m): its damage margins are pair_life's at m = 1."""
    light = gd.LoadSpectrum.from_bins([0.5, 0.3], 1000, time_h=[2000.0, 8000.0])
    a = gd.shift_atlas([20], [60], checks={"spectrum": light, "material": "42CrMo4", "face_width_mm": 10.0},
                       face_width_mm=10.0)
    row = a.iloc[0]
    assert bool(row["feasible"])
    d = pair_life(np.float64(1.0), 20, 60, float(row["x1"]), float(row["x2"]), spectrum=light, material1="42CrMo4",
                  face_width_mm=10.0)
    assert float(row["margin_pitting_damage1"]) == pytest.approx(1.0 - d["D_H1"], rel=1e-7, abs=1e-9)


def test_the_optimums_sensitivity_to_damage_max_is_a_finite_difference_of_the_optimum():
    r = gd.optimize_shifts(20, 60, m=4, checks=CASE, objective="max_x_sum")
    h = 1e-4
    up = gd.optimize_shifts(20, 60, m=4, checks={**CASE, "damage_max": 1.0 + h}, objective="max_x_sum")
    down = gd.optimize_shifts(20, 60, m=4, checks={**CASE, "damage_max": 1.0 - h}, objective="max_x_sum")
    assert r.sensitivity["pitting_damage1"] == pytest.approx((up.fun - down.fun) / (2 * h), rel=1e-3)


@pytest.mark.parametrize("method", ["exact", "grid"])
def test_a_spectrum_counted_for_other_teeth_is_refused_by_name(method):
    """Fuzzing found optimize_shifts(17, 26) with a spectrum counted per tooth for (101, 103) running > 30 s and
    ending in 'no finite result ... undefined at (-1.5, -1.5)': pair_life's refusal was taken for a failing design,
    design by design, at every point of the solver. Now the spectrum's teeth are checked once, by name."""
    phi = np.linspace(0.0, 720.0, 721)
    curve = gd.LoadSpectrum.from_curve(300.0 + 0.0 * phi, angle_deg=phi, n_rpm=1700, teeth=(101, 103))
    with pytest.raises(GearDesignError, match=r"counted per tooth for teeth \(101, 103\), the pair has \(17, 26\)"):
        gd.optimize_shifts(17, 26, m=4.0, method=method,
                           checks={"spectrum": curve, "material": "42CrMo4", "face_width_mm": 10.0})


def test_the_damage_model_far_from_its_centre_gives_no_overflow():
    """Fuzzing found 'RuntimeWarning: overflow encountered in exp' (12 of them) from optimize_shifts with the damage
    checks of a 13/40 pair at m = 8 under 2675 N·m, 10 000 rpm: the Taylor model of ln D read far from its centre.
    Its ln D is read up to 600 now; the answer is the same refusal, naming the check that holds nowhere."""
    import warnings

    s = gd.LoadSpectrum.from_bins(torque_nm=[1876.2, 1104.8, 2675.3], n_rpm=10000.0, time_h=[20000.0, 20000.0, 100.0])
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        r = gd.optimize_shifts(13, 40, checks={"spectrum": s, "material": "18CrNiMo7-6", "face_width_mm": 40.0,
                                               "damage_max": 1.0, "mean_stress_factor": 1.0}, m=8.0, method="exact")
    assert not r.success and "damage" in r.message and "holds nowhere" in r.message


_NO_YIELD = dict(name="custom", kind="V", E_mpa=170000.0, nu=0.3, hardness=600.0, hardness_scale="HV",
                 sigma_Hlim_mpa=740.0, sigma_Flim_mpa=300.0)


@pytest.mark.parametrize("where", ["pair", "set"])
def test_a_material_the_root_cannot_rate_is_refused_by_name_as_with_a_load(where):
    """A through-hardened material without yield_mpa: the root's Y_δrelT needs it (ISO 6336-3:2019 clause 13), so the
    chain refuses every design. With a load the solvers say so by name; with a spectrum the damage checks took the
    refusal design by design (a chain call per grid node: minutes for a set), every margin NaN, and ended in
    "no finite result ... check the window" (fuzz planetary_spectrum). Now the same refusal as with a load."""
    mat = gd.Material(**_NO_YIELD)
    spec = gd.LoadSpectrum.from_bins([100.0, -40.0], 1000, time_h=[100, 50])
    for case in ({"load": gd.Load(torque_nm=100, n_rpm=1000)}, {"spectrum": spec, "mean_stress_factor": 0.7}):
        checks = {**case, "material": mat, "face_width_mm": 20.0}
        with pytest.raises(GearDesignError, match="needs yield_mpa"):
            if where == "pair":
                gd.optimize_shifts(20, 60, m=2, checks=checks, method="grid", grid_n=21)
            else:
                gd.optimize_planetary_shifts(21, 43, 108, 3, 1.0, checks=checks, method="grid", grid_n=21)
