"""The `geardesign key` command. Expected designs are the ones derived by hand in
tests/drives/test_key.py (seed 002 recomputed)."""
import json

from geardesign.cli import main


def test_key_select(capsys):
    # d = 60, T = 503 N·m, hub 50 with [σ] = 130 MPa: two keys 18x11x45 (tests/drives/test_key.py)
    assert main(["key", "--d", "60", "--torque", "503", "--hub-length", "50", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert (data["n_keys"], data["length_mm"], data["b_mm"]) == (2, 45.0, 18.0)
    assert main(["key", "--d", "60", "--torque", "503.129", "--hub-length", "50", "--crush", "300",
                 "--shear", "120"]) == 0
    out = " ".join(capsys.readouterr().out.split())     # the lines wrap at the width (80 columns here)
    assert out.startswith("OK: one key 18x11x45") and "t2 = 4.4 mm" in out


def test_key_capacity_and_errors(capsys):
    # 300·60·(11 - 7)·(32 - 18)/2000 = 504 N·m
    assert main(["key", "--d", "60", "--length", "32", "--crush", "300", "--shear", "120"]) == 0
    assert "carries 504.0 N·m" in capsys.readouterr().out
    assert main(["key", "--d", "60", "--torque", "503", "--hub-length", "10"]) == 1
    assert main(["key", "--d", "60", "--torque", "503"]) == 2
    assert "--hub-length" in capsys.readouterr().err
