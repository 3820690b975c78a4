"""Issue 35 §7: the strength model's options on the command line (--accuracy-grade, --factor NAME=VALUE, --fma,
--nu40, --rz-flank, --rz-root, --sh-min, --sf-min) give exactly the Python call's result, on `pair`, `shift`,
`teeth`, `planetary` and `drive` and in scenes; errors name the option, not the Python keyword; materials match
any case and a miss lists the nearest names; a bad option value is one line.

The reference values are the library's own ISO 6336 chain (validated against ISO/TR 6336-30 and an independent
DIN 3990 program in tests/gears/strength): here the command line must reproduce the Python call to the last bit.
The worked case is docs/strength.md's "One pair" (20/60, m = 4, 15 kW at 1450 rpm, 42CrMo4, 20 000 h): S_H 1.032
and OK at accuracy grade 6, which the command line could not reach before (issue 35 saw S_H 0.920, FAILS: the
default grade 7).
"""
from __future__ import annotations

import json
import math
import re

import pytest

import geardesign as gd
from geardesign.cli import build_parser, main
from geardesign.gears.strength import Load

PAIR = ["pair", "--module", "4", "--z1", "20", "--z2", "60", "--x1", "0.3", "--x2", "0.1", "--face-width", "40"]
LOAD = ["--power", "15", "--speed", "1450", "--life-h", "20000", "--material", "42CrMo4"]
DOCS_PAIR = gd.GearPair(m=4, z1=20, z2=60, x1=0.3, x2=0.1, face_width_mm=40)
DOCS_LOAD = Load(power_kw=15, n_rpm=1450, life_h=20_000)
FIELDS = ("S_H1", "S_H2", "S_F1", "S_F2", "sigma_H1", "sigma_F2", "sigma_HP1", "sigma_FP2", "S_Hmin", "S_Fmin",
          "given", "factors")


def _json(capsys, argv):
    code = main([*argv, "--json"])
    return code, json.loads(capsys.readouterr().out)


def test_docs_grade_6_example_from_the_command_line(capsys):
    """docs/strength.md: S_H 1.032, OK at grade 6 in Python; the same from the CLI (and 0.920, FAILS at grade 7)."""
    py = DOCS_PAIR.strength(DOCS_LOAD, material="42CrMo4", accuracy_grade=6)
    code, out = _json(capsys, [*PAIR, *LOAD, "--accuracy-grade", "6"])
    assert code == 0 and out["ok"] is True
    assert out["strength"]["S_H1"] == py.S_H1 and round(out["strength"]["S_H1"], 3) == 1.032
    code, out = _json(capsys, [*PAIR, *LOAD])
    assert code == 1 and round(out["strength"]["S_H1"], 3) == 0.920
    assert main([*PAIR, *LOAD, "--accuracy-grade", "6"]) == 0
    text = capsys.readouterr().out
    assert text.startswith("OK:") and "StrengthResult 20/60 m=4: OK" in text and "1.032" in text


