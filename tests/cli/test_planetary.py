"""geardesign planetary: optimise, check given shifts, search tooth counts; one line for bad input."""
import json

import pytest

from geardesign.cli import main


def test_optimum_json_is_coaxial(capsys):
    code = main(["planetary", "--module", "1.75", "--planets", "3", "--z-sun", "21", "--z-planet", "43",
                 "--z-ring", "108", "--objective", "max_eps_alpha", "--json"])
    out = json.loads(capsys.readouterr().out)
    assert code == 0 and out["status"] == "success"
    assert abs(out["a_w"] - out["a_w_planet_ring"]) < 1e-9


def test_given_shifts_name_the_failing_check(capsys):
    # LECAD's printed shifts: coaxial, but the ring's tip reaches the planet's fillet (ρ_p < ρ_l)
    code = main(["planetary", "--module", "1.75", "--planets", "3", "--z-sun", "21", "--z-planet", "43",
                 "--z-ring", "108", "--x-sun", "0.438", "--x-planet", "0.0426", "--x-ring", "0"])
    out = capsys.readouterr().out
    assert code == 1 and "FAILS: planet-ring:interference_planet" in out


def test_teeth_search_and_files(tmp_path, capsys):
    plot, drawing = tmp_path / "r.png", tmp_path / "s.png"
    assert main(["planetary", "--module", "2", "--planets", "3", "--ratio", "5", "--z-sun-range", "18:21"]) == 0
    assert "candidates" in capsys.readouterr().out
    assert main(["planetary", "--module", "2", "--planets", "3", "--z-sun", "18", "--z-planet", "27", "--z-ring",
                 "72", "--plot", str(plot), "--drawing", str(drawing)]) == 0
    assert plot.stat().st_size > 10_000 and drawing.stat().st_size > 10_000
    capsys.readouterr()
    # an existing file is not replaced without --overwrite
    assert main(["planetary", "--module", "2", "--planets", "3", "--z-sun", "18", "--z-planet", "27", "--z-ring",
                 "72", "--plot", str(plot)]) == 2
    assert "overwrite" in capsys.readouterr().err


@pytest.mark.parametrize("argv, words", [
    (["--z-sun", "20"], "--z-planet, --z-ring needed"),
    (["--z-sun", "20", "--z-planet", "30", "--z-ring", "30"], "z_ring must exceed z_planet"),
    (["--z-sun", "20", "--z-planet", "25", "--z-ring", "72", "--x-sun", "0.1"], "--x-sun and --x-planet go together"),
    (["--ratio", "0.5"], "ratio = 0.5"),
    (["--ratio", "5", "--z-sun-range", "a:b"], "--z-sun-range"),
])
def test_bad_input_is_one_line(argv, words, capsys):
    assert main(["planetary", "--module", "2", "--planets", "3", *argv]) == 2
    err = capsys.readouterr().err.strip()
    assert words in err and len(err.splitlines()) == 1


def test_plot_and_drawing_with_ratio_are_refused_and_nothing_written(tmp_path, capsys):
    """Issue 29 §3.10: --ratio with --plot/--drawing exited 0 and wrote neither file."""
    rc = main(["planetary", "--ratio", "5", "--module", "2", "--planets", "3", "--plot", str(tmp_path / "r.png"),
               "--drawing", str(tmp_path / "s.png")])
    err = capsys.readouterr().err
    assert rc == 2 and err.count("\n") == 1 and "--z-sun" in err and "--ratio" in err
    assert list(tmp_path.iterdir()) == []


def test_given_shifts_write_both_plot_and_drawing(tmp_path, capsys):
    rc = main(["planetary", "--module", "1.75", "--planets", "3", "--z-sun", "21", "--z-planet", "43", "--z-ring",
               "108", "--x-sun", "0.438", "--x-planet", "0.0426", "--plot", str(tmp_path / "r.png"),
               "--drawing", str(tmp_path / "s.png")])
    assert rc in (0, 1)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["r.png", "s.png"]
    assert all((tmp_path / n).read_bytes()[:4] == b"\x89PNG" for n in ("r.png", "s.png"))


def test_ratio_is_signed_on_the_command_line_too(capsys):
    # issue 36 §1.8: the carrier-fixed set's ratio is -z_r/z_s, asked and printed with its sign
    args = ["planetary", "-m", "2.5", "--planets", "2", "--ratio-tol", "0.05", "--z-sun-range", "12:12",
            "--nonstandard-max", "0", "--arrangement", "carrier_fixed", "--json"]
    assert main(args + ["--ratio", "12"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "must be < -1" in err[0] and "give -12" in err[0]
    assert main(args + ["--ratio", "-12"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["ok"] and out["table"][0]["ratio"] == -144 / 12
    assert all(row["ratio"] == -row["z_ring"] / row["z_sun"] for row in out["table"])
