"""The `geardesign chain` command. Expected designs are the ones derived by hand in
tests/drives/chain/ and tests/drives/test_sprocket.py (seed 002 recomputed)."""
import json
import subprocess
import sys
from pathlib import Path

import pytest

from geardesign.cli import main

SEED = ["chain", "--torque", "380", "--n1", "120", "--ratio", "1", "--z1", "13", "--strands", "1,2",
        "--k-e", "2.148", "--p-allow", "29"]


def test_chain_table(capsys):
    assert main(SEED + ["--objective", "min_sprocket_diameter", "--top", "3"]) == 0
    out = capsys.readouterr().out
    # seed 002's choice: two-strand 31.75 mm chain; pitch estimates 36.2 / 30.35 mm (seed 1.9.5)
    assert out.startswith("OK: 2PR-31,75-177 x2, z1/z2 = 13/13")   # the verdict first (issue 35 §8)
    assert "2PR-31,75-177 with z1/z2 = 13/13" in out
    assert "K_e =\n  2.148 (given by --k-e)" in out or "K_e = 2.148 (given by --k-e)" in out
    assert "1 strand t >= 36.2" in out and "2 strands t >= 30.35" in out
    assert "candidates (3 of" in out


def test_chain_json(capsys):
    assert main(SEED + ["--json", "--top", "0"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["success"] and data["best"]["designation"] == "PR-38,1-127"
    assert len(data["candidates"]) == data["n_candidates"]
    assert data["candidates"][0]["rank"] == 1


def test_chain_infeasible_exit_1(capsys):
    assert main(["chain", "--torque", "20000", "--n1", "120", "--ratio", "1", "--z1", "13", "--strands", "1,2",
                 "--p-allow", "29"]) == 1
    out = capsys.readouterr().out
    assert "no candidate passes" in out and "what stops each chain family" in out


def test_chain_bad_input_exit_2(capsys):
    assert main(["chain", "--torque", "-380", "--n1", "120", "--ratio", "1"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--torque must be in [0.001, 1e+07] N·m, got -380" in err[0]   # the option's name
    assert main(["chain", "--torque", "380", "--n1", "120", "--ratio", "1", "--catalog", "din8187"]) == 2
    assert "catalog must be one of" in capsys.readouterr().err
    assert main(["chain", "--torque", "380", "--n1", "120", "--ratio", "1", "--strands", "one"]) == 2


def test_chain_power_rating(capsys):
    # Bhandari Ex. 14.3 inputs; published choice 08A, 122 links, a = 500.8 mm
    assert main(["chain", "--power", "5", "--n1", "1400", "--ratio", "3", "--z1", "21", "--k-e", "1.3",
                 "--catalog", "iso606a", "--strands", "1", "--center-distance", "500", "--method", "power_rating",
                 "--json"]) == 0
    best = json.loads(capsys.readouterr().out)["best"]
    assert best["designation"] == "08A" and best["links"] == 122


@pytest.mark.slow
def test_python_m_geardesign_chain():
    root = Path(__file__).resolve().parents[2]
    proc = subprocess.run([sys.executable, "-m", "geardesign"] + SEED + ["--json", "--top", "2"],
                          cwd=root, capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert json.loads(proc.stdout)["best"]["designation"] == "PR-38,1-127"