@pytest.mark.parametrize("flags, options", [
    (["--accuracy-grade", "5"], {"accuracy_grade": 5}),
    (["--factor", "K_Hbeta=1.3"], {"factors": {"K_Hbeta": 1.3}}),
    (["--factor", "K_Hbeta=1.3", "--factor", "Z_X=0.95", "--factor", "K_v=1.1"],
     {"factors": {"K_Hbeta": 1.3, "Z_X": 0.95, "K_v": 1.1}}),
    (["--fma", "5"], {"factors": {"f_ma": 5.0}}),
    (["--fma", "0", "--factor", "K_v=1.05"], {"factors": {"f_ma": 0.0, "K_v": 1.05}}),
    (["--nu40", "100"], {"nu40": 100.0}),
    (["--rz-flank", "3"], {"Rz_flank_um": 3.0}),
    (["--rz-root", "20"], {"Rz_root_um": 20.0}),
    (["--sh-min", "1.2"], {"S_Hmin": 1.2}),
    (["--sf-min", "2"], {"S_Fmin": 2.0}),
    (["--accuracy-grade", "8", "--nu40", "320", "--rz-flank", "2", "--rz-root", "5", "--fma", "8", "--sh-min", "0.9",
      "--sf-min", "1.6", "--factor", "Y_X1=0.98"],
     {"accuracy_grade": 8, "nu40": 320.0, "Rz_flank_um": 2.0, "Rz_root_um": 5.0, "S_Hmin": 0.9, "S_Fmin": 1.6,
      "factors": {"f_ma": 8.0, "Y_X1": 0.98}}),
])
def test_each_option_gives_the_python_call(capsys, flags, options):
    from geardesign.results import plain

    py = json.loads(json.dumps(plain(DOCS_PAIR.strength(DOCS_LOAD, material="42CrMo4", **options).to_dict())))
    code, out = _json(capsys, [*PAIR, *LOAD, *flags])
    for k in FIELDS:
        assert out["strength"][k] == py[k], k          # bit for bit (every factor too): the same call
    checks = {c["check"]: c for c in out["checks"]}
    assert checks["contact_strength"]["value"] == pytest.approx(min(py["S_H1"], py["S_H2"]), rel=1e-12)
    assert checks["contact_strength"]["limit"] == options.get("S_Hmin", 1.0)
    assert checks["root_strength2"]["limit"] == options.get("S_Fmin", 1.4)
    assert code == (0 if out["ok"] else 1)


def test_the_check_limit_spellings_agree(capsys):
    """--sh-min is the check option --S-Hmin by a second name: one value, one argument."""
    _, a = _json(capsys, [*PAIR, *LOAD, "--sh-min", "1.1"])
    _, b = _json(capsys, [*PAIR, *LOAD, "--S-Hmin", "1.1"])
    assert a == b


def test_shift_optimum_with_the_options_rechecks_in_python(capsys):
    load = ["--torque", "600", "--speed", "1000", "--material", "18CrNiMo7-6", "--life-h", "20000"]
    code, out = _json(capsys, ["shift", "--z1", "20", "--z2", "60", "--module", "4", "--face-width", "40", *load,
                               "--accuracy-grade", "5", "--factor", "K_Hbeta=1.15", "--nu40", "150"])
    assert code == 0 and out["success"]
    r = gd.GearPair(4, 20, 60, out["x1"], out["x2"], face_width_mm=40).strength(
        Load(torque_nm=600, n_rpm=1000, life_h=20000), "18CrNiMo7-6", accuracy_grade=5, factors={"K_Hbeta": 1.15},
        nu40=150.0)
    assert out["margins"]["contact_strength"] == pytest.approx(min(r.S_H1, r.S_H2) - 1.0, abs=1e-9)
    assert out["margins"]["root_strength1"] == pytest.approx(r.S_F1 / 1.4 - 1.0, abs=1e-9)
    # the same call in Python: the same optimum
    py = gd.optimize_shifts(20, 60, m=4, face_width_mm=40, checks={
        "load": Load(torque_nm=600, n_rpm=1000, life_h=20000), "material": "18CrNiMo7-6",
        "strength": {"accuracy_grade": 5.0, "factors": {"K_Hbeta": 1.15}, "nu40": 150.0}})
    assert (out["x1"], out["x2"]) == pytest.approx((py.x1, py.x2), abs=1e-12)


def test_teeth_search_carries_the_options(capsys):
    load = ["--torque", "400", "--speed", "1000", "--material", "42CrMo4", "--face-width", "30"]
    base = ["teeth", "--ratio", "3", "--module", "3", "--z1-min", "20", "--z1-max", "22", *load]
    _, plain = _json(capsys, base)
    _, given = _json(capsys, [*base, "--factor", "K_Hbeta=1.0", "--accuracy-grade", "4"])
    best = given["table"][0]
    r = gd.GearPair(3, best["z1"], best["z2"], best["x1"], best["x2"], face_width_mm=30).strength(
        Load(torque_nm=400, n_rpm=1000), "42CrMo4", factors={"K_Hbeta": 1.0}, accuracy_grade=4)
    assert best["margin_contact_strength"] == pytest.approx(min(r.S_H1, r.S_H2) - 1.0, abs=1e-9)
    assert best["margin_contact_strength"] != plain["table"][0]["margin_contact_strength"]


