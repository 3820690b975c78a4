"""``data_block = true`` in a scene's [gear]: the drawing's data block of both gears of each pair in the report."""
import geardesign as gd
from geardesign.gears.data_block import data_block


def test_scene_report_has_the_data_blocks(tmp_path):
    scene = tmp_path / "s.toml"
    scene.write_text("[gear]\nmodule = 3\nz1 = 12\nz2 = 24\nx1 = 0.6\nx2 = 0.36\ndata_block = true\naccuracy_class = 7\n")
    rep = gd.run_scene(scene, tmp_path / "out")
    report = (tmp_path / "out" / "report.md").read_text(encoding="utf-8")
    assert "Data blocks of the given pair" in report and "Data blocks of the optimum pair" in report
    table = rep.tables["gear_data_block_given_2"]
    expected = data_block(gd.GearPair(3, 12, 24, 0.6, 0.36), 2, 7)
    assert table.equals(expected)
    assert "ISO 1328-1:2013 class 7" in report
    plain = tmp_path / "p.toml"
    plain.write_text("[gear]\nmodule = 3\nz1 = 12\nz2 = 24\n")
    assert not [k for k in gd.run_scene(plain, tmp_path / "out2").tables if k.startswith("gear_data_block")]
