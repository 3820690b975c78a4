"""The `geardesign run` command: one-line errors with nothing written, and both example scenes
and a [teeth] scene run end to end, checked against hand formulas."""
import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from scipy.optimize import brentq

import geardesign as gd
from geardesign.catalogs import key_lengths_mm
from geardesign.cli import main

from tests.scene_files import GOOD_GEAR, write

SCENES = Path(__file__).resolve().parents[2] / "studies" / "scenes"


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


def test_a_failed_run_leaves_no_parent_folders(tmp_path, capsys):
    # issue 36 §1.2: a wrong scene exited 2 but left the parents of --out that it had created
    p = write(tmp_path, GOOD_GEAR + "colour = 'red'\n")
    before = sorted(x.name for x in tmp_path.iterdir())
    assert main(["run", str(p), "--out", str(tmp_path / "a" / "b" / "out")]) == 2
    assert len(capsys.readouterr().err.strip().splitlines()) == 1
    assert sorted(x.name for x in tmp_path.iterdir()) == before
    # a good run keeps them: they hold the report
    assert main(["run", str(write(tmp_path, GOOD_GEAR)), "--out", str(tmp_path / "a" / "b" / "out")]) in (0, 1)
    assert (tmp_path / "a" / "b" / "out" / "report.md").is_file()


def test_out_below_a_file_is_one_line(tmp_path, capsys, monkeypatch):
    # issue 36 §1.7: --out afile/sub, afile a file, was a FileExistsError traceback
    monkeypatch.chdir(tmp_path)
    Path("afile").write_text("mine", encoding="utf-8")
    write(tmp_path, GOOD_GEAR)
    for out in ("afile/sub", "afile/sub/deeper"):
        assert main(["run", "case.toml", "--out", out]) == 2
        err = capsys.readouterr().err.strip()
        assert err.splitlines() == [f"geardesign run: error: --out '{out}': 'afile' is a file, not a folder"]
    assert Path("afile").read_text(encoding="utf-8") == "mine"


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
    assert main(["run", str(SCENES / "seed000_gear.toml"), "--out", str(out)]) == 1   # the given shifts fail
    printed = capsys.readouterr().out
    assert printed.splitlines()[0] == "FAILS: gear: the given shifts fail contact_ratio"
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


# A scene with a [teeth] section: u = 1.5 at m = 8 (seed 000's ratio), run end to end.
SCENE = """
title = "u = 1.5 tooth counts (seed 000)"
[teeth]
ratio = 1.5
ratio_tol = 0.02
module = 8
z1_range = [14, 20]
z_sum_max = 45
"""


def test_teeth_scene(tmp_path, capsys):
    path = tmp_path / "teeth.toml"
    path.write_text(SCENE, encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(path), "--out", str(out)]) == 0
    table = pd.read_csv(out / "teeth.csv")
    # every listed pair has its ratio within 2 % of 1.5 and respects the size bound (hand arithmetic)
    assert ((table.z2 / table.z1 - 1.5).abs() / 1.5 <= 0.02 + 1e-12).all()
    assert ((table.z1 + table.z2) <= 45).all() and table.z1.between(14, 20).all()
    # the enumeration is complete: every such pair by brute force is in the table
    brute = {(z1, z2) for z1 in range(14, 21) for z2 in range(z1, 46)
             if abs(z2 / z1 - 1.5) / 1.5 <= 0.02 and z1 + z2 <= 45}
    assert brute == set(zip(table.z1, table.z2))
    best = table.iloc[0]
    assert bool(best.feasible)
    # the chosen pair's shifts hold every check when recomputed with GearPair
    checks = gd.GearPair(8, int(best.z1), int(best.z2), best.x1, best.x2).checks(jamming=False)
    assert (checks["margin"] >= -1e-9).all()
    # and a_w agrees with the textbook formula a cos α / cos α_w
    inv = lambda a: math.tan(a) - a
    al = math.radians(20)
    target = inv(al) + 2 * (best.x1 + best.x2) * math.tan(al) / (best.z1 + best.z2)
    lo, hi = al, 1.2
    for _ in range(200):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if inv(mid) < target else (lo, mid)
    a_w = 8 * (best.z1 + best.z2) / 2 * math.cos(al) / math.cos(lo)
    assert abs(best.a_w_mm - a_w) < 1e-9
    report = (out / "report.md").read_text(encoding="utf-8")
    assert "Tooth counts for u = 1.5" in report
    assert f"{int(best.z1)}/{int(best.z2)}" in capsys.readouterr().out