def test_planetary_check_carries_the_options(capsys):
    from geardesign.gears.planetary import PlanetarySet

    argv = ["planetary", "--module", "1.75", "--planets", "3", "--z-sun", "21", "--z-planet", "43", "--z-ring", "108",
            "--x-sun", "0.6705", "--x-planet", "1.1547", "--torque", "150", "--speed", "1500", "--material",
            "18CrNiMo7-6", "--face-width", "25", "--life-h", "10000", "--accuracy-grade", "6", "--rz-flank", "3"]
    code, out = _json(capsys, argv)
    s = PlanetarySet.coaxial(1.75, 21, 43, 108, 3, 0.6705, 1.1547)
    table = s.checks({"load": Load(torque_nm=150, n_rpm=1500, life_h=10_000), "material": "18CrNiMo7-6",
                      "face_width_mm": 25, "strength": {"K_gamma": 1.0, "accuracy_grade": 6.0, "Rz_flank_um": 3.0},
                      "neighbour_clearance": 0.5})
    want = dict(zip(table["check"], table["margin"]))
    got = {c["check"]: c["margin"] for c in out["checks"]}
    assert got["sun-planet:contact_strength"] == want["sun-planet:contact_strength"]
    assert got["planet-ring:root_strength_ring"] == want["planet-ring:root_strength_ring"]
    assert code == (0 if out["ok"] else 1)


LOADED = ("[drive]\npower_kw = 7.5\nn_in_rpm = 1450\n[[drive.stage]]\nkind = 'given'\nratio = 2\nefficiency = 0.95\n"
          "[[drive.stage]]\nkind = 'gear'\nmodule = 4\nz1 = 20\nz2 = 60\nface_width_mm = 40\n")


@pytest.mark.parametrize("flags, options", [
    (["--accuracy-grade", "5", "--factor", "K_Hbeta=1.2"], {"accuracy_grade": 5, "factors": {"K_Hbeta": 1.2}}),
    (["--nu40", "68", "--rz-flank", "1.5", "--rz-root", "4", "--fma", "0"],
     {"nu40": 68.0, "Rz_flank_um": 1.5, "Rz_root_um": 4.0, "factors": {"f_ma": 0.0}}),
    (["--sh-min", "1.3", "--sf-min", "2.2"], {"S_Hmin": 1.3, "S_Fmin": 2.2}),
])
def test_drive_options_reach_the_gear_stage(tmp_path, capsys, flags, options):
    """The drive's gear stage carries 7.5 kW·2·0.95 at 725 rpm (the belt's u = 2, η = 0.95 upstream): its strength
    margins equal GearPair.strength with the same options, S/S_min − 1."""
    scene = tmp_path / "d.toml"
    scene.write_text(LOADED)
    code, out = _json(capsys, ["drive", str(scene), "--material", "42CrMo4", *flags])
    stage = out["analysis"]["stages"][1]
    torque = 7500 / (2 * math.pi * 1450 / 60) * 2 * 0.95
    r = gd.GearPair(4, 20, 60, stage["x1"], stage["x2"], face_width_mm=40).strength(
        Load(torque_nm=torque, n_rpm=725), "42CrMo4", **options)
    got = {c["check"]: c["margin"] for c in out["analysis"]["checks"] if c["item"] == "gear"}
    assert got["contact_strength"] == pytest.approx(min(r.S_H1, r.S_H2) / r.S_Hmin - 1, rel=1e-12)
    assert got["root_strength2"] == pytest.approx(r.S_F2 / r.S_Fmin - 1, rel=1e-12)
    assert r.S_Hmin == options.get("S_Hmin", 1.0)
    # the stage's own scene keys win over the command line's
    scene.write_text(LOADED + "accuracy_grade = 9\n")
    _, own = _json(capsys, ["drive", str(scene), "--material", "42CrMo4", *flags])
    r9 = gd.GearPair(4, 20, 60, stage["x1"], stage["x2"], face_width_mm=40).strength(
        Load(torque_nm=torque, n_rpm=725), "42CrMo4", **{**options, "accuracy_grade": 9})
    got9 = {c["check"]: c["margin"] for c in own["analysis"]["checks"] if c["item"] == "gear"}
    assert got9["contact_strength"] == pytest.approx(min(r9.S_H1, r9.S_H2) / r9.S_Hmin - 1, rel=1e-12)


