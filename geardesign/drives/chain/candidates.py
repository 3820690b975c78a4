"""The candidates of a chain design: validated inputs, the catalog and reference tables as arrays
(cached by file), every catalog row × small-sprocket teeth, and every margin of each, vectorised."""
from __future__ import annotations

import os
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import Mapping

import numpy as np
import pandas as pd

from .. import sprocket
from ...catalogs.tables import BUNDLED, chain_catalog, load_catalog
from ...errors import GearDesignError
from ...validate import ndim, one_number, require_count, require_int, require_positive, require_range
from .formulas import interp_speed, hinge_pressure_mpa, rated_power_link_plate_kw, rated_power_roller_bushing_kw, recommended_z1, safety_factor


OBJECTIVES = ("min_mass", "min_width", "min_sprocket_diameter", "max_safety")

METHODS = ("hinge_pressure", "power_rating")

FACTOR_NAMES = ("k_d", "k_a", "k_n", "k_reg", "k_lub", "k_mode")

TORQUE_RANGE_NM = (1e-3, 1e7)       # a watch escapement to a mill drive; outside, margins overflow

POWER_RANGE_KW = (1e-6, 1e5)

N1_RANGE_RPM = (0.1, 20_000.0)      # a hand crank to the fastest small-pitch chain (tables stop lower)

RATIO_RANGE = (1.0, 10.0)           # one roller-chain stage; beyond ~7 the small sprocket wraps too little

K_E_RANGE = (0.1, 20.0)             # the product of the operating factors, or one given K_e

FACTOR_RANGE = (0.1, 10.0)          # each operating factor k_d ... k_mode

SAFETY_FACTOR_RANGE = (1.0, 100.0)  # an allowable breaking-load safety factor

SAG_FACTOR_RANGE = (0.0, 10.0)      # k_f of the sag tension (6 horizontal ... 1 vertical)

Z1_RANGE = (7, 200)                 # small sprocket teeth a catalog row may be given

STRANDS_RANGE = (1, 4)

CENTER_DISTANCE_MAX_MM = 1e5        # 100 m: past any roller-chain drive

CENTER_DISTANCE_PITCHES_MAX = 80.0  # longest span a roller chain is laid out for (a <= 80 p; ISO 10823 notes)

Z2_MAX_LIMIT = 250                  # largest sprocket the tooth-count rules are written for


@dataclass(frozen=True)
class Conditions:
    """Operating factors of the hinge-pressure method; K_e is their product.

    k_d dynamic load, k_a centre distance, k_n inclination, k_reg tension adjustment, k_lub
    lubrication, k_mode duty (shifts). Use :meth:`from_mapping` to give factors by the
    condition names of catalogs/chain_operating_factors.csv (``{"k_lub": "irregular"}``).
    """

    k_d: float = 1.0
    k_a: float = 1.0
    k_n: float = 1.0
    k_reg: float = 1.0
    k_lub: float = 1.0
    k_mode: float = 1.0

    def __post_init__(self):
        for name in FACTOR_NAMES:
            require_range(name, getattr(self, name), *FACTOR_RANGE)

    @property
    def k_e(self) -> float:
        return self.k_d * self.k_a * self.k_n * self.k_reg * self.k_lub * self.k_mode

    @classmethod
    def from_mapping(cls, mapping: Mapping) -> "Conditions":
        table = load_catalog("chain_operating_factors")
        values = {}
        for key, value in mapping.items():
            if key not in FACTOR_NAMES:
                raise GearDesignError(f"conditions key must be one of {', '.join(FACTOR_NAMES)}, got {key!r}")
            if isinstance(value, str):
                rows = table[(table["factor"] == key) & (table["condition"] == value)]
                if rows.empty:
                    known = table.loc[table["factor"] == key, "condition"].tolist()
                    raise GearDesignError(f"conditions[{key!r}] must be a number or one of {', '.join(known)}, "
                                          f"got {value!r}")
                values[key] = float(rows["value"].iloc[0])
            else:
                values[key] = one_number(f"conditions[{key!r}]", require_positive(f"conditions[{key!r}]", value))
        return cls(**values)


