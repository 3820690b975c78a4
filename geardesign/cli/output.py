"""Shared output helpers of the subcommands: JSON, human tables, a progress bar."""
from __future__ import annotations

import json
import sys

import pandas as pd

from ..results import plain


def print_json(obj) -> None:
    print(json.dumps(plain(obj), indent=2, ensure_ascii=False))


def frame_records(frame: pd.DataFrame) -> list[dict]:
    return [plain(r) for r in frame.to_dict(orient="records")]


def print_frame(frame: pd.DataFrame, title: str | None = None, float_format="{:.6g}") -> None:
    if title:
        print(title)
    with pd.option_context("display.max_rows", 500, "display.max_columns", 50, "display.width", 160):
        print(frame.to_string(index=False, float_format=float_format.format))


def add_json_flag(parser) -> None:
    parser.add_argument("--json", action="store_true", help="print JSON instead of tables")


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
