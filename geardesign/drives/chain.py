"""Roller-chain drive design from standard catalogs.

:func:`design` enumerates every candidate — each catalog row (a chain with its strand count)
times each small-sprocket tooth count — evaluates all checks in one vectorised pass and ranks
the candidates for an objective. It is a recipe of small steps (validate the inputs, build the
candidate table, evaluate every margin, rank, wrap the result in a :class:`ChainDesign`), each
working on numpy arrays. Every check is a signed dimensionless margin (>= 0 holds):

- hinge pressure ``1 - p/[p]`` with p = F_t·K_e / (A·m_eff) (hinge-pressure method);
- breaking-load safety ``s/[s] - 1`` with s = Q / (K_d·F_t + F_v + F_f);
- speed ``1 - n1/n1_max`` and impacts per second ``1 - w/[w]`` (hinge-pressure method);
- rated power ``P_rated/P_design - 1`` (power-rating method, ISO 606 / ANSI chains).

Units at the interface: torque N·m, power kW, speed rpm, lengths mm, forces N, pressure MPa.
Inside, powers are in W and chain speeds in m/s.
"""
from __future__ import annotations

import os
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Mapping

import numpy as np
import pandas as pd

from . import sprocket
from ..catalogs.tables import BUNDLED, catalog_dir, chain_catalog, load_catalog
from ..errors import GearDesignError
from ..results import Result, plain
from ..validate import ndim, one_number, require_count, require_int, require_positive, require_range

__all__ = [
    "Conditions",
    "ChainDesign",
    "design",
    "recommended_z1",
    "pitch_estimate_mm",
    "hinge_pressure_mpa",
    "safety_factor",
    "rated_power_link_plate_kw",
    "rated_power_roller_bushing_kw",
    "allowable_pressure_mpa",
    "OBJECTIVES",
    "METHODS",
]

OBJECTIVES = ("min_mass", "min_width", "min_sprocket_diameter", "max_safety")
METHODS = ("hinge_pressure", "power_rating")
HP_TO_KW = 0.745699872  # 1 mechanical horsepower in kW
IN_MM = 25.4
G = 9.81  # m/s²

FACTOR_NAMES = ("k_d", "k_a", "k_n", "k_reg", "k_lub", "k_mode")


# --------------------------------------------------------------------------------------------
# Formulas
# --------------------------------------------------------------------------------------------

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


def recommended_z1(ratio):
    """Small-sprocket teeth from the rule z1 = 29 − 2u, rounded to odd, bounded to [13, 29].

    Source: Russian course-design practice (Chernavsky, course design of machine parts, chain
    drives; docs/references.md): odd tooth counts spread the wear with an even number of links.

    >>> recommended_z1(1), recommended_z1(3), recommended_z1(8)
    (27, 23, 13)
    """
    u = float(ratio)
    z = 29.0 - 2.0 * u
    odd = 2 * np.floor(z / 2.0) + 1  # the nearest odd number (an even z rounds up)
    return int(np.clip(odd, 13, 29))


def pitch_estimate_mm(torque_nm, z1, allowable_pressure_mpa, k_e=1.0, strand_factor=1.0):
    """Classic starting estimate of the pitch, t >= 2.8·(T1·K_e / (z1·[p]·m))^(1/3) [mm].

    T1 in N·mm inside the root (the argument is N·m); m = strands·K_m is the effective strand
    factor (1, 1.7, 2.5, 3). It follows from p = F_t·K_e/A with A ≈ 0.28·t² per strand and
    F_t = 2T/d, d ≈ z·t/π. Source: Chernavsky, course design of machine parts; seed 002 1.9.5.

    >>> round(float(pitch_estimate_mm(380, 13, 29, 2.1484, 1.0)), 2)  # seed 002: 36.23 mm
    36.23
    >>> round(float(pitch_estimate_mm(380, 13, 29, 2.1484, 2 * 0.85)), 2)  # seed 002: 30.35 mm
    30.35
    """
    t_nmm = np.asarray(torque_nm, dtype=float) * 1000.0
    return 2.8 * np.cbrt(t_nmm * k_e / (np.asarray(z1, dtype=float) * allowable_pressure_mpa * strand_factor))


