"""The `geardesign pair` command: tables, JSON, a housing centre distance, and one-line errors
naming the input and its range; `python -m geardesign` from any directory."""
import json
import os
import subprocess
import sys

import pytest

import geardesign as gd
from geardesign.cli import main


def test_pair_cli_with_both_shifts_and_a_housing(capsys):
    assert main(["pair", "--module", "8", "--z1", "17", "--z2", "26", "--x1", "0.898", "--x2", "0.517",
                 "--center-distance", "180"]) == 1
    out = capsys.readouterr().out
    assert "center_distance" in out and "x1 = 0.898, x2 = 0.517" in out


def test_cli_refusals_name_the_input_and_its_range():
    for argv, words in [
        (["pair", "--module", "1", "--z1", "1e308", "--z2", "26"], ["z1", "1e+308", "[3, 100000]"]),
        (["pair", "--module", "1", "--z1", "17", "--z2", "26", "--x1", "1e308"], ["x1", "1e+308", "[-10, 10]"]),
        (["pair", "--module", "1e308", "--z1", "17", "--z2", "26"], ["m (module)", "1e+308"]),
    ]:
        proc = subprocess.run([sys.executable, "-m", "geardesign", *argv], capture_output=True, text=True)
        assert proc.returncode == 2
        lines = proc.stderr.strip().splitlines()
        assert len(lines) == 1, proc.stderr
        for w in words:
            assert w in lines[0], (w, lines[0])


def test_cli_table(capsys):
    assert main(["pair", "--module", "8", "--z1", "17", "--z2", "26", "--x1", "0.898", "--x2", "0.517"]) == 1
    out = capsys.readouterr().out
    assert "operating pressure angle" in out and "α_w" in out and "contact_ratio" in out
    assert out.splitlines()[0].startswith("FAILS: contact_ratio")      # the verdict first, on line 1


def test_cli_json(capsys):
    assert main(["pair", "--module", "3", "--z1", "12", "--z2", "24", "--x1", "0.6", "--x2", "0.36", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    for k in ("alpha_w_deg", "inv_alpha_w", "a", "a_w", "y", "dy", "d1", "d2", "db1", "db2", "dw1", "dw2",
              "da1", "da2", "df1", "df2", "s1", "s2", "sa1", "sa2", "p_b", "g_alpha", "eps_alpha"):
        assert k in doc["geometry"]
    assert round(doc["geometry"]["alpha_w_deg"], 4) == 26.0886        # KHK
    assert {"check", "value", "limit", "margin", "ok"} == set(doc["checks"][0])


def test_cli_center_distance(capsys):
    assert main(["pair", "--module", "3", "--z1", "12", "--z2", "24", "--x1", "0.6",
                 "--center-distance", "56.4999", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert abs(doc["input"]["x1"] + doc["input"]["x2"] - 0.960013) < 5e-7   # KHK x-sum


def test_cli_no_tip_shortening(capsys):
    main(["pair", "--module", "8", "--z1", "17", "--z2", "26", "--x1", "0.898", "--x2", "0.517",
          "--no-tip-shortening", "--json"])
    doc = json.loads(capsys.readouterr().out)
    assert doc["geometry"]["da1"] == pytest.approx(8 * (17 + 2 * (1 + 0.898)), rel=1e-15)


def test_cli_error_is_one_line(capsys):
    assert main(["pair", "--module", "-8", "--z1", "17", "--z2", "26"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "m (module) must be > 0 mm, got -8.0" in err[0]


def test_installed_command_from_another_directory(tmp_path):
    # `python -m geardesign` from an unrelated directory: the package works wherever it is run
    env = dict(os.environ)
    r = subprocess.run([sys.executable, "-m", "geardesign", "pair", "--module", "2", "--z1", "17",
                        "--z2", "34", "--json"], cwd=tmp_path, capture_output=True, text=True, env=env)
    if r.returncode != 0 and "No module named geardesign" in r.stderr:
        # running from a source checkout that is not installed: point Python at it
        env["PYTHONPATH"] = os.path.dirname(os.path.dirname(gd.__file__))
        r = subprocess.run([sys.executable, "-m", "geardesign", "pair", "--module", "2", "--z1", "17",
                            "--z2", "34", "--json"], cwd=tmp_path, capture_output=True, text=True, env=env)
    assert r.returncode == 1, r.stderr          # x1 = 0 on 17 teeth undercuts (x_min = 0.0057): a failing design
    out = json.loads(r.stdout)
    assert out["geometry"]["a_w"] == pytest.approx(51.0) and out["ok"] is False   # seed 001 task 2
    bad = subprocess.run([sys.executable, "-m", "geardesign", "pair", "--module", "2", "--z1", "1",
                          "--z2", "34"], cwd=tmp_path, capture_output=True, text=True, env=env)
    assert bad.returncode == 2 and "Traceback" not in bad.stderr and "z1" in bad.stderr
