"""One result base for every job: a status word, a message, and the same ways out (dict, JSON, frame).

A result class is a dataclass that sets ``_success_field`` (the boolean field that says whether it
succeeded) and lists in ``_table_fields`` the DataFrame fields that ``to_dict`` gives as records.
``to_dict`` returns plain, JSON-ready values (numpy scalars as Python numbers, NaN and ±inf as
None), so ``json.dumps(result.to_dict())`` always works; ``to_json`` does just that.

>>> from dataclasses import dataclass
>>> @dataclass
... class Demo(Result):
...     ok: bool
...     message: str
...     value: float
...     _success_field = "ok"
>>> d = Demo(True, "fine", float("nan"))
>>> d.status, d.to_dict()
('success', {'ok': True, 'message': 'fine', 'value': None, 'status': 'success'})
"""
from __future__ import annotations

import html
import json
import math
from dataclasses import MISSING, fields

import numpy as np

__all__ = ["Result", "RankedTable", "plain", "compact_repr", "frame_html"]

REPR_TABLE_ROWS = 5        # rows of a table a repr shows (a repr stays within ~15 lines)
HTML_TABLE_ROWS = 20       # rows of a table an HTML view shows


def compact_repr(obj) -> str:
    """``Name(field=value, ...)`` with only the fields that differ from their defaults, arrays and
    tables as their shape: a dataclass's one-line repr that never dumps data."""
    parts = []
    for f in fields(obj):
        if not f.repr or f.name.startswith("_"):
            continue
        v = getattr(obj, f.name)
        default = f.default if f.default is not MISSING else (
            f.default_factory() if f.default_factory is not MISSING else MISSING)
        try:
            same = default is not MISSING and bool(v == default)
        except (TypeError, ValueError):
            same = False
        if not same:
            parts.append(f"{f.name}={short_value(v)}")
    return f"{type(obj).__name__}({', '.join(parts)})"


def notes_text(notes, shown: int = 3) -> list:
    """A result's repr lines for its notes: the first ``shown``, then how many more ``.notes`` holds.

    >>> notes_text(["a", "b", "c", "d"])
    ['  note: a', '  note: b', '  note: c', '  ... 1 more notes (.notes)']
    """
    lines = [f"  note: {n}" for n in notes[:shown]]
    if len(notes) > shown:
        lines.append(f"  ... {len(notes) - shown} more notes (.notes)")
    return lines


def short_value(v) -> str:
    """A value in a few characters: arrays and tables by their shape, floats to 6 digits."""
    if isinstance(v, np.ndarray):
        return f"<array {'x'.join(map(str, v.shape))}>"
    if hasattr(v, "columns") and hasattr(v, "shape"):
        return f"<table {v.shape[0]} rows>"
    if hasattr(v, "index") and hasattr(v, "to_dict"):       # a Series: a catalog row, named by its first value
        return repr(str(v.iloc[0])) if len(v) else "<row>"
    if isinstance(v, float):
        return f"{v:.6g}"
    text = repr(v)
    return text if len(text) <= 80 else text[:77] + "..."


def frame_html(frame, title: str = "", rows: int = HTML_TABLE_ROWS) -> str:
    """An HTML view: a title line and the first ``rows`` rows of a table."""
    head = f"<p><b>{html.escape(title)}</b></p>" if title else ""
    if frame is None:
        return head
    more = f"<p>… {len(frame) - rows} more rows</p>" if len(frame) > rows else ""
    return head + frame.head(rows).to_html(index=False, na_rep="", float_format="{:.6g}".format) + more


def plain(value):
    """numpy and pandas values as JSON-ready Python values: NaN and ±inf become None, arrays lists,
    DataFrames lists of records, Series dicts."""
    if isinstance(value, dict):
        return {str(k): plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [plain(v) for v in value]
    if isinstance(value, np.ndarray):
        return [plain(v) for v in value.tolist()]
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, np.integer):
        return int(value)
    if isinstance(value, (float, np.floating)):
        v = float(value)
        return v if math.isfinite(v) else None
    if hasattr(value, "to_dict") and hasattr(value, "columns"):      # a DataFrame
        return plain(value.to_dict(orient="records"))
    if hasattr(value, "to_dict") and hasattr(value, "index"):        # a Series (a catalog row)
        return plain(value.to_dict())
    if isinstance(value, Result):
        return value.to_dict()
    return value


class Result:
    """Base of the result objects (see the module docstring)."""

    _success_field = "success"
    _table_fields: tuple = ()      # DataFrame fields: records in to_dict, the first one is to_frame()

    @property
    def status(self) -> str:
        """``"success"`` when the job found what it was asked for, else ``"failed"`` (the message says why)."""
        return "success" if bool(getattr(self, self._success_field)) else "failed"

    def to_dict(self) -> dict:
        out = {f.name: plain(getattr(self, f.name)) for f in fields(self) if not f.name.startswith("_")}
        out["status"] = self.status
        return out

    def to_json(self, indent: int | None = 2) -> str:
        return json.dumps(self.to_dict(), indent=indent, ensure_ascii=False)

    def _repr_html_(self) -> str:
        """Jupyter's view: the repr's first lines as the title and the main table (when there is one)."""
        try:
            table = self.to_frame()
        except NotImplementedError:
            table = None
        return f"<pre>{html.escape(repr(self))}</pre>" + frame_html(table)

    def to_frame(self):
        """The result's main table (a copy)."""
        if not self._table_fields:
            raise NotImplementedError(f"{type(self).__name__} has no table")
        return getattr(self, self._table_fields[0]).copy()


class RankedTable(Result):
    """A search result whose ``table`` is ranked best first and has a boolean ``feasible`` column:
    ``best`` is the first row when it is feasible (else None), ``found`` whether there is one."""

    _success_field = "found"
    _table_fields = ("table",)

    @property
    def best(self):
        if self.table.empty or not bool(self.table["feasible"].iloc[0]):
            return None
        return self.table.iloc[0]

    @property
    def found(self) -> bool:
        """True when the best row is feasible."""
        return self.best is not None