def hinge_pressure_mpa(force_n, k_e, hinge_area_mm2, strand_factor):
    """Hinge (pin-bushing) pressure p = F_t·K_e / (A·m_eff) [MPa].

    A is the projected bearing area of one strand (pin diameter × inner-link width) in mm²,
    m_eff = strands·K_m. Source: Chernavsky, course design of machine parts (chain check
    p <= [p]); GOST 13568-75 gives A.

    >>> round(float(hinge_pressure_mpa(5785.0, 2.148, 260.0, 1.7)), 2)
    28.11
    """
    return np.asarray(force_n, dtype=float) * k_e / (np.asarray(hinge_area_mm2, dtype=float) * strand_factor)


def safety_factor(breaking_load_n, force_n, k_d, mass_kg_m, speed_m_s, center_distance_mm, sag_factor=6.0):
    """Breaking-load safety factor s = Q / (K_d·F_t + F_v + F_f).

    F_v = q·v² (centrifugal tension), F_f = 9.81·k_f·q·a (sag tension, a in m; k_f = 6 for a
    horizontal drive, 1.5 at 40°, 1 vertical). Source: Chernavsky, course design of machine
    parts; Ivanov, Machine parts (chain drives).

    Bhandari Ex. 14.1 uses s = Q/F_t alone (no K_d, no F_v, no F_f): 31 100 N over the tension
    that carries 14.32 kW at 5.3975 m/s gives 11.722:

    >>> round(float(safety_factor(31100, 14320 / 5.3975, 1.0, 0.0, 5.3975, 0.0)), 4)
    11.7222
    """
    q = np.asarray(mass_kg_m, dtype=float)
    v = np.asarray(speed_m_s, dtype=float)
    f_v = q * v * v
    f_f = G * sag_factor * q * np.asarray(center_distance_mm, dtype=float) / 1000.0
    return np.asarray(breaking_load_n, dtype=float) / (k_d * np.asarray(force_n, dtype=float) + f_v + f_f)


def rated_power_link_plate_kw(z1, n1_rpm, pitch_mm, k_plate=0.004):
    """Link-plate fatigue rating of one strand, ANSI: HP = K·N^1.08·n^0.9·p^(3.0 − 0.07p) [kW].

    N small-sprocket teeth, n its rpm, p the pitch in inches; K = 0.004 (0.0022 for No. 41).
    Source: ANSI/ASME B29.1 horsepower formulas as printed in roller-chain catalogue pages
    (docs/references.md).

    >>> hp = 0.004 * 17**1.08 * 1400**0.9 * 0.5**(3.0 - 0.07 * 0.5)
    >>> round(float(rated_power_link_plate_kw(17, 1400, 12.7)) / 0.745699872 - hp, 12)
    0.0
    """
    p_in = np.asarray(pitch_mm, dtype=float) / IN_MM
    hp = (np.asarray(k_plate, dtype=float) * np.asarray(z1, dtype=float) ** 1.08
          * np.asarray(n1_rpm, dtype=float) ** 0.9 * p_in ** (3.0 - 0.07 * p_in))
    return hp * HP_TO_KW


def rated_power_roller_bushing_kw(z1, n1_rpm, pitch_mm, k_roller=17.0):
    """Roller-bushing impact rating of one strand, ANSI: HP = 1000·K·N^1.5·p^0.8 / n^1.5 [kW].

    K = 29 for No. 25 and 35, 3.4 for No. 41, 17 for No. 40-240. Same source as
    :func:`rated_power_link_plate_kw`.
    """
    p_in = np.asarray(pitch_mm, dtype=float) / IN_MM
    hp = (1000.0 * np.asarray(k_roller, dtype=float) * np.asarray(z1, dtype=float) ** 1.5 * p_in ** 0.8
          / np.asarray(n1_rpm, dtype=float) ** 1.5)
    return hp * HP_TO_KW


