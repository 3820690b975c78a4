"""Scene sections: the gear section with given shifts and a housing centre distance."""
import pandas as pd
import pytest

import geardesign as gd


def test_scene_with_given_shifts_and_a_housing_center_distance(tmp_path):
    """Given x1/x2 and a housing a_w: the optimum is the best split on that a_w (balanced sliding by
    default) and the given shifts get a center_distance check (their own a_w is 181.60 mm)."""
    scene = tmp_path / "s.toml"
    scene.write_text("[gear]\nmodule = 8\nz1 = 17\nz2 = 26\nx1 = 0.898\nx2 = 0.517\na_w = 180\n")
    rep = gd.run_scene(scene, tmp_path / "out")
    given = pd.read_csv(tmp_path / "out" / "gear_given_checks.csv").set_index("check")
    assert not given.loc["center_distance", "ok"]
    assert given.loc["center_distance", "value"] == pytest.approx(181.6016, abs=1e-4)
    assert "balanced_sliding" in rep.summary[0] and "a_w = 180.0000 mm" in rep.summary[0]
