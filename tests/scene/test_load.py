"""Scene files: the parser's errors (one message naming file, key and expectation), nothing
written on failure, and `geardesign run` on both example scenes checked against hand formulas."""
import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from scipy.optimize import brentq

import geardesign as gd
from geardesign.catalogs import key_lengths_mm
from geardesign.cli import main
from geardesign.errors import GearDesignError
from geardesign.scene import load_scene

SCENES = Path(__file__).resolve().parents[1] / "studies" / "scenes"

GOOD_GEAR = """
[gear]
module = 8
z1 = 17
z2 = 26
"""


def write(tmp_path, text, name="case.toml"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


@pytest.mark.parametrize("text, key, expected", [
    # unknown section
    (GOOD_GEAR + "\n[gears]\nz1 = 3\n", "gears", "expected sections"),
    # unknown key
    (GOOD_GEAR + "modul = 8\n", "modul", "unknown key; expected one of module"),
    # unknown key in a sub-table
    (GOOD_GEAR + "[gear.checks]\neps_min = 1.2\n", "eps_min", "unknown key; expected one of eps_alpha_min"),
    # wrong type
    (GOOD_GEAR.replace("z1 = 17", 'z1 = "seventeen"'), "z1", "expected a whole number in [3, 100000]"),   # gears.mesh Z_MIN, Z_MAX
    (GOOD_GEAR.replace("z1 = 17", "z1 = 17.5"), "z1", "expected a whole number"),
    (GOOD_GEAR + "tip_shortening = 1\n", "tip_shortening", "expected true or false"),
    (GOOD_GEAR + 'objective = "max_xsum"\n', "objective", "expected one of 'max_x_sum'"),
    # missing required value
    (GOOD_GEAR.replace("z2 = 26\n", ""), "z2", "missing; expected a whole number"),
    ("[chain]\ntorque_nm = 380\nratio = 1\n", "n1_rpm", "missing"),
    (GOOD_GEAR + "x1 = 0.5\n", "x2", "give both x1 and x2"),
    # out of range
    (GOOD_GEAR.replace("module = 8", "module = -8"), "module", "expected a number in [0.0001, 10000]"),   # gears.geometry M_RANGE_MM
    (GOOD_GEAR + "[gear.rack]\nalpha_deg = 50\n", "alpha_deg", "expected a number in [1, 44]"),   # gears.rack ALPHA_RANGE_DEG
    ("[chain]\ntorque_nm = 380\nn1_rpm = 120\nratio = 0.5\n", "ratio", "expected a number in [1, 10]"),
    ("[key]\nd_mm = 60\ntorque_nm = 380\nhub_length_mm = 50\nmax_keys = 3\n", "max_keys", "[1, 2]"),
    (GOOD_GEAR + "[study]\nparameter = \"colour\"\nvalues = [1, 2]\n", "parameter", "expected one of eps_alpha_min"),
    (GOOD_GEAR + "[study]\ntarget = \"chain\"\nparameter = \"k_e\"\nvalues = [1, 2]\n", "target", "[chain] is missing"),
])
def test_scene_errors_name_file_key_and_expectation(tmp_path, text, key, expected):
    p = write(tmp_path, text)
    with pytest.raises(GearDesignError) as info:
        load_scene(p)
    msg = str(info.value)
    assert str(p) in msg and key in msg and expected in msg
    assert "\n" not in msg


def test_not_toml_and_empty_scene(tmp_path):
    with pytest.raises(GearDesignError, match="not a valid TOML file"):
        load_scene(write(tmp_path, "[gear\nz1 = 17"))
    with pytest.raises(GearDesignError, match="expected at least one of the sections"):
        load_scene(write(tmp_path, 'title = "nothing"\n'))
    with pytest.raises(GearDesignError, match="cannot read"):
        load_scene(tmp_path / "missing.toml")


@pytest.mark.parametrize("text", [
    GOOD_GEAR + "colour = 'red'\n",                                    # caught by the parser
    GOOD_GEAR + "[gear.rack]\nrho_f = 0.9\n",                          # caught by BasicRack, still up front
    GOOD_GEAR + "[study]\nparameter = 'eps_alpha_min'\nvalues = []\n",  # empty list
])
def test_cli_one_line_exit_2_and_nothing_written(tmp_path, capsys, text):
    p = write(tmp_path, text)
    out = tmp_path / "out"
    before = sorted(x.name for x in tmp_path.iterdir())
    assert main(["run", str(p), "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and str(p) in err
    assert not out.exists()
    assert sorted(x.name for x in tmp_path.iterdir()) == before     # no temporary directory left either


def _eps_alpha_by_hand(m, z1, z2, x1, x2, alpha_deg=20.0, ha=1.0):
    """ε_α of a shifted pair from the textbook formulas (GOST 16532-70), written out here."""
    al = math.radians(alpha_deg)
    inv = lambda a: math.tan(a) - a
    inv_w = inv(al) + 2 * (x1 + x2) * math.tan(al) / (z1 + z2)
    aw = brentq(lambda a: inv(a) - inv_w, 1e-6, 1.5, xtol=1e-15)
    a = m * (z1 + z2) / 2
    a_w = a * math.cos(al) / math.cos(aw)
    dy = x1 + x2 - (a_w - a) / m
    ra = [m * z / 2 + (ha + x - dy) * m for z, x in ((z1, x1), (z2, x2))]
    rb = [m * z / 2 * math.cos(al) for z in (z1, z2)]
    g = sum(math.sqrt(r * r - b * b) for r, b in zip(ra, rb)) - a_w * math.sin(aw)
    return g / (math.pi * m * math.cos(al)), a_w


def test_run_seed000_gear_scene(tmp_path, capsys):
    out = tmp_path / "s0"
    assert main(["run", str(SCENES / "seed000_gear.toml"), "--out", str(out)]) == 0
    printed = capsys.readouterr().out
    for f in ("report.md", "gear_region.png", "gear_optimum.csv", "gear_given_checks.csv", "gear_given_geometry.csv",
              "study_sweep.csv", "study_margins.png", "study_region_motion.png", "study_tornado.png"):
        assert (out / f).stat().st_size > 0, f
    report = (out / "report.md").read_text(encoding="utf-8")
    # the seed's shifts fail the contact ratio (seed 000 prints ε_α = 0.133; the truth is ~1.153 < 1.2)
    eps, a_w = _eps_alpha_by_hand(8, 17, 26, 0.898, 0.517)
    assert eps < 1.2
    assert "**fails** contact_ratio" in report and "FAILS contact_ratio" in printed
    geo = pd.read_csv(out / "gear_given_geometry.csv").set_index("quantity")["value"]
    assert geo["eps_alpha"] == pytest.approx(eps, rel=1e-10)
    assert geo["a_w"] == pytest.approx(a_w, rel=1e-12)
    assert f"{eps:.4f}" in report
    # the optimum sits on ε_α = 1.2 exactly, and a hand ε_α at its shifts agrees
    opt = pd.read_csv(out / "gear_optimum.csv").iloc[0]
    assert _eps_alpha_by_hand(8, 17, 26, opt["x1"], opt["x2"])[0] == pytest.approx(1.2, abs=1e-9)
    assert "contact_ratio" in opt["active"]
    assert f"{opt['x1']:.4f}" in printed
    # the sweep: the limit is met with equality along it, and a stricter limit leaves less x-sum
    sw = pd.read_csv(out / "study_sweep.csv")
    assert np.allclose(sw["eps_alpha"], sw["eps_alpha_min"], atol=1e-8)
    assert (np.diff(sw["x_sum"]) < 0).all()
    assert "![blocking contour](gear_region.png)" in report


def test_run_seed002_chain_scene(tmp_path, capsys):
    out = tmp_path / "s2"
    assert main(["run", str(SCENES / "seed002_chain.toml"), "--out", str(out), "--json"]) == 0
    capsys.readouterr()
    for f in ("report.md", "chain_candidates.csv", "chain_blocking.csv", "keys.csv", "study_sweep.csv",
              "study_margins.png"):
        assert (out / f).stat().st_size > 0, f
    report = (out / "report.md").read_text(encoding="utf-8")
    # the seed's choice: two-strand 31.75 chain; its hinge pressure by hand
    assert "2PR-31,75-177" in report
    cand = pd.read_csv(out / "chain_candidates.csv")
    best = cand.iloc[0]
    v = 13 * 31.75 * 120 / 60000                         # m/s
    F = 380 * 2 * math.pi * 120 / 60 / v                  # N
    p = F * 2.148 / (260.0 * 1.7)                         # hinge area 260 mm², m·K_m = 1.7 for two strands
    assert best["designation"] == "2PR-31,75-177"
    assert best["pressure_mpa"] == pytest.approx(p, rel=1e-9)
    assert best["margin_pressure"] == pytest.approx(1 - p / 29, rel=1e-9)
    # two-sprocket link count: L = 2a/t + z = 2·180/31.75 + 13 = 24.3 → 24 (the seed's 30 is its three-sided layout)
    assert int(best["links"]) == 24
    # keys: crushing stress by hand for the key chosen, which is the longest standard length that
    # fits its hub less 5 mm (Dunaevsky & Lelikov §6.1)
    keys = pd.read_csv(out / "keys.csv")
    lengths = key_lengths_mm()
    for k in keys.itertuples():
        lp = k.length_mm - k.b_mm
        sigma = 2 * k.torque_nm * 1000 / (k.d_mm * (k.h_mm - k.t1_mm) * lp)
        assert k.crush_mpa == pytest.approx(sigma, rel=1e-12) and sigma <= 300
        assert k.length_mm == lengths[lengths <= k.hub_length_mm - 5].max()
    assert "18x11x45" in report


def test_scene_takes_a_users_chain_catalog_beside_it(tmp_path):
    """`catalog = "my_chains.csv"` is read relative to the scene file, as the CLI reads a path:
    the same rows give the same best chain as the built-in ISO 606 table they were copied from."""
    from geardesign.catalogs import catalog_dir

    (tmp_path / "my_chains.csv").write_bytes((catalog_dir() / "chains_iso606.csv").read_bytes())
    scene = tmp_path / "s.toml"
    scene.write_text('[chain]\ntorque_nm = 380\nn1_rpm = 120\nratio = 1\ncatalog = "my_chains.csv"\n')
    rep = gd.run_scene(scene, tmp_path / "out")
    ref = gd.chain.design(torque_nm=380, n1_rpm=120, ratio=1, catalog="iso606")
    assert any(ref.best["designation"] in line for line in rep.summary)
    bad = tmp_path / "bad.toml"
    bad.write_text('[chain]\ntorque_nm = 380\nn1_rpm = 120\nratio = 1\ncatalog = "keys"\n')
    with pytest.raises(gd.GearDesignError, match="or a .csv file of chains"):
        gd.load_scene(bad)


def test_study_sizes_are_refused_before_any_work():
    with pytest.raises(gd.GearDesignError, match="values must hold 1 to 2000 values, got 20000"):
        gd.sweep("eps_alpha_min", np.linspace(1.0, 1.5, 20000), z1=17, z2=26)
    with pytest.raises(gd.GearDesignError, match="at most 10,000 points"):
        gd.sweep("eps_alpha_min", np.linspace(1.0, 1.5, 200), "sa_min", np.linspace(0.2, 0.4, 200), z1=17, z2=26)


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
