"""Issue 35 §8: every command's first line of text is its verdict, ``OK: ...`` or ``FAILS: check (value, limit)``,
and its exit status agrees (0 with OK, 1 with FAILS). Before, `shift` printed FAILS on line 38, `mesh` last, `pair`
on line 2, `drive`, `teeth`, `chain`, `atlas`, `measure` and `shift` without given shifts none at all.

The passing and failing designs are those of the commands' own tests: seed 000's x = 0.898/0.517 (ε_α = 1.153 <
1.2), LECAD's printed planetary shifts (the ring's tip reaches the planet's fillet), seed 002's chain and key
(Dunaevsky & Lelikov's key capacity 504 N·m), an 8/9 pair whose undercut and contact-ratio checks conflict.
"""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from geardesign.cli import main

SCENES = Path(__file__).resolve().parents[2] / "studies" / "scenes"
ENGINE = ["--module", "8", "--z1", "17", "--z2", "26"]
SEED = ENGINE + ["--x1", "0.898", "--x2", "0.517"]
LECAD = ["planetary", "--module", "1.75", "--planets", "3", "--z-sun", "21", "--z-planet", "43", "--z-ring", "108"]
KEY = ["key", "--d", "60", "--length", "32", "--crush", "300", "--shear", "120"]
LOADED = ("[drive]\npower_kw = 7.5\nn_in_rpm = 1450\n[[drive.stage]]\nkind = 'given'\nratio = 2\nefficiency = 0.95\n"
          "[[drive.stage]]\nkind = 'gear'\nmodule = 4\nz1 = 20\nz2 = 60\nface_width_mm = 40\n")

SHAFT = ["shaft", "--sections", "40x35,40x40,120x45,40x40,40x35", "--supports", "20,260", "--load",
         "x=140,fy=-3000,fz=1100,fx=800,y=60,torque=120", "--load", "x=280,fz=-1500,torque=-120", "--notch", "x=140,kind=key"]
CASES = [
    (SHAFT, 0, "OK: least safety"),
    (SHAFT + ["--s-min", "9"], 1, "FAILS: din743_safety"),
    (["bearing", "--designation", "6208", "--fr", "3200", "--fa", "1800", "--speed", "650"], 0, "OK"),
    (["bearing", "--designation", "6208", "--fr", "3200", "--fa", "1800", "--speed", "650", "--life-h", "100000"], 1,
     "FAILS: life"),
    (["pair", *SEED], 1, "FAILS: contact_ratio (value 1.153, limit 1.2)"),
    (["pair", *ENGINE, "--x1", "0.3", "--x2", "0.9"], 0, "OK"),
    (["measure", "--module", "3", "--z", "24", "--x", "0.4"], 0, "OK"),
    (["measure", "--module", "3", "--z", "24", "--x", "0.4", "--k", "12"], 1, "FAILS: span_ok"),
    (["mesh", *SEED], 1, "FAILS: contact_ratio (value 1.153, limit 1.2)"),
    (["mesh", *ENGINE, "--x1", "0.3", "--x2", "0.9"], 0, "OK"),
    (["shift", "--z1", "17", "--z2", "26"], 0, "OK: optimum"),
    (["shift", "--z1", "8", "--z2", "9"], 1, "FAILS: undercut1"),
    (["shift", "--z1", "17", "--z2", "26", "--module", "8", "--x1", "0.898", "--x2", "0.517"], 1,
     "FAILS: contact_ratio (value 1.153, limit 1.2)"),
    (["atlas", "--z1", "17", "--z2", "26:27"], 0, "OK"),
    (["teeth", "--ratio", "1.5", "--module", "8", "--z1-max", "20"], 0, "OK: z1/z2 ="),
    (["teeth", "--ratio", "1.5", "--module", "8", "--z1-max", "9", "--eps-alpha-min", "1.9"], 1, "FAILS: contact_ratio"),
    (LECAD, 0, "OK: optimum"),
    ([*LECAD, "--x-sun", "0.438", "--x-planet", "0.0426", "--x-ring", "0"], 1,
     "FAILS: planet-ring:interference_planet (value 4.311, limit 4.554)"),
    (["planetary", "--module", "1.75", "--planets", "3", "--ratio", "6"], 0, "OK: z_s/z_p/z_r"),
    (["worm", "--module", "3", "--z1", "2", "--z2", "30", "--q", "10"], 0, "OK: all checks hold"),
    (["worm", "--module", "3", "--z1", "2", "--z2", "30", "--q", "10", "--x2", "1.2"], 1,
     "FAILS: x2_range (value 1.2, limit 1)"),
    (["chain", "--torque", "380", "--n1", "120", "--ratio", "1"], 0, "OK"),
    (["chain", "--torque", "38000", "--n1", "120", "--ratio", "1"], 1, "FAILS: pressure"),
    (["key", "--d", "60", "--torque", "503", "--hub-length", "50"], 0, "OK"),
    (["key", "--d", "60", "--torque", "50300", "--hub-length", "50"], 1, "FAILS"),
    ([*KEY, "--torque", "503"], 0, "OK: 504.0 N·m >= the torque 503 N·m"),
    ([*KEY, "--torque", "505"], 1, "FAILS: 504.0 N·m < the torque 505 N·m"),
    (["drive", str(SCENES / "seed002_drive.toml")], 0, "OK"),
    (["drive", "LOADED", "--material", "C45", "--power", "40"], 1, "FAILS: gear:contact_strength (margin -"),
    (["run", str(SCENES / "seed002_chain.toml"), "--out", "OUT"], 0, "OK: every design of the scene passes."),
    (["run", str(SCENES / "seed000_gear.toml"), "--out", "OUT"], 1,
     "FAILS: gear: the given shifts fail contact_ratio"),
]


