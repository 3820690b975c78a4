"""`geardesign bearing`: the verdict on the first line, --json with "ok", exit 0/1/2, errors naming the option.
Expected bearings come from NTN's Example 2 (tests/data/bearing_life_examples.csv: 6208 gives about 10 400 h
at Fr 3.2 kN, Fa 1.8 kN, 650 min⁻¹) and the catalog rows NTN prints (6208 C = 32.5 kN, 6308 C = 45 kN)."""
import json

import pytest

from geardesign.cli import main

NTN2 = ["--fr", "3200", "--fa", "1800", "--speed", "650"]


def test_check_a_given_bearing(capsys):
    assert main(["bearing", "--designation", "6208", *NTN2, "--life-h", "10000"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[0].startswith("OK: 6208 holds")
    assert main(["bearing", "--designation", "6208", *NTN2, "--life-h", "11000"]) == 1
    out = capsys.readouterr().out.splitlines()
    assert out[0].startswith("FAILS: life")


def test_select_the_smallest(capsys):
    # 20 000 h: 6208 (10 411 h) and 6209 (C 36 kN: 13 377 h) fall short, 6308 (C 45 kN) reaches 23 759 h
    assert main(["bearing", "--series", "62,63", "--bore", "40", *NTN2, "--life-h", "20000", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["ok"] is True and data["bearing"]["designation"] == "6308"
    assert data["bearing"]["L10h"] == pytest.approx(1e6 * (45 / (data["bearing"]["P_n"] / 1000)) ** 3 / 39000)
    assert data["candidates"][0]["designation"] == "6308"


def test_nothing_passes(capsys):
    assert main(["bearing", "--series", "NU2", "--bore", "40", *NTN2, "--life-h", "2000"]) == 1
    out = capsys.readouterr().out.splitlines()
    assert out[0].startswith("FAILS: axial_load")
    assert main(["bearing", "--series", "NU2", "--bore", "40", *NTN2, "--life-h", "2000", "--json"]) == 1
    assert json.loads(capsys.readouterr().out)["ok"] is False


@pytest.mark.parametrize("argv, option", [
    (["--designation", "6208", "--fr", "-3", "--speed", "650"], "--fr"),
    (["--designation", "6208", "--fr", "3", "--speed", "0"], "--speed"),
    (["--bore", "40", "--fr", "3", "--speed", "100", "--life-h", "100", "--reliability", "93"], "--reliability"),
    (["--bore", "40", "--fr", "3", "--speed", "100", "--life-h", "100", "--series", "64"], "--series"),
    (["--bore", "400", "--fr", "3", "--speed", "100", "--life-h", "100"], "--bore"),
    (["--fr", "3", "--speed", "100", "--life-h", "100"], "--bore"),
    (["--bore", "40", "--fr", "3", "--speed", "100"], "--life-h"),
    (["--designation", "6208", "--fr", "3", "--speed", "100", "--kappa", "1"], "--kappa"),
    (["--designation", "6208", "--fr", "3", "--speed", "100", "--kappa", "1", "--ec", "2"], "--ec"),
    (["--type", "tapered", "--series", "62", "--bore", "40", "--fr", "3", "--speed", "100", "--life-h", "100"],
     "--series"),
    (["--type", "tapered", "--designation", "6208", "--fr", "3", "--speed", "100"], "--type"),
])
def test_bad_input_names_the_option(argv, option, capsys):
    assert main(["bearing", *argv]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and option in err[0] and "Traceback" not in err[0]


def test_tapered_type_selects_from_every_tapered_series(capsys):
    """--type tapered: all of 302, 303, 320X, 322, 323 (SKF 17000 tables); 30206 (C = 50 kN, e = 0.37, Y = 1.6)
    under Fr 4 kN, Fa 2 kN: Fa/Fr = 0.5 > e, P = 0.4 Fr + 1.6 Fa = 4 800 N, L10h = 10^6 (50/4.8)^(10/3)/60 000."""
    assert main(["bearing", "--type", "tapered", "--designation", "30206", "--fr", "4000", "--fa", "2000",
                 "--speed", "1000", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["P_n"] == pytest.approx(0.4 * 4000 + 1.6 * 2000, rel=1e-12)
    assert data["L10h"] == pytest.approx(1e6 * (50 / 4.8) ** (10 / 3) / 60000, rel=1e-12)
    assert main(["bearing", "--type", "tapered", "--bore", "30", "--fr", "8000", "--fa", "3000", "--speed", "1000",
                 "--life-h", "20000", "--json", "--top", "0"]) == 0
    data = json.loads(capsys.readouterr().out)
    series = {c["series"] for c in data["candidates"]}
    assert series == {"302", "303", "320X", "322", "323"}
    assert data["bearing"]["series"] in series and data["bearing"]["d_mm"] >= 30
