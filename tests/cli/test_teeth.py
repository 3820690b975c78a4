"""The `geardesign teeth` command: JSON, table and CSV, one-line errors, exit 1 when nothing is feasible."""
import json

import pandas as pd
import pytest

from geardesign.cli import main


def test_cli_json(capsys):
    rc = main(["teeth", "--ratio", "1.5", "--module", "8", "--center-distance", "180", "--json"])
    out = json.loads(capsys.readouterr().out)
    assert rc == 0
    assert out["best"]["z1"] == 18 and out["best"]["z2"] == 27
    assert out["table"][0]["a_w_mm"] == pytest.approx(180.0)
    assert all(r["reason"] for r in out["skipped"])


def test_cli_table_and_csv(capsys, tmp_path):
    path = tmp_path / "table.csv"
    rc = main(["teeth", "--ratio", "2", "--ratio-tol", "0", "--module", "2", "--z1-min", "20", "--z1-max", "22",
               "--method", "grid", "--out", str(path)])
    text = capsys.readouterr().out
    assert rc == 0 and "choice:" in text and "rank" in text
    frame = pd.read_csv(path)
    assert sorted(zip(frame["z1"], frame["z2"])) == [(20, 40), (21, 42), (22, 44)]


@pytest.mark.parametrize("argv,words", [
    (["--ratio", "0.5", "--module", "8"], ["ratio", "0.5"]),
    (["--ratio", "1.5", "--module", "eight"], ["--module", "'eight'"]),
    (["--ratio", "1.5", "--module", "8", "--center-distance", "-5"], ["a_w", "-5"]),
    (["--ratio", "1.5", "--module", "8", "--z1-min", "2"], ["z1_range min", "2"]),
])
def test_cli_errors(capsys, argv, words):
    rc = main(["teeth"] + argv)
    err = capsys.readouterr().err
    assert rc == 2 and err.count("\n") == 1 and err.startswith("geardesign teeth: error:")
    for w in words:
        assert w in err


def test_cli_no_feasible_exit_1(capsys):
    rc = main(["teeth", "--ratio", "1", "--ratio-tol", "0", "--module", "1", "--z1-min", "5", "--z1-max", "6"])
    assert rc == 1 and "no feasible" in capsys.readouterr().out


@pytest.mark.parametrize("argv", [
    ["--ratio", "9.99", "--module", "1e+308"],                              # issue 29 §3: printed NaN
    ["--ratio", "1.9", "--module", "1e300", "--z1-min", "8", "--z1-max", "9"],   # §3.3: exited 0
    ["--ratio", "1.9", "--module", "1e-5", "--z1-min", "8", "--z1-max", "9"],
])
def test_cli_module_out_of_range_is_refused_like_shift(capsys, argv):
    rc = main(["teeth"] + argv)
    captured = capsys.readouterr()
    assert rc == 2 and captured.out == "" and captured.err.count("\n") == 1
    assert "m (module) must be in [0.0001, 10000] mm" in captured.err
    rc = main(["shift", "--z1", "17", "--z2", "26", "--module", argv[3], "--center-distance", "30"])
    assert rc == 2 and "m (module) must be in [0.0001, 10000] mm" in capsys.readouterr().err