def _interp_speed(values_n, values_y, n1):
    """Interpolate a table row y(n1) linearly; return (value, status).

    status 0: inside the table; -1: below its first speed (the first value is returned: the
    allowable values fall, and [s] rises, with speed, so the first column is the conservative
    one for [p] and is flagged); +1: above its last speed (NaN: no silent extrapolation).
    """
    if n1 < values_n[0]:
        return float(values_y[0]), -1
    if n1 > values_n[-1]:
        return float("nan"), 1
    return float(np.interp(n1, values_n, values_y)), 0


def allowable_pressure_mpa(pitch_mm, n1_rpm, table: pd.DataFrame | None = None):
    """Allowable hinge pressure [p] for a pitch at small-sprocket speed n1 [MPa], with status.

    Linear interpolation between the table's speeds. Returns ``(value, status)`` with status
    as in :func:`_interp_speed`; a pitch outside every group gives (NaN, 2).
    Source: catalogs/chain_allowable_pressure.csv (Chernavsky/Sheinblit layout, z1 = 17 basis).

    >>> allowable_pressure_mpa(31.75, 200)
    (29.0, 0)
    >>> allowable_pressure_mpa(31.75, 125)  # halfway between 35 MPa (50 rpm) and 29 MPa (200 rpm)
    (32.0, 0)
    """
    table = load_catalog("chain_allowable_pressure") if table is None else table
    tol = 1e-6
    rows = table[(table["pitch_min_mm"] - tol <= pitch_mm) & (pitch_mm <= table["pitch_max_mm"] + tol)]
    if rows.empty:
        return float("nan"), 2
    return _interp_speed(rows["n1_rpm"].to_numpy(), rows["allowable_pressure_mpa"].to_numpy(), n1_rpm)


# --------------------------------------------------------------------------------------------
# Inputs
# --------------------------------------------------------------------------------------------

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


# --------------------------------------------------------------------------------------------
# Result
# --------------------------------------------------------------------------------------------

@dataclass(frozen=True, eq=False)
class ChainDesign(Result):
    """Result of :func:`design`: every candidate ranked, the best feasible one, and why.

    Attributes
    ----------
    candidates : DataFrame, ranked (feasible first, then by the objective).
    best : Series or None, the top feasible candidate.
    success : bool; message : str.
    blocking : DataFrame, per chain family (designation) the candidate closest to passing, its
        limiting check and margin — filled whenever no candidate passes, and always available.
    pitch_estimate_mm : dict strands -> classic pitch estimate (hinge method), a starting point.
    """

    candidates: pd.DataFrame
    best: pd.Series | None
    success: bool
    message: str
    method: str
    objective: str
    catalog: str
    k_e: float
    inputs: dict
    pitch_estimate_mm: dict
    blocking: pd.DataFrame
    notes: tuple = field(default_factory=tuple)

    _table_fields = ("candidates",)

    def to_dict(self) -> dict:
        return plain({
            "status": self.status,
            "success": self.success,
            "message": self.message,
            "method": self.method,
            "objective": self.objective,
            "catalog": self.catalog,
            "k_e": self.k_e,
            "inputs": self.inputs,
            "pitch_estimate_mm": self.pitch_estimate_mm,
            "best": None if self.best is None else dict(self.best.items()),
            "blocking": self.blocking,
            "notes": list(self.notes),
            "n_candidates": int(len(self.candidates)),
            "n_feasible": int(self.candidates["feasible"].sum()),
        })

    def __repr__(self) -> str:
        lines = [f"ChainDesign({self.method}, objective={self.objective}, catalog={self.catalog}, "
                 f"K_e={self.k_e:.4g}): {self.message}"]
        if self.pitch_estimate_mm:
            est = ", ".join(f"{k} strand{'s' if k > 1 else ''}: {v:.2f} mm" for k, v in self.pitch_estimate_mm.items())
            lines.append(f"  pitch estimate t >= {est}")
        if self.best is not None:
            b = self.best
            lines.append(
                f"  best: {b['designation']}  p={b['pitch_mm']:g} mm x{int(b['strands'])}  z1/z2={int(b['z1'])}/{int(b['z2'])}"
                f"  links={int(b['links'])}  a={b['center_distance_mm']:.1f} mm  v={b['speed_m_s']:.3g} m/s"
                f"  F_t={b['force_n']:.0f} N")
            checks = "  ".join(f"{c[7:]}={b[c]:+.3f}" for c in _MARGINS if c in b and np.isfinite(b[c]))
            lines.append(f"  margins: {checks}")
        lines.append(f"  {len(self.candidates)} candidates, {int(self.candidates['feasible'].sum())} feasible")
        return "\n".join(lines)


