"""Scenes' [gear.spectrum] (issue 38 §4): a CSV spectrum beside the scene switches the damage checks on in the
gear section's optimum and region, and the report carries the life at the optimum (its D from pair_life)."""
import numpy as np
import pytest

import geardesign as gd
from geardesign.errors import GearDesignError
from geardesign.gears.strength.service_life import pair_life

SCENE = """title = "20/60 under a spectrum"

[gear]
module = 4
z1 = 20
z2 = 60
face_width_mm = 40

[gear.spectrum]
file = "{file}"
material = "42CrMo4"
sn_curve = "haibach"
"""


def _scene(tmp_path, csv="torque_nm,n_rpm,time_h\n120,1000,2000\n90,1000,8000\n60,1000,10000\n", file="spec.csv"):
    (tmp_path / "spec.csv").write_text(csv, encoding="utf-8")
    path = tmp_path / "s.toml"
    path.write_text(SCENE.format(file=file), encoding="utf-8")
    return path


def test_a_scene_with_a_spectrum_checks_and_reports_the_damage(tmp_path):
    rep = gd.run_scene(_scene(tmp_path), tmp_path / "out")
    res = rep.results["gear"]["optimum"]
    assert res.success and "pitting_damage1" in res.active
    spec = gd.LoadSpectrum.from_csv(tmp_path / "spec.csv")
    d = pair_life(np.float64(4.0), 20, 60, res.x1, res.x2, spectrum=spec, material1="42CrMo4", face_width_mm=40.0,
                  sn_curve="haibach")
    assert d["D_H1"] == pytest.approx(1.0, abs=1e-6)
    assert "gear_life_optimum" in rep.tables and "gear_life_optimum" in rep.figures
    assert any("damage D_H" in line for line in rep.summary)
    assert "pitting_damage1" in set(rep.results["gear"]["region"].checks)


def test_a_bad_spectrum_file_names_the_key(tmp_path):
    with pytest.raises(GearDesignError, match=r"gear\.spectrum.*file.*row 2, column 'n_rpm'"):
        gd.load_scene(_scene(tmp_path, csv="torque_nm,n_rpm,time_h\n120,abc,2\n"))
    with pytest.raises(GearDesignError, match="cannot be read"):
        gd.load_scene(_scene(tmp_path, file="none.csv"))


PLANETARY = """title = "20/31/82, 3 planets, under a spectrum on the sun"

[planetary]
module = 2
z_sun = 20
z_planet = 31
z_ring = 82
n_planets = 3
x_sun = 0.3
x_planet = 0.1

[planetary.spectrum]
file = "{file}"
material = "18CrNiMo7-6"
face_width_mm = 25
{extra}
"""


def _planetary(tmp_path, csv="torque_nm,n_rpm,time_h\n600,1500,2000\n450,1500,5000\n250,1500,3000\n",
               extra="mean_stress_factor = 0.7\nlife_h = 20000"):
    (tmp_path / "spec.csv").write_text(csv, encoding="utf-8")
    path = tmp_path / "p.toml"
    path.write_text(PLANETARY.format(file="spec.csv", extra=extra), encoding="utf-8")
    return path


def test_a_planetary_scene_takes_a_spectrum_on_the_sun(tmp_path):
    # [planetary.spectrum], spelled as [gear.spectrum]: the damage checks of both meshes join the set's checks, and
    # the report carries planetary_life's table (the planet over both meshes) for the given set
    from geardesign.gears.strength.planetary_meshes import planetary_life

    rep = gd.run_scene(_planetary(tmp_path), tmp_path / "out")
    s = rep.results["planetary"]
    spec = gd.LoadSpectrum.from_csv(tmp_path / "spec.csv")
    want = s.checks({"spectrum": spec, "material": "18CrNiMo7-6", "face_width_mm": 25.0, "mean_stress_factor": 0.7,
                     "life_h": 20000.0}).set_index("check")["value"]
    got = rep.tables["planetary_checks"].set_index("check")["value"]
    names = [n for n in want.index if "damage" in n]
    assert len(names) == 8 and all(float(got[n]) == pytest.approx(float(want[n]), rel=1e-12) for n in names)
    life = planetary_life(s, spec, "18CrNiMo7-6", face_width_mm=25.0, mean_stress_factor=0.7, life_h=20000.0)
    t = rep.tables["planetary_life"].set_index(["gear", "mode"])["D"]
    assert float(t[("planet", "root")]) == pytest.approx(life["D_F_planet"], rel=1e-12) and life["D_F_planet"] > 0
    assert float(t[("sun", "pitting")]) == pytest.approx(life["D_H_sun"], rel=1e-12)


def test_a_planetary_scene_takes_a_reversing_spectrum(tmp_path):
    # the planet's damage summed per flank across both meshes (a check of the set), as planetary_life sums it
    from geardesign.gears.strength.planetary_meshes import planetary_life

    csv = "torque_nm,n_rpm,time_h\n600,1500,2000\n-450,1500,5000\n250,1500,3000\n"
    rep = gd.run_scene(_planetary(tmp_path, csv), tmp_path / "out")
    s = rep.results["planetary"]
    spec = gd.LoadSpectrum.from_csv(tmp_path / "spec.csv")
    life = planetary_life(s, spec, "18CrNiMo7-6", face_width_mm=25.0, mean_stress_factor=0.7, life_h=20000.0)
    got = rep.tables["planetary_checks"].set_index("check")["value"]
    assert float(got["set:pitting_damage_planet"]) == pytest.approx(life["D_H_planet"], rel=1e-12)
    assert float(got["set:root_damage_planet"]) == pytest.approx(life["D_F_planet"], rel=1e-12)
    assert life["D_H_planet"] > 0 and max(life["planet_flanks"]["H"]) > min(life["planet_flanks"]["H"]) > 0


@pytest.mark.parametrize("csv, extra, words", [
    ("torque_nm,n_rpm,time_h\n60,abc,2000\n", "mean_stress_factor = 0.7",
     r"\[planetary.spectrum\] file: .*row 2, column 'n_rpm'"),
    ("torque_nm,n_rpm,time_h\n60,1500,2000\n", "", r"\[planetary.spectrum\] mean_stress_factor: missing"),
    ("torque_nm,n_rpm,time_h\n60,1500,2000\n", "mean_stress_factor = 0.7\non_gear = 2",
     r"\[planetary.spectrum\] on_gear"),
])
def test_a_bad_planetary_spectrum_is_one_error_naming_the_key(tmp_path, csv, extra, words):
    with pytest.raises(GearDesignError, match=words):
        gd.run_scene(_planetary(tmp_path, csv, extra), tmp_path / "out")
    assert not (tmp_path / "out").exists()
