"""The strength checks of a planetary set (issue 26 §3: "planetary optimisation"): each mesh loaded with the
sun's torque shared over the planets at the speeds relative to the carrier, as a check of the optimisation,
the set's check table and the CLI; and designs past the root section's range that give a failing margin
instead of an error."""
import math

import numpy as np
import pytest

import geardesign as gd
from geardesign.cli import main as cli_main
from geardesign.gears.strength import Load, pair_strength
from geardesign.gears.strength import planetary_strength
from geardesign.gears.strength.root import root_form_factors

SET = (21, 43, 108, 3)           # LECAD's set (tests/data/planetary_examples.csv), m = 1.75 mm
M = 1.75
MAT = "18CrNiMo7-6"


def _checks(torque_nm, **more):
    return dict(load=Load(torque_nm=torque_nm, n_rpm=1500, life_h=10000), material=MAT, face_width_mm=25.0, **more)


def test_each_mesh_carries_the_suns_torque_shared_over_the_planets():
    # by hand: ring fixed, the carrier turns at n_s z_s/(z_s + z_r) = 1500·21/129; the sun meets the planets at
    # n_s − n_c and each mesh carries T_s/3 (the planet's torque T_s/3 · z_p/z_s at (n_s − n_c) z_s/z_p)
    s = gd.PlanetarySet.coaxial(M, *SET, 0.5, 0.5)
    table = s.checks(_checks(300.0)).set_index("check")
    n_rel = 1500.0 - 1500.0 * 21 / 129
    sp = pair_strength(M, 21, 43, 0.5, 0.5, load=Load(torque_nm=100.0, n_rpm=n_rel, life_h=10000), material1=MAT,
                       face_width_mm=25.0, cycles_per_rev=(3, 1), tip_shortening=False)
    pr = pair_strength(M, 43, 108, 0.5, s.x_ring, load=Load(torque_nm=100.0 * 43 / 21, n_rpm=n_rel * 21 / 43,
                       life_h=10000), material1=MAT, face_width_mm=25.0, internal=True, cycles_per_rev=(1, 3),
                       tip_shortening=False)
    assert table.loc["sun-planet:contact_strength", "value"] == pytest.approx(min(sp["S_H1"], sp["S_H2"]), rel=1e-12)
    assert table.loc["sun-planet:root_strength_sun", "value"] == pytest.approx(float(sp["S_F1"]), rel=1e-12)
    assert table.loc["sun-planet:root_strength_planet", "value"] == pytest.approx(float(sp["S_F2"]), rel=1e-12)
    assert table.loc["planet-ring:root_strength_planet", "value"] == pytest.approx(float(pr["S_F1"]), rel=1e-12)
    assert table.loc["planet-ring:root_strength_ring", "value"] == pytest.approx(float(pr["S_F2"]), rel=1e-12)
    # the same numbers as the set's strength report
    rep = planetary_strength(s, Load(torque_nm=300.0, n_rpm=1500, life_h=10000), MAT, face_width_mm=25.0)
    assert table.loc["planet-ring:contact_strength", "value"] == pytest.approx(
        min(rep["planet-ring"].S_H1, rep["planet-ring"].S_H2), rel=1e-12)


def test_contact_stress_grows_with_the_root_of_the_torque_per_planet():
    # σ_H0 ∝ √F_t: the same sun torque over 3 planets against over 1 (a single planet set, same teeth)
    s3 = gd.PlanetarySet.coaxial(M, *SET[:3], 3, 0.3, 0.3)
    s1 = gd.PlanetarySet.coaxial(M, *SET[:3], 1, 0.3, 0.3)
    load = Load(torque_nm=200.0, n_rpm=1500)
    r3 = planetary_strength(s3, load, MAT, face_width_mm=25.0)["sun-planet"]
    r1 = planetary_strength(s1, load, MAT, face_width_mm=25.0)["sun-planet"]
    assert r3.sigma_H0 / r1.sigma_H0 == pytest.approx(1.0 / math.sqrt(3.0), rel=1e-12)


@pytest.mark.parametrize("method", ["exact", "convex"])
def test_an_optimum_with_a_load_rechecks_and_the_methods_agree(method):
    ck = _checks(150.0)
    r = gd.optimize_planetary_shifts(*SET, M, checks=ck, method=method)
    assert r.success
    s = gd.PlanetarySet(M, *SET, r.x_sun, r.x_planet, r.x_ring)
    assert s.ok(checks=ck)
    assert "sun-planet:contact_strength" in r.margins and "planet-ring:root_strength_ring" in r.margins
    ref = gd.optimize_planetary_shifts(*SET, M, checks=ck, method="exact")
    assert (r.x_sun, r.x_planet) == pytest.approx((ref.x_sun, ref.x_planet), abs=1e-7)


