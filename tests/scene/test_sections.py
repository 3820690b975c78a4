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


@pytest.mark.slow
def test_mesh_drawing_adds_the_drawing_and_diagrams_of_both_pairs(tmp_path):
    """``mesh_drawing = true``: the optimum's and the given pair's meshing drawing and diagrams are
    written and linked from the report; without it, none are."""
    scene = tmp_path / "s.toml"
    scene.write_text("[gear]\nmodule = 8\nz1 = 17\nz2 = 26\nx1 = 0.898\nx2 = 0.517\nmesh_drawing = true\n")
    gd.run_scene(scene, tmp_path / "out")
    report = (tmp_path / "out" / "report.md").read_text(encoding="utf-8")
    for tag in ("optimum", "given"):
        for kind in ("mesh", "diagrams"):
            png = tmp_path / "out" / f"gear_{kind}_{tag}.png"
            assert png.read_bytes()[:4] == b"\x89PNG"
            assert f"(gear_{kind}_{tag}.png)" in report
    assert "x1/x2 = 0.8980/0.5170" in report
    ring = tmp_path / "r.toml"      # a ring pair: drawn with the ring its shaper cutter generates
    ring.write_text("[gear]\nmodule = 2\nz1 = 20\nz2 = 60\nx1 = 0.3\nx2 = 0.6\ninternal = true\nmesh_drawing = true\n")
    gd.run_scene(ring, tmp_path / "out3")
    for tag in ("optimum", "given"):
        assert (tmp_path / "out3" / f"gear_mesh_{tag}.png").read_bytes()[:4] == b"\x89PNG"
    plain = tmp_path / "p.toml"
    plain.write_text("[gear]\nmodule = 8\nz1 = 17\nz2 = 26\n")
    gd.run_scene(plain, tmp_path / "out2")
    assert not list((tmp_path / "out2").glob("gear_mesh_*"))


@pytest.mark.slow
def test_planetary_section_optimises_checks_and_searches(tmp_path):
    """[planetary]: the best coaxial shifts with the region and the set's drawing; given shifts get
    every check of both meshes and of the set (LECAD's printed set fails the planet's fillet by the
    ring's tip); a ratio searches tooth counts; a missing tooth count is one line."""
    opt = tmp_path / "o.toml"
    opt.write_text("[planetary]\nmodule = 1.75\nz_sun = 21\nz_planet = 43\nz_ring = 108\nn_planets = 3\n"
                   "objective = \"max_eps_alpha\"\n")
    rep = gd.run_scene(opt, tmp_path / "o")
    r = rep.results["planetary"]
    assert r.success and abs(r.a_w - r.a_w_planet_ring) < 1e-9
    for png in ("planetary_region.png", "planetary_set.png"):
        assert (tmp_path / "o" / png).read_bytes()[:4] == b"\x89PNG"
    given = tmp_path / "g.toml"
    given.write_text("[planetary]\nmodule = 1.75\nz_sun = 21\nz_planet = 43\nz_ring = 108\nn_planets = 3\n"
                     "x_sun = 0.438\nx_planet = 0.0426\nx_ring = 0.0\n")
    gd.run_scene(given, tmp_path / "g")
    t = pd.read_csv(tmp_path / "g" / "planetary_checks.csv").set_index("check")
    assert t.loc["set:coaxiality", "ok"] and not t.loc["planet-ring:interference_planet", "ok"]
    search = tmp_path / "s.toml"
    search.write_text("[planetary]\nmodule = 2\nn_planets = 3\nratio = 5\nz_sun_range = [18, 21]\n")
    rep = gd.run_scene(search, tmp_path / "s")
    assert rep.results["planetary"].found
    bad = tmp_path / "b.toml"
    bad.write_text("[planetary]\nmodule = 2\nn_planets = 3\nz_sun = 20\n")
    with pytest.raises(gd.GearDesignError, match=r"\[planetary\] z_planet: missing"):
        gd.load_scene(bad)
