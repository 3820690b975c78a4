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
