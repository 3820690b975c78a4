"""The load case on the command line (issue 26 §4): the strength checks join the others and `pair` prints
the ISO 6336 result; the numbers are the library's GearPair.strength (validated in tests/gears/strength)."""
import json

import pytest

import geardesign as gd
from geardesign.cli import main
from geardesign.gears.strength import Load

PAIR = ["pair", "--module", "4", "--z1", "20", "--z2", "60", "--x1", "0.3", "--x2", "0.2", "--face-width", "40"]
LOAD = ["--torque", "600", "--speed", "1000", "--material", "18CrNiMo7-6", "--life-h", "20000"]


def test_pair_with_a_load_prints_the_strength_and_its_checks(capsys):
    assert main(PAIR + LOAD + ["--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    ref = gd.GearPair(4, 20, 60, 0.3, 0.2, face_width_mm=40).strength(
        Load(torque_nm=600, n_rpm=1000, life_h=20000), "18CrNiMo7-6")
    assert out["strength"]["S_H1"] == pytest.approx(ref.S_H1, rel=1e-12)
    checks = {c["check"]: c for c in out["checks"]}
    assert checks["root_strength2"]["value"] == pytest.approx(ref.S_F2, rel=1e-9)
    assert main(PAIR + LOAD) == 0
    text = capsys.readouterr().out
    assert "StrengthResult 20/60 m=4: OK" in text and "K_Hbeta" in text


def test_the_issue_pinion_fails_by_strength_with_exit_1(capsys):
    """Issue 26's 75 kW at 1480 rpm on a 17-tooth module-1 pinion: geometry alone passes it, load does not."""
    base = ["pair", "--module", "1", "--z1", "17", "--z2", "98", "--x1", "0.1", "--face-width", "10", "--json"]
    assert main(base) == 0
    capsys.readouterr()
    assert main(base + ["--power", "75", "--speed", "1480", "--material", "42CrMo4"]) == 1
    out = json.loads(capsys.readouterr().out)
    assert {"contact_strength", "root_strength1", "root_strength2"} <= set(out["failing_checks"])


def test_a_material_without_a_load_is_refused_by_name(capsys):
    assert main(PAIR + ["--material", "42CrMo4"]) == 2
    assert "give either --torque or --power" in capsys.readouterr().err   # the option, not Load's keyword


def test_shift_optimum_respects_the_load(capsys):
    assert main(["shift", "--z1", "20", "--z2", "60", "--module", "4", "--face-width", "40", "--json"] + LOAD) == 0
    out = json.loads(capsys.readouterr().out)
    assert "contact_strength" in out["active"]
