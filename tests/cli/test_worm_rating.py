"""``geardesign worm --speed/--torque``: the efficiency and the rating the command prints are the library's, a
failing rating exits 1 naming its check, and every bad rating option is refused on one stderr line naming it."""
import json

import pytest

import geardesign as gd
from geardesign.cli import main
from geardesign.gears.worm.rating import load_capacity
from geardesign.gears.worm.temperature import housing_area_estimate

PAIR = ["--module", "8", "--z1", "2", "--z2", "25", "--q", "10"]


def _run(capsys, *argv):
    try:
        code = main(["worm", *argv])
    except SystemExit as exc:
        code = exc.code
    out, err = capsys.readouterr()
    return code, out, err


def test_efficiency_is_the_pairs(capsys):
    code, out, err = _run(capsys, *PAIR, "--speed", "1500", "--json")
    data = json.loads(out)
    want = gd.WormPair(8, 2, 25, 10).efficiency(1500.0)
    assert code == 0 and not err and "rating" not in data
    for k, v in want.items():
        assert data["efficiency"][k] == pytest.approx(v, rel=1e-15) if isinstance(v, float) else data["efficiency"][k] == v
    code, out, _ = _run(capsys, *PAIR, "--speed", "1500")
    assert code == 0 and "Efficiency at n1 = 1500 rpm" in out and "eta_z_reverse" in out


def test_rating_and_load_capacity_are_the_librarys(capsys):
    code, out, _ = _run(capsys, *PAIR, "--speed", "1500", "--torque", "842", "--bearing-span", "250",
                        "--heat-transfer", "28", "--no-load-loss", "40", "--json")
    data = json.loads(out)
    pair = gd.WormPair(8, 2, 25, 10)
    r = pair.rating(842.0, 1500.0, l_1=250.0, k_heat=28.0, A_housing=float(housing_area_estimate(140.0)), P_V0=40.0)
    assert code == 0 and data["ok"]
    for k in ("S_T", "S_delta", "eta_z", "eta_total", "theta_S"):
        assert data["rating"][k] == pytest.approx(getattr(r, k), rel=1e-14)
    assert data["rating"]["S_H"] is None                    # not computed: no flags for it, and it says so
    assert data["load_capacity"]["T2_max"] == pytest.approx(load_capacity(r, P_const=40.0)["T2_max"], rel=1e-14)
    code, out, _ = _run(capsys, *PAIR, "--speed", "1500", "--torque", "842", "--bearing-span", "250")
    assert code == 0 and "WormRating: OK at T2 = 842" in out and "carries T2 =" in out


def test_a_failing_rating_exits_1_and_names_its_check(capsys):
    # a small housing at a large torque: the oil would pass its limit
    code, out, _ = _run(capsys, *PAIR, "--speed", "1500", "--torque", "3000", "--heat-transfer", "10",
                        "--housing-area", "0.3")
    assert code == 1 and out.startswith("FAILS:") and "rating S_T" in out.splitlines()[0]


@pytest.mark.parametrize("argv, flag", [
    (["--torque", "100"], "--torque"),
    (["--bearing-span", "200"], "--bearing-span"),
    (["--speed", "-5"], "--speed"),
    (["--speed", "1500", "--torque", "0"], "--torque"),
    (["--speed", "1500", "--mu", "2"], "--mu"),
    (["--speed", "1500", "--torque", "500", "--bearing-span", "-1"], "--bearing-span"),
    (["--speed", "1500", "--torque", "500", "--heat-transfer", "20", "--housing-area", "0"], "--housing-area"),
    (["--speed", "1500", "--torque", "500", "--heat-transfer", "20", "--ambient", "95"], "--oil-limit"),
    (["--speed", "1500", "--torque", "500", "--heat-transfer", "20", "--no-load-loss", "-3"], "--no-load-loss"),
])
def test_bad_rating_options_are_named(capsys, argv, flag):
    code, out, err = _run(capsys, *PAIR, *argv)
    assert code == 2 and not out and len(err.strip().splitlines()) == 1 and flag in err, err
