"""Options shared by subcommands (geardesign.cli.options): --objective/--method take exactly the
library's registries, and an output file that exists is refused without --overwrite (common rules),
checked through the real commands on files written here."""
import argparse

import pytest

from geardesign.cli import build_parser, main
from geardesign.cli.options import add_output_file, add_solver_args
from geardesign.shifts.objectives import OBJECTIVES
from geardesign.shifts.optimize import METHODS


def test_solver_args_take_the_registries():
    p = argparse.ArgumentParser()
    add_solver_args(p, "max_x_sum")
    args = p.parse_args([])
    assert args.objective == "max_x_sum" and args.method == "exact"
    for name in OBJECTIVES:
        assert p.parse_args(["--objective", name]).objective == name
    for name in METHODS:
        assert p.parse_args(["--method", name]).method == name
    with pytest.raises(SystemExit) as e:
        p.parse_args(["--objective", "max_beauty"])
    assert e.value.code == 2


def test_output_file_and_overwrite_flag():
    p = argparse.ArgumentParser()
    add_output_file(p, "--out", "CSV", "the table")
    assert vars(p.parse_args([])) == {"out": None, "overwrite": False}
    assert vars(p.parse_args(["--out", "t.csv", "--overwrite"])) == {"out": "t.csv", "overwrite": True}


def test_every_command_with_an_output_file_offers_overwrite():
    sub = next(a for a in build_parser()._actions if isinstance(a, argparse._SubParsersAction))
    with_output = [name for name, p in sub.choices.items()
                   if any(o in p._option_string_actions for o in ("--out", "--plot"))]
    assert {"atlas", "shift", "teeth", "planetary", "drive"} <= set(with_output)
    for name in with_output:
        assert "--overwrite" in sub.choices[name]._option_string_actions, name


def test_existing_output_refused_without_overwrite_and_kept(tmp_path, capsys):
    out = tmp_path / "atlas.csv"
    out.write_text("keep me\n")
    argv = ["atlas", "--z1", "12:13", "--z2", "20,30", "--out", str(out)]
    assert main(argv) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--overwrite" in err[0]
    assert out.read_text() == "keep me\n"
    assert main(argv + ["--overwrite"]) == 0
    assert out.read_text() != "keep me\n"


@pytest.mark.parametrize("command", [["pair", "--module", "4", "--z1", "20", "--z2", "60"],
                                     ["shift", "--module", "4", "--z1", "20", "--z2", "60"]])
def test_a_spectrum_that_is_a_device_is_refused_naming_the_option(command, tmp_path):
    """Fuzzing found `--spectrum /dev/zero` reading one endless line (the header's peek for n_rpm): unbounded work.
    Run in a subprocess with a time limit, so that the old behaviour fails rather than hangs the suite."""
    import subprocess
    import sys
    proc = subprocess.run([sys.executable, "-m", "geardesign", *command, "--spectrum", "/dev/zero", "--material",
                           "C45", "--face-width", "20", "--speed", "1000"], capture_output=True, text=True,
                          cwd=tmp_path, timeout=120)
    lines = proc.stderr.strip().splitlines()
    assert proc.returncode == 2 and len(lines) == 1, proc.stderr
    assert "--spectrum: spectrum file '/dev/zero' is not a regular file" in lines[0]


@pytest.mark.parametrize("argv, said, not_said", [
    (["pair", "--z1", "2", "--z2", "30", "--module", "2"], "--z1 must be a whole number", "error: z1"),
    (["planetary", "-m", "2", "--planets", "3", "--ratio", "5", "--z-sun-range", "40:12"],
     "--z-sun-range must be (lo, hi)", "z_sun_range"),
])
def test_an_error_names_the_option_spelled_like_its_keyword(argv, said, not_said, capsys):
    # the new user's finding: the library's keyword (z1, z_sun_range) was printed where the option (--z1,
    # --z-sun-range) is what the user typed
    from geardesign.cli import main

    assert main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and said in err and not_said not in err
