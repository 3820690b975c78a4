"""Shared output helpers of the subcommands: JSON, human tables, a progress bar."""
from __future__ import annotations

import json
import math
import shutil
import sys
import textwrap
from typing import NamedTuple

from ..progress import Bar
from ..results import plain

from typing import TYPE_CHECKING

if TYPE_CHECKING:       # pandas is imported where a table is made (start-up cost)
    import pandas as pd


def print_json(obj) -> None:
    print(json.dumps(plain(obj), indent=2, ensure_ascii=False))


def frame_records(frame: pd.DataFrame | Rows) -> list[dict]:
    if isinstance(frame, Rows):
        return [plain(dict(zip(frame.columns, r))) for r in frame.rows]
    return [plain(r) for r in frame.to_dict(orient="records")]


class Rows(NamedTuple):
    """A table without pandas: column names and row tuples, each column all text, all numbers (``None`` or
    NaN empty) or all booleans. :func:`print_frame` prints it as it prints the same DataFrame (a plain
    ``geardesign pair`` then never imports pandas, ~0.2 s of its start)."""
    columns: tuple
    rows: list

    def select(self, *names) -> Rows:
        """The columns ``names``, in that order."""
        at = [self.columns.index(n) for n in names]
        return Rows(tuple(names), [tuple(r[i] for i in at) for r in self.rows])

    def to_frame(self) -> pd.DataFrame:
        import pandas as pd   # a table that the plain printer does not lay out (see _plain_columns)

        return pd.DataFrame(self.rows, columns=list(self.columns))


DEFAULT_WIDTH = 80     # columns when the output is not a terminal (a pipe, a file, a test)
TEXT_MAX = 60          # a text cell longer than this is cut with an ellipsis (the JSON keeps it whole)


def terminal_width() -> int:
    """The terminal's width in columns (``COLUMNS`` first), or :data:`DEFAULT_WIDTH` off a terminal."""
    return shutil.get_terminal_size((DEFAULT_WIDTH, 24)).columns


def print_frame(frame: pd.DataFrame | Rows, title: str | None = None, float_format="{:.6g}") -> None:
    """A table folded to the terminal's width: long text cut (the first column, the rows' names, down to
    :data:`KEY_MIN` characters when that makes the table fit), then the columns that still do not fit continue
    below in blocks that each repeat the first column. ``frame`` a DataFrame or :class:`Rows`."""
    if isinstance(frame, Rows):
        columns = _plain_columns(frame)
        if columns is not None:
            if title:
                print(title)
            for block in _plain_fold(columns, max(terminal_width(), 40), float_format):
                print(block)
            return
        frame = frame.to_frame()
    import pandas as pd   # here: pandas costs ~0.2 s to import, and `--help` or a plain `pair` prints no frame
    if title:
        print(title)
    width = max(terminal_width(), 40)
    shown = _cut_text(frame, min(TEXT_MAX, width - 10))
    if shown.shape[1] > 1 and _is_text(shown.iloc[:, 0]):
        widths = [len(_column_lines(shown, i, float_format)[0]) for i in range(shown.shape[1])]
        excess = sum(widths) + len(widths) - 1 - width
        if excess > 0 and widths[0] - excess >= KEY_MIN:
            first = _cut_text(frame.iloc[:, [0]], widths[0] - excess)
            shown = pd.concat([first, shown.iloc[:, 1:]], axis=1)
    for block in fold_columns(shown, width, float_format):
        print(block)


KEY_MIN = 30   # characters of a table's first (name) column kept when it is cut to fit the width


def _is_text(column: pd.Series) -> bool:
    import pandas as pd   # loaded already: a frame is being printed

    return column.dtype == object or pd.api.types.is_string_dtype(column)


def _cut_text(frame: pd.DataFrame, limit: int) -> pd.DataFrame:
    """``frame`` with text longer than ``limit`` cut with an ellipsis and text columns left-aligned."""
    shown = frame.copy()
    for i, col in enumerate(frame.columns):
        column = frame.iloc[:, i]
        if not _is_text(column):
            continue
        cut = [v if not isinstance(v, str) or len(v) <= limit else v[:limit - 1] + "…" for v in column]
        if all(isinstance(v, str) for v in cut):     # text reads left-aligned
            pad = max([len(str(col))] + [len(v) for v in cut])
            cut = [v.ljust(pad) for v in cut]
            shown = shown.rename(columns={col: str(col).ljust(pad)})
        shown.isetitem(i, cut)
    return shown


