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

import json
import math
from dataclasses import fields

import numpy as np

__all__ = ["Result", "RankedTable", "plain"]


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