def test_out_as_a_link_to_a_folder_keeps_the_link(tmp_path, capsys):
    """Issue 29 §3.9: `run --out link` replaced the link with a real folder and left
    '.link.XXXX.old -> real' behind."""
    real = tmp_path / "real"
    real.mkdir()
    (real / "stale.txt").write_text("old")
    link = tmp_path / "link"
    link.symlink_to(real, target_is_directory=True)
    rc = main(["run", str(SCENES / "seed002_chain.toml"), "--out", str(link), "--overwrite"])
    assert rc == 0, capsys.readouterr().err
    assert link.is_symlink() and (real / "report.md").is_file() and not (real / "stale.txt").exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["link", "real"]


ENGINE_EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_run_models_an_engine_section(tmp_path, capsys):
    """[engine] was refused as an unknown section; now it is the torque curve's table, plot and summary."""
    from geardesign.scene.engine import load_engine

    out = tmp_path / "out"
    assert main(["run", str(ENGINE_EXAMPLES / "seed000_engine.toml"), "--out", str(out)]) == 0
    text = capsys.readouterr().out
    res = load_engine(ENGINE_EXAMPLES / "seed000_engine.toml").engine.analyse(720)
    assert f"engine: mean torque M_i = {res.mean_torque_nm:.6g} N·m" in text and "8 reversals per cycle" in text
    table = pd.read_csv(out / "engine_torque.csv")
    np.testing.assert_allclose(table["torque_nm"], res.torque_nm, rtol=1e-9, atol=1e-9)
    assert (out / "engine_torque.png").stat().st_size > 10_000 and "engine_torque.png" in (out / "report.md").read_text()


def test_run_the_seed_engine_end_to_end(tmp_path, capsys):
    """examples/seed000_engine_gear.toml through `run`: the torque curve, the spectrum's histogram, the S-N diagrams
    and the damage tables in the report; exit 1 (the seed's shifts fail eps_alpha >= 1.2); the life at the given
    shifts is the engine command's."""
    from geardesign.scene.engine_gear import engine_gear
    from geardesign.scene.load import load_scene

    out = tmp_path / "out"
    assert main(["run", str(ENGINE_EXAMPLES / "seed000_engine_gear.toml"), "--out", str(out)]) == 1
    text = capsys.readouterr().out
    assert text.startswith("FAILS: gear: the given shifts fail contact_ratio")
    for name in ("engine_torque", "gear_spectrum", "gear_life_given", "gear_life_optimum", "gear_region"):
        assert (out / f"{name}.png").stat().st_size > 10_000, name
    report = (out / "report.md").read_text(encoding="utf-8")
    for part in ("## Engine: 2 cylinder(s), 1700 rpm", "### Load spectrum (ISO 6336-6)", "counted at the mesh instants",
                 "Y_M = 0.7", "| mode | gear | D | life_h | S | ok |", "![S-N diagrams with the spectrum]"):
        assert part in report, part
    g = engine_gear(load_scene(ENGINE_EXAMPLES / "seed000_engine_gear.toml"))
    damage = pd.read_csv(out / "gear_damage_given.csv")
    np.testing.assert_allclose(damage["D"], g.life["given"].damage_table()["D"], rtol=1e-12)
    opt = pd.read_csv(out / "gear_optimum.csv")
    assert opt["objective"][0] == "max_life"
    assert opt["x1"][0] == pytest.approx(g.optimum.x1, abs=1e-9) and opt["x2"][0] == pytest.approx(g.optimum.x2, abs=1e-9)
    hist = pd.read_csv(out / "gear_spectrum.csv")
    assert hist["share"].sum() == pytest.approx(1.0) and set(hist["flank"]) == {"drive", "coast"}