def _column_lines(frame: pd.DataFrame, i: int, float_format) -> list[str]:
    """Column ``i`` as pandas prints it (header, then the rows), every line of one width."""
    lines = frame.iloc[:, [i]].to_string(index=False, float_format=float_format.format, na_rep="").split("\n")
    n = max(map(len, lines))
    return [line.rjust(n) for line in lines]


def fold_columns(frame: pd.DataFrame, width: int, float_format="{:.6g}") -> list[str]:
    """The table as text blocks of at most ``width`` columns (a column wider than that alone is left whole):
    the columns in order, each block starting with the first column again, blocks apart by an empty line."""
    if frame.shape[1] == 0 or len(frame) == 0:
        return [frame.to_string(index=False)]
    return _fold([_column_lines(frame, i, float_format) for i in range(frame.shape[1])], width)


def _fold(cols: list[list[str]], width: int) -> list[str]:
    """Columns' lines (each column's lines of one width) as :func:`fold_columns`' blocks."""
    key = cols[0]
    blocks, current, used = [], [key], len(key[0])
    for col in cols[1:]:
        if used + 1 + len(col[0]) > width and len(current) > 1:
            blocks.append(current)
            current, used = [key], len(key[0])
        current.append(col)
        used += 1 + len(col[0])
    blocks.append(current)
    return ["\n\n".join("\n".join(" ".join(col[i] for col in block).rstrip() for i in range(len(key)))
                        for block in blocks)]


def _plain_columns(table: Rows) -> list | None:
    """``[name, kind, values]`` per column of ``table`` (kind ``text``, ``float``, ``int`` or ``bool``, as
    pandas' dtype would be), or None when a column mixes kinds or the table is empty (pandas prints those)."""
    if not table.rows or not table.columns:
        return None
    out = []
    for i, name in enumerate(table.columns):
        values = [r[i] for r in table.rows]
        if all(isinstance(v, str) for v in values):
            kind = "text"
        elif all(isinstance(v, bool) for v in values):
            kind = "bool"
        elif all(isinstance(v, int) and not isinstance(v, bool) for v in values):
            kind = "int"
        elif all(v is None or isinstance(v, (int, float)) and not isinstance(v, bool) for v in values) and \
                any(v is not None for v in values):
            kind = "float"
        else:
            return None
        out.append([str(name), kind, values])
    return out


def _plain_cut_text(columns: list, limit: int) -> list:
    """:func:`_cut_text` of plain columns."""
    shown = []
    for name, kind, values in columns:
        if kind == "text":
            values = [v if len(v) <= limit else v[:limit - 1] + "…" for v in values]
            pad = max([len(name)] + [len(v) for v in values])
            name, values = name.ljust(pad), [v.ljust(pad) for v in values]
        shown.append([name, kind, values])
    return shown


_ESCAPES = str.maketrans({"\t": "\\t", "\n": "\\n", "\r": "\\r"})   # as pandas shows them in a table


def _plain_column_lines(column: list, float_format) -> list[str]:
    """:func:`_column_lines` of a plain column: pandas' layout of one column (``to_string(index=False)``): a
    number's header one space in, NaN and None empty, text with its tabs and newlines escaped, all right-aligned."""
    name, kind, values = column
    if kind == "text":
        lines = [name] + [v.translate(_ESCAPES) for v in values]
    elif kind == "float":
        lines = [" " + name] + ["" if v is None or math.isnan(v) else float_format.format(float(v)) for v in values]
    else:
        lines = [" " + name] + [str(v) for v in values]
    n = max(map(len, lines))
    return [line.rjust(n) for line in lines]


