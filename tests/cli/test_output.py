"""Output helpers of the subcommands (geardesign.cli.output): JSON with NaN as null and numpy values
as plain ones, tables with a title, the progress bar only on a terminal."""
import io
import json

import numpy as np
import pandas as pd
import pytest

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


def _wide_frame():
    """12 columns of 10 rows: about 150 characters wide, as a drive's alternatives or a chain's candidates."""
    rng = np.random.default_rng(35)
    data = {"designation": [f"2PR-{i},75-177" for i in range(10)]}
    data.update({f"column_{k}_mm": rng.uniform(0, 1e4, 10) for k in range(10)})
    data["limiting_check"] = ["pressure"] * 10
    return pd.DataFrame(data)


def _blocks(text: str) -> list[list[str]]:
    return [b.splitlines() for b in text.strip("\n").split("\n\n")]


@pytest.mark.parametrize("columns", ["80", "120", None])
def test_tables_fold_to_the_width(capsys, monkeypatch, columns):
    """Issue 35 §8: a wide table is folded into blocks that fit (80 columns off a terminal, else COLUMNS), each
    block repeating the first column, every column once, no pandas '\\' continuation; the values are those of the
    frame, row by row."""
    if columns is None:
        monkeypatch.delenv("COLUMNS", raising=False)     # captured output is not a terminal: 80 columns
    else:
        monkeypatch.setenv("COLUMNS", columns)
    width = 80 if columns is None else int(columns)
    f = _wide_frame()
    print_frame(f)
    text = capsys.readouterr().out
    assert "\\" not in text
    assert max(len(line) for line in text.splitlines()) <= width
    blocks = _blocks(text)
    assert len(blocks) >= 2       # ~150 characters do not fit in one
    seen = []
    for block in blocks:
        header = block[0].split()
        assert header[0] == "designation" and len(block) == 11
        assert [row.split()[0] for row in block[1:]] == list(f["designation"])
        for j, name in enumerate(header[1:], 1):
            seen.append(name)
            if name.startswith("column_"):
                got = [float(row.split()[j]) for row in block[1:]]
                assert got == pytest.approx(list(f[name]), rel=1e-5)   # printed to 6 significant digits
    assert seen == list(f.columns[1:])


def test_a_long_name_column_is_cut_before_folding(capsys, monkeypatch):
    """The handbook's table (quantity | symbol | unit | gear 1 | gear 2) stays one block at 80 columns: its
    quantity names are cut (with an ellipsis) rather than the gear columns moved below."""
    monkeypatch.setenv("COLUMNS", "80")
    import geardesign as gd

    print_frame(gd.GearPair(8, 17, 26, 0.898, 0.517).geometry().to_table())
    lines = capsys.readouterr().out.splitlines()
    assert len(_blocks("\n".join(lines))) == 1 and max(map(len, lines)) <= 80
    assert lines[0].split()[-4:] == ["gear", "1", "gear", "2"] and any("…" in line for line in lines)


@pytest.mark.parametrize("argv", [
    ["pair", "--module", "8", "--z1", "17", "--z2", "26", "--x1", "0.898", "--x2", "0.517"],
    ["pair", "--module", "4", "--z1", "20", "--z2", "60", "--x1", "0.3", "--x2", "0.1", "--face-width", "40",
     "--power", "15", "--speed", "1450", "--material", "42CrMo4"],
    ["chain", "--torque", "380", "--n1", "120", "--ratio", "1"],
    ["teeth", "--ratio", "1.5", "--module", "8", "--z1-max", "20"],
    ["planetary", "--module", "1.75", "--planets", "3", "--ratio", "6"],
])
def test_piped_output_fits_80_columns(argv):
    """A pipe (no terminal, no COLUMNS): 80 columns, every line."""
    import os
    import subprocess
    import sys

    env = {k: v for k, v in os.environ.items() if k != "COLUMNS"}
    proc = subprocess.run([sys.executable, "-m", "geardesign", *argv], capture_output=True, text=True, env=env)
    assert proc.returncode in (0, 1), proc.stderr
    long = [line for line in proc.stdout.splitlines() if len(line) > 80]
    assert not long, long[:3]


def _printed(table, width, monkeypatch, capsys, float_format="{:.6g}"):
    monkeypatch.setenv("COLUMNS", str(width))
    print_frame(table, "t", float_format=float_format)
    return capsys.readouterr().out


@pytest.mark.parametrize("seed", range(6))
def test_rows_print_as_pandas_prints_the_same_frame(seed, monkeypatch, capsys):
    """Issue 36 §3: a plain `pair` prints its tables from plain rows (no pandas import); pandas' own layout of
    the same DataFrame is the reference, character for character: text left-aligned and cut, numbers with NaN,
    None, ±inf, -0 and tiny or huge values, booleans, the name column cut and the columns folded."""
    from geardesign.cli.output import Rows

    rng = np.random.default_rng(seed)
    words = ["a", "contact_ratio", "tip thickness of gear 1: s_a1/m >= sa_min (normal section), a long label",
             "ε_α", "ϑ_root", "x" * 45, "tab\there"]
    specials = [None, float("nan"), float("inf"), -float("inf"), -0.0, 0.0, 1e-300, 5.1e-31, 1e16, -123456.789]
    n = int(rng.integers(1, 12))
    columns = ["name", "val", "ok", "other", "wide number", "label"]
    rows = []
    for _ in range(n):
        rows.append((str(rng.choice(words)), float(rng.normal() * 10.0 ** rng.integers(-8, 8)),
                     bool(rng.integers(2)),
                     specials[int(rng.integers(len(specials)))] if rng.random() < 0.5 else float(rng.normal()),
                     float(rng.normal() * 1e6), str(rng.choice(words))))
    rows[0] = rows[0][:3] + (1.0,) + rows[0][4:]     # a column of numbers, not all None
    table = Rows(tuple(columns), rows)
    assert frame_records(table) == frame_records(table.to_frame())
    for width in (40, 63, 80, 120, 250):
        for fmt in ("{:.6g}", "{:.8g}", "{:.5f}"):
            assert (_printed(table, width, monkeypatch, capsys, fmt)
                    == _printed(table.to_frame(), width, monkeypatch, capsys, fmt))
    ints = Rows(("k", "n"), [("a", 1), ("bb", -20)])
    assert _printed(ints, 80, monkeypatch, capsys) == _printed(ints.to_frame(), 80, monkeypatch, capsys)


def test_a_failing_check_undefined_for_the_design_is_said_so_not_printed_as_nan():
    """A check with no value at the design (NaN: PlanetarySet.checks() labels it "undefined for this design", margin
    −inf) printed "value nan" in the FAILS line (fuzz planetary_spectrum: a set whose ring mesh the chain cannot
    rate). The rows here: a failing number, an undefined value, a passing row (left out)."""
    from geardesign.cli.output import check_details

    table = pd.DataFrame({"check": ["contact_ratio", "set:root_damage_planet", "undercut1"],
                          "value": [0.9857, np.nan, 0.3], "limit": [1.2, 1.0, -0.1], "ok": [False, False, True]})
    assert check_details(table) == {"contact_ratio": "value 0.9857, limit 1.2",
                                    "set:root_damage_planet": "undefined for this design, limit 1"}
