"""The worm package: its names reach the top level (gd.WormPair, gd.worm_geometry, gd.select_worm), and importing
the gears' checks registers the worm's checks whichever module comes first."""
import subprocess
import sys

import geardesign as gd


def test_top_level_names():
    from geardesign.gears.worm import geometry, pair, series

    assert gd.WormPair is pair.WormPair and gd.worm_geometry is geometry.worm_geometry
    assert gd.select_worm is series.select_worm


def test_registry_is_the_same_whichever_module_is_imported_first():
    code = ("import geardesign.gears.checks as ck; print(sorted(ck.options()))")
    code2 = ("import geardesign.gears.worm.pair; import geardesign.gears.checks as ck; print(sorted(ck.options()))")
    outs = [subprocess.run([sys.executable, "-c", c], capture_output=True, text=True, check=True).stdout
            for c in (code, code2)]
    assert outs[0] == outs[1] and "x2_abs_max" in outs[0]
