"""`geardesign drive ... --spectrum CSV` and the scene's [drive.spectrum]: the drive's spectrum at its input shaft,
each gear stage's duty cycle. The stage's bins are worked by hand here (the belt's u = 2, η = 0.95 ahead of the gear
stage: T = P/ω·2·0.95 at n/2) and its life is the stage's own pair's ``GearPair.life`` under them."""
import json
import math

import numpy as np
import pytest

import geardesign as gd
from geardesign.cli import main

SCENE = ("[drive]\npower_kw = 7.5\nn_in_rpm = 1450\n[[drive.stage]]\nkind = 'given'\nname = 'belt'\nratio = 2\n"
         "efficiency = 0.95\n[[drive.stage]]\nkind = 'gear'\nz1 = 20\nz2 = 60\n")
T_IN = 7500 / (2 * math.pi * 1450 / 60)
T_GEAR, N_GEAR = T_IN * 2 * 0.95, 725.0
CSV = "torque_nm,time_h\n# the motor's torque: a start-up overload, the nominal, part load\n150,200\n49.3929,8000\n25,11800\n"


def _files(tmp_path, scene=SCENE, csv=CSV):
    (tmp_path / "in.csv").write_text(csv)
    p = tmp_path / "d.toml"
    p.write_text(scene)
    return str(p), str(tmp_path / "in.csv")


def _hand_life(stage: dict, csv_rows, life_h):
    T = np.array([r[0] for r in csv_rows]) / T_IN * T_GEAR
    t = np.array([r[1] for r in csv_rows], dtype=float)
    spec = gd.LoadSpectrum.from_bins(T, N_GEAR, share=t / t.sum(), duration_h=life_h)
    pair = gd.GearPair(stage["m"], stage["z1"], stage["z2"], stage["x1"], stage["x2"],
                       face_width_mm=stage["face_width_mm"])
    return pair.life(spec, "42CrMo4")


@pytest.mark.parametrize("options, life_h", [([], 20000.0), (["--life-h", "30000"], 30000.0)])
def test_drive_spectrum_rates_each_gear_stage_by_its_life(tmp_path, capsys, options, life_h):
    scene, csv = _files(tmp_path)
    code = main(["drive", scene, "--material", "42CrMo4", "--spectrum", csv, *options, "--json"])
    data = json.loads(capsys.readouterr().out)
    stage = data["analysis"]["stages"][1]
    want = _hand_life(stage, [(150, 200), (49.3929, 8000), (25, 11800)], life_h)
    life = stage["life"]
    assert life["required_life_h"] == life_h
    for mode in ("H1", "H2", "F1", "F2"):
        assert life["D_" + mode] == pytest.approx(getattr(want, "D_" + mode), rel=1e-12)
    assert len(life["bins"]) == 3 and stage["damage"] == pytest.approx(want.governing[1], rel=1e-12)
    margins = {c["check"]: c["margin"] for c in data["analysis"]["checks"] if c["item"] == "gear"}
    assert margins["pitting_damage1"] == pytest.approx(1 - want.D_H1, rel=1e-12, abs=1e-12)
    assert code == 0 and data["ok"] and want.ok


def test_a_heavier_drive_spectrum_sizes_a_larger_stage_and_prints_its_life(tmp_path, capsys):
    scene, csv = _files(tmp_path)
    assert main(["drive", scene, "--material", "42CrMo4", "--json"]) == 0
    plain = json.loads(capsys.readouterr().out)["analysis"]["stages"][1]
    assert main(["drive", scene, "--material", "42CrMo4", "--spectrum", csv, "--json"]) == 0
    rated = json.loads(capsys.readouterr().out)["analysis"]["stages"][1]
    assert (rated["m"], rated["face_width_mm"]) > (plain["m"], plain["face_width_mm"])     # the 3x overload sizes it
    assert main(["drive", scene, "--material", "42CrMo4", "--spectrum", csv]) == 0
    out = capsys.readouterr().out
    assert "service life of stage 'gear'" in out and "pitting, gear 1  D = " in out