def _conditions(conditions, k_e):
    if conditions is not None and k_e is not None:
        raise GearDesignError("give either conditions (the named factors) or k_e (their product), not both")
    if conditions is None:
        k = 1.0 if k_e is None else one_number("k_e", require_range("k_e", k_e, *K_E_RANGE))
        return None, k, 1.0
    if isinstance(conditions, Mapping):
        conditions = Conditions.from_mapping(conditions)
    if not isinstance(conditions, Conditions):
        raise GearDesignError(f"conditions must be a Conditions or a mapping of factors, got {type(conditions).__name__}")
    return conditions, conditions.k_e, conditions.k_d


@dataclass(frozen=True)
class Inputs:
    """The inputs of :func:`design` after validation, in the units used inside (power in W)."""

    torque: float                    # N·m on the small sprocket
    power_w: float                   # W
    n1: float                        # rpm of the small sprocket
    u: float                         # speed ratio
    conditions: Conditions | None    # the named factors, when given
    k_e: float                       # product of the operating factors
    k_d: float                       # dynamic factor (1 unless the named factors give it)
    strands: tuple                   # strand counts asked for, in the order given
    allowable_pressure_mpa: float | None
    allowable_safety_factor: float | None
    sag: float                       # k_f of the sag tension
    z2_max: int
    z1_values: np.ndarray            # small-sprocket tooth counts to try (int64)
    z1_given: bool                   # the caller listed z1 (else the z1 rule chose them)
    center_distance_mm: float | None
    center_distance_pitches: float
    objective: str
    method: str
    catalog: object                  # as given: a table name or a path


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


class Candidates:
    """The candidate table under construction: one entry per (chain row, z1) pair.

    ``rows`` indexes the chain table; ``columns`` maps a computed column to its numpy array in
    candidate order. A catalog column is read (as floats) only when a step asks for it, and
    taken in full only when the result table is built.
    """

    def __init__(self, chains: _ChainTable, rows: np.ndarray, z1: np.ndarray, z2: np.ndarray):
        self.chains = chains
        self.rows = rows
        self.columns: dict[str, np.ndarray] = {"z1": z1, "z2": z2}
        self._read: dict[str, np.ndarray] = {}

    def __len__(self) -> int:
        return len(self.rows)

    def __contains__(self, name) -> bool:
        return name in self.columns or name in self.chains.values

    def __getitem__(self, name) -> np.ndarray:
        if name in self.columns:
            return self.columns[name]
        if name not in self._read:
            self._read[name] = self.chains.floats(name)[self.rows]
        return self._read[name]

    def __setitem__(self, name, values) -> None:
        self.columns[name] = values

OBJECTIVE_KEYS = {"min_mass": ("mass_kg_m", True), "min_width": ("width_mm", True),
                   "min_sprocket_diameter": ("sprocket2_tip_diameter_mm", True), "max_safety": ("min_margin", False)}


