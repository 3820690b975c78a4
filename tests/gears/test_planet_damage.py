"""The planet's damage as a check of the set under a reversing spectrum (geardesign.gears.planet_damage, issue 38):
its two parts are the flank sums that planetary_life computes bin by bin (the independent implementation: each bin's
n/N of each mesh, paired by the bin's sign), its gradients are the sums' central differences in the set's shifts,
and max_life of a set reads them: no feasible node of a grid around the optimum lives longer."""
import numpy as np
import pytest

import geardesign as gd
from geardesign.gears.planet_damage import PlanetDamage
from geardesign.gears.planetary import PlanetaryMeshes, set_checks, set_geometry
from geardesign.gears.strength.planetary_meshes import planetary_life

SUN = gd.LoadSpectrum.from_bins([450, -300, 200], 1500, time_h=[2000, 3000, 5000])


def _planet_checks(checks, meshes=PlanetaryMeshes(20, 31, 82, 3)):
    return [c for c in set_checks(meshes, checks) if isinstance(c, PlanetDamage)]


@pytest.mark.parametrize("life_h", [None, 20000.0])
def test_the_planets_parts_are_planetary_lifes_flank_sums(life_h):
    checks = {"spectrum": SUN, "material": "18CrNiMo7-6", "face_width_mm": 25.0, "mean_stress_factor": 0.7,
              "life_h": life_h}
    pitting, root = _planet_checks(checks)
    assert (pitting.name, root.name) == ("set:pitting_damage_planet", "set:root_damage_planet")
    s = gd.PlanetarySet.coaxial(2, 20, 31, 82, 3, 0.3, 0.1)
    life = planetary_life(s, SUN, "18CrNiMo7-6", face_width_mm=25.0, mean_stress_factor=0.7, life_h=life_h)
    geo = set_geometry(PlanetaryMeshes(20, 31, 82, 3), 2.0, 0.3, 0.1)
    for check, mode in ((pitting, "H"), (root, "F")):
        got = check.flank_damage(geo)
        want = life["planet_flanks"][mode]
        assert got == pytest.approx(want, rel=1e-12) and min(want) >= 0 and max(want) > 0
        assert check.part_margins(geo) == pytest.approx([1.0 - d for d in want], rel=1e-12, abs=1e-15)
        assert check.value(geo) == pytest.approx(life[f"D_{mode}_planet"], rel=1e-12)
    # the table of the set's checks: the planet's rows are these, the sun's and the ring's their meshes' own
    t = s.checks(checks).set_index("check")["value"]
    assert float(t["set:root_damage_planet"]) == pytest.approx(life["D_F_planet"], rel=1e-12)
    assert float(t["sun-planet:pitting_damage_sun"]) == pytest.approx(life["D_H_sun"], rel=1e-12)
    assert not any(n.endswith("damage_planet") and not n.startswith("set:") for n in t.index)


def test_the_planets_gradients_are_central_differences_in_the_sets_shifts():
    checks = {"spectrum": SUN, "material": "18CrNiMo7-6", "face_width_mm": 25.0, "mean_stress_factor": 0.7}
    meshes = PlanetaryMeshes(20, 31, 82, 3)
    h = 1e-5
    for check in _planet_checks(checks):
        grads = check.flank_damage_gradients(set_geometry(meshes, 2.0, 0.3, 0.1))
        for k in range(2):
            fd = [(check.flank_damage(set_geometry(meshes, 2.0, 0.3 + h * (j == 0), 0.1 + h * (j == 1)))[k]
                   - check.flank_damage(set_geometry(meshes, 2.0, 0.3 - h * (j == 0), 0.1 - h * (j == 1)))[k])
                  / (2 * h) for j in range(2)]
            assert grads[k] == pytest.approx(fd, rel=1e-5, abs=1e-9)


def test_max_life_of_a_set_under_a_reversing_spectrum_reads_the_planets_flanks():
    """A planet of a weaker steel (42CrMo4 against the sun's and ring's 18CrNiMo7-6) governs: the sun and the ring
    take no damage, so without the planet's set check max_life would have nothing to read. Its optimum is −ln of
    planetary_life's largest damage there, and no feasible node of a 9 × 9 grid around it lives longer."""
    spec = gd.LoadSpectrum.from_bins([35, -35, 17.5], 1500, time_h=[2000, 3000, 5000])
    checks = {"spectrum": spec, "material": "18CrNiMo7-6", "planet_material": "42CrMo4", "face_width_mm": 40.0,
              "mean_stress_factor": 0.7, "life_h": 20000.0}
    r = gd.optimize_planetary_shifts(20, 31, 82, 3, 2, checks=checks, objective="max_life")
    assert r.success

    def worst(x_sun, x_planet):
        s = gd.PlanetarySet.coaxial(2, 20, 31, 82, 3, x_sun, x_planet)
        life = planetary_life(s, spec, "18CrNiMo7-6", planet_material="42CrMo4", face_width_mm=40.0,
                              mean_stress_factor=0.7, life_h=20000.0)
        return max(v for k, v in life.items() if k.startswith("D_")), life

    d_best, life = worst(r.x_sun, r.x_planet)
    assert life["D_H_planet"] == d_best > 0 and life["D_H_sun"] == 0.0
    assert r.fun == pytest.approx(-np.log(d_best), rel=1e-9)
    beaten = feasible = 0
    for xs in np.linspace(r.x_sun - 0.4, r.x_sun + 0.4, 9):
        for xp in np.linspace(r.x_planet - 0.4, r.x_planet + 0.4, 9):
            try:
                ok = gd.PlanetarySet.coaxial(2, 20, 31, 82, 3, xs, xp).checks(checks)["ok"].all()
            except gd.GearDesignError:      # the set does not exist there
                continue
            feasible += bool(ok)
            if ok:
                beaten += worst(xs, xp)[0] < d_best * (1 - 1e-9)
    assert beaten == 0 and feasible >= 10


@pytest.mark.parametrize("torques", [[20.0, 80.0], [20.0, -80.0]])
def test_a_planet_root_the_chain_cannot_rate_fails_its_damage_check(torques):
    """30/15/60 × 5 at x = (−0.119, −0.298), m 1: the planet-ring mesh's ε_α is 2.75, past the 2.42 at which ISO 6336-3
    method B's outer point of single contact leaves the planet's base circle, so the planet's root has no load point
    there: planetary_life (each mesh's pair_life, the independent rating) refuses it. The set's damage check of that
    root (the ring mesh's one-sided, or the set's summed over both meshes when the spectrum reverses) must fail as
    undefined; before the fix (fuzz planetary_spectrum) the chain's NaN stress fell onto the S-N curve's horizontal
    tail: D = 0, the check held."""
    s = gd.PlanetarySet.coaxial(1.0, 30, 15, 60, 5, -0.119, -0.298)
    spec = gd.LoadSpectrum.from_bins(torques, 3500, time_h=[500, 500])
    with pytest.raises(gd.GearDesignError, match="eps_alpha_n"):
        planetary_life(s, spec, "42CrMo4", face_width_mm=20.0, mean_stress_factor=1.0)
    t = s.checks({"spectrum": spec, "material": "42CrMo4", "face_width_mm": 20.0, "mean_stress_factor": 1.0})
    row = t.set_index("check").loc["set:root_damage_planet" if min(torques) < 0 else "planet-ring:root_damage_planet"]
    assert np.isnan(row["value"]) and row["margin"] == -np.inf and not row["ok"]
    assert "undefined for this design" in row["label"]