def _argv(argv, tmp_path):
    loaded = tmp_path / "loaded.toml"
    loaded.write_text(LOADED)
    return [str(loaded) if a == "LOADED" else str(tmp_path / "out") if a == "OUT" else a for a in argv]


@pytest.mark.parametrize("argv, code, first", CASES, ids=[" ".join(c[0][:3]) + f" -> {c[1]}" for c in CASES])
def test_the_verdict_is_line_1_and_agrees_with_the_exit_status(tmp_path, capsys, argv, code, first):
    got = main(_argv(argv, tmp_path))
    out = capsys.readouterr().out
    line1 = out.splitlines()[0]
    assert got == code, out[:400]
    assert line1.startswith("OK: " if got == 0 else "FAILS: "), out[:400]
    assert line1.startswith(first), line1


def test_every_command_has_a_case():
    from geardesign.cli import SUBCOMMANDS

    covered = {argv[0] for argv, _, _ in CASES}
    assert covered == set(SUBCOMMANDS)
    assert {(argv[0], code) for argv, code, _ in CASES} >= {(c, k) for c in SUBCOMMANDS for k in (0, 1)} - {("atlas", 1)}


def test_json_and_text_agree(tmp_path, capsys):
    """The first line's verdict is the JSON's "ok" (atlas: a table, always ok)."""
    for argv, code, _ in CASES:
        if argv[0] in ("run",):
            continue
        got = main([*_argv(argv, tmp_path), "--json"])
        assert json.loads(capsys.readouterr().out)["ok"] is (code == 0) and got == code, argv


def test_piped_verdict_first_in_a_subprocess(tmp_path):
    """The console entry point, piped (not a terminal): the same first line."""
    proc = subprocess.run([sys.executable, "-m", "geardesign", "shift", "--z1", "17", "--z2", "26", "--module", "8",
                           "--x1", "0.898", "--x2", "0.517"], capture_output=True, text=True)
    assert proc.returncode == 1
    assert proc.stdout.splitlines()[0].startswith("FAILS: contact_ratio (value 1.153, limit 1.2)")