def validate_inputs(torque_nm, power_kw, n1_rpm, ratio, conditions, k_e, allowable_pressure_mpa,
                     allowable_safety_factor, catalog, strands, z1, center_distance_mm, objective, method,
                     sag_factor, z2_max, center_distance_pitches) -> Inputs:
    """Check every input of :func:`design` against its range and return them as :class:`Inputs`.

    The load is carried as both torque and power (P = T·ω, ω = 2π·n1/60). Without ``z1`` the
    tooth counts tried are the odd ones from 13 to the rule z1 = 29 − 2u (:func:`recommended_z1`).
    Raises GearDesignError naming the input, the value and its range.
    """
    if (torque_nm is None) == (power_kw is None):
        raise GearDesignError("give exactly one of torque_nm or power_kw")
    n1 = one_number("n1_rpm", require_range("n1_rpm", n1_rpm, *N1_RANGE_RPM, unit="rpm"))
    u = one_number("ratio", require_range("ratio", ratio, *RATIO_RANGE))
    omega = 2.0 * np.pi * n1 / 60.0
    if torque_nm is not None:
        torque = one_number("torque_nm", require_range("torque_nm", torque_nm, *TORQUE_RANGE_NM, unit="N·m"))
        power_w = torque * omega
    else:
        power_w = one_number("power_kw", require_range("power_kw", power_kw, *POWER_RANGE_KW, unit="kW")) * 1000.0
        torque = power_w / omega
    if objective not in OBJECTIVES:
        raise GearDesignError(f"objective must be one of {', '.join(OBJECTIVES)}, got {objective!r}")
    if method not in METHODS:
        raise GearDesignError(f"method must be one of {', '.join(METHODS)}, got {method!r}")
    cond, k_e_val, k_d = _conditions(conditions, k_e)
    if ndim(strands) < 0 or isinstance(strands, (str, bytes)):
        raise GearDesignError(f"strands must be whole numbers in [1, 4], got {strands!r}")
    strands_t = tuple(int(s) for s in np.atleast_1d(require_int("strands", strands, *STRANDS_RANGE)).ravel())
    if not strands_t or max(strands_t) > 4:
        raise GearDesignError(f"strands must be whole numbers in [1, 4], got {strands!r}")
    if allowable_pressure_mpa is not None:
        allowable_pressure_mpa = one_number("allowable_pressure_mpa", require_positive(
            "allowable_pressure_mpa", allowable_pressure_mpa, "MPa"))
    if allowable_safety_factor is not None:
        allowable_safety_factor = one_number("allowable_safety_factor", require_range(
            "allowable_safety_factor", allowable_safety_factor, *SAFETY_FACTOR_RANGE))
    sag = one_number("sag_factor", require_range("sag_factor", sag_factor, *SAG_FACTOR_RANGE))
    z2_max = require_count("z2_max", z2_max, 9, Z2_MAX_LIMIT)
    if z1 is None:
        # odd counts from 13 up to the rule z1 = 29 − 2u; at u > 8 the rule falls below 13,
        # the smallest small sprocket of the tables, which is then the only candidate
        z1_values = np.arange(13, max(recommended_z1(u), 13) + 1, 2, dtype=np.int64)
        if round(u * 13) > z2_max:
            raise GearDesignError(
                f"ratio = {u:g} needs z2 = {round(u * 13)} teeth on the smallest small sprocket (z1 = 13), above "
                f"z2_max = {z2_max}; the ratio can be at most {z2_max / 13:.4g} here (raise z2_max or split the ratio)")
    else:
        z1_values = np.atleast_1d(require_int("z1", z1, *Z1_RANGE)).astype(np.int64)
        if z1_values.size == 0 or z1_values.size > 100:
            raise GearDesignError(f"z1 must list 1 to 100 tooth counts, got {z1_values.size}")
        z2_given = np.round(u * z1_values)
        if (z2_given > z2_max).any():
            raise GearDesignError(
                f"z1 = {int(z1_values[np.argmax(z2_given > z2_max)])} with ratio {u:g} needs "
                f"z2 = {int(z2_given.max())} teeth, above z2_max = {z2_max}; choose a smaller z1")
    if center_distance_mm is not None:
        center_distance_mm = one_number("center_distance_mm", require_range(
            "center_distance_mm", center_distance_mm, 0.0, CENTER_DISTANCE_MAX_MM, lo_open=True, unit="mm"))
    cpitches = one_number("center_distance_pitches", require_range(
        "center_distance_pitches", center_distance_pitches, 10.0, 100.0))
    return Inputs(torque=torque, power_w=power_w, n1=n1, u=u, conditions=cond, k_e=k_e_val, k_d=k_d,
                   strands=strands_t, allowable_pressure_mpa=allowable_pressure_mpa,
                   allowable_safety_factor=allowable_safety_factor, sag=sag, z2_max=z2_max, z1_values=z1_values,
                   z1_given=z1 is not None, center_distance_mm=center_distance_mm,
                   center_distance_pitches=cpitches, objective=objective, method=method, catalog=catalog)

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


def with_loads(inp: Inputs, n1_rpm, torque_nm) -> Inputs:
    """``inp`` with one load per candidate: arrays of small-sprocket speed [rpm] and torque [N·m]
    (power P = T·ω follows), for :func:`evaluate` on candidates built by the caller."""
    from dataclasses import replace

    n1 = np.asarray(n1_rpm, dtype=float)
    torque = np.asarray(torque_nm, dtype=float)
    return replace(inp, n1=n1, torque=torque, power_w=torque * 2.0 * np.pi * n1 / 60.0)