_MARGINS = ("margin_pressure", "margin_safety", "margin_speed", "margin_impacts", "margin_power")


# --------------------------------------------------------------------------------------------
# Design: a recipe of steps
#
#   design(...) = _validate_inputs -> (_load_chains, _reference_tables) -> _candidate_table
#                 -> _evaluate -> _rank -> _wrap_result
#
# Every step works on numpy arrays, one entry per candidate. pandas appears only where a table
# is read (once per file version: the arrays are kept) and where the ranked table the user sees
# is built (once per call).
# --------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class _Inputs:
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
class _ReferenceTables:
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


class _Candidates:
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


# The computed columns, in the order they follow the catalog's own columns before the result
# table puts the main ones first (see _RESULT_FRONT).
_COMPUTED_ORDER = (
    "z1", "z2", "speed_m_s", "force_n", "links", "center_distance_mm",
    "sprocket1_pitch_diameter_mm", "sprocket1_tip_diameter_mm", "sprocket1_root_diameter_mm",
    "sprocket2_pitch_diameter_mm", "sprocket2_tip_diameter_mm", "sprocket2_root_diameter_mm",
    "width_mm", "chain_mass_kg", "impacts_per_s", "breaking_load_n", "margin_center_distance", "safety_factor",
    "n1_max_rpm", "allowable_impacts_per_s", "allowable_safety_factor", "margin_safety", "strand_factor",
    "pressure_mpa", "allowable_pressure_mpa", "margin_pressure", "margin_speed", "margin_impacts",
    "rated_power_kw", "rating_limit", "design_power_kw", "margin_power",
    "min_margin", "limiting_check", "feasible",
)
_RESULT_FRONT = ("rank", "designation", "pitch_mm", "strands", "z1", "z2", "links", "center_distance_mm",
                 "speed_m_s", "force_n", "pressure_mpa", "allowable_pressure_mpa", "safety_factor",
                 "allowable_safety_factor", "mass_kg_m", "feasible", "min_margin", "limiting_check")
_RESULT_TAIL = ("edition", "source", "note")
_BLOCKING_COLUMNS = ("designation", "pitch_mm", "strands", "z1", "feasible", "limiting_check", "min_margin")
_OBJECTIVE_KEYS = {"min_mass": ("mass_kg_m", True), "min_width": ("width_mm", True),
                   "min_sprocket_diameter": ("sprocket2_tip_diameter_mm", True), "max_safety": ("min_margin", False)}


# ---- step 1: inputs ----

