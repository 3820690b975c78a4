"""`geardesign measure` and `geardesign pair --measurements`: tables, JSON, exit codes, one-line errors."""
import json
import subprocess
import sys

import pytest

from geardesign.cli import main
from geardesign.gears.measurement import tooth_measurements
from geardesign.gears.tolerances import flank_tolerances


def test_measure_json_is_the_library_result(capsys):
    assert main(["measure", "-m", "3", "--z", "24", "--x", "0.4", "--beta", "20", "--face-width", "30",
                 "--allowance", "-0.05", "-0.1", "--accuracy-class", "6", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    t = tooth_measurements(3, 24, 0.4, beta_deg=20, face_width_mm=30, thickness_allowance_mm=(-0.05, -0.1))
    assert out["measurements"]["w_k"] == t.w_k and out["measurements"]["m_d_min"] == t.m_d_min
    assert out["tolerances"]["F_pT"] == flank_tolerances(3, 24, 6, beta_deg=20, face_width_mm=30).F_pT


def test_measure_table_and_the_machinecalcs_span(capsys):
    assert main(["measure", "-m", "2", "--z", "20"]) == 0
    out = capsys.readouterr().out
    assert "span W_k" in out and "15.32088" in out and "40.59021" in out


def test_measure_flags_exit_1(capsys):
    assert main(["measure", "-m", "2", "--z", "40", "--k", "15"]) == 1      # anvils above the tip
    assert "False" in capsys.readouterr().out
    assert main(["measure", "-m", "2", "--z", "60", "--x", "0.3", "--internal"]) == 0   # a ring: M_d is measured
    assert "note: ring" in capsys.readouterr().out


@pytest.mark.slow
@pytest.mark.parametrize("argv, words", [
    (["measure", "-m", "3", "--z", "2"], ["z", "[3, 100000]"]),
    (["measure", "-m", "3", "--z", "24", "--allowance", "-0.1", "-0.05"], ["A_sni"]),
    (["measure", "-m", "3", "--z", "24", "--allowance", "1", "2", "3"], ["--allowance"]),
    (["measure", "-m", "3", "--z", "24", "--accuracy-class", "12"], ["accuracy_class", "[1, 11]"]),
    (["measure", "-m", "0.1", "--z", "24", "--accuracy-class", "5"], ["m_n", "ISO 1328-1:2013"]),
])
def test_errors_are_one_line_exit_2(argv, words):
    proc = subprocess.run([sys.executable, "-m", "geardesign", *argv], capture_output=True, text=True)
    assert proc.returncode == 2
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1, proc.stderr
    for w in words:
        assert w in lines[0], (w, lines[0])


def test_pair_measurements_flag(capsys):
    assert main(["pair", "--module", "3", "--z1", "12", "--z2", "24", "--x1", "0.6", "--x2", "0.36",
                 "--measurements", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert [g["z"] for g in out["measurements"]] == [12, 24]
    assert main(["pair", "--module", "3", "--z1", "12", "--z2", "24", "--x1", "0.6", "--x2", "0.36",
                 "--measurements"]) == 0
    assert "Measuring sizes" in capsys.readouterr().out
