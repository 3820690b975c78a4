"""Shared output helpers of the subcommands: JSON, human tables, a progress bar."""
from __future__ import annotations

import json
import shutil
import sys
import textwrap

from ..results import plain


def print_json(obj) -> None:
    print(json.dumps(plain(obj), indent=2, ensure_ascii=False))


def frame_records(frame: pd.DataFrame) -> list[dict]:
    return [plain(r) for r in frame.to_dict(orient="records")]


DEFAULT_WIDTH = 100    # columns when the output is not a terminal (a pipe, a file, a test)
TEXT_MAX = 60          # a text cell longer than this is cut with an ellipsis (the JSON keeps it whole)


def terminal_width() -> int:
    """The terminal's width in columns (``COLUMNS`` first), or :data:`DEFAULT_WIDTH` off a terminal."""
    return shutil.get_terminal_size((DEFAULT_WIDTH, 24)).columns


def print_frame(frame: pd.DataFrame, title: str | None = None, float_format="{:.6g}") -> None:
    """A table folded to the terminal's width: columns that do not fit continue below, long text cut."""
    import pandas as pd   # here: pandas costs ~0.2 s to import, and `--help` or a plain `pair` prints no frame
    if title:
        print(title)
    width = max(terminal_width(), 40)
    limit = min(TEXT_MAX, width - 10)
    shown = frame.copy()
    for col in shown.columns:
        if shown[col].dtype == object or pd.api.types.is_string_dtype(shown[col]):
            cut = [v if not isinstance(v, str) or len(v) <= limit else v[:limit - 1] + "…" for v in shown[col]]
            if all(isinstance(v, str) for v in cut):     # text reads left-aligned
                pad = max([len(str(col))] + [len(v) for v in cut])
                cut = [v.ljust(pad) for v in cut]
                shown = shown.rename(columns={col: str(col).ljust(pad)})
                col = str(col).ljust(pad)
            shown[col] = cut
    with pd.option_context("display.max_rows", 500, "display.max_columns", 50, "display.width", width):
        print(shown.to_string(index=False, float_format=float_format.format, line_width=width, na_rep=""))


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


def check_details(table: pd.DataFrame) -> dict:
    """``check -> "value 1.153 against limit 1.2"`` for a checks table's failing rows."""
    out = {}
    for _, row in table.loc[~table["ok"]].iterrows():
        try:
            out[row["check"]] = f"value {float(row['value']) + 0.0:.4g}, limit {float(row['limit']) + 0.0:.4g}"
        except (TypeError, ValueError):
            out[row["check"]] = ""
    return out


def add_json_flag(parser) -> None:
    parser.add_argument("--json", action="store_true",
                        help='print JSON instead of tables (its "ok" says whether the design passes)')


class Progress:
    """A one-line progress bar on stderr, shown only on a terminal."""

    def __init__(self, total: int, label: str = "", stream=None):
        self.total = max(int(total), 1)
        self.label = label
        self.stream = stream or sys.stderr
        self.enabled = self.stream.isatty()
        self.done = 0

    def update(self, n: int = 1) -> None:
        self.done += n
        if self.enabled:
            shown = min(self.done, self.total)   # a caller that overshoots its total still reads n/n
            bar = "#" * int(30 * shown / self.total)
            self.stream.write(f"\r{self.label} [{bar:<30}] {shown}/{self.total}")
            self.stream.flush()

    def to(self, done: int, total: int, label: str | None = None) -> None:
        """Show ``done`` of ``total`` (a callback that reports counts rather than steps)."""
        self.total = max(int(total), 1)
        if label is not None:
            self.label = label
        self.update(done - self.done)

    def close(self) -> None:
        if self.enabled:
            self.stream.write("\n")
            self.stream.flush()