def _validate_inputs(torque_nm, power_kw, n1_rpm, ratio, conditions, k_e, allowable_pressure_mpa,
                     allowable_safety_factor, catalog, strands, z1, center_distance_mm, objective, method,
                     sag_factor, z2_max, center_distance_pitches) -> _Inputs:
    """Check every input of :func:`design` against its range and return them as :class:`_Inputs`.

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
    return _Inputs(torque=torque, power_w=power_w, n1=n1, u=u, conditions=cond, k_e=k_e_val, k_d=k_d,
                   strands=strands_t, allowable_pressure_mpa=allowable_pressure_mpa,
                   allowable_safety_factor=allowable_safety_factor, sag=sag, z2_max=z2_max, z1_values=z1_values,
                   z1_given=z1 is not None, center_distance_mm=center_distance_mm,
                   center_distance_pitches=cpitches, objective=objective, method=method, catalog=catalog)


# ---- step 2: tables and candidates ----

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


def _load_chains(inp: _Inputs, folder) -> _ChainTable:
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
def _cached_reference_tables(keys) -> _ReferenceTables:
    """The four reference tables as arrays, kept per the :func:`_file_key` ``keys`` of their files."""
    speed, strand, safety, pressure = (load_catalog(name) for name in _REFERENCE_NAMES)

    def cols(frame, *names):
        return tuple(_read_only(frame[n].to_numpy(dtype=float)) for n in names)

    return _ReferenceTables(*cols(speed, "pitch_mm", "n1_max_rpm", "impacts_allowed_per_s"),
                            _read_only(strand["strands"].to_numpy()),
                            *cols(strand, "hinge_strand_factor", "power_strand_factor"),
                            safety=cols(safety, "pitch_mm", "n1_rpm", "allowable_safety_factor"),
                            pressure=cols(pressure, "pitch_min_mm", "pitch_max_mm", "n1_rpm", "allowable_pressure_mpa"))


def _reference_tables(folder) -> _ReferenceTables:
    """The speed-limit, strand-factor, [s] and [p] tables as arrays, read once per file version."""
    keys = tuple(_file_key(name, folder) for name in _REFERENCE_NAMES)
    if any(k is None for k in keys):
        return _cached_reference_tables.__wrapped__(keys)
    return _cached_reference_tables(keys)


def _candidate_table(chains: _ChainTable, inp: _Inputs) -> _Candidates:
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
    return _Candidates(chains, rows[keep], z1[keep], z2[keep])


# ---- step 3: evaluate every candidate ----

def _layout(c: _Candidates, inp: _Inputs) -> None:
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
    order). Status as in :func:`_interp_speed`; 2 where no row matches (value NaN).
    """
    _, inverse = np.unique(pitches, return_inverse=True)
    values = np.full(len(match), np.nan)
    status = np.full(len(match), 2, dtype=np.int64)
    for i in np.flatnonzero(match.any(axis=1)):
        rows = match[i]
        values[i], status[i] = _interp_speed(table_n[rows], table_y[rows], n1)
    return values[inverse], status[inverse]


def _pressure_groups(unique_pitches, pitch_min, pitch_max, tol=1e-6):
    """match[i, j]: the i-th pitch lies in the j-th row's pitch group of the [p] table."""
    p = unique_pitches[:, None]
    return (pitch_min[None, :] - tol <= p) & (p <= pitch_max[None, :] + tol)


def _speed_limits(c: _Candidates, inp: _Inputs, tables: _ReferenceTables) -> None:
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
    if inp.method == "hinge_pressure" and np.isfinite(n_max_u).any() and inp.n1 > np.nanmax(n_max_u):
        j = int(np.nanargmax(n_max_u))
        raise GearDesignError(
            f"n1_rpm = {inp.n1:g} rpm is above the maximum speed of every chain in {str(inp.catalog)!r} "
            f"(the fastest, pitch {unique[j]:g} mm, allows {n_max_u[j]:g} rpm); use a belt or gear stage first")
    c["n1_max_rpm"] = n_max_u[inverse]
    c["allowable_impacts_per_s"] = w_max_u[inverse]


def _safety_check(c: _Candidates, inp: _Inputs, tables: _ReferenceTables, notes: list) -> None:
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
            notes.append(f"n1 = {inp.n1:g} rpm is below the [s] table: its lowest-speed column is used")
    c["allowable_safety_factor"] = s_allow
    c["margin_safety"] = c["safety_factor"] / s_allow - 1.0


def _hinge_checks(c: _Candidates, inp: _Inputs, tables: _ReferenceTables, notes: list) -> list:
    """Hinge-pressure method: p = F_t·K_e/(A·m_eff) against [p], n1 against n1_max, w against [w].

    Margins 1 − p/[p], 1 − n1/n1_max, 1 − w/[w] (Chernavsky, course design of machine parts).
    m_eff = strands·K_m from catalogs/chain_strand_factors.csv; [p] is the override or
    catalogs/chain_allowable_pressure.csv interpolated along n1, never extrapolated above the
    table (NaN: the check has no data). Returns the names of the checks that decide feasibility.
    """
    t = c["pitch_mm"]
    m_eff = tables.hinge_strand_factor[_strand_index(tables, c["strands"])]
    p = hinge_pressure_mpa(c["force_n"], inp.k_e, c["hinge_area_mm2"], m_eff)
    if inp.allowable_pressure_mpa is not None:
        p_allow = np.full(t.shape, inp.allowable_pressure_mpa)
    else:
        lo, hi, n1_rpm, value = tables.pressure
        p_allow, p_status = _lookup_by_pitch(t, _pressure_groups(np.unique(t), lo, hi), n1_rpm, value, inp.n1)
        if (p_status == -1).any():
            notes.append(f"n1 = {inp.n1:g} rpm is below the [p] table (50 rpm): the 50 rpm value is used "
                         "(conservative: [p] falls with speed)")
        if (p_status == 1).any():
            notes.append(f"n1 = {inp.n1:g} rpm is above the [p] table for some pitches: no extrapolation, "
                         "those candidates fail with 'pressure (no [p] data)'")
    c["strand_factor"] = m_eff
    c["pressure_mpa"] = p
    c["allowable_pressure_mpa"] = p_allow
    c["margin_pressure"] = 1.0 - p / p_allow
    c["margin_speed"] = 1.0 - inp.n1 / c["n1_max_rpm"]
    c["margin_impacts"] = 1.0 - c["impacts_per_s"] / c["allowable_impacts_per_s"]
    return ["margin_pressure", "margin_safety", "margin_speed", "margin_impacts"]