def test_an_active_contact_strength_is_met_exactly():
    # the balanced-sliding optimum's S_H, asked 0.2 % higher: contact_strength becomes the active check and
    # holds with equality at the new optimum
    ck = _checks(150.0)
    r0 = gd.optimize_planetary_shifts(*SET, M, checks=ck, objective="balanced_sliding")
    s0 = gd.PlanetarySet(M, *SET, r0.x_sun, r0.x_planet, r0.x_ring)
    S_H = s0.checks(ck).set_index("check").loc["sun-planet:contact_strength", "value"]
    r = gd.optimize_planetary_shifts(*SET, M, checks=_checks(150.0, S_Hmin=S_H * 1.002), objective="balanced_sliding")
    assert r.success and "sun-planet:contact_strength" in r.active
    assert abs(r.margins["sun-planet:contact_strength"]) < 1e-9


def test_an_overloaded_set_names_a_strength_check():
    r = gd.optimize_planetary_shifts(*SET, M, checks=_checks(400.0))
    assert not r.success
    assert any("strength" in c for c in r.conflict), r.conflict


def test_set_load_options_are_refused_by_name():
    with pytest.raises(gd.GearDesignError, match="material2 is a pair's"):
        gd.optimize_planetary_shifts(*SET, M, checks=_checks(150.0, material2=MAT))
    with pytest.raises(gd.GearDesignError, match="planet_material given without a load"):
        gd.optimize_planetary_shifts(*SET, M, checks={"planet_material": MAT})
    with pytest.raises(gd.GearDesignError, match="arrangement must be 'ring_fixed' or 'carrier_fixed'"):
        gd.optimize_planetary_shifts(*SET, M, checks=_checks(150.0), arrangement="sun_fixed")


def test_the_grid_and_the_region_of_a_loaded_set():
    ck = _checks(150.0)
    grid = gd.optimize_planetary_shifts(*SET, M, checks=ck, method="grid")
    exact = gd.optimize_planetary_shifts(*SET, M, checks=ck)
    assert grid.success and grid.fun <= exact.fun + 1e-9 and exact.fun - grid.fun < 0.05
    assert gd.planetary_region(*SET, M, checks=ck).feasible


def test_planetary_cli_takes_the_suns_load(capsys):
    args = ["planetary", "-m", "1.75", "--planets", "3", "--z-sun", "21", "--z-planet", "43", "--z-ring", "108",
            "--speed", "1500", "--material", MAT, "--face-width", "25", "--life-h", "10000"]
    assert cli_main(args + ["--torque", "150"]) == 0
    assert "sun-planet:contact_strength" in capsys.readouterr().out
    assert cli_main(args + ["--torque", "400"]) == 1
    assert "strength" in capsys.readouterr().out.split("conflict:")[1].splitlines()[0]


@pytest.mark.parametrize("method", ["exact", "convex", "grid"])
def test_shifts_past_the_root_section_fail_the_strength_margin_instead_of_raising(method):
    # 43/108 internal: the pinion's 30° tangent leaves the fillet near x = 2.75 (ISO 6336-3 clause 6.2), inside the
    # solvers' bounds; there the strength margins are undefined (failing), not an error
    ck = dict(load=Load(torque_nm=100, n_rpm=1500, life_h=10000), material=MAT, face_width_mm=25)
    r = gd.optimize_shifts(43, 108, m=2, method=method, checks=ck, internal=True)
    assert r.success
    assert gd.GearPair(2, 43, 108, r.x1, r.x2, internal=True).ok(**ck)


def test_root_form_factors_nan_where_the_design_has_no_root_section():
    with pytest.raises(gd.GearDesignError, match="30-degree tangent"):
        root_form_factors(43, 2.9, 43 + 2 + 2 * 2.9, eps_alpha=1.3)
    out = root_form_factors(np.array([43, 43]), np.array([0.5, 2.9]), np.array([46.0, 50.8]), eps_alpha=1.3,
                            refuse=False)
    assert np.isfinite(out["Y_F"][0]) and np.isnan(out["Y_F"][1])