def _plain_fold(columns: list, width: int, float_format) -> list[str]:
    """:func:`print_frame`'s blocks of plain columns (the same steps as for a DataFrame)."""
    shown = _plain_cut_text(columns, min(TEXT_MAX, width - 10))
    if len(shown) > 1 and shown[0][1] == "text":
        widths = [len(_plain_column_lines(c, float_format)[0]) for c in shown]
        excess = sum(widths) + len(widths) - 1 - width
        if excess > 0 and widths[0] - excess >= KEY_MIN:
            shown[0] = _plain_cut_text(columns[:1], widths[0] - excess)[0]
    return _fold([_plain_column_lines(c, float_format) for c in shown], width)


def print_wrapped(text: str, indent: str = "  ") -> None:
    """A long line wrapped to the terminal's width, continuation lines indented."""
    print(textwrap.fill(text, width=max(terminal_width(), 40), subsequent_indent=indent,
                        break_on_hyphens=False))


def print_verdict(failed: list, details: dict | None = None, what: str = "checks") -> None:
    """One line: every check holds, or which fail (with their value and limit where given)."""
    if not failed:
        print(f"OK: all {what} hold.")
        return
    details = details or {}
    print_wrapped("FAILS: " + "; ".join(f"{name}{' (' + details[name] + ')' if details.get(name) else ''}"
                                for name in failed))


def print_verdict_line(ok: bool, text: str) -> None:
    """The first line of every command's text output: ``OK: text`` or ``FAILS: text`` (wrapped)."""
    print_wrapped(("OK: " if ok else "FAILS: ") + text)


def failing_margins(margins: dict, names=None) -> str:
    """``check (margin -0.1336); ...`` of the failing (or the named) checks of a {check: margin} dict."""
    from ..gears.checks.base import FEASIBILITY_TOL

    names = [k for k, v in margins.items() if not v >= -FEASIBILITY_TOL] if names is None else names
    return "; ".join(f"{k} (margin {float(margins[k]) + 0.0:+.4g})" if k in margins else k for k in names)


def check_details(table: pd.DataFrame | Rows) -> dict:
    """``check -> "value 1.153, limit 1.2"`` for a checks table's failing rows ("undefined for this design" for a
    value the check has none of there)."""
    out = {}
    rows = ([dict(zip(table.columns, r)) for r in table.rows] if isinstance(table, Rows)
            else [r for _, r in table.iterrows()])
    for row in rows:
        if row["ok"]:
            continue
        try:
            value, limit = float(row["value"]) + 0.0, float(row["limit"]) + 0.0
        except (TypeError, ValueError):
            out[row["check"]] = ""
            continue
        # NaN: a check undefined for the design (its label says so), which fails; not a value to print as "nan"
        out[row["check"]] = (f"value {value:.4g}" if math.isfinite(value) else "undefined for this design") + (
            f", limit {limit:.4g}" if math.isfinite(limit) else "")
    return out


def add_progress_flag(parser) -> None:
    parser.add_argument("--progress", action="store_true",
                        help="show the progress bar on stderr also when it is not a terminal (it shows on a terminal "
                             "anyway, once the work has run a few seconds)")


def add_json_flag(parser) -> None:
    parser.add_argument("--json", action="store_true",
                        help='print JSON instead of tables (its "ok" says whether the design passes)')


class Progress:
    """A progress bar on stderr (tqdm, :class:`geardesign.progress.Bar`), shown only on a terminal and once
    the work has run a few seconds; never on stdout, so ``--json`` stays clean."""

    def __init__(self, total: int, label: str = "", stream=None, show: bool | None = None, **bar):
        self.total = max(int(total), 1)
        self.label = label
        self.done = 0
        self._bar = Bar(show, stream or sys.stderr, **bar)    # bar: delay_s, min_interval_s of Bar
        self.enabled = self._bar.show

    def update(self, n: int = 1) -> None:
        self.done += n
        self._bar(self.label, min(self.done, self.total), self.total)   # an overshooting caller reads n/n

    def to(self, done: int, total: int, label: str | None = None) -> None:
        """Show ``done`` of ``total`` (a callback that reports counts rather than steps)."""
        self.total = max(int(total), 1)
        if label is not None:
            self.label = label
        self.update(done - self.done)

    def report(self, label: str, done: int, total: int) -> None:
        """A ``progress(label, done, total)`` of the library's long steps (each step its own bar)."""
        if label != self.label:
            self.done = 0
        self.to(done, total, label)

    def close(self) -> None:
        self._bar.close()
