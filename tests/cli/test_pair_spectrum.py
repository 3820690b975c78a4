"""`geardesign pair ... --spectrum spec.csv` (issue 38): the damage checks join the pair's checks, the life result
follows (text and JSON, with pair_life's values), and a bad file or option is one stderr line naming --spectrum
(exit 2)."""
import json
import subprocess
import sys

import numpy as np
import pytest

from geardesign.cli import main
from geardesign.gears.spectrum import LoadSpectrum
from geardesign.gears.strength.service_life import pair_life

PAIR = ["pair", "-m", "4", "--z1", "20", "--z2", "60", "--x1", "0.3", "--x2", "0.1", "--face-width", "40"]


def _spec(tmp_path, text="torque_nm,n_rpm,time_h\n120,1000,2000\n90,1000,8000\n60,1000,10000\n"):
    p = tmp_path / "spec.csv"
    p.write_text(text, encoding="utf-8")
    return p


def test_pair_with_a_spectrum_json(tmp_path, capsys):
    path = _spec(tmp_path)
    code = main([*PAIR, "--spectrum", str(path), "--material", "42CrMo4", "--json"])
    out = json.loads(capsys.readouterr().out)
    expect = pair_life(np.float64(4.0), 20, 60, 0.3, 0.1, spectrum=LoadSpectrum.from_csv(path), material1="42CrMo4",
                       face_width_mm=40.0)
    assert out["life"]["D_H1"] == pytest.approx(expect["D_H1"], rel=1e-9)
    checks = {c["check"]: c for c in out["checks"]}
    assert checks["pitting_damage1"]["value"] == pytest.approx(expect["D_H1"], rel=1e-9)
    assert code == (0 if expect["D_H1"] <= 1 and expect["D_H2"] <= 1 else 1) and out["ok"] is (code == 0)


def test_pair_with_a_spectrum_text_and_shares(tmp_path, capsys):
    path = _spec(tmp_path, "torque_nm,share\n100,0.5\n50,0.5\n")
    main([*PAIR, "--spectrum", str(path), "--speed", "1000", "--life-h", "20000", "--material", "42CrMo4",
          "--sn-curve", "haibach"])
    out = capsys.readouterr().out
    assert "LifeResult 20/60" in out and "S-N curve 'haibach'" in out and "ISO 6336-6 bins" in out


@pytest.mark.parametrize("extra, text, words", [
    ([], "torque_nm,n_rpm,time_h\n120,abc,2\n", "--spectrum: spectrum file"),
    ([], "torque_nm,n_rpm,time_h\n120,1000,2\n-50,1000,1\n", "--mean-stress-factor"),
    (["--mean-stress-factor", "1.5"], "torque_nm,n_rpm,time_h\n120,1000,2\n-50,1000,1\n", "1.5"),
    (["--no-file"], "", "--spectrum: "),
])
def test_bad_spectra_are_one_line_naming_the_option(tmp_path, extra, text, words):
    path = _spec(tmp_path, text) if text else tmp_path / "none.csv"
    extra = [e for e in extra if e != "--no-file"]
    proc = subprocess.run([sys.executable, "-m", "geardesign", *PAIR, "--spectrum", str(path), "--material",
                           "42CrMo4", *extra], capture_output=True, text=True)
    assert proc.returncode == 2, proc.stderr
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and words in lines[0], proc.stderr


def test_a_spectrum_needs_a_material(tmp_path):
    proc = subprocess.run([sys.executable, "-m", "geardesign", *PAIR, "--spectrum", str(_spec(tmp_path))],
                          capture_output=True, text=True)
    assert proc.returncode == 2 and "--spectrum needs --material" in proc.stderr