@pytest.mark.parametrize("objective", ["balanced_root_strength", "max_min_safety"])
def test_the_strength_objectives_of_a_set(objective):
    # issue 36 §1.1: both raised a bare ValueError (a minimum over no pieces: the set's objective was never bound to
    # its meshes' strength checks). Without a load: refused by name, as optimize_shifts refuses it
    with pytest.raises(gd.GearDesignError, match=f"objective '{objective}' needs a load"):
        gd.optimize_planetary_shifts(16, 25, 66, 4, m=4, objective=objective)
    # with one: solved, and fun is the smallest S/S_min of both meshes' set report at the shifts found
    ck = _checks(150.0)
    r = gd.optimize_planetary_shifts(*SET, M, objective=objective, checks=ck)
    assert r.success and min(r.margins.values()) >= 0
    s = gd.PlanetarySet.coaxial(M, *SET, r.x_sun, r.x_planet)
    rep = planetary_strength(s, ck["load"], MAT, face_width_mm=25.0)
    roots = [rep[t].S_F1 / rep[t].S_Fmin for t in ("sun-planet", "planet-ring")]
    roots += [rep[t].S_F2 / rep[t].S_Fmin for t in ("sun-planet", "planet-ring")]
    contact = [min(rep[t].S_H1, rep[t].S_H2) / rep[t].S_Hmin for t in ("sun-planet", "planet-ring")]
    want = min(roots) if objective == "balanced_root_strength" else min(roots + contact)
    assert r.fun == pytest.approx(want, rel=1e-9)
    # no node of a fine grid beats it
    grid = gd.optimize_planetary_shifts(*SET, M, objective=objective, checks=ck, method="grid", grid_n=81)
    assert grid.fun <= r.fun + 1e-9


def test_planetary_cli_strength_objective(capsys):
    # issue 36 §1.1: a traceback (exit 1) before
    args = ["planetary", "-m", "2", "--planets", "3", "--z-sun", "20", "--z-planet", "31", "--z-ring", "82",
            "--objective", "max_min_safety"]
    assert cli_main(args + ["--torque", "10", "--speed", "1000", "--material", "42CrMo4", "--face-width", "20"]) == 0
    assert "(max_min_safety)" in capsys.readouterr().out
    assert cli_main(args) == 2
    assert "needs a load" in capsys.readouterr().err


def test_max_life_of_a_set_under_a_spectrum():
    """The damage checks of both meshes (a spectrum on the sun) in the set's solver: max_life's optimum holds every
    check, its fun is −ln of the largest damage of the set's checks there, and the max_x_sum optimum (another
    feasible point) lives no longer. A reversing spectrum is solved too, the planet's damage a check of the set
    (tests/gears/test_planet_damage.py)."""
    import numpy as np

    import geardesign as gd
    from geardesign.errors import GearDesignError
    from geardesign.shifts.planetary import optimize_planetary_shifts

    reversing = gd.LoadSpectrum.from_bins([20.0, 12.0, -6.0], 1500, time_h=[2000, 6000, 2000])
    r = optimize_planetary_shifts(20, 31, 82, 3, 2, checks={"spectrum": reversing, "material": "42CrMo4",
                                                            "face_width_mm": 25.0, "mean_stress_factor": 0.7},
                                  objective="max_life")
    assert r.success and "set:pitting_damage_planet" in r.margins
    with pytest.raises(GearDesignError, match="mean_stress_factor"):      # a reversing spectrum still needs Y_M
        optimize_planetary_shifts(20, 31, 82, 3, 2, checks={"spectrum": reversing, "material": "42CrMo4",
                                                            "face_width_mm": 25.0}, objective="max_life")
    spec = gd.LoadSpectrum.from_bins([20.0, 12.0, 6.0], 1500, time_h=[2000, 6000, 2000])
    checks = {"spectrum": spec, "material": "42CrMo4", "face_width_mm": 25.0, "mean_stress_factor": 0.7,
              "damage_max": 10.0}
    best = optimize_planetary_shifts(20, 31, 82, 3, 2, checks=checks, objective="max_life")
    other = optimize_planetary_shifts(20, 31, 82, 3, 2, checks=checks, objective="max_x_sum")
    assert best.success and other.success

    def worst(r):
        t = gd.PlanetarySet.coaxial(2, 20, 31, 82, 3, r.x_sun, r.x_planet).checks(checks)
        assert t["ok"].all()
        return float(t.loc[t["check"].str.contains("damage"), "value"].max())

    assert 0 < worst(best) <= worst(other)
    assert best.fun == pytest.approx(-np.log(worst(best)), rel=1e-9)
