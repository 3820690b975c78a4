"""A scene's [gear.load] table: the strength checks join the section's checks and the report carries the
ISO 6336 result of the optimum and of the given shifts (the values: GearPair.strength)."""
import pytest

import geardesign as gd
from geardesign.errors import GearDesignError
from geardesign.gears.strength import Load

SCENE = """
[gear]
module = 4
z1 = 20
z2 = 60
x1 = 0.3
x2 = 0.2
face_width_mm = 40
[gear.load]
torque_nm = 600
n_rpm = 1000
life_h = 20000
material = "18CrNiMo7-6"
"""


def test_scene_load_reaches_the_checks_and_the_report(tmp_path):
    path = tmp_path / "load.toml"
    path.write_text(SCENE)
    rep = gd.run_scene(path, tmp_path / "out")
    assert "contact_strength" in rep.tables["gear_optimum_checks"]["check"].tolist()
    ref = gd.GearPair(4, 20, 60, 0.3, 0.2, face_width_mm=40).strength(Load(torque_nm=600, n_rpm=1000, life_h=20000),
                                                                    "18CrNiMo7-6")
    table = rep.tables["gear_strength_given"].set_index(["symbol", "gear"])
    assert table.loc[("K_Hbeta", 0), "value"] == pytest.approx(ref.factors.set_index(["symbol", "gear"])
                                                                 .loc[("K_Hbeta", 0), "value"])
    assert any("given pair: S_H = 1.030" in s for s in rep.summary)


def test_scene_load_without_a_material_names_the_key(tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text(SCENE.replace('material = "18CrNiMo7-6"\n', ""))
    with pytest.raises(GearDesignError, match=r"\[gear.load\] material"):
        gd.load_scene(path)
