"""Bad input raises GearDesignError naming the input, its value and the allowed range;
the `geardesign pair` command prints tables, JSON, and one-line errors."""
import json
import os
import subprocess
import sys

import numpy as np
import pytest

import geardesign as gd
from geardesign.cli import main


@pytest.mark.parametrize("kwargs,words", [
    (dict(m=0, z1=17, z2=26), ["m (module)", "0", "> 0"]),
    (dict(m=-1, z1=17, z2=26), ["m (module)", "-1"]),
    (dict(m=2, z1=2, z2=26), ["z1", "in [3, 100000]", "2"]),
    (dict(m=2, z1=17.5, z2=26), ["z1", "whole number", "17.5"]),
    (dict(m=2, z1=17, z2=26, x1=float("nan")), ["x1", "finite", "nan"]),
    (dict(m=float("inf"), z1=17, z2=26), ["m (module)", "finite"]),
    (dict(m=2, z1=17, z2=26, x1=-3, x2=-3), ["x1 + x2", "-6", "> -0.88"]),
    (dict(m=2, z1=40, z2=40, x1=-2.5, x2=2.6), ["x1 = -2.5", "tip circle", "base circle"]),
])
def test_bad_pair_input(kwargs, words):
    with pytest.raises(gd.GearDesignError) as info:
        gd.GearPair(**kwargs)
    assert isinstance(info.value, ValueError)
    for w in words:
        assert w in str(info.value), (w, str(info.value))


@pytest.mark.parametrize("alpha", [0.0, 45.0, -5.0, float("nan")])
def test_bad_rack(alpha):
    with pytest.raises(gd.GearDesignError, match="alpha_deg"):
        gd.BasicRack(alpha_deg=alpha)


def test_bad_fillet():
    with pytest.raises(gd.GearDesignError, match=r"rho_f must be in \[0, 0\.47"):
        gd.BasicRack(rho_f=0.6)


def test_vectorised_error_names_index():
    with pytest.raises(gd.GearDesignError, match="index 2"):
        gd.pair_geometry(1.0, 20, 30, np.array([0.0, 0.1, -40.0]), 0.0)


def test_scalar_in_scalar_out_and_broadcast():
    g = gd.pair_geometry(2.0, 17, 34, 0.0, 0.0)
    assert isinstance(g.a_w, float)
    ga = gd.pair_geometry(2.0, np.array([17, 18]), np.array([[34], [40], [50]]), 0.1, 0.2)
    assert ga.a_w.shape == (3, 2)
    assert ga.to_frame().shape[0] == 6


def test_center_distance_too_small():
    with pytest.raises(gd.GearDesignError, match="a_w = 40 mm is too small"):
        gd.GearPair.from_center_distance(2, 17, 34, 40.0)


def test_cli_table(capsys):
    assert main(["pair", "--module", "8", "--z1", "17", "--z2", "26", "--x1", "0.898", "--x2", "0.517"]) == 0
    out = capsys.readouterr().out
    assert "alpha_w_deg" in out and "contact_ratio" in out and "Failing checks: contact_ratio" in out


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
    assert r.returncode == 0, r.stderr
    assert json.loads(r.stdout)["geometry"]["a_w"] == pytest.approx(51.0)   # seed 001 task 2
    bad = subprocess.run([sys.executable, "-m", "geardesign", "pair", "--module", "2", "--z1", "1",
                          "--z2", "34"], cwd=tmp_path, capture_output=True, text=True, env=env)
    assert bad.returncode == 2 and "Traceback" not in bad.stderr and "z1" in bad.stderr
