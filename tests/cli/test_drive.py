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
    assert out.startswith("optimum (min_mass, u = 12.5 ± 0 %)")
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
    capsys.readouterr()
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
