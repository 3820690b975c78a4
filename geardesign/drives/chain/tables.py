"""The chain catalog and the reference tables as read-only arrays, cached per file version."""
from __future__ import annotations

import os
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import numpy as np

from ...catalogs.tables import BUNDLED, chain_catalog, load_catalog
from ...errors import GearDesignError
from .inputs import Inputs

from typing import TYPE_CHECKING

if TYPE_CHECKING:       # pandas is imported where a table is made (start-up cost)
    import pandas as pd


@dataclass(frozen=True)
class ReferenceTables:
    """The tables every design reads besides the chain catalog, as read-only numpy arrays.

    Sources: catalogs/chain_speed_limits.csv, chain_strand_factors.csv, chain_safety_factor.csv
    and chain_allowable_pressure.csv (see their ``source`` columns).
    """

    speed_pitch_mm: np.ndarray
    n1_max_rpm: np.ndarray
    impacts_allowed_per_s: np.ndarray
    strands: np.ndarray
    hinge_strand_factor: np.ndarray
    power_strand_factor: np.ndarray
    safety: tuple      # (pitch_mm, n1_rpm, allowable_safety_factor)
    pressure: tuple    # (pitch_min_mm, pitch_max_mm, n1_rpm, allowable_pressure_mpa)


class _ChainTable:
    """A validated chain catalog as :func:`~geardesign.catalogs.tables.chain_catalog` returns it
    (sorted by pitch and strands), its columns read out once: ``values`` holds each column's
    numpy or extension array, :meth:`floats` a column as float64 (read on first use). Kept
    between calls, so every array in it is read-only.
    """

    def __init__(self, frame: pd.DataFrame):
        self.attrs = dict(frame.attrs)
        self.columns = list(frame.columns)
        self.values = {}
        for name in self.columns:
            col = frame[name]
            self.values[name] = _read_only(col.to_numpy()) if isinstance(col.dtype, np.dtype) else col.array
        self.strands = self.values["strands"]
        self._frame = frame
        self._floats: dict[str, np.ndarray] = {}

    def floats(self, name: str) -> np.ndarray:
        if name not in self._floats:
            self._floats[name] = _read_only(self._frame[name].to_numpy(dtype=float))
        return self._floats[name]

    def take(self, name: str, rows: np.ndarray):
        """Column ``name`` at ``rows``, in the column's own dtype."""
        col = self.values[name]
        return col[rows] if isinstance(col, np.ndarray) else col.take(rows)


def _read_only(a: np.ndarray) -> np.ndarray:
    """A read-only copy of ``a`` (arrays kept between calls must not be changed by one)."""
    a = np.array(a, copy=True)
    a.flags.writeable = False
    return a


_TABLE_CACHE_SIZE = 32


def _file_key(name_or_path, folder):
    """What identifies the file behind a table name or CSV path: (name, path, mtime, size).

    None when there is no plain file to stat (a zipped package, a missing file, an argument
    :func:`~geardesign.catalogs.tables.load_catalog` refuses): such tables are not cached, and
    loading them raises the catalog's own error.
    """
    if isinstance(name_or_path, str) and name_or_path in BUNDLED:
        path = folder / BUNDLED[name_or_path][0]
    elif isinstance(name_or_path, (str, Path)):
        path = Path(name_or_path)
    else:
        return None
    if not isinstance(path, Path):
        return None
    try:
        st = path.stat()
    except (OSError, ValueError):
        return None
    return (type(name_or_path).__name__, str(name_or_path), os.path.abspath(path), st.st_mtime_ns, st.st_size)


@lru_cache(maxsize=_TABLE_CACHE_SIZE)
def _cached_chain_table(key, name_or_path) -> _ChainTable:
    """The chain table of ``name_or_path``, kept per :func:`_file_key` ``key``."""
    return _ChainTable(chain_catalog(name_or_path))


def load_chains(inp: Inputs, folder) -> _ChainTable:
    """The validated chain catalog (:func:`~geardesign.catalogs.tables.chain_catalog`), read once.

    Kept (like the catalog loader's own cache) per file, modification time and size, so an
    edited CSV is read again. Raises GearDesignError when no row has an asked strand count.
    """
    key = _file_key(inp.catalog, folder)
    chains = (_ChainTable(chain_catalog(inp.catalog)) if key is None
              else _cached_chain_table(key, inp.catalog))
    if not np.isin(chains.strands, inp.strands).any():
        raise GearDesignError(f"catalog {str(inp.catalog)!r} has no chain with strands in {inp.strands}")
    return chains

_REFERENCE_NAMES = ("chain_speed_limits", "chain_strand_factors", "chain_safety_factor", "chain_allowable_pressure")


@lru_cache(maxsize=_TABLE_CACHE_SIZE)
def _cached_reference_tables(keys) -> ReferenceTables:
    """The four reference tables as arrays, kept per the :func:`_file_key` ``keys`` of their files."""
    speed, strand, safety, pressure = (load_catalog(name) for name in _REFERENCE_NAMES)

    def cols(frame, *names):
        return tuple(_read_only(frame[n].to_numpy(dtype=float)) for n in names)

    return ReferenceTables(*cols(speed, "pitch_mm", "n1_max_rpm", "impacts_allowed_per_s"),
                            _read_only(strand["strands"].to_numpy()),
                            *cols(strand, "hinge_strand_factor", "power_strand_factor"),
                            safety=cols(safety, "pitch_mm", "n1_rpm", "allowable_safety_factor"),
                            pressure=cols(pressure, "pitch_min_mm", "pitch_max_mm", "n1_rpm", "allowable_pressure_mpa"))


def reference_tables(folder) -> ReferenceTables:
    """The speed-limit, strand-factor, [s] and [p] tables as arrays, read once per file version."""
    keys = tuple(_file_key(name, folder) for name in _REFERENCE_NAMES)
    if any(k is None for k in keys):
        return _cached_reference_tables.__wrapped__(keys)
    return _cached_reference_tables(keys)


def strand_index(tables: ReferenceTables, strands: np.ndarray) -> np.ndarray:
    """Row of the strand-factor table for each strand count (KeyError for a count it lacks)."""
    idx = np.searchsorted(tables.strands, strands)
    ok = idx < len(tables.strands)
    ok[ok] = tables.strands[idx[ok]] == strands[ok]
    if not ok.all():
        raise KeyError(f"strands {sorted(set(strands[~ok].tolist()))} not in chain_strand_factors")
    return idx
