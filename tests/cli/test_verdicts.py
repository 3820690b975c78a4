"""Issue 28: every command's verdict — exit status 1 for a design that fails a check, 0 when it passes,
``"ok"`` in every ``--json``, the verdict first in the text — and readable output (the handbook's
two-column geometry, tables within the terminal's width, chain candidates nearest-failing second).

The failing designs are the seeds' own: seed 000's x = 0.898/0.517 (ε_α = 1.153 < 1.2, recomputed by
hand in tests/cli/test_run.py) and LECAD's printed planetary shifts (the ring's tip reaches the planet's
fillet, tests/gears/test_planetary_golden.py).
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from geardesign.cli import build_parser, main

ENGINE = ["--module", "8", "--z1", "17", "--z2", "26"]
SEED = ENGINE + ["--x1", "0.898", "--x2", "0.517"]
LECAD = ["planetary", "--module", "1.75", "--planets", "3", "--z-sun", "21", "--z-planet", "43", "--z-ring", "108"]
SCENES = Path(__file__).resolve().parents[2] / "studies" / "scenes"


def _run(argv, capsys):
    code = main(argv)
    return code, capsys.readouterr().out


@pytest.mark.parametrize("argv, code, first_failing", [
    (["pair", *SEED], 1, "contact_ratio"),
    (["pair", *ENGINE, "--x1", "0.3", "--x2", "0.9"], 0, None),
    (["shift", "--z1", "17", "--z2", "26", "--module", "8", "--x1", "0.898", "--x2", "0.517"], 1, "contact_ratio"),
    (["mesh", *SEED], 1, "contact_ratio"),
    ([*LECAD, "--x-sun", "0.438", "--x-planet", "0.0426", "--x-ring", "0"], 1, "planet-ring:interference_planet"),
    (["key", "--d", "60", "--length", "32", "--crush", "300", "--shear", "120", "--torque", "600"], 1, None),
    (["key", "--d", "60", "--length", "32", "--crush", "300", "--shear", "120", "--torque", "500"], 0, None),
])
def test_exit_status_and_verdict(argv, code, first_failing, capsys):
    got, out = _run(argv, capsys)
    assert got == code, out
    verdict = [line for line in out.splitlines() if line.startswith(("OK", "FAILS"))]
    assert verdict, out
    assert verdict[0].startswith("FAILS" if code else "OK")
    if first_failing:
        assert verdict[0].startswith(f"FAILS: {first_failing}")


def test_key_capacity_against_the_torque_by_hand(capsys):
    """Dunaevsky & Lelikov's crushing capacity T = [σ]·d·(h − t1)·l_p/2000: 300·60·(11 − 7)·(32 − 18)/2000
    = 504 N·m for key 18x11x32 (GOST 23360: b 18, h 11, t1 7 for d = 60): 503 passes, 505 fails."""
    t = 300 * 60 * (11 - 7) * (32 - 18) / 2000
    base = ["key", "--d", "60", "--length", "32", "--crush", "300", "--shear", "120"]
    assert main(base + ["--torque", str(t - 1)]) == 0
    assert main(base + ["--torque", str(t + 1)]) == 1
    capsys.readouterr()


@pytest.mark.parametrize("argv, ok", [
    (["pair", *SEED, "--json"], False),
    (["pair", *ENGINE, "--x1", "0.3", "--x2", "0.9", "--json"], True),
    (["shift", "--z1", "17", "--z2", "26", "--json"], True),
    (["shift", "--z1", "17", "--z2", "26", "--module", "8", "--x1", "0.898", "--x2", "0.517", "--json"], False),
    (["mesh", *SEED, "--json"], False),
    ([*LECAD, "--x-sun", "0.438", "--x-planet", "0.0426", "--x-ring", "0", "--json"], False),
    (["chain", "--torque", "380", "--n1", "120", "--ratio", "1", "--z1", "13", "--json"], True),
    (["key", "--d", "60", "--torque", "503", "--hub-length", "50", "--json"], True),
    (["key", "--d", "60", "--length", "32", "--json"], True),
    (["teeth", "--ratio", "1.5", "--module", "8", "--z1-max", "20", "--json"], True),
    (["atlas", "--z1", "17", "--z2", "26", "--json"], True),
])
def test_json_carries_ok(argv, ok, capsys):
    code, out = _run(argv, capsys)
    doc = json.loads(out)
    assert doc["ok"] is ok
    assert code == (0 if ok else 1)


def test_drive_and_run_json_ok(tmp_path, capsys):
    assert main(["drive", str(SCENES / "seed002_drive.toml"), "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["ok"] is True
    out = tmp_path / "a" / "b" / "engine"          # parents created (issue 28: a fresh clone has no out/)
    assert main(["run", str(SCENES / "seed000_gear.toml"), "--out", str(out), "--json"]) == 1
    doc = json.loads(capsys.readouterr().out)
    assert doc["ok"] is False and doc["failures"] == ["gear: the given shifts fail contact_ratio"]
    assert (out / "report.md").is_file()


def test_mesh_drawing_title_names_the_failing_check():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    import geardesign as gd

    ax = gd.plot_mesh(gd.GearPair(8, 17, 26, 0.898, 0.517))
    try:
        assert "FAILS contact_ratio (1.153 vs limit 1.2)" in ax.get_title()
    finally:
        plt.close(ax.figure)
    ax = gd.plot_mesh(gd.GearPair(8, 17, 26, 0.3, 0.9))
    try:
        assert "every check holds" in ax.get_title()
    finally:
        plt.close(ax.figure)


def test_pair_output_verdict_first_and_two_columns(capsys):
    """The handbook's layout (GOST 16532-70 Table 1): one row per quantity, gear 1 and gear 2 side by side,
    symbols not code names. d = m·z (the reference diameters 136 and 208 mm) and d_w = 2·a_w·z/(z1 + z2)."""
    code, out = _run(["pair", *SEED], capsys)
    lines = out.splitlines()
    assert lines[0].startswith("FAILS: contact_ratio")
    header = next(line for line in lines if line.startswith("quantity"))
    assert header.split()[-4:] == ["gear", "1", "gear", "2"]
    d_row = next(line for line in lines if line.startswith("reference diameter ")).split()
    assert [float(v) for v in d_row[-2:]] == [8 * 17, 8 * 26]
    a_w = float(next(line for line in lines if line.startswith("operating centre distance")).split()[-1])
    dw_row = next(line for line in lines if line.startswith("operating pitch diameter")).split()
    assert dw_row[-4] == "d_w"
    assert float(dw_row[-2]) == pytest.approx(2 * a_w * 17 / 43, rel=1e-7)
    assert float(dw_row[-1]) == pytest.approx(2 * a_w * 26 / 43, rel=1e-7)
    assert " dw1 " not in out and "alpha_w_deg" not in out


@pytest.mark.parametrize("argv", [["pair", *SEED], ["drive", str(SCENES / "seed002_drive.toml")],
                                  ["shift", "--z1", "17", "--z2", "26", "--module", "8", "--x1", "0.898", "--x2", "0.517"],
                                  ["chain", "--torque", "380", "--n1", "120", "--ratio", "1"],
                                  ["teeth", "--ratio", "1.5", "--module", "8", "--z1-max", "20"],
                                  ["key", "--d", "60", "--torque", "503", "--hub-length", "50"], ["mesh", *SEED],
                                  LECAD])
def test_output_fits_100_columns(argv):
    env = dict(os.environ, COLUMNS="100")
    proc = subprocess.run([sys.executable, "-m", "geardesign", *argv], capture_output=True, text=True, env=env)
    assert proc.returncode in (0, 1), proc.stderr
    widths = [len(line) for line in proc.stdout.splitlines()]
    assert max(widths) <= 100, [line for line in proc.stdout.splitlines() if len(line) > 100][:3]


def test_chain_top_ranks_feasible_then_nearest_failing(capsys):
    """Seed 002 at [p] = 29 MPa, 180 mm: after the feasible chain come the failing ones by their worst margin,
    the nearest first (issue 28 saw a chain at 4 483 MPa ranked second)."""
    argv = ["chain", "--torque", "380", "--n1", "120", "--ratio", "1", "--z1", "13", "--strands", "1,2",
            "--k-e", "2.148", "--p-allow", "29", "--objective", "min_sprocket_diameter", "--center-distance", "180",
            "--top", "6", "--json"]
    assert main(argv) == 0
    rows = json.loads(capsys.readouterr().out)["candidates"]
    feasible = [r["feasible"] for r in rows]
    assert feasible == sorted(feasible, reverse=True) and feasible[0]
    failing = [r["min_margin"] for r in rows if not r["feasible"]]
    assert failing == sorted(failing, reverse=True) and len(failing) >= 2
    assert all(r["pressure_mpa"] < 100 for r in rows)


def test_version_and_help_on_every_option(capsys):
    import geardesign

    with pytest.raises(SystemExit) as exc:
        main(["--version"])
    assert exc.value.code == 0 and capsys.readouterr().out.strip() == f"geardesign {geardesign.__version__}"
    import argparse

    parser = build_parser()
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    missing = [(name, action.option_strings or action.dest) for name, p in sub.choices.items()
               for action in p._actions if not action.help]
    assert missing == []
    for name, p in sub.choices.items():
        assert "Exit status" in p.description or "exit" in p.description.lower(), name


def test_key_help_says_longest(capsys):
    with pytest.raises(SystemExit):
        main(["key", "--help"])
    text = " ".join(capsys.readouterr().out.split())
    assert "longest standard length that fits the hub" in text and "shortest" not in text
