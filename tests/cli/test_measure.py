"""`geardesign measure` and `geardesign pair --measurements`: tables, JSON, exit codes, one-line errors."""
import json
import subprocess
import sys

import pytest

import geardesign as gd
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
    (["measure", "-m", "3", "--z", "24", "--accuracy-class", "12"], ["--accuracy-class", "[1, 11]"]),
    (["measure", "-m", "0.1", "--z", "24", "--accuracy-class", "5"], ["m (ISO 1328-1:2013 range)", "[0.5, 70]"]),
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


@pytest.mark.parametrize("args, option", [
    (["measure", "-m", "3", "--z", "24", "--allowance", "0.1", "0.05"], "--allowance"),
    (["pair", "-m", "3", "--z1", "20", "--z2", "40", "--measurements", "--allowance2", "0.02"], "--allowance2"),
])
def test_an_allowance_that_thickens_the_tooth_is_one_line_naming_the_option(capsys, args, option):
    # issue 36 §1.5: `measure --allowance 0.1 0.05` was accepted silently
    assert main(args) == 2
    captured = capsys.readouterr()
    err = captured.err.strip().splitlines()
    assert captured.out == "" and len(err) == 1
    assert f"error: {option}: A_sne = " in err[0] and "A_sni <= A_sne <= 0" in err[0]


def _rows(out: str, title: str) -> dict:
    """{quantity: (gear 1, gear 2)} of the measuring-size table printed under ``title``."""
    lines = out.split(title, 1)[1].strip().splitlines()[2:]
    rows = {}
    for line in lines:
        if not line.strip():
            break
        parts = line.rsplit(None, 3)
        rows.setdefault(parts[0].strip(), parts[1:3])     # the first of a repeated label: the span's
    return rows


def test_pair_measurements_take_each_gear_s_allowances(capsys):
    # issue 36 §1.5: largest = smallest = nominal (no allowances taken) and a "least face width (helical) 0.00000" row
    # on a spur gear
    args = ["pair", "-m", "3", "--z1", "20", "--z2", "40", "--x1", "0.3", "--measurements",
            "--allowance1", "-0.05", "-0.1", "--allowance2", "-0.06", "-0.12"]
    assert main(args) == 0
    out = capsys.readouterr().out
    assert "least face width" not in out
    rows = _rows(out, "Measuring sizes")
    pair = gd.GearPair(3, 20, 40, 0.3, 0.0)
    for i, a in ((1, (-0.05, -0.1)), (2, (-0.06, -0.12))):
        t = pair.measurements(gear=i, thickness_allowance_mm=a)
        assert float(rows["largest (A_sne / A_sni)"][i - 1]) == pytest.approx(t.w_k_max, abs=6e-6)
        assert float(rows["smallest"][i - 1]) == pytest.approx(t.w_k_min, abs=6e-6)
        assert t.w_k_min < t.w_k_max < t.w_k
    helical = ["pair", "-m", "3", "--z1", "20", "--z2", "40", "--beta", "15", "--face-width", "30", "--measurements"]
    assert main(helical) == 0
    assert "least face width (helical)" in capsys.readouterr().out


def test_pair_backlash_and_data_block_on_the_command_line(capsys):
    args = ["pair", "-m", "3", "--z1", "20", "--z2", "40", "--x1", "0.3", "--allowance1", "-0.05", "-0.1",
            "--allowance2", "-0.06", "-0.12", "--center-distance-allowance", "-0.02", "0.02", "--backlash",
            "--data-block", "7", "--json"]
    assert main(args) == 0
    out = json.loads(capsys.readouterr().out)
    pair = gd.GearPair(3, 20, 40, 0.3, 0.0)
    b = pair.backlash((-0.05, -0.1), (-0.06, -0.12), (-0.02, 0.02))
    assert out["backlash"]["jbn_min"] == b.jbn_min and out["backlash"]["jt_max"] == b.jt_max
    for i, a in ((1, (-0.05, -0.1)), (2, (-0.06, -0.12))):
        want = gd.data_block(pair, i, 7, thickness_allowance_mm=a, center_distance_allowance_mm=(-0.02, 0.02))
        assert [r["value"] for r in out["data_block"][i - 1]] == list(want["value"])
    assert main(args[:-3] + ["--data-block", "12"]) == 2
    assert "--data-block CLASS must be" in capsys.readouterr().err