def _power_checks(c: _Candidates, inp: _Inputs, tables: _ReferenceTables, notes: list) -> list:
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
    m_pow = tables.power_strand_factor[_strand_index(tables, c["strands"])]
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


def _strand_index(tables: _ReferenceTables, strands: np.ndarray) -> np.ndarray:
    """Row of the strand-factor table for each strand count (KeyError for a count it lacks)."""
    idx = np.searchsorted(tables.strands, strands)
    ok = idx < len(tables.strands)
    ok[ok] = tables.strands[idx[ok]] == strands[ok]
    if not ok.all():
        raise KeyError(f"strands {sorted(set(strands[~ok].tolist()))} not in chain_strand_factors")
    return idx


def _limiting_check(c: _Candidates, checks: list) -> None:
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


def _evaluate(c: _Candidates, inp: _Inputs, tables: _ReferenceTables) -> tuple[list, list]:
    """Every check of every candidate, vectorised: layout, speed limits, safety, the method's checks.

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
    _limiting_check(c, checks)
    return checks, notes


# ---- step 4: rank ----

def _rank(c: _Candidates, inp: _Inputs) -> np.ndarray:
    """The candidate order: feasible first, then the objective, then smaller pitch, fewer
    strands, z1 nearest the rule z1 = 29 − 2u. A stable sort; NaN objective values go last.
    """
    column, ascending = _OBJECTIVE_KEYS[inp.objective]
    key = np.asarray(c[column], dtype=float)
    nan = np.isnan(key)
    key = np.where(nan, 0.0, key if ascending else -key)
    zdist = np.abs(c["z1"] - recommended_z1(inp.u))
    return np.lexsort((zdist, c["strands"], c["pitch_mm"], key, nan, ~c["feasible"]))


# ---- step 5: result ----

def _result_table(c: _Candidates, order: np.ndarray, checks: list) -> dict:
    """The ranked candidate table as {column: array}, in the column order users see.

    First rank, the chain, the geometry, the loads, feasibility and the margins that decide it;
    then the other columns (the catalog's, then the computed ones); the catalog's edition,
    source and note last.
    """
    catalog_cols = c.chains.columns
    columns = catalog_cols + [k for k in _COMPUTED_ORDER if k in c.columns and k not in catalog_cols]
    columns += [k for k in c.columns if k not in columns]
    front = list(_RESULT_FRONT) + checks
    rest = [k for k in columns if k not in front and k not in _RESULT_TAIL]
    tail = [k for k in _RESULT_TAIL if k in columns]
    rows = c.rows[order]
    table = {}
    for k in front + rest + tail:
        if k == "rank":
            table[k] = np.arange(1, len(order) + 1)
        elif k in c.columns:
            table[k] = np.asarray(c.columns[k])[order]
        else:
            table[k] = c.chains.take(k, rows)
    return table


def _frame(table: dict, index, attrs: dict) -> pd.DataFrame:
    """A DataFrame of some rows (``index``, or all) of a column table, with the catalog's attrs."""
    frame = pd.DataFrame({k: v if index is None else v[index] for k, v in table.items()}, copy=False)
    frame.attrs = dict(attrs)
    return frame


def _blocking(table: dict, attrs: dict) -> tuple[pd.DataFrame, int]:
    """Per chain family (designation) the candidate closest to passing, by pitch and strands.

    Returns the table and the row (in ranked order) of the candidate closest to passing overall
    (largest smallest margin; NaN margins last; ties keep the ranked order).
    """
    mm = np.asarray(table["min_margin"], dtype=float)
    nan = np.isnan(mm)
    by_margin = np.lexsort((np.where(nan, 0.0, -mm), nan))
    first: dict = {}
    for i, name in enumerate(np.asarray(table["designation"], dtype=object)[by_margin].tolist()):
        first.setdefault(name, i)
    keep = by_margin[np.fromiter(first.values(), dtype=np.int64, count=len(first))]
    keep = keep[np.lexsort((table["strands"][keep], table["pitch_mm"][keep]))]
    blocking = _frame({k: table[k] for k in _BLOCKING_COLUMNS}, keep, attrs)
    return blocking, int(by_margin[0])


def _message(best, table: dict, closest: int) -> str:
    """One line: the best candidate and its limiting check, or the candidate closest to passing."""
    if best is not None:
        return (f"{best['designation']} with z1/z2 = {int(best['z1'])}/{int(best['z2'])}, {int(best['links'])} links; "
                f"limiting check {best['limiting_check']} (margin {best['min_margin']:+.3f})")
    return (f"no candidate passes; closest is {table['designation'][closest]} (z1 = {int(table['z1'][closest])}), "
            f"stopped by {table['limiting_check'][closest]} with margin {table['min_margin'][closest]:+.3f}; "
            "see .blocking for every family")


def _pitch_estimates(c: _Candidates, inp: _Inputs, tables: _ReferenceTables) -> dict:
    """Classic pitch estimate (:func:`pitch_estimate_mm`) per strand count, hinge method only.

    [p] is the override or the largest table [p] among that strand count's candidates; z1 the
    first given tooth count or the rule's. A strand count without [p] data gets no estimate.
    """
    estimate = {}
    if inp.method != "hinge_pressure":
        return estimate
    strands, p_allow = c["strands"], np.asarray(c["allowable_pressure_mpa"], dtype=float)
    for s in inp.strands:
        p_ref = inp.allowable_pressure_mpa
        if p_ref is None:
            mine = strands == s
            p_ref = np.nanmax(p_allow[mine], initial=np.nan) if mine.any() else np.nan
        z_ref = float(inp.z1_values[0]) if inp.z1_given else float(recommended_z1(inp.u))
        factor = float(tables.hinge_strand_factor[_strand_index(tables, np.array([s]))[0]])
        t_est = float(pitch_estimate_mm(inp.torque, z_ref, p_ref, inp.k_e, factor))
        if np.isfinite(t_est):   # no [p] for these pitches and speed: no estimate either
            estimate[s] = t_est
    return estimate


def _inputs_record(inp: _Inputs) -> dict:
    """The inputs as the result reports them (``ChainDesign.inputs``)."""
    inputs = dict(torque_nm=inp.torque, power_kw=inp.power_w / 1000.0, n1_rpm=inp.n1, ratio=inp.u, k_e=inp.k_e,
                  k_d=inp.k_d, allowable_pressure_mpa=inp.allowable_pressure_mpa,
                  allowable_safety_factor=inp.allowable_safety_factor, strands=list(inp.strands),
                  z1=[int(z) for z in inp.z1_values] if inp.z1_given else None,
                  center_distance_mm=inp.center_distance_mm, sag_factor=inp.sag)
    if inp.conditions is not None:
        inputs.update({k: getattr(inp.conditions, k) for k in FACTOR_NAMES})
    return inputs


def _wrap_result(c: _Candidates, order: np.ndarray, checks: list, notes: list, inp: _Inputs,
                 tables: _ReferenceTables) -> ChainDesign:
    """Build the ranked candidate table, the best feasible row, the blocking table and the message."""
    attrs = c.chains.attrs
    table = _result_table(c, order, checks)
    candidates = _frame(table, None, attrs)
    best = candidates.iloc[0] if table["feasible"][0] else None
    blocking, closest = _blocking(table, attrs)
    return ChainDesign(candidates=candidates, best=best, success=best is not None,
                       message=_message(best, table, closest), method=inp.method, objective=inp.objective,
                       catalog=str(inp.catalog), k_e=inp.k_e, inputs=_inputs_record(inp),
                       pitch_estimate_mm=_pitch_estimates(c, inp, tables), blocking=blocking, notes=tuple(notes))


def design(torque_nm=None, power_kw=None, *, n1_rpm, ratio, conditions=None, k_e=None,
           allowable_pressure_mpa=None, allowable_safety_factor=None, catalog="gost13568",
           strands=(1, 2, 3), z1=None, center_distance_mm=None, objective="min_mass",
           method="hinge_pressure", sag_factor=6.0, z2_max=120, center_distance_pitches=40.0) -> ChainDesign:
    """Size a roller-chain drive from a catalog.

    Parameters
    ----------
    torque_nm, power_kw : float
        Load on the small (driving) sprocket: give one, torque in N·m or power in kW.
    n1_rpm : float
        Speed of the small sprocket [rpm].
    ratio : float
        Speed ratio u = n1/n2 in [1, 10]; with the smallest small sprocket z1 = 13 the large one
        needs z2 = 13·u <= ``z2_max``, so above z2_max/13 (9.23 at the default 120, the usual limit
        of chain wear elongation) raise ``z2_max`` (at most 250) or split the ratio.
    conditions : Conditions or mapping, optional
        The operating factors K_d, K_a, K_n, K_reg, K_lub, K_mode (numbers or condition names);
        K_e is their product. ``k_e`` gives the product directly (K_d is then taken as 1 in
        the safety factor). Neither: K_e = 1.
    allowable_pressure_mpa, allowable_safety_factor : float, optional
        Override the [p] and [s] tables.
    catalog : str or path
        ``"gost13568"``, ``"iso606"``, ``"iso606a"``, ``"iso606b"``, ``"ansi_b29"`` or a CSV path.
    strands : iterable of int
        Strand counts to consider.
    z1 : int, optional
        Small-sprocket teeth. Default: every odd count from 13 to the rule z1 = 29 − 2u.
    center_distance_mm : float, optional
        Target centre distance; default 40 pitches (30-50 recommended), at least the sprocket
        clearance 0.5·(D_e1 + D_e2) + 30 mm. The link count is the nearest even number and the
        centre distance is recomputed exactly for it.
    objective : {"min_mass", "min_width", "min_sprocket_diameter", "max_safety"}
        min_mass: lightest chain per metre; min_width: narrowest chain over all strands;
        min_sprocket_diameter: smallest tip diameter of the large sprocket; max_safety: largest
        smallest margin. Ties go to the smaller pitch, then to fewer strands.
    method : {"hinge_pressure", "power_rating"}
        hinge_pressure: checks p <= [p], s >= [s], n1 <= n1_max, impacts <= [w] (Russian
        practice, GOST tables). power_rating: rated power of the strands (ANSI link-plate and
        roller-bushing formulas, z1 enters directly, multiple-strand factor) against the design
        power P·K_e; [s] is checked only when ``allowable_safety_factor`` is given.
    sag_factor : float
        k_f of the sag tension (6 horizontal, 1.5 at 40°, 1 vertical).

    The steps: :func:`_validate_inputs`, :func:`_candidate_table` (catalog rows × z1),
    :func:`_evaluate` (every margin, vectorised), :func:`_rank`, :func:`_wrap_result`.
    """
    inp = _validate_inputs(torque_nm, power_kw, n1_rpm, ratio, conditions, k_e, allowable_pressure_mpa,
                           allowable_safety_factor, catalog, strands, z1, center_distance_mm, objective, method,
                           sag_factor, z2_max, center_distance_pitches)
    folder = catalog_dir()
    chains = _load_chains(inp, folder)
    tables = _reference_tables(folder)
    cand = _candidate_table(chains, inp)
    checks, notes = _evaluate(cand, inp, tables)
    order = _rank(cand, inp)
    return _wrap_result(cand, order, checks, notes, inp, tables)
