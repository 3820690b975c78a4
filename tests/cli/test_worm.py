"""``geardesign worm``: the verdict and exit status of a pair, the shift for a centre distance, the best x2, the
choice from the series, and every bad option refused on one stderr line naming the option (exit 2)."""
import json

import pytest

from geardesign.cli import main


def _run(capsys, *argv):
    try:
        code = main(["worm", *argv])
    except SystemExit as exc:      # argparse's own errors (a value that is not a number)
        code = exc.code
    out, err = capsys.readouterr()
    return code, out, err


def test_a_pair_that_passes(capsys):
    code, out, err = _run(capsys, "--module", "3", "--z1", "2", "--z2", "30", "--q", "14.6666666667",
                          "--measurements")
    assert code == 0 and out.startswith("OK: all checks hold.") and not err
    assert "Measuring sizes" in out and "s_x1" in out


def test_a_failing_pair_names_the_check_and_exits_1(capsys):
    code, out, _ = _run(capsys, "--module", "3", "--z1", "2", "--z2", "30", "--q", "10", "--x2", "1.2")
    assert code == 1 and out.startswith("FAILS: x2_range")


def test_center_distance_fixes_x2_json(capsys):
    code, out, _ = _run(capsys, "--module", "8", "--z1", "2", "--z2", "31", "--q", "8", "--center-distance", "160",
                        "--json")
    data = json.loads(out)
    assert code == 0 and data["ok"] and data["input"]["x2"] == 0.5 and data["geometry"]["a"] == 160.0


def test_optimize_x2(capsys):
    code, out, _ = _run(capsys, "--module", "4", "--z1", "1", "--z2", "16", "--q", "10", "--optimize-x2",
                        "min_abs_x2", "--json")
    data = json.loads(out)
    assert code == 0 and data["optimum"]["success"] and data["input"]["x2"] == pytest.approx(1.25 - 0.38 * 0.6579798566743311 - 8 * 0.11697777844051097, abs=1e-12)


def test_choice_from_the_series(capsys):
    code, out, _ = _run(capsys, "--ratio", "12.5", "--center-distance", "125", "--top", "3", "--json")
    data = json.loads(out)
    assert code == 0 and data["ok"] and len(data["candidates"]) == 3
    assert all(abs(c["a"] - 125.0) < 1e-9 for c in data["candidates"])


@pytest.mark.parametrize("argv,words", [
    (["--module", "0", "--z1", "1", "--z2", "40", "--q", "10"], ["--module must be > 0"]),
    (["--module", "2", "--z1", "0", "--z2", "40", "--q", "10"], ["--z1 must be a whole number in [1, 10]"]),
    (["--module", "2", "--z1", "1", "--z2", "40", "--q", "2"], ["--q must be in (2.5, 100]"]),
    (["--module", "2", "--z1", "1", "--z2", "40", "--q", "10", "--flank-form", "ZX"], ["--flank-form must be one of"]),
    (["--module", "2", "--z1", "1", "--z2", "40", "--q", "10", "--x2", "0", "--center-distance", "50"],
     ["--x2 or --center-distance"]),
    (["--module", "2", "--z1", "1", "--z2", "40", "--q", "10", "--center-distance", "500"],
     ["--center-distance must be in [30, 70] mm"]),
    (["--module", "2", "--z1", "1", "--z2", "40", "--q", "10", "--optimize-x2", "best"],
     ["--optimize-x2 must be one of"]),
    (["--module", "2", "--z1", "1", "--q", "10"], ["--z2 is needed"]),
    (["--module", "2", "--z1", "1", "--z2", "40", "--q", "10", "--worm-length", "-5"], ["--worm-length", "-5"]),
    (["--module", "2", "--z1", "1", "--z2", "40", "--q", "10", "--x2-abs-max", "9"], ["--x2-abs-max must be in"]),
    (["--module", "abc"], ["--module", "invalid float value"]),
    ([], ["--module is needed"]),
])
def test_bad_options(capsys, argv, words):
    code, out, err = _run(capsys, *argv)
    assert code == 2 and not out and len(err.strip().splitlines()) == 1
    for w in words:
        assert w in err, (w, err)