def test_a_sized_stage_is_sized_with_the_options():
    """A stage of free module, sized by its load, takes the options: grade 5 with a measured K_Hβ = 1.2 needs a
    smaller module than the default grade 7 with K_Hβ by method C (the issue's 1.6 to 2.2)."""
    flow = dict(power_kw=7.5, n_in_rpm=1450)
    plain = gd.Drive([gd.GearStage(z1=20, z2=60, material="42CrMo4")], **flow).analyse()
    given = gd.Drive([gd.GearStage(z1=20, z2=60, material="42CrMo4",
                                   strength={"accuracy_grade": 5, "factors": {"K_Hbeta": 1.2}})], **flow).analyse()
    assert given.stages[0]["summary"]["m"] < plain.stages[0]["summary"]["m"]
    assert given.stages[0]["strength"].given == ("K_Hbeta",)


def test_scene_gear_load_takes_the_options(tmp_path):
    """[gear.load] accuracy_grade = 6 and [gear.load.factors]: the scene's given pair is docs/strength.md's."""
    scene = tmp_path / "g.toml"
    scene.write_text("[gear]\nmodule = 4\nz1 = 20\nz2 = 60\nx1 = 0.3\nx2 = 0.1\nface_width_mm = 40\n"
                     "[gear.load]\npower_kw = 15\nn_rpm = 1450\nlife_h = 20000\nmaterial = '42CrMo4'\n"
                     "accuracy_grade = 6\n[gear.load.factors]\nZ_X = 1.0\n")
    rep = gd.run_scene(scene, tmp_path / "out")
    py = DOCS_PAIR.strength(DOCS_LOAD, material="42CrMo4", accuracy_grade=6, factors={"Z_X": 1.0})
    table = rep.tables["gear_strength_given"]
    assert "given pair: S_H = 1.032" in " ".join(rep.summary) and not rep.failures
    k_hb = table.loc[table["symbol"] == "K_Hbeta", "value"].iloc[0]
    assert k_hb == py.factors.loc[py.factors["symbol"] == "K_Hbeta", "value"].iloc[0]


@pytest.mark.parametrize("flags, words", [
    (["--accuracy-grade", "13"], "--accuracy-grade must be in [0, 12], got 13"),
    (["--factor", "K_Hbeta=500"], "--factor K_Hbeta must be in [0.01, 100], got 500"),
    (["--factor", "K_Hbet=1.2"], "argument --factor: unknown factor 'K_Hbet'; nearest: K_Hbeta"),
    (["--factor", "K_Hbeta"], "argument --factor: expected NAME=VALUE"),
    (["--factor", "K_Hbeta=high"], "argument --factor: K_Hbeta: expected a number"),
    (["--factor", "K_Hbeta=1.2", "--factor", "K_Hbeta=1.3"], "--factor K_Hbeta given twice"),
    (["--fma", "5", "--factor", "f_ma=4"], "--fma and --factor 'f_ma=...' both given"),
    (["--nu40", "0"], "--nu40 must be in [1, 10000] mm²/s, got 0"),
    (["--rz-root", "50"], "--rz-root must be in [0.01, 40] µm, got 50"),
    (["--sh-min", "0.1"], "--sh-min must be in [0.5, 10], got 0.1"),
    (["--speed", "-5"], "--speed must be in (0, 1e+06] rpm, got -5"),
    (["--life-h", "0"], "--life-h must be in (0, 1e+07] h, got 0"),
    (["--application-factor", "0.5"], "--application-factor must be in [1, 10], got 0.5"),
    (["--material", "42CrMo5"], "--material must be a name of the catalog or an ISO 6336-5 group (see "
                                "material_names()), got '42CrMo5'; nearest: 42CrMo4"),
])
def test_bad_values_are_one_line_naming_the_option(capsys, flags, words):
    argv = [*PAIR, *LOAD, *flags] if "--speed" not in flags else [*PAIR, "--power", "15", "--material", "C45", *flags]
    assert _status(argv) == 2
    captured = capsys.readouterr()
    err = captured.err.strip().splitlines()
    assert captured.out == "" and len(err) == 1 and err[0].startswith("geardesign pair: error: "), err
    assert words in err[0], err[0]
    python_names = r"(?<![-\w])(n_rpm|life_h|application_factor|accuracy_grade|nu40|Rz_root_um|material)\b|factors\["
    assert re.search(python_names, err[0].removeprefix("geardesign pair: error: ")) is None, err[0]


