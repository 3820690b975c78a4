"""The inputs of a chain design: ranges, the operating factors, and the validated inputs in the
units used inside (power in W)."""
from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Mapping

import numpy as np

from ...catalogs.tables import load_catalog
from ...errors import GearDesignError
from ...validate import ndim, one_number, require_count, require_int, require_positive, require_range
from .formulas import recommended_z1

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

CENTER_DISTANCE_MIN_MM = 1.0        # a given centre distance below a millimetre fits no chain (pitches start at 6.35 mm)
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


OBJECTIVE_KEYS = {"min_mass": ("mass_kg_m", True), "min_width": ("width_mm", True),
                   "min_sprocket_diameter": ("sprocket2_tip_diameter_mm", True), "max_safety": ("min_margin", False)}


def _z1_values(z1, u: float, z2_max: int) -> np.ndarray:
    """The small-sprocket tooth counts to try (int64): the given ones, else the odd counts from 13
    to the rule z1 = 29 − 2u; refused when z2 = u·z1 would exceed ``z2_max``."""
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
    return z1_values


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
    z1_values = _z1_values(z1, u, z2_max)
    if center_distance_mm is not None:
        center_distance_mm = one_number("center_distance_mm", require_range(
            "center_distance_mm", center_distance_mm, CENTER_DISTANCE_MIN_MM, CENTER_DISTANCE_MAX_MM, unit="mm"))
    cpitches = one_number("center_distance_pitches", require_range(
        "center_distance_pitches", center_distance_pitches, 10.0, 100.0))
    return Inputs(torque=torque, power_w=power_w, n1=n1, u=u, conditions=cond, k_e=k_e_val, k_d=k_d,
                   strands=strands_t, allowable_pressure_mpa=allowable_pressure_mpa,
                   allowable_safety_factor=allowable_safety_factor, sag=sag, z2_max=z2_max, z1_values=z1_values,
                   z1_given=z1 is not None, center_distance_mm=center_distance_mm,
                   center_distance_pitches=cpitches, objective=objective, method=method, catalog=catalog)


def with_loads(inp: Inputs, n1_rpm, torque_nm) -> Inputs:
    """``inp`` with one load per candidate: arrays of small-sprocket speed [rpm] and torque [N·m]
    (power P = T·ω follows), for :func:`evaluate` on candidates built by the caller."""
    n1 = np.asarray(n1_rpm, dtype=float)
    torque = np.asarray(torque_nm, dtype=float)
    return replace(inp, n1=n1, torque=torque, power_w=torque * 2.0 * np.pi * n1 / 60.0)