@pytest.mark.parametrize("scene, csv, options, words", [
    (SCENE, CSV, ["--spectrum", "missing.csv", "--material", "42CrMo4"], "--spectrum: spectrum file 'missing.csv' cannot be read"),
    (SCENE, CSV, ["--spectrum", "{csv}"], "--spectrum: gear stage 'gear' has no material"),
    (SCENE, "torque_nm,time_h\n150,abc\n", ["--spectrum", "{csv}", "--material", "42CrMo4"], "--spectrum: spectrum file"),
    (SCENE.replace("power_kw = 7.5", "output_torque_nm = 250"), CSV, ["--spectrum", "{csv}", "--material", "42CrMo4"],
     "--spectrum: a drive's spectrum is read relative to its nominal input torque"),
    (SCENE, CSV, ["--mean-stress-factor", "0.7", "--material", "42CrMo4"], "--mean-stress-factor needs --spectrum"),
    (SCENE, "torque_nm,time_h\n-40,100\n49,1000\n", ["--spectrum", "{csv}", "--material", "42CrMo4"],
     "mean-stress-factor"),
    (SCENE, "torque_nm,share\n49,1\n", ["--spectrum", "{csv}", "--material", "42CrMo4"], "duration_h"),
])
def test_bad_drive_spectrum_one_line_naming_the_option_exit_2(tmp_path, capsys, scene, csv, options, words):
    scene, path = _files(tmp_path, scene, csv)
    assert main(["drive", scene, *[o.format(csv=path) for o in options]]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and words in err[0]


def test_scene_drive_spectrum_beside_the_scene_and_the_report(tmp_path, capsys):
    body = SCENE.replace("z2 = 60\n", "z2 = 60\nmaterial = '42CrMo4'\n") + "[drive.spectrum]\nfile = 'in.csv'\n"
    scene, _ = _files(tmp_path, body)
    assert main(["drive", scene, "--json"]) == 0
    stage = json.loads(capsys.readouterr().out)["analysis"]["stages"][1]
    want = _hand_life(stage, [(150, 200), (49.3929, 8000), (25, 11800)], 20000.0)
    assert stage["life"]["D_H1"] == pytest.approx(want.D_H1, rel=1e-12)
    out = tmp_path / "out"
    assert main(["run", scene, "--out", str(out)]) == 0
    text = (out / "report.md").read_text()
    assert "### Service life of stage 'gear' (ISO 6336-6:2019)" in text and (out / "drive_life_gear.csv").is_file()
    html = tmp_path / "r.html"
    assert main(["drive", scene, "--report", str(html)]) == 0
    assert "Service life under the spectrum (ISO 6336-6:2019)" in html.read_text()
    bad = body.replace("file = 'in.csv'", "file = 'none.csv'")
    scene, _ = _files(tmp_path, bad)
    capsys.readouterr()
    assert main(["drive", scene]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "[drive.spectrum] file" in err[0] and "none.csv" in err[0]


def test_a_scene_stage_sets_its_own_life_keys(tmp_path, capsys):
    # single_load = false: the stage is rated by the spectrum alone (no single-load checks), its own S-N curve kept
    body = (SCENE.replace("z2 = 60\n", "z2 = 60\nmaterial = '42CrMo4'\nsingle_load = false\nsn_curve = 'elementary'\n")
            + "[drive.spectrum]\nfile = 'in.csv'\nsn_curve = 'original'\nlife_h = 25000\n")
    scene, _ = _files(tmp_path, body)
    assert main(["drive", scene, "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    stage = data["analysis"]["stages"][1]
    checks = {c["check"] for c in data["analysis"]["checks"] if c["item"] == "gear"}
    assert "contact_strength" not in checks and {"pitting_damage1", "root_damage2"} <= checks
    assert stage["life"]["sn_curve"] == "elementary" and stage["life"]["required_life_h"] == 25000
    assert "strength" not in stage
    scene, _ = _files(tmp_path, body.replace("single_load = false", "single_load = 'no'"))
    assert main(["drive", scene]) == 2
    assert "single_load" in capsys.readouterr().err


def test_a_scene_stage_s_own_spectrum_is_its_pinions_loads(tmp_path, capsys):
    # [drive.stage.spectrum]: the CSV's torques and speeds are the stage's pinion's, as they are (a LoadSpectrum);
    # it wins over the drive's [drive.spectrum]
    (tmp_path / "stage.csv").write_text("torque_nm,n_rpm,time_h\n300,725,200\n94,725,19800\n")
    body = (SCENE.replace("z2 = 60\n", "z2 = 60\nmaterial = '42CrMo4'\n[drive.stage.spectrum]\nfile = 'stage.csv'\n")
            + "[drive.spectrum]\nfile = 'in.csv'\n")
    scene, _ = _files(tmp_path, body)
    assert main(["drive", scene, "--json"]) == 0
    stage = json.loads(capsys.readouterr().out)["analysis"]["stages"][1]
    pair = gd.GearPair(stage["m"], 20, 60, stage["x1"], stage["x2"], face_width_mm=stage["face_width_mm"])
    want = pair.life(gd.LoadSpectrum.from_bins([300.0, 94.0], 725.0, time_h=[200.0, 19800.0]), "42CrMo4")
    assert stage["life"]["D_H1"] == pytest.approx(want.D_H1, rel=1e-12) and stage["life"]["required_life_h"] == 20000
    scene, _ = _files(tmp_path, body.replace("'stage.csv'", "'gone.csv'"))
    assert main(["drive", scene]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "[drive.stage.spectrum] file" in err[0] and "gone.csv" in err[0]