def _status(argv) -> int:
    """main's exit status; a parse error leaves argparse by SystemExit, as the console script does."""
    try:
        return main(argv)
    except SystemExit as exc:
        return exc.code


def test_strength_options_need_a_load(capsys):
    assert main([*PAIR, "--accuracy-grade", "6", "--factor", "K_v=1"]) == 2
    err = capsys.readouterr().err.strip()
    assert err == ("geardesign pair: error: --accuracy-grade, --factor: the strength options need a load (--torque "
                   "or --power, --speed and --material)")


def test_material_names_ignore_case(capsys):
    _, upper = _json(capsys, [*PAIR, *LOAD])
    _, lower = _json(capsys, [*PAIR, *LOAD[:-1], "42crmo4"])
    assert lower["strength"] == upper["strength"]
    assert gd.gears.strength.material("c45").name == "C45" and gd.gears.strength.material("v_ALLOY", hardness=300).group == "V_alloy"
    assert gd.gears.strength.material("40х").name == "40Cr"       # a Cyrillic alias, lower case


def _every_subparser():
    import argparse

    parser = build_parser()
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    return sub.choices


# one option of each command that takes a number, given a word
BAD_NUMBER = {"pair": ["--module", "x"], "measure": ["--module", "x"], "mesh": ["--module", "x"],
              "shift": ["--z1", "x"], "atlas": ["--z1", "17", "--z2", "20", "--method", "x"],
              "teeth": ["--ratio", "x"], "planetary": ["--module", "x"], "chain": ["--n1", "x"],
              "key": ["--d", "x"], "drive": ["s.toml", "--speed", "x"], "run": ["s.toml", "--out", "o", "--workers"],
              "bearing": ["--fr", "x"], "shaft": ["--rz", "x"], "engine": ["s.toml", "--points", "x"],
              "worm": ["--module", "x"]}


@pytest.mark.parametrize("command", sorted(BAD_NUMBER))
def test_a_bad_option_value_is_one_line_not_the_usage_block(capsys, command):
    """argparse prints its whole usage block (17 lines for `pair`) before the error; every command: one line."""
    assert set(BAD_NUMBER) == set(_every_subparser())
    with pytest.raises(SystemExit) as exc:
        main([command, *BAD_NUMBER[command]])
    assert exc.value.code == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith(f"geardesign {command}: error: ") and "usage:" not in err[0], err


def test_a_scene_error_keeps_the_scene_key(tmp_path, capsys):
    """An error in the scene file names the scene's key (accuracy_grade, life_h), not the command's option."""
    scene = tmp_path / "d.toml"
    scene.write_text(LOADED + "accuracy_grade = 14\n")
    assert main(["drive", str(scene), "--material", "C45"]) == 2
    err = capsys.readouterr().err.strip()
    assert err == (f"geardesign drive: error: {scene}: [drive.stage #2] accuracy_grade: expected a number in [0, 12], "
                   f"got 14 (integer)")
