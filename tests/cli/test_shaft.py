"""``geardesign shaft``: verdict first, exit 0/1/2, JSON with ok, every error naming its option, the TOML file
giving the same result as the options, the plot written whole and never over a file without --overwrite."""
import json
import subprocess
import sys

import pytest


def _cli(*args):
    return subprocess.run([sys.executable, "-m", "geardesign", "shaft", *args], capture_output=True, text=True)


BASE = ["--sections", "40x35,40x40,120x45,40x40,40x35", "--supports", "20,260",
        "--load", "x=140,fy=-3000,fz=1100,fx=800,y=60,torque=120", "--load", "x=280,fz=-1500,torque=-120"]


def test_cli_verdict_json_and_errors(tmp_path):
    ok = _cli(*BASE, "--notch", "x=140,kind=key")
    assert ok.returncode == 0 and ok.stdout.startswith("OK:")
    fails = _cli(*BASE, "--notch", "x=140,kind=key", "--s-min", "20")
    assert fails.returncode == 1 and fails.stdout.startswith("FAILS:")
    js = json.loads(_cli(*BASE, "--notch", "x=140,kind=key", "--json").stdout)
    assert js["ok"] is True and js["safety"]["table"][0]["notch"] == "key"
    bad = _cli("--sections", "40x35", "--supports", "0")
    assert bad.returncode == 2 and "--supports" in bad.stderr and "Traceback" not in bad.stderr
    bad = _cli(*BASE, "--notch", "x=140,kind=spline")
    assert bad.returncode == 2 and "--notch" in bad.stderr
    png = tmp_path / "s.png"
    assert _cli(*BASE, "--plot", str(png)).returncode == 0 and png.stat().st_size > 1000
    again = _cli(*BASE, "--plot", str(png))
    assert again.returncode == 2 and "--overwrite" in again.stderr


@pytest.mark.parametrize("extra, option", [(["--rz", "0"], "--rz"), (["--peak-factor", "0.5"], "--peak-factor"),
                                           (["--s-min", "nan"], "--s-min"), (["--axial-support", "5"], "--axial-support"),
                                           (["--material", "foo"], "--material"),
                                           (["--notch", "x=150,kind=shoulder,r=1"], "--notch"),
                                           (["--load", "x=10,torque=5"], "--load"), (["--sections", "40x0"], "--sections")])
def test_cli_errors_name_the_option(extra, option):
    r = _cli(*BASE, "--notch", "x=140,kind=key", *extra)
    assert r.returncode == 2 and r.stderr.count("\n") == 1 and option in r.stderr and "Traceback" not in r.stderr


def test_cli_toml_file_equals_options(tmp_path):
    """studies/shafts/pinion_shaft.toml describes the shaft of docs/shafts.md's command: the same JSON."""
    from pathlib import Path

    toml = Path(__file__).resolve().parents[2] / "studies" / "shafts" / "pinion_shaft.toml"
    by_file = json.loads(_cli(str(toml), "--peak-factor", "2", "--json").stdout)
    by_options = json.loads(_cli(
        "--sections", "40x35,40x40,110x48,40x40,50x32", "--supports", "20,210",
        "--load", "x=110,fy=-1386.55,fz=3726.28,fx=792.05,y=32.2037,torque=120,mass=1.5,name=pinion",
        "--load", "x=280,torque=-120,name=coupling", "--notch", "x=110,kind=key",
        "--notch", "x=80,kind=shoulder,r=1.6", "--material", "C45", "--peak-factor", "2", "--json").stdout)
    assert by_file == by_options and by_file["ok"] is True
    bad = tmp_path / "bad.toml"
    bad.write_text('[shaft]\nsections = [[40, 35]]\nsupports = [0, 40]\nspeed = 3\n')
    r = _cli(str(bad))
    assert r.returncode == 2 and "unknown key" in r.stderr and "speed" in r.stderr


def test_least_beyond_din743s_range_is_bad_input():
    r = _cli("--sections", "100x10", "--supports", "0,100", "--load", "x=50,fy=-1e9", "--notch", "x=50", "--least")
    assert r.returncode == 2 and "no scale up to" in r.stderr and "--s-min" in r.stderr