def reference_tables(folder) -> ReferenceTables:
    """The speed-limit, strand-factor, [s] and [p] tables as arrays, read once per file version."""
    keys = tuple(_file_key(name, folder) for name in _REFERENCE_NAMES)
    if any(k is None for k in keys):
        return _cached_reference_tables.__wrapped__(keys)
    return _cached_reference_tables(keys)


def candidate_table(chains: _ChainTable, inp: Inputs) -> Candidates:
    """Every chain row of the asked strand counts times every z1, z2 = round(u·z1) <= z2_max.

    Rows vary slowest (the catalog's order), z1 fastest; built with np.repeat / np.tile.
    """
    rows = np.flatnonzero(np.isin(chains.strands, inp.strands))
    nz = len(inp.z1_values)
    rows = np.repeat(rows, nz)
    z1 = np.tile(inp.z1_values, len(rows) // nz)
    z2 = np.round(inp.u * z1).astype(np.int64)
    keep = z2 <= inp.z2_max
    if not keep.any():
        raise GearDesignError(f"no small sprocket z1 in {[int(z) for z in inp.z1_values]} keeps z2 = u·z1 <= "
                              f"z2_max = {inp.z2_max} at ratio {inp.u:g}")
    return Candidates(chains, rows[keep], z1[keep], z2[keep])


def _layout(c: Candidates, inp: Inputs) -> None:
    """Chain speed, pull, loop and sprocket geometry of every candidate (formulas in :mod:`.sprocket`).

    v = z1·t·n1/60 000, F_t = P/v; the loop is laid out at the asked centre distance (default
    ``center_distance_pitches``·t) where the sprockets clear each other, 0.5·(D_e1 + D_e2) + 30 mm,
    and the span is at most 80 pitches (ISO 10823 notes); otherwise at the nearest such distance,
    and the candidate fails the center_distance check by the shortfall or the excess. The link
    count is the nearest even number and the centre distance is exact for it. The chain width
    is the inner width A/d_pin plus (strands − 1) transverse pitches.
    """
    t, z1a, z2a = c["pitch_mm"], c["z1"].astype(float), c["z2"].astype(float)
    m = c["strands"]
    v = sprocket.chain_speed_m_s(z1a, t, inp.n1)
    de1 = sprocket.tip_diameter_mm(t, z1a)
    de2 = sprocket.tip_diameter_mm(t, z2a)
    clearance = 0.5 * (de1 + de2) + 30.0
    given = inp.center_distance_mm is not None
    a_asked = np.full(t.shape, inp.center_distance_mm) if given else inp.center_distance_pitches * t
    a_span_max = CENTER_DISTANCE_PITCHES_MAX * t
    a0 = np.clip(a_asked, clearance, np.maximum(a_span_max, clearance)) if given else np.maximum(a_asked, clearance)
    links = sprocket.even_links(sprocket.link_count(a0, t, z1a, z2a))
    roller = c["roller_d1_mm"]
    c["speed_m_s"] = v
    c["force_n"] = inp.power_w / v
    c["links"] = links
    c["center_distance_mm"] = sprocket.center_distance_for_links_mm(links, t, z1a, z2a)
    c["sprocket1_pitch_diameter_mm"] = sprocket.pitch_diameter_mm(t, z1a)
    c["sprocket1_tip_diameter_mm"] = de1
    c["sprocket1_root_diameter_mm"] = sprocket.root_diameter_mm(t, z1a, roller)
    c["sprocket2_pitch_diameter_mm"] = sprocket.pitch_diameter_mm(t, z2a)
    c["sprocket2_tip_diameter_mm"] = de2
    c["sprocket2_root_diameter_mm"] = sprocket.root_diameter_mm(t, z2a, roller)
    c["width_mm"] = c["hinge_area_mm2"] / c["pin_d_mm"] + (m - 1) * np.nan_to_num(c["transverse_pitch_mm"])
    c["chain_mass_kg"] = c["mass_kg_m"] * links * t / 1000.0
    c["impacts_per_s"] = sprocket.impacts_per_second(z1a, inp.n1, links)
    c["breaking_load_n"] = c["breaking_load_kn"] * 1000.0
    if given:
        c["margin_center_distance"] = np.minimum(a_asked / clearance, a_span_max / a_asked) - 1.0


def _lookup_by_pitch(pitches: np.ndarray, match: np.ndarray, table_n: np.ndarray, table_y: np.ndarray, n1: float):
    """Interpolate a table along n1 for each distinct pitch; returns (values, status) per candidate.

    ``match[i, j]`` says whether table row j belongs to the i-th distinct pitch (np.unique
    order). Status as in :func:`interp_speed`; 2 where no row matches (value NaN).
    """
    _, inverse = np.unique(pitches, return_inverse=True)
    if np.ndim(n1):
        return _lookup_per_candidate(inverse, match, table_n, table_y, np.asarray(n1, dtype=float))
    values = np.full(len(match), np.nan)
    status = np.full(len(match), 2, dtype=np.int64)
    for i in np.flatnonzero(match.any(axis=1)):
        rows = match[i]
        values[i], status[i] = interp_speed(table_n[rows], table_y[rows], n1)
    return values[inverse], status[inverse]


def _lookup_per_candidate(inverse, match, table_n, table_y, n1):
    """:func:`_lookup_by_pitch` when each candidate has its own speed n1 (same rule as
    :func:`interp_speed`: the first value below the table with status -1, NaN above it with 1)."""
    values = np.full(len(n1), np.nan)
    status = np.full(len(n1), 2, dtype=np.int64)
    for i in np.flatnonzero(match.any(axis=1)):
        mine = inverse == i
        tn, ty, n = table_n[match[i]], table_y[match[i]], n1[mine]
        below, above = n < tn[0], n > tn[-1]
        values[mine] = np.where(below, ty[0], np.where(above, np.nan, np.interp(n, tn, ty)))
        status[mine] = np.where(below, -1, np.where(above, 1, 0))
    return values, status


def _pressure_groups(unique_pitches, pitch_min, pitch_max, tol=1e-6):
    """match[i, j]: the i-th pitch lies in the j-th row's pitch group of the [p] table."""
    p = unique_pitches[:, None]
    return (pitch_min[None, :] - tol <= p) & (p <= pitch_max[None, :] + tol)


def _speed_limits(c: Candidates, inp: Inputs, tables: ReferenceTables) -> None:
    """Maximum small-sprocket speed n1_max and allowed impacts per second [w] of each pitch.

    A pitch matches a table row within np.isclose (atol 1e-6 mm); a pitch without a row gets
    NaN (the check then has no table data). Source: catalogs/chain_speed_limits.csv.
    Raises GearDesignError (hinge-pressure method) when n1 is above the limit of every pitch.
    """
    t = c["pitch_mm"]
    unique, inverse = np.unique(t, return_inverse=True)
    close = np.isclose(tables.speed_pitch_mm[None, :], unique[:, None], atol=1e-6)
    match = np.where(close.any(axis=1), close.argmax(axis=1), -1)
    n_max_u = np.where(match >= 0, tables.n1_max_rpm[match], np.nan)
    w_max_u = np.where(match >= 0, tables.impacts_allowed_per_s[match], np.nan)
    if (inp.method == "hinge_pressure" and np.ndim(inp.n1) == 0 and np.isfinite(n_max_u).any()
            and inp.n1 > np.nanmax(n_max_u)):
        j = int(np.nanargmax(n_max_u))
        raise GearDesignError(
            f"n1_rpm = {inp.n1:g} rpm is above the maximum speed of every chain in {str(inp.catalog)!r} "
            f"(the fastest, pitch {unique[j]:g} mm, allows {n_max_u[j]:g} rpm); use a belt or gear stage first")
    c["n1_max_rpm"] = n_max_u[inverse]
    c["allowable_impacts_per_s"] = w_max_u[inverse]


def _safety_check(c: Candidates, inp: Inputs, tables: ReferenceTables, notes: list) -> None:
    """Breaking-load safety s (:func:`safety_factor`) against [s]: margin s/[s] − 1.

    [s] is the override or the catalogs/chain_safety_factor.csv value of the pitch,
    interpolated linearly along n1 (its lowest-speed column below the table, with a note).
    """
    c["safety_factor"] = safety_factor(c["breaking_load_n"], c["force_n"], inp.k_d, c["mass_kg_m"],
                                       c["speed_m_s"], c["center_distance_mm"], inp.sag)
    t = c["pitch_mm"]
    if inp.allowable_safety_factor is not None:
        s_allow = np.full(t.shape, inp.allowable_safety_factor)
    else:
        pitch, n1_rpm, value = tables.safety
        match = np.isclose(pitch[None, :], np.unique(t)[:, None], rtol=0, atol=1e-6)
        s_allow, s_status = _lookup_by_pitch(t, match, n1_rpm, value, inp.n1)
        if (s_status == -1).any():
            notes.append(f"n1 = {_speed_text(inp.n1)} rpm is below the [s] table: its lowest-speed column is used")
    c["allowable_safety_factor"] = s_allow
    c["margin_safety"] = c["safety_factor"] / s_allow - 1.0


def _hinge_checks(c: Candidates, inp: Inputs, tables: ReferenceTables, notes: list) -> list:
    """Hinge-pressure method: p = F_t·K_e/(A·m_eff) against [p], n1 against n1_max, w against [w].

    Margins 1 − p/[p], 1 − n1/n1_max, 1 − w/[w] (Chernavsky, course design of machine parts).
    m_eff = strands·K_m from catalogs/chain_strand_factors.csv; [p] is the override or
    catalogs/chain_allowable_pressure.csv interpolated along n1, never extrapolated above the
    table (NaN: the check has no data). Returns the names of the checks that decide feasibility.
    """
    t = c["pitch_mm"]
    m_eff = tables.hinge_strand_factor[strand_index(tables, c["strands"])]
    p = hinge_pressure_mpa(c["force_n"], inp.k_e, c["hinge_area_mm2"], m_eff)
    if inp.allowable_pressure_mpa is not None:
        p_allow = np.full(t.shape, inp.allowable_pressure_mpa)
    else:
        lo, hi, n1_rpm, value = tables.pressure
        p_allow, p_status = _lookup_by_pitch(t, _pressure_groups(np.unique(t), lo, hi), n1_rpm, value, inp.n1)
        if (p_status == -1).any():
            notes.append(f"n1 = {_speed_text(inp.n1)} rpm is below the [p] table (50 rpm): the 50 rpm value is used "
                         "(conservative: [p] falls with speed)")
        if (p_status == 1).any():
            notes.append(f"n1 = {_speed_text(inp.n1)} rpm is above the [p] table for some pitches: no extrapolation, "
                         "those candidates fail with 'pressure (no [p] data)'")
    c["strand_factor"] = m_eff
    c["pressure_mpa"] = p
    c["allowable_pressure_mpa"] = p_allow
    c["margin_pressure"] = 1.0 - p / p_allow
    c["margin_speed"] = 1.0 - inp.n1 / c["n1_max_rpm"]
    c["margin_impacts"] = 1.0 - c["impacts_per_s"] / c["allowable_impacts_per_s"]
    return ["margin_pressure", "margin_safety", "margin_speed", "margin_impacts"]


def _power_checks(c: Candidates, inp: Inputs, tables: ReferenceTables, notes: list) -> list:
    """Power-rating method: rated power of the strands against the design power P·K_e.

    Rated power = min(link-plate, roller-bushing rating) of one strand (ANSI B29.1 formulas,
    :func:`rated_power_link_plate_kw`, :func:`rated_power_roller_bushing_kw`; K from the
    catalog's rating_k_plate / rating_k_roller columns, else 0.004 and 17) times the
    multiple-strand factor of catalogs/chain_strand_factors.csv; margin P_rated/P_design − 1.
    The hinge pressure is reported at K_e = 1 and not checked. Returns the check names.
    """
    t, z1a = c["pitch_mm"], c["z1"].astype(float)
    k_pl = c["rating_k_plate"] if "rating_k_plate" in c else np.full(t.shape, 0.004)
    k_rb = c["rating_k_roller"] if "rating_k_roller" in c else np.full(t.shape, 17.0)
    m_pow = tables.power_strand_factor[strand_index(tables, c["strands"])]
    plate = rated_power_link_plate_kw(z1a, inp.n1, t, k_pl)
    roller = rated_power_roller_bushing_kw(z1a, inp.n1, t, k_rb)
    c["strand_factor"] = m_pow
    c["rated_power_kw"] = np.minimum(plate, roller) * m_pow
    c["rating_limit"] = np.where(plate <= roller, "link_plate", "roller_bushing")
    c["design_power_kw"] = np.full(t.shape, inp.power_w / 1000.0 * inp.k_e)
    c["margin_power"] = c["rated_power_kw"] / c["design_power_kw"] - 1.0
    c["pressure_mpa"] = hinge_pressure_mpa(c["force_n"], 1.0, c["hinge_area_mm2"], m_pow)
    c["allowable_pressure_mpa"] = np.full(t.shape, np.nan)
    if not str(inp.catalog).startswith("ansi") and not str(inp.catalog).startswith("iso606a"):
        notes.append("power ratings use the ANSI B29.1 formulas; for chains that are not ANSI/ISO A series "
                     "they are an approximation")
    return ["margin_power"]


def _speed_text(n1) -> str:
    """n1 for a note: the one speed, or the range when each candidate has its own."""
    return f"{n1:g}" if np.ndim(n1) == 0 else f"{np.min(n1):g}…{np.max(n1):g}"


def strand_index(tables: ReferenceTables, strands: np.ndarray) -> np.ndarray:
    """Row of the strand-factor table for each strand count (KeyError for a count it lacks)."""
    idx = np.searchsorted(tables.strands, strands)
    ok = idx < len(tables.strands)
    ok[ok] = tables.strands[idx[ok]] == strands[ok]
    if not ok.all():
        raise KeyError(f"strands {sorted(set(strands[~ok].tolist()))} not in chain_strand_factors")
    return idx


def _limiting_check(c: Candidates, checks: list) -> None:
    """The smallest margin of each candidate, the check it belongs to, and feasibility.

    A check without table data (NaN margin) cannot pass but is named as limiting only when
    every check that has data holds; a candidate is feasible when every margin is >= 0.
    """
    margins = np.column_stack([np.asarray(c[k], dtype=float) for k in checks])
    no_data = np.isnan(margins)
    rows = np.arange(len(c))
    worst = np.argmin(np.where(no_data, np.inf, margins), axis=1)
    min_margin = np.where(no_data.all(axis=1), np.nan, margins[rows, np.minimum(worst, len(checks) - 1)])
    names = np.array([k[len("margin_"):] for k in checks], dtype=object)
    missing = np.argmax(no_data, axis=1)
    show_missing = no_data.any(axis=1) & ~(min_margin < 0)
    c["min_margin"] = min_margin
    c["limiting_check"] = np.where(show_missing, names[missing] + " (no table data)", names[worst])
    c["feasible"] = ~no_data.any(axis=1) & (min_margin >= 0)


def evaluate(c: Candidates, inp: Inputs, tables: ReferenceTables, summary: bool = True) -> tuple[list, list]:
    """Every check of every candidate, vectorised: layout, speed limits, safety, the method's checks.

    ``inp.n1``, ``inp.power_w`` and ``inp.torque`` are one load for all candidates (:func:`design`)
    or arrays aligned with them (a drive, where each candidate's load follows the ratio split
    upstream; see :func:`with_loads`): the same formulas either way, and a speed above every
    chain's limit then fails the speed check of those candidates instead of stopping the design.
    ``summary=False`` leaves out min_margin, limiting_check and feasible (a caller that combines
    the margins with its own checks computes them itself).

    Returns (checks, notes): the margin columns that decide feasibility, in report order, and
    the notes about table ranges.
    """
    notes: list[str] = []
    _layout(c, inp)
    _speed_limits(c, inp, tables)
    _safety_check(c, inp, tables, notes)
    cd_check = ["margin_center_distance"] if inp.center_distance_mm is not None else []
    if inp.method == "hinge_pressure":
        checks = _hinge_checks(c, inp, tables, notes) + cd_check
    else:
        checks = (_power_checks(c, inp, tables, notes) + cd_check
                  + (["margin_safety"] if inp.allowable_safety_factor is not None else []))
    if summary:
        _limiting_check(c, checks)
    return checks, notes
