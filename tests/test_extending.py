"""docs/extending.md's worked examples run as written, in order, in one namespace (the guide's own
contract: every addition it shows works)."""
import pathlib
import re

import matplotlib

matplotlib.use("Agg")

GUIDE = pathlib.Path(__file__).resolve().parents[1] / "docs" / "extending.md"


def _blocks():
    return re.findall(r"^```python\n(.*?)^```", GUIDE.read_text(encoding="utf-8"), flags=re.S | re.M)


def test_extending_guide_examples_run(capsys):
    blocks = _blocks()
    assert len(blocks) >= 5
    namespace = {}
    for code in blocks:
        exec(compile(code, str(GUIDE), "exec"), namespace)
    out = capsys.readouterr().out
    assert "operating_angle" in out                       # the new check is active in the optimum
    assert "min_tip_diameter True" in out
    assert "grid101 True" in out and "ISO VG 320" in out
    assert "247.0 True" in out                            # the load model: 2000·400/80.958/40 N/mm


def test_extending_guide_leaves_the_registries_as_it_found_them():
    import geardesign as gd
    from geardesign.gears.checks import options
    from geardesign.shifts.methods import METHODS
    assert "alpha_w_min_deg" not in options() and "line_load_max_n_mm" not in options() and "grid101" not in METHODS
    assert "min_tip_diameter" not in gd.OBJECTIVES
    from geardesign.catalogs.tables import catalog_names
    assert "oils" not in catalog_names()
