"""`geardesign drive` and the [drive] scene section. The figures are the hand-checked seed 002 flow of
tests/drives/test_drive.py (4 kW at 1500 rpm through u = 12.5, η = 0.87; chain u = 1, η = 0.96)."""
import json
import math
from pathlib import Path

import pytest

from geardesign.cli import main
from geardesign.scene import load_scene

SCENES = Path(__file__).resolve().parents[2] / "studies" / "scenes"
SEED = str(SCENES / "seed002_drive.toml")
T1 = 4000 / (2 * math.pi * 1500 / 60) * 12.5 * 0.87


def test_drive_table_and_exit_0(capsys):
    assert main(["drive", SEED]) == 0
    out = capsys.readouterr().out
    assert out.startswith("OK: u = 12.5")          # the verdict first (issue 35 §8)
    assert out.splitlines()[2].startswith("optimum (min_mass, u = 12.5 ± 0 %)")
    assert f"{T1:.6g}".rstrip("0") in out          # 276.93 N·m on the driving sprocket's shaft
    assert "alternatives" in out and "power flow:" in out and "keys:" in out


def test_drive_json_matches_the_hand_flow(capsys):
    assert main(["drive", SEED, "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    flow = data["analysis"]["flow"]
    assert [r["n_rpm"] for r in flow] == pytest.approx([1500, 120, 120])
    assert flow[1]["torque_nm"] == pytest.approx(T1, rel=1e-14)
    assert flow[2]["torque_nm"] == pytest.approx(T1 * 0.96, rel=1e-14)
    assert data["optimum"]["table"][0]["rank"] == 1 and data["optimum"]["success"]


def test_drive_plot_written_whole_and_not_overwritten(tmp_path, capsys):
    png = tmp_path / "drive.png"
    assert main(["drive", SEED, "--plot", str(png)]) == 0
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    # said as the report is (the new user's finding: --report said so, --plot did not)
    assert f"diagram written to {png}" in capsys.readouterr().err
    assert main(["drive", SEED, "--plot", str(png)]) == 2
    assert "--overwrite" in capsys.readouterr().err


def _scene(tmp_path, body):
    p = tmp_path / "d.toml"
    p.write_text(body)
    return str(p)


GIVEN = "[drive]\npower_kw = 4\nn_in_rpm = 1500\n[[drive.stage]]\nkind = 'given'\nratio = 12.5\nefficiency = 0.87\n"


@pytest.mark.parametrize("extra, words", [
    ("[[drive.stage]]\nkind = 'belt'\n", "kind"),
    ("[[drive.stage]]\nkind = 'chain'\nz1 = 13\nz2 = 13\ndesignation = 'PR-99'\n", "PR-99"),
    ("[[drive.shaft]]\nat = 5\nd_mm = 60\nhub_length_mm = 50\n", "at = 5"),
    ("[[drive.stage]]\nkind = 'gear'\nmodule = 3\nz1 = 17\n", "free tooth counts"),
])
def test_bad_drive_scene_one_line_exit_2(tmp_path, capsys, extra, words):
    path = _scene(tmp_path, GIVEN + extra)
    code = main(["drive", path])
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 2 and len(err) == 1 and words in err[0]


def test_infeasible_drive_exit_1_names_the_stage(tmp_path, capsys):
    # 276.9 N·m on a 20 mm shaft in a 25 mm hub: the 6x6 key cannot carry it, one or two
    path = _scene(tmp_path, GIVEN + "[[drive.shaft]]\nat = 1\nname = 'out'\nd_mm = 20\nhub_length_mm = 25\n")
    assert main(["drive", path]) == 1
    out = capsys.readouterr().out
    assert "fails key 'out': crushing" in out


def test_old_sections_still_load_beside_drive(tmp_path):
    body = GIVEN + "[key]\nd_mm = 60\ntorque_nm = 503\nhub_length_mm = 50\n"
    scene = load_scene(_scene(tmp_path, body))
    assert set(scene.sections) == {"drive", "key"}


def test_run_writes_the_drive_report(tmp_path, capsys):
    out = tmp_path / "out"
    assert main(["run", SEED, "--out", str(out)]) == 0
    text = (out / "report.md").read_text()
    assert "### Power flow" in text and "![drive diagram](drive_diagram.png)" in text
    assert (out / "drive_diagram.png").is_file() and (out / "drive_flow.csv").is_file()


# -- the load options (--material, --power/--torque/--speed, --life-h, ...): each gear stage's strength checks
# equal the pair's own StrengthResult (GearPair.strength) at the torque and speed the flow brings it, worked by
# hand here: T = P/ω·u·η upstream of the stage.
LOADED = ("[drive]\npower_kw = 7.5\nn_in_rpm = 1450\n[[drive.stage]]\nkind = 'given'\nratio = 2\nefficiency = 0.95\n"
          "[[drive.stage]]\nkind = 'gear'\nmodule = 4\nz1 = 20\nz2 = 60\nface_width_mm = 40\n")


def _strength_margins(stage, torque_nm, n_rpm, material="42CrMo4", **load):
    import geardesign as gd
    from geardesign.gears.strength import Load

    pair = gd.GearPair(stage["m"], stage["z1"], stage["z2"], stage["x1"], stage["x2"], face_width_mm=40)
    res = pair.strength(Load(torque_nm=torque_nm, n_rpm=n_rpm, **load), material)
    return {"contact_strength": min(res.S_H1, res.S_H2) / res.S_Hmin - 1, "root_strength1": res.S_F1 / res.S_Fmin - 1,
            "root_strength2": res.S_F2 / res.S_Fmin - 1}


def _drive_json(capsys, argv):
    code = main(["drive", *argv, "--json"])
    data = json.loads(capsys.readouterr().out)
    got = {c["check"]: c["margin"] for c in data["analysis"]["checks"] if c["item"] == "gear"}
    return code, data, got


@pytest.mark.parametrize("options, torque_nm, n_rpm, load", [
    ([], 7500 / (2 * math.pi * 1450 / 60) * 2 * 0.95, 725, {}),                     # the scene's input
    (["--power", "15", "--speed", "1000"], 15000 / (2 * math.pi * 1000 / 60) * 2 * 0.95, 500, {}),
    (["--torque", "80"], 80 * 2 * 0.95, 725, {}),                                     # at the scene's 1450 rpm
    (["--life-h", "2000", "--application-factor", "1.25"], 7500 / (2 * math.pi * 1450 / 60) * 2 * 0.95, 725,
     {"life_h": 2000, "application_factor": 1.25}),
])
def test_drive_load_options_reach_the_gear_stage(tmp_path, capsys, options, torque_nm, n_rpm, load):
    code, data, got = _drive_json(capsys, [_scene(tmp_path, LOADED), "--material", "42CrMo4", *options])
    flow = data["analysis"]["flow"]
    assert flow[1]["torque_nm"] == pytest.approx(torque_nm / 0.98 * 0.98, rel=1e-13)   # into the gear stage
    assert flow[1]["n_rpm"] == pytest.approx(n_rpm, rel=1e-14)
    want = _strength_margins(data["analysis"]["stages"][1], torque_nm, n_rpm, **load)
    assert {k: got[k] for k in want} == pytest.approx(want, rel=1e-12)
    assert code == (0 if min(data["analysis"]["checks"], key=lambda c: c["margin"])["margin"] >= -1e-9 else 1)


def test_drive_stage_material_of_the_scene_wins_and_a_free_module_is_sized(tmp_path, capsys):
    body = LOADED.replace("module = 4\n", "material = 'C45'\n").replace("face_width_mm = 40\n", "")
    code, data, got = _drive_json(capsys, [_scene(tmp_path, body), "--material", "42CrMo4"])
    stage = data["analysis"]["stages"][1]
    # sized by its own load, with its own material: the smallest ISO 54 module whose checks hold
    assert code == 0 and stage["m"] in (1, 1.125, 1.25, 1.375, 1.5, 1.75, 2, 2.25, 2.5, 2.75, 3, 3.5, 4, 4.5, 5, 5.5, 6)
    import geardesign as gd
    from geardesign.gears.strength import Load

    pair = gd.GearPair(stage["m"], 20, 60, stage["x1"], stage["x2"], face_width_mm=stage["face_width_mm"])
    res = pair.strength(Load(torque_nm=7500 / (2 * math.pi * 1450 / 60) * 2 * 0.95, n_rpm=725), "C45")
    assert got["contact_strength"] == pytest.approx(min(res.S_H1, res.S_H2) / res.S_Hmin - 1, rel=1e-12)
    assert min(got.values()) >= -1e-9


@pytest.mark.parametrize("options, words", [
    (["--on-gear", "2"], "--on-gear"),
    (["--material2", "C45"], "--material2"),
    (["--material", "unobtainium"], "unobtainium"),
    (["--life-h", "-5", "--material", "C45"], "--life-h must"),   # the option, not GearStage's life_h
    (["--power", "4", "--torque", "20"], "torque"),
])
def test_drive_bad_load_options_one_line_exit_2(tmp_path, capsys, options, words):
    assert main(["drive", _scene(tmp_path, LOADED), *options]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and words in err


# every gear stage sets its own load case: the options fill nothing in, yet a bad value was passed over with exit 0
OWN = LOADED.replace("face_width_mm = 40\n", "face_width_mm = 40\nmaterial = 'C45'\nlife_h = 20000\n"
                     "application_factor = 1.25\naccuracy_grade = 7\nS_Hmin = 1.1\n[drive.stage.factors]\nK_Hbeta = 1.3\n")


@pytest.mark.parametrize("options, words", [
    (["--material", "unobtainium"], "--material must be a name"),
    (["--life-h", "nan"], "--life-h must be finite"),
    (["--application-factor", "nan"], "--application-factor must be finite"),
    (["--sh-min", "0"], "--sh-min must be in"),
    (["--accuracy-grade", "20"], "--accuracy-grade must be in"),
    (["--factor", "K_Hbeta=-3"], "--factor K_Hbeta must be in"),
    (["--strength-width", "-4"], "--strength-width must be in"),
    (["--speed", "0"], "--speed must be in"),            # named by the option, not by the Drive's n_in_rpm
])
def test_drive_bad_load_options_refused_where_every_stage_sets_its_own(tmp_path, capsys, options, words):
    assert main(["drive", _scene(tmp_path, OWN), *options]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and words in err


def test_drive_without_a_design_says_its_files_are_not_written(tmp_path, capsys):
    # no chain carries 4 kW·12.5/0.87 through the key of a 20 mm shaft: the search ends without a design, and the
    # asked-for plot and report were silently not written
    body = GIVEN.replace("n_in_rpm = 1500\n", "n_in_rpm = 1500\ntotal_ratio = 25\n") + (
        "[[drive.stage]]\nkind = 'chain'\n[[drive.shaft]]\nat = 1\nname = 'out'\nd_mm = 20\nhub_length_mm = 25\n")
    png, html = tmp_path / "d.png", tmp_path / "d.html"
    assert main(["drive", _scene(tmp_path, body), "--plot", str(png), "--report", str(html)]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert err == ["no design to draw or report: --plot, --report not written"]
    assert not png.exists() and not html.exists()


def test_drive_load_options_without_a_gear_stage_or_beside_a_motor_are_refused(tmp_path, capsys):
    assert main(["drive", _scene(tmp_path, GIVEN), "--material", "C45"]) == 2
    assert "no gear stage" in capsys.readouterr().err
    motor = GIVEN.replace("power_kw = 4\nn_in_rpm = 1500\n", "[drive.motor]\npower_kw = 4\nn_rpm = 1500\n")
    assert main(["drive", _scene(tmp_path, motor), "--power", "3"]) == 2
    assert "[drive.motor]" in capsys.readouterr().err


def test_drive_strength_width_is_the_face_width_of_stages_without_one(tmp_path, capsys):
    import geardesign as gd
    from geardesign.gears.strength import Load

    body = LOADED.replace("face_width_mm = 40\n", "")
    code, data, got = _drive_json(capsys, [_scene(tmp_path, body), "--material", "42CrMo4", "--strength-width", "30"])
    stage = data["analysis"]["stages"][1]
    assert stage["face_width_mm"] == 30
    pair = gd.GearPair(4, 20, 60, stage["x1"], stage["x2"], face_width_mm=30)
    res = pair.strength(Load(torque_nm=7500 / (2 * math.pi * 1450 / 60) * 2 * 0.95, n_rpm=725), "42CrMo4")
    assert got["root_strength1"] == pytest.approx(res.S_F1 / res.S_Fmin - 1, rel=1e-12)


def test_drive_progress_never_touches_the_json(capsys):
    """--progress asks for the bar on stderr even off a terminal; stdout stays one JSON document."""
    assert main(["drive", SEED, "--json", "--progress"]) == 0
    captured = capsys.readouterr()
    assert json.loads(captured.out)["ok"] is True
    assert "{" not in captured.err


# -- the drive's shafts (docs/shafts_in_drive.md): options, scene tables, output, bad input by option name

REDUCER = ("[drive]\npower_kw = 11\nn_in_rpm = 960\n"
           "[[drive.stage]]\nkind = 'gear'\nname = 'fast'\nmodule = 3\nz1 = 20\nz2 = 80\nx1 = 0.3\nx2 = 0.1\n"
           "material = '42CrMo4-IF'\nface_width_mm = 45\n"
           "[[drive.stage]]\nkind = 'gear'\nname = 'slow'\nmodule = 4\nz1 = 21\nz2 = 84\nx1 = 0.3\nx2 = 0.1\n"
           "material = '42CrMo4-IF'\nface_width_mm = 65\n")


def test_drive_shafts_tables_and_json(tmp_path, capsys):
    path = _scene(tmp_path, REDUCER)
    code = main(["drive", path, "--shafts", "--oil", "220,19", "--json"])
    data = json.loads(capsys.readouterr().out)
    an = data["analysis"]
    assert code == (0 if data["ok"] else 1)
    assert [r["shaft"] for r in an["shafts"]] == [0, 1, 2]
    assert {r["source"] for r in an["efficiency"]} == {"computed"}
    assert {r["item"] for r in an["checks"]} >= {"shaft 1", "key 2 slow"}
    b1a = next(b for b in an["bearings"] if b["shaft"] == 1 and b["name"].startswith("bearing 1A"))
    assert b1a["name"] == f"bearing 1A {b1a['designation']}" and b1a["name"] in {r["item"] for r in an["checks"]}
    assert 0.95 < an["overall_efficiency"] < 1 and an["heat_kw"] > 0
    main(["drive", path, "--shafts"])
    out = capsys.readouterr().out
    assert "bearings (ISO 281):" in out and "K_Hβ from the shafts" in out


@pytest.mark.parametrize("args, option", [(["--bearing-life", "-3"], "--bearing-life"),
                                          (["--shaft-material", "cheese"], "--shaft-material"),
                                          (["--bearing-series", "64"], "--bearing-series"),
                                          (["--shaft-safety", "0"], "--shaft-safety"),
                                          (["--oil", "220"], "--oil"), (["--oil", "19,220"], "--oil"),
                                          (["--oil-temperature", "900"], "--oil-temperature"),
                                          (["--bearing-type", "spherical"], "--bearing-type"),
                                          (["--bearing-type", "one=tapered"], "--bearing-type"),
                                          (["--bearing-type", "1=spherical"], "--bearing-type"),
                                          (["--arrangement", "Y"], "--arrangement"),
                                          (["--bearing-type", "3=tapered"], "--bearing-type"),
                                          (["--bearing-series", "62,63", "--bearing-type", "tapered"],
                                           "--bearing-series with --bearing-type")])
def test_drive_shaft_options_bad_input_one_line_exit_2(tmp_path, capsys, args, option):
    code = main(["drive", _scene(tmp_path, REDUCER)] + args)
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 2 and len(err) == 1 and option in err[0]


def test_drawn_shaft_in_a_scene_fails_by_name(tmp_path, capsys):
    # shaft 1 drawn 16 mm thick with 6202 bearings: its key seat under 'slow' is too weak (DIN 743), exit 1
    body = REDUCER + ("[[drive.shaft]]\nat = 1\nlengths_mm = [40, 170, 40]\ndiameters_mm = [15, 16, 15]\n"
                      "supports_mm = [20, 230]\nbearing_a = '6202'\nbearing_b = '6202'\n"
                      "[drive.shaft.positions]\nfast = 72.5\nslow = 152.5\n")
    assert main(["drive", _scene(tmp_path, body)]) == 1
    out = capsys.readouterr().out
    assert "shaft 1:safety key slow" in out.split("\n\n")[0]       # on the verdict line(s)


@pytest.mark.parametrize("extra, words", [
    ("[[drive.shaft]]\nat = 1\nlengths_mm = [250]\ndiameters_mm = [40, 45]\nsupports_mm = [20, 230]\n"
     "[drive.shaft.positions]\nfast = 72.5\nslow = 152.5\n", "diameters_mm"),
    ("[[drive.shaft]]\nat = 1\nlengths_mm = [250]\ndiameters_mm = [40]\nsupports_mm = [20, 230]\n", "positions"),
    ("[[drive.shaft]]\nat = 1\nlengths_mm = [250]\ndiameters_mm = [40]\nsupports_mm = [20, 230]\n"
     "[drive.shaft.positions]\nfast = 'left'\n", "fast"),
    ("[drive.shafting]\nnu40 = 220\n", "nu100"),
    ("[drive.shafting]\nlife_h = -1\n", "life_h"),
])
def test_bad_shafting_scene_one_line_exit_2(tmp_path, capsys, extra, words):
    code = main(["drive", _scene(tmp_path, REDUCER + extra)])
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 2 and len(err) == 1 and words in err[0]


def test_layout_plot_needs_shafts_and_is_written_whole(tmp_path, capsys):
    path = _scene(tmp_path, REDUCER)
    png = tmp_path / "layout.png"
    assert main(["drive", path, "--layout-plot", str(png)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--layout-plot" in err[0] and not png.exists()
    assert main(["drive", path, "--shafts", "--layout-plot", str(png)]) in (0, 1)
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert f"shaft layout written to {png}" in capsys.readouterr().err


def test_reports_carry_the_shafting(tmp_path, capsys):
    scene = str(SCENES / "reducer_shafts.toml")
    out = tmp_path / "out"
    assert main(["run", scene, "--out", str(out)]) == 0
    text = (out / "report.md").read_text()
    assert "### Shafts, bearings and efficiency" in text and "#### mesh misalignment" in text
    assert (out / "drive_bearings.csv").is_file() and (out / "drive_layout.png").is_file()
    html = tmp_path / "r.html"
    assert main(["drive", scene, "--report", str(html)]) == 0
    page = html.read_text()
    assert "Shafts, bearings and efficiency" in page and 'id="layout"' in page and "6311" in page


def _bearing_types(capsys, args) -> dict:
    assert main(args + ["--json"]) in (0, 1)
    an = json.loads(capsys.readouterr().out)["analysis"]
    return {r["shaft"]: (r["bearing_type"], r["mounting"]) for r in an["shafts"]}


def test_bearing_type_per_shaft_from_scene_and_options(tmp_path, capsys):
    # [[drive.shaft]] with at and bearing_type (a default shaft), and one drawn with its bearing_type; the command
    # line's --bearing-type SHAFT=TYPE wins over the scene's
    body = REDUCER + ("[drive.shafting]\narrangement = 'O'\n[[drive.shaft]]\nat = 2\nbearing_type = 'tapered'\n"
                      "[[drive.shaft]]\nat = 1\nlengths_mm = [25, 130, 25]\ndiameters_mm = [55, 60, 55]\n"
                      "supports_mm = [15, 165]\nbearing_type = 'tapered'\n"
                      "[drive.shaft.positions]\nfast = 57.5\nslow = 122.5\n")
    path = _scene(tmp_path, body)
    types = _bearing_types(capsys, ["drive", path])
    assert types[1] == types[2] == ("tapered_roller", "tapered pair (O)")
    assert types[0][0] != "tapered_roller"
    types = _bearing_types(capsys, ["drive", path, "--bearing-type", "0=tapered,2=deep_groove", "--arrangement", "X"])
    assert types[0] == types[1] == ("tapered_roller", "tapered pair (X)") and types[2][0] == "deep_groove_ball"
    types = _bearing_types(capsys, ["drive", _scene(tmp_path, REDUCER), "--bearing-type", "tapered"])
    assert {t for t, _ in types.values()} == {"tapered_roller"}
    with pytest.raises(Exception, match="bearing_type"):
        load_scene(_scene(tmp_path, REDUCER + "[[drive.shaft]]\nat = 1\nbearing_type = 'spherical'\n"))


def test_drive_help_says_the_load_options_as_a_drive_takes_them(capsys):
    # the pair's wording: "--torque: torque on gear 1 (--on-gear)", "--spectrum ... torques of gear --on-gear",
    # though a drive refuses --on-gear and takes its load at the input shaft
    with pytest.raises(SystemExit):
        main(["drive", "--help"])
    text = " ".join(capsys.readouterr().out.split())
    assert "--torque NM the drive's input torque (on its input shaft)" in text
    assert "--speed RPM the drive's input speed" in text and "--on-gear {1,2} refused" in text
    assert "(--on-gear)" not in text and "torques of gear --on-gear" not in text and "of gear 1 with" not in text
