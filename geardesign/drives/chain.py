"""Roller-chain drive design from standard catalogs.

:func:`design` enumerates every candidate — each catalog row (a chain with its strand count)
times each small-sprocket tooth count — evaluates all checks in one vectorised pass and ranks
the candidates for an objective. Every check is a signed dimensionless margin (>= 0 holds):

- hinge pressure ``1 - p/[p]`` with p = F_t·K_e / (A·m_eff) (hinge-pressure method);
- breaking-load safety ``s/[s] - 1`` with s = Q / (K_d·F_t + F_v + F_f);
- speed ``1 - n1/n1_max`` and impacts per second ``1 - w/[w]`` (hinge-pressure method);
- rated power ``P_rated/P_design - 1`` (power-rating method, ISO 606 / ANSI chains).

Units at the interface: torque N·m, power kW, speed rpm, lengths mm, forces N, pressure MPa.
Inside, powers are in W and chain speeds in m/s.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Mapping

import numpy as np
import pandas as pd

from . import sprocket
from ..catalogs.tables import chain_catalog, load_catalog
from ..errors import GearDesignError
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

    Source: Russian course-design practice (Chernavsky; reference/chain_service_factors.csv,
    "z1 rule"): odd tooth counts spread the wear with an even number of links.

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
    Source: ANSI/ASME B29.1 horsepower formulas as printed in the 'Roller Chains' catalogue
    pages (reference/chain_service_factors.csv).

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
class ChainDesign:
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

    def to_frame(self) -> pd.DataFrame:
        return self.candidates.copy()

    def to_dict(self) -> dict:
        best = None if self.best is None else {k: _plain(v) for k, v in self.best.items()}
        return {
            "success": self.success,
            "message": self.message,
            "method": self.method,
            "objective": self.objective,
            "catalog": self.catalog,
            "k_e": self.k_e,
            "inputs": {k: _plain(v) for k, v in self.inputs.items()},
            "pitch_estimate_mm": {str(k): _plain(v) for k, v in self.pitch_estimate_mm.items()},
            "best": best,
            "blocking": [{k: _plain(v) for k, v in r.items()} for r in self.blocking.to_dict(orient="records")],
            "notes": list(self.notes),
            "n_candidates": int(len(self.candidates)),
            "n_feasible": int(self.candidates["feasible"].sum()),
        }

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


def _plain(v):
    if isinstance(v, (np.integer,)):
        return int(v)
    if isinstance(v, (np.floating, float)):
        return float(v) if np.isfinite(v) else None
    if isinstance(v, np.bool_):
        return bool(v)
    return v


_MARGINS = ("margin_pressure", "margin_safety", "margin_speed", "margin_impacts", "margin_power")


# --------------------------------------------------------------------------------------------
# Design
# --------------------------------------------------------------------------------------------

def _table_lookup(pitches: np.ndarray, n1: float, table: pd.DataFrame, value: str, exact_pitch=True):
    """Per unique pitch, interpolate ``value`` along n1; returns (values, status) per pitch."""
    out = np.full(pitches.shape, np.nan)
    status = np.full(pitches.shape, 2, dtype=np.int64)
    for p in np.unique(pitches):
        if exact_pitch:
            rows = table[np.isclose(table["pitch_mm"], p, rtol=0, atol=1e-6)]
            if rows.empty:
                continue
            y, s = _interp_speed(rows["n1_rpm"].to_numpy(), rows[value].to_numpy(), n1)
        else:
            y, s = allowable_pressure_mpa(p, n1, table)
        out[pitches == p] = y
        status[pitches == p] = s
    return out, status


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
    """
    # ---- inputs ----
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
        allowable_pressure_mpa = one_number("allowable_pressure_mpa", require_positive("allowable_pressure_mpa", allowable_pressure_mpa, "MPa"))
    if allowable_safety_factor is not None:
        allowable_safety_factor = one_number("allowable_safety_factor", require_range("allowable_safety_factor", allowable_safety_factor, *SAFETY_FACTOR_RANGE))
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
        center_distance_mm = one_number("center_distance_mm", require_range("center_distance_mm", center_distance_mm, 0.0, CENTER_DISTANCE_MAX_MM,
                                                 lo_open=True, unit="mm"))
    cpitches = one_number("center_distance_pitches", require_range("center_distance_pitches", center_distance_pitches, 10.0, 100.0))

    chains = chain_catalog(catalog)
    cat_name = str(catalog)
    chains = chains[chains["strands"].isin(strands_t)].reset_index(drop=True)
    if chains.empty:
        raise GearDesignError(f"catalog {cat_name!r} has no chain with strands in {strands_t}")
    strand_tab = load_catalog("chain_strand_factors").set_index("strands")

    # ---- candidate table: every chain row x every z1 ----
    nc, nz = len(chains), len(z1_values)
    cand = chains.loc[np.repeat(np.arange(nc), nz)].reset_index(drop=True)
    cand["z1"] = np.tile(z1_values, nc)
    cand["z2"] = np.round(u * cand["z1"].to_numpy()).astype(np.int64)
    cand = cand[cand["z2"] <= z2_max].reset_index(drop=True)
    if cand.empty:
        raise GearDesignError(f"no small sprocket z1 in {[int(z) for z in z1_values]} keeps z2 = u·z1 <= z2_max = "
                              f"{z2_max} at ratio {u:g}")

    t = cand["pitch_mm"].to_numpy(dtype=float)
    z1a = cand["z1"].to_numpy(dtype=float)
    z2a = cand["z2"].to_numpy(dtype=float)
    m = cand["strands"].to_numpy()
    v = sprocket.chain_speed_m_s(z1a, t, n1)
    force = power_w / v
    de1 = sprocket.tip_diameter_mm(t, z1a)
    de2 = sprocket.tip_diameter_mm(t, z2a)
    clearance = 0.5 * (de1 + de2) + 30.0
    a_asked = np.full(t.shape, center_distance_mm) if center_distance_mm is not None else cpitches * t
    # the loop is laid out at the asked distance where the sprockets clear each other and the
    # chain is not longer than 80 pitches of span; otherwise at the nearest such distance, and
    # the candidate fails the center_distance check by the shortfall or excess
    a_span_max = CENTER_DISTANCE_PITCHES_MAX * t
    a0 = (np.clip(a_asked, clearance, np.maximum(a_span_max, clearance)) if center_distance_mm is not None
          else np.maximum(a_asked, clearance))
    links = sprocket.even_links(sprocket.link_count(a0, t, z1a, z2a))
    a = sprocket.center_distance_for_links_mm(links, t, z1a, z2a)
    q = cand["mass_kg_m"].to_numpy(dtype=float)
    width_inner = cand["hinge_area_mm2"].to_numpy(dtype=float) / cand["pin_d_mm"].to_numpy(dtype=float)
    pt = np.nan_to_num(cand["transverse_pitch_mm"].to_numpy(dtype=float))

    cand["speed_m_s"] = v
    cand["force_n"] = force
    cand["links"] = links
    cand["center_distance_mm"] = a
    cand["sprocket1_pitch_diameter_mm"] = sprocket.pitch_diameter_mm(t, z1a)
    cand["sprocket1_tip_diameter_mm"] = de1
    cand["sprocket1_root_diameter_mm"] = sprocket.root_diameter_mm(t, z1a, cand["roller_d1_mm"].to_numpy())
    cand["sprocket2_pitch_diameter_mm"] = sprocket.pitch_diameter_mm(t, z2a)
    cand["sprocket2_tip_diameter_mm"] = de2
    cand["sprocket2_root_diameter_mm"] = sprocket.root_diameter_mm(t, z2a, cand["roller_d1_mm"].to_numpy())
    cand["width_mm"] = width_inner + (m - 1) * pt
    cand["chain_mass_kg"] = q * links * t / 1000.0
    cand["impacts_per_s"] = sprocket.impacts_per_second(z1a, n1, links)
    cand["breaking_load_n"] = cand["breaking_load_kn"].to_numpy(dtype=float) * 1000.0
    cd_check = []
    if center_distance_mm is not None:
        cand["margin_center_distance"] = np.minimum(a_asked / clearance, a_span_max / a_asked) - 1.0
        cd_check = ["margin_center_distance"]
    cand["safety_factor"] = safety_factor(cand["breaking_load_n"].to_numpy(), force, k_d, q, v, a, sag)
    notes = []

    # ---- allowable values from the tables ----
    speed_tab = load_catalog("chain_speed_limits")
    sp = speed_tab.set_index("pitch_mm")
    match = np.array([np.isclose(sp.index.to_numpy(), x, atol=1e-6).argmax() if np.isclose(sp.index.to_numpy(), x, atol=1e-6).any()
                      else -1 for x in np.unique(t)], dtype=np.int64)
    n_max_u = np.where(match >= 0, sp["n1_max_rpm"].to_numpy()[match], np.nan)
    w_max_u = np.where(match >= 0, sp["impacts_allowed_per_s"].to_numpy()[match], np.nan)
    inv = np.searchsorted(np.unique(t), t)
    cand["n1_max_rpm"] = n_max_u[inv]
    if method == "hinge_pressure" and np.isfinite(n_max_u).any() and n1 > np.nanmax(n_max_u):
        j = int(np.nanargmax(n_max_u))
        raise GearDesignError(
            f"n1_rpm = {n1:g} rpm is above the maximum speed of every chain in {cat_name!r} "
            f"(the fastest, pitch {np.unique(t)[j]:g} mm, allows {n_max_u[j]:g} rpm); use a belt or gear stage first")
    cand["allowable_impacts_per_s"] = w_max_u[inv]

    if allowable_safety_factor is not None:
        s_allow, s_status = np.full(t.shape, allowable_safety_factor), np.zeros(t.shape, dtype=np.int64)
    else:
        s_allow, s_status = _table_lookup(t, n1, load_catalog("chain_safety_factor"), "allowable_safety_factor")
        if (s_status == -1).any():
            notes.append(f"n1 = {n1:g} rpm is below the [s] table: its lowest-speed column is used")
    cand["allowable_safety_factor"] = s_allow
    cand["margin_safety"] = cand["safety_factor"] / s_allow - 1.0

    if method == "hinge_pressure":
        m_eff = strand_tab.loc[m, "hinge_strand_factor"].to_numpy(dtype=float)
        p = hinge_pressure_mpa(force, k_e_val, cand["hinge_area_mm2"].to_numpy(), m_eff)
        if allowable_pressure_mpa is not None:
            p_allow, p_status = np.full(t.shape, allowable_pressure_mpa), np.zeros(t.shape, dtype=np.int64)
        else:
            p_allow, p_status = _table_lookup(t, n1, load_catalog("chain_allowable_pressure"), "", exact_pitch=False)
            if (p_status == -1).any():
                notes.append(f"n1 = {n1:g} rpm is below the [p] table (50 rpm): the 50 rpm value is used "
                             "(conservative: [p] falls with speed)")
            if (p_status == 1).any():
                notes.append(f"n1 = {n1:g} rpm is above the [p] table for some pitches: no extrapolation, "
                             "those candidates fail with 'pressure (no [p] data)'")
        cand["strand_factor"] = m_eff
        cand["pressure_mpa"] = p
        cand["allowable_pressure_mpa"] = p_allow
        cand["margin_pressure"] = 1.0 - p / p_allow
        cand["margin_speed"] = 1.0 - n1 / cand["n1_max_rpm"].to_numpy()
        cand["margin_impacts"] = 1.0 - cand["impacts_per_s"].to_numpy() / cand["allowable_impacts_per_s"].to_numpy()
        checks = ["margin_pressure", "margin_safety", "margin_speed", "margin_impacts"] + cd_check
    else:
        k_pl = cand["rating_k_plate"].to_numpy(dtype=float) if "rating_k_plate" in cand else np.full(t.shape, 0.004)
        k_rb = cand["rating_k_roller"].to_numpy(dtype=float) if "rating_k_roller" in cand else np.full(t.shape, 17.0)
        m_pow = strand_tab.loc[m, "power_strand_factor"].to_numpy(dtype=float)
        plate = rated_power_link_plate_kw(z1a, n1, t, k_pl)
        roller = rated_power_roller_bushing_kw(z1a, n1, t, k_rb)
        cand["strand_factor"] = m_pow
        cand["rated_power_kw"] = np.minimum(plate, roller) * m_pow
        cand["rating_limit"] = np.where(plate <= roller, "link_plate", "roller_bushing")
        cand["design_power_kw"] = power_w / 1000.0 * k_e_val
        cand["margin_power"] = cand["rated_power_kw"] / cand["design_power_kw"] - 1.0
        cand["pressure_mpa"] = hinge_pressure_mpa(force, 1.0, cand["hinge_area_mm2"].to_numpy(), m_pow)
        cand["allowable_pressure_mpa"] = np.nan
        checks = ["margin_power"] + cd_check + (["margin_safety"] if allowable_safety_factor is not None else [])
        if not str(cat_name).startswith("ansi") and not str(cat_name).startswith("iso606a"):
            notes.append("power ratings use the ANSI B29.1 formulas; for chains that are not ANSI/ISO A series "
                         "they are an approximation")

    margins = cand[checks].to_numpy(dtype=float)
    no_data = np.isnan(margins)
    rows = np.arange(len(cand))
    # the worst available margin; a check without table data cannot pass but is named only
    # when every check that has data holds
    worst = np.argmin(np.where(no_data, np.inf, margins), axis=1)
    min_margin = np.where(no_data.all(axis=1), np.nan, margins[rows, np.minimum(worst, len(checks) - 1)])
    names = np.array([c[len("margin_"):] for c in checks], dtype=object)
    missing = np.argmax(no_data, axis=1)
    show_missing = no_data.any(axis=1) & ~(min_margin < 0)
    cand["min_margin"] = min_margin
    cand["limiting_check"] = np.where(show_missing, names[missing] + " (no table data)", names[worst])
    cand["feasible"] = ~no_data.any(axis=1) & (min_margin >= 0)

    # ---- rank ----
    key = {"min_mass": ("mass_kg_m", True), "min_width": ("width_mm", True),
           "min_sprocket_diameter": ("sprocket2_tip_diameter_mm", True), "max_safety": ("min_margin", False)}[objective]
    z_rule = recommended_z1(u)
    cand["_infeasible"] = ~cand["feasible"]
    cand["_zdist"] = np.abs(cand["z1"] - z_rule)
    cand = cand.sort_values(["_infeasible", key[0], "pitch_mm", "strands", "_zdist"],
                            ascending=[True, key[1], True, True, True], kind="stable")
    cand = cand.drop(columns=["_infeasible", "_zdist"]).reset_index(drop=True)
    cand.insert(0, "rank", np.arange(1, len(cand) + 1))
    front = ["rank", "designation", "pitch_mm", "strands", "z1", "z2", "links", "center_distance_mm", "speed_m_s",
             "force_n", "pressure_mpa", "allowable_pressure_mpa", "safety_factor", "allowable_safety_factor",
             "mass_kg_m", "feasible", "min_margin", "limiting_check"] + checks
    rest = [c for c in cand.columns if c not in front and c not in ("edition", "source", "note")]
    cand = cand[front + rest + [c for c in ("edition", "source", "note") if c in cand.columns]]

    feasible = cand[cand["feasible"]]
    best = feasible.iloc[0] if len(feasible) else None
    # per family (designation): the candidate closest to passing
    order = cand.sort_values("min_margin", ascending=False, kind="stable")
    blocking = order.drop_duplicates("designation")[
        ["designation", "pitch_mm", "strands", "z1", "feasible", "limiting_check", "min_margin"]
    ].sort_values(["pitch_mm", "strands"]).reset_index(drop=True)

    if best is not None:
        message = (f"{best['designation']} with z1/z2 = {int(best['z1'])}/{int(best['z2'])}, {int(best['links'])} links; "
                   f"limiting check {best['limiting_check']} (margin {best['min_margin']:+.3f})")
    else:
        closest = order.iloc[0]
        message = (f"no candidate passes; closest is {closest['designation']} (z1 = {int(closest['z1'])}), stopped by "
                   f"{closest['limiting_check']} with margin {closest['min_margin']:+.3f}; see .blocking for every family")

    estimate = {}
    if method == "hinge_pressure":
        for s in strands_t:
            p_ref = allowable_pressure_mpa
            if p_ref is None:
                p_ref = np.nanmax(cand.loc[cand["strands"] == s, "allowable_pressure_mpa"].to_numpy(dtype=float),
                                  initial=np.nan) if (cand["strands"] == s).any() else np.nan
            z_ref = float(z1_values[0]) if z1 is not None else float(recommended_z1(u))
            t_est = float(pitch_estimate_mm(torque, z_ref, p_ref, k_e_val, float(strand_tab.loc[s, "hinge_strand_factor"])))
            if np.isfinite(t_est):   # no [p] for these pitches and speed: no estimate either
                estimate[s] = t_est
    inputs = dict(torque_nm=torque, power_kw=power_w / 1000.0, n1_rpm=n1, ratio=u, k_e=k_e_val, k_d=k_d,
                  allowable_pressure_mpa=allowable_pressure_mpa, allowable_safety_factor=allowable_safety_factor,
                  strands=list(strands_t), z1=None if z1 is None else [int(z) for z in z1_values],
                  center_distance_mm=center_distance_mm, sag_factor=sag)
    if cond is not None:
        inputs.update({k: getattr(cond, k) for k in FACTOR_NAMES})
    return ChainDesign(candidates=cand, best=best, success=best is not None, message=message, method=method,
                       objective=objective, catalog=cat_name, k_e=k_e_val, inputs=inputs,
                       pitch_estimate_mm=estimate, blocking=blocking, notes=tuple(notes))
