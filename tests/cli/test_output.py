"""Output helpers of the subcommands (geardesign.cli.output): JSON with NaN as null and numpy values
as plain ones, tables with a title, the progress bar only on a terminal."""
import io
import json

import numpy as np
import pandas as pd

from geardesign.cli.output import Progress, add_json_flag, frame_records, print_frame, print_json


def test_print_json_is_strict_json(capsys):
    print_json({"a": np.float64(1.5), "b": np.nan, "c": np.arange(3), "d": np.int64(4), "e": np.bool_(True),
                "f": float("inf"), "g": "ε_α"})
    text = capsys.readouterr().out
    assert json.loads(text) == {"a": 1.5, "b": None, "c": [0, 1, 2], "d": 4, "e": True, "f": None, "g": "ε_α"}
    assert "NaN" not in text and "Infinity" not in text and "ε_α" in text


def test_frame_records_and_table(capsys):
    f = pd.DataFrame({"z1": [17, 18], "x1": [0.898, np.nan]})
    assert frame_records(f) == [{"z1": 17, "x1": 0.898}, {"z1": 18, "x1": None}]
    print_frame(f, title="pairs")
    lines = capsys.readouterr().out.splitlines()
    assert lines[0] == "pairs" and lines[1].split() == ["z1", "x1"] and lines[2].split() == ["17", "0.898"]


def test_json_flag():
    import argparse
    p = argparse.ArgumentParser()
    add_json_flag(p)
    assert p.parse_args([]).json is False and p.parse_args(["--json"]).json is True


class _Tty(io.StringIO):
    def isatty(self):
        return True


def test_progress_only_on_a_terminal():
    quiet = io.StringIO()
    bar = Progress(4, "walk", stream=quiet, delay_s=0)
    bar.update(2)
    bar.close()
    assert quiet.getvalue() == ""
    tty = _Tty()
    bar = Progress(4, "walk", stream=tty, delay_s=0, min_interval_s=0)
    bar.update(2)
    bar.update(5)           # past the total: the bar stays full and reads 4/4, not 7/4
    bar.close()
    out = tty.getvalue()
    assert "walk" in out and "2/4" in out and "4/4" in out and "7/4" not in out


def test_progress_waits_a_few_seconds_before_it_shows():
    tty = _Tty()
    bar = Progress(4, "walk", stream=tty)      # the default delay: a quick step shows nothing
    bar.update(4)
    bar.close()
    assert tty.getvalue().strip() == ""


def test_progress_to_takes_counts_and_a_zero_total():
    """Callbacks report (done, total): the bar shows them as given; a total of 0 (nothing to solve yet)
    is shown as 0/1, not a division by zero."""
    tty = _Tty()
    bar = Progress(1, "walk", stream=tty, delay_s=0, min_interval_s=0)
    bar.to(0, 0)
    bar.to(3, 6, "run")
    bar.close()
    out = tty.getvalue()
    assert "walk" in out and "0/1" in out and "run" in out and "3/6" in out
