"""The stages of a drive (a bought unit, a gear pair, a roller chain) and the keyed hubs on its shafts.

A stage turns its input shaft's speed and torque into its output shaft's: n_out = n_in/u,
T_out = T_in·u·η (u = n_in/n_out its ratio, η its efficiency). Each stage states its free design
variables (what :meth:`~geardesign.drives.drive.Drive.optimize` may choose) and its checks as
signed margins (>= 0 holds), the same ones its standalone function reports.

Shafts are numbered along the power flow: 0 is the input (motor) shaft, k the output shaft of
stage k. A :class:`Shaft` is a keyed hub on one of them; its torque is that shaft's.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import lru_cache

import numpy as np

from ..errors import GearDesignError
from ..renamed import renamed_keywords
from ..gears.geometry import require_module
from ..gears.mesh import BETA_RANGE_DEG, FACE_WIDTH_RANGE_MM, Z_MAX, Z_MIN
from ..results import compact_repr
from ..validate import _show, ndim, one_number, require_count, require_range
from . import key
from ..catalogs.tables import catalog_dir
from ..gears.checks import resolve_checks
from ..gears.pair import GearPair
from ..gears.strength import Load
from ..shifts.objectives import OBJECTIVES
from .chain.formulas import recommended_z1
from .chain.inputs import RATIO_RANGE, Z1_RANGE, validate_inputs
from .chain.tables import load_chains

__all__ = ["GivenStage", "GearStage", "ChainStage", "Shaft", "EFFICIENCY_RANGE", "GEAR_EFFICIENCY", "GIVEN_RATIO_RANGE",
           "GEAR_PAIRS_MAX", "STEEL_DENSITY_KG_M3", "FACE_WIDTH_PITCHES", "stage_area_mm2", "disc_mass_kg",
           "stage_material"]

EFFICIENCY_RANGE = (0.3, 1.0)
GEAR_EFFICIENCY = 0.98            # a gear stage's efficiency when neither given nor computed (Drive shafting)     # a stage that loses more than 70 % is a brake, not a transmission
GIVEN_RATIO_RANGE = (1e-3, 1e4)   # a bought unit may step up (u < 1) or be a worm gear (u to ~100s)
GEAR_PAIRS_MAX = 5000             # tooth pairs one gear stage may enumerate (each may need a shift solve)
STEEL_DENSITY_KG_M3 = 7850.0      # gear blanks and sprockets as steel discs
# Gear face width of the mass model when none is given: b = 4p = 4πm, the middle of the usual
# 3p…5p (Budynas & Nisbett, Shigley's Mechanical Engineering Design, ch. 14: "3p < F < 5p").
FACE_WIDTH_PITCHES = 4.0


def stage_area_mm2(center_distance_mm, d1_mm, d2_mm):
    """Side-view envelope of a two-wheel stage [mm²]: (a + (D1 + D2)/2)·max(D1, D2), the
    rectangle that holds both wheels' outer circles at centre distance a (our size model).

    >>> float(stage_area_mm2(100, 40, 160))
    32000.0
    """
    d1, d2 = np.asarray(d1_mm, dtype=float), np.asarray(d2_mm, dtype=float)
    return (np.asarray(center_distance_mm, dtype=float) + 0.5 * (d1 + d2)) * np.maximum(d1, d2)


def disc_mass_kg(d_mm, width_mm):
    """Mass of a solid steel disc of diameter d and width b [kg]: ρ·π/4·d²·b (our blank model).

    >>> round(float(disc_mass_kg(100, 10)), 4)
    0.6165
    """
    d, b = np.asarray(d_mm, dtype=float), np.asarray(width_mm, dtype=float)
    return STEEL_DENSITY_KG_M3 * math.pi / 4.0 * d * d * b * 1e-9


@lru_cache(maxsize=64)
def _named_material(name: str):
    from ..gears.strength import material   # here: the materials catalog loads pandas
    return material(name)


def stage_material(value):
    """A gear stage's material as a geardesign Material (a catalog name is looked up once: ~20 ms each)."""
    return _named_material(value) if isinstance(value, str) else value


def _efficiency(eta):
    return one_number("efficiency", require_range("efficiency", eta, *EFFICIENCY_RANGE, lo_open=True))


def _name(name, default):
    if name is None:
        return default
    if not isinstance(name, str) or not name.strip():
        raise GearDesignError(f"name must be a non-empty string, got {name!r}")
    return name.strip()


def _range(name, value, lo, hi):
    try:
        a, b = value
    except (TypeError, ValueError):
        raise GearDesignError(f"{name} must be (min, max), got {value!r}") from None
    a = one_number(f"{name} min", require_range(f"{name} min", a, lo, hi))
    b = one_number(f"{name} max", require_range(f"{name} max", b, lo, hi))
    if a > b:
        raise GearDesignError(f"{name} must be (min, max) with min <= max, got {value!r}")
    return (a, b)


@dataclass(frozen=True)
class GivenStage:
    """A bought unit of fixed ratio and efficiency (a gear motor, a reducer).

    ``rated_output_torque_nm``, when given, is checked: margin 1 − T_out/[T] (check ``rated_torque``).
    """

    ratio: float
    efficiency: float
    name: str = "given"
    rated_output_torque_nm: float | None = None

    kind = "given"

    __repr__ = compact_repr     # only what differs from the defaults

    def __post_init__(self):
        object.__setattr__(self, "ratio", one_number("ratio", require_range("ratio", self.ratio, *GIVEN_RATIO_RANGE)))
        object.__setattr__(self, "efficiency", _efficiency(self.efficiency))
        object.__setattr__(self, "name", _name(self.name, "given"))
        if self.rated_output_torque_nm is not None:
            object.__setattr__(self, "rated_output_torque_nm", one_number("rated_output_torque_nm", require_range(
                "rated_output_torque_nm", self.rated_output_torque_nm, 0.0, 1e9, lo_open=True, unit="N·m")))

    def margins(self, torque_out_nm):
        """{check: margin array} at output torques ``torque_out_nm`` (N·m)."""
        if self.rated_output_torque_nm is None:
            return {}
        return {"rated_torque": 1.0 - np.asarray(torque_out_nm, dtype=float) / self.rated_output_torque_nm}


# GearStage.module_series: ISO 54 series I first (series II only where no series I module gives a design), or both
MODULE_SERIES_RULES = ("preferred", "both")


@dataclass(frozen=True)
class GearStage:
    """A spur or helical external gear pair of module ``m`` [mm] (normal module when helical).

    Free variables: the tooth counts (``z1``/``z2`` None: z1 in ``z1_range``, z2 up to ``z2_max``,
    z2/z1 in ``ratio_range``) and the shifts (``x1``/``x2`` None: chosen per tooth pair by
    :func:`~geardesign.shifts.optimize.optimize_shifts` for ``shift_objective``; None follows the
    drive's objective: ``max_margin`` for max_margin, else ``max_x_sum``, the contact-strength
    choice). ``checks`` are the pair's geometric checks as for optimize_shifts (a dict of limits).
    ``face_width_mm`` enters ε_β (helical) and the mass model (default 4πm).

    ``m=None`` leaves the module (and, with ``face_width_mm=None``, the face width) to be sized by
    the load the stage carries: with a ``material``, the smallest module of the ISO 54 series (then the
    narrowest face width) whose ISO 6336 strength checks hold at each design's torque and speed
    (:mod:`geardesign.drives.stage_kinds.gear_strength`); or the sizing function installed with
    :func:`geardesign.drives.stage_kinds.set_sizing`. Without either such a stage is refused by name.

    ``module_series`` is how such a stage takes the ISO 54 series: "preferred" (the default) takes a module of
    series I (1, 1.25, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10, ...) wherever one gives the tooth pair a design that holds
    every check, and a series II module (1.125, 1.375, 1.75, 2.25, 2.75, 3.5, 4.5, 5.5, 7, 9, ...) only where none
    does (ISO 54:1996, DIN 780-1: series I is to be preferred to series II); "both" takes the smallest module of
    either series.

    ``life_h`` (None: endurance, Z_NT = Y_NT = 1) and ``application_factor`` (K_A) are the load case of
    the strength checks of a stage with a ``material``, as in :class:`geardesign.gears.strength.Load`.

    The housing and the shop (:mod:`geardesign.drives.housing`, :mod:`geardesign.gears.manufactured`):
    ``center_distance`` is "free" (the shifts' objective sets it), a standard series ("gost2185", the default of
    a stage sized by its load; "gost2185-1", "R10", "R20", "R40": the smallest standard a_w whose shift sum lies
    in the reducer window, the objective splitting it), or a housing's a_w in mm. ``shift_bounds`` is the window
    of x1 and x2 (default (−1.2, 1.2) for a stage sized by its load, else optimize_shifts' own).
    ``mating_type`` (GOST 1643-81 H … A; default "B" for a stage sized by its load, "none" otherwise) makes
    every design hold its geometric checks also at its manufactured state (teeth thinned by their allowances,
    the housing within its centre-distance allowance); the margins there are ``<check>_manufactured``.
    ``strength`` is a dict of :func:`~geardesign.gears.strength.pair_strength` options for the strength checks
    (``accuracy_grade``, ``nu40``, ``Rz_flank_um``, ``Rz_root_um``, ``S_Hmin``, ``S_Fmin``, ``factors``, ...;
    None: the model's defaults).

    ``spectrum`` sizes and checks the stage by its service life (ISO 6336-6, :mod:`geardesign.gears.checks.damage`):
    a :class:`~geardesign.drives.duty_cycle.DutyCycle` (relative to the stage's nominal load, the torque and speed the
    power flow brings it, over the required life ``life_h``) or a :class:`~geardesign.LoadSpectrum` (the torques
    in N·m and speeds of the stage's pinion as they are, whatever the flow; ``life_h`` None: its duration). The
    damage checks ``pitting_damage1``, ``pitting_damage2``, ``root_damage1``, ``root_damage2`` (margin 1 − D) then
    join the stage's checks, with ``sn_curve`` and ``mean_stress_factor`` (Y_M, needed when the torque reverses) as
    :func:`~geardesign.gears.strength.service_life.pair_life` takes them. ``single_load`` (default True) keeps the
    strength checks at the nominal load beside them; False sizes the stage by the spectrum alone.

    ``efficiency``: None (the default) takes :data:`GEAR_EFFICIENCY` (0.98), or the efficiency computed from the
    stage's losses when the drive has a :class:`~geardesign.drives.shafting.Shafting` with a lubricant; a given
    number always wins (``efficiency_given`` records which: it is set from ``efficiency`` and carried over by
    ``dataclasses.replace``).
    """

    m: float | None = None
    z1: int | None = None
    z2: int | None = None
    x1: float | None = None
    x2: float | None = None
    efficiency: float | None = None
    checks: dict | None = None
    beta_deg: float = 0.0
    face_width_mm: float | None = None
    z1_range: tuple = (17, 25)
    z2_max: int = 150
    ratio_range: tuple = (1.0, 6.3)
    shift_objective: str | None = None
    name: str = "gear"
    material: object = None
    life_h: float | None = None
    application_factor: float = 1.0
    center_distance: object = None
    shift_bounds: tuple | None = None
    mating_type: str | None = None
    strength: dict | None = None
    spectrum: object = None
    sn_curve: str = "iso"
    mean_stress_factor: object = None
    single_load: bool = True
    module_series: str = "preferred"
    efficiency_given: bool | None = field(default=None, repr=False)

    kind = "gear"

    def __repr__(self) -> str:
        """Only what differs from the defaults (an efficiency only when given)."""
        text = compact_repr(self)
        if self.efficiency_given:
            return text
        return text.replace(f"efficiency={self.efficiency:g}, ", "").replace(f", efficiency={self.efficiency:g})", ")")

    def __post_init__(self):
        if self.m is not None:    # None: sized by the load (see the class docstring)
            object.__setattr__(self, "m", one_number("m (module)", require_module(self.m)))
        if self.efficiency_given is None:   # resolved once; a replace() carries it over with the number
            object.__setattr__(self, "efficiency_given", self.efficiency is not None)
        object.__setattr__(self, "efficiency", _efficiency(GEAR_EFFICIENCY if self.efficiency is None
                                                          else self.efficiency))
        object.__setattr__(self, "name", _name(self.name, "gear"))
        object.__setattr__(self, "beta_deg", one_number("beta_deg", require_range("beta_deg", self.beta_deg,
                                                                                   *BETA_RANGE_DEG, unit="deg")))
        if self.face_width_mm is not None:
            object.__setattr__(self, "face_width_mm", one_number("face_width_mm", require_range(
                "face_width_mm", self.face_width_mm, *FACE_WIDTH_RANGE_MM, lo_open=True, unit="mm")))
        for k in ("z1", "z2"):
            if getattr(self, k) is not None:
                object.__setattr__(self, k, require_count(k, getattr(self, k), Z_MIN, Z_MAX))
        if (self.x1 is None) != (self.x2 is None):
            raise GearDesignError("give both x1 and x2 (fixed shifts) or neither (shifts chosen per tooth pair)")
        if self.x1 is not None and (self.z1 is None or self.z2 is None):
            raise GearDesignError("fixed shifts x1/x2 need fixed tooth counts z1 and z2")
        lo, hi = (int(v) for v in _range("z1_range", self.z1_range, Z_MIN, Z_MAX))
        object.__setattr__(self, "z1_range", (lo, hi))
        object.__setattr__(self, "z2_max", require_count("z2_max", self.z2_max, Z_MIN, Z_MAX))
        object.__setattr__(self, "ratio_range", _range("ratio_range", self.ratio_range, 1.0, 100.0))
        if self.checks is not None and not isinstance(self.checks, dict):
            raise GearDesignError(f"checks must be a dict of limits (eps_alpha_min, sa_min, undercut, interference, "
                                  f"eps_gamma_min), got {type(self.checks).__name__}")
        resolve_checks(self.checks)    # unknown keys are refused here, not mid-search
        if self.material is not None:   # an unknown material is refused here, not mid-search
            stage_material(self.material)
        from ..gears.strength.load import APPLICATION_FACTOR_RANGE, LIFE_RANGE_H
        object.__setattr__(self, "application_factor", one_number("application_factor", require_range(
            "application_factor", self.application_factor, *APPLICATION_FACTOR_RANGE)))
        if self.life_h is not None:
            object.__setattr__(self, "life_h", one_number("life_h", require_range(
                "life_h", self.life_h, *LIFE_RANGE_H, lo_open=True, unit="h")))
        if self.strength is not None:   # options out of range are refused here, not mid-search
            if not isinstance(self.strength, dict):
                raise GearDesignError(f"strength must be a dict of pair_strength options, got "
                                      f"{type(self.strength).__name__}")
            from ..gears.strength.chain import check_options   # here: the chain loads the materials catalog
            object.__setattr__(self, "strength", dict(check_options(self.strength)))
        self._check_spectrum()
        if self.x1 is not None and self.m is not None:
            self.fixed_pair()          # a fixed pair that cannot be built is refused here
        from .housing import check_center_distance
        object.__setattr__(self, "center_distance", check_center_distance(self.center_distance))
        if self.shift_bounds is not None:
            lo, hi = _range("shift_bounds", self.shift_bounds, -3.0, 3.0)
            if not lo < hi:
                raise GearDesignError(f"shift_bounds must be (min, max) with min < max, got {self.shift_bounds!r}")
            object.__setattr__(self, "shift_bounds", (lo, hi))
        if self.mating_type is not None:
            from ..gears.backlash import GOST1643_TYPES
            if self.mating_type not in GOST1643_TYPES + ("none",):
                raise GearDesignError(f"mating_type must be one of {', '.join(GOST1643_TYPES)} (GOST 1643-81) or "
                                      f"'none', got {self.mating_type!r}")
        if self.shift_objective is not None:
            if self.shift_objective not in OBJECTIVES:
                raise GearDesignError(f"shift_objective must be one of {', '.join(OBJECTIVES)}, "
                                      f"got {self.shift_objective!r}")
        if self.module_series not in MODULE_SERIES_RULES:
            raise GearDesignError(f"module_series must be one of {', '.join(MODULE_SERIES_RULES)} (ISO 54 series I "
                                  f"first, or both series alike), got {_show(self.module_series)}")

    def _check_spectrum(self) -> None:
        """The service-life load case (``spectrum``, ``sn_curve``, ``mean_stress_factor``, ``single_load``) checked
        here, not mid-search."""
        from ..gears.spectrum import MEAN_STRESS_FACTOR_RANGE, SN_CURVES, LoadSpectrum
        from ..validate import require_bool, require_choice
        from .duty_cycle import DutyCycle

        require_choice("sn_curve", self.sn_curve, SN_CURVES)
        require_bool("single_load", self.single_load)
        if self.mean_stress_factor is not None:
            y_m = require_range("mean_stress_factor", self.mean_stress_factor, *MEAN_STRESS_FACTOR_RANGE).ravel()
            if y_m.size not in (1, 2):
                raise GearDesignError(f"mean_stress_factor must be Y_M or (Y_M1, Y_M2), got {self.mean_stress_factor!r}")
            object.__setattr__(self, "mean_stress_factor", float(y_m[0]) if y_m.size == 1 else tuple(map(float, y_m)))
        s = self.spectrum
        if s is None:
            if not self.single_load:
                raise GearDesignError(f"gear stage '{self.name}': single_load=False needs a spectrum (the stage "
                                      f"would have no load check)")
            return
        if not isinstance(s, (DutyCycle, LoadSpectrum)):
            raise GearDesignError(f"gear stage '{self.name}': spectrum must be a DutyCycle (relative to the stage's "
                                  f"nominal load) or a LoadSpectrum (its pinion's loads), got {type(s).__name__}")
        if self.material is None:
            raise GearDesignError(f"gear stage '{self.name}': a spectrum needs a material (the damage checks' S-N "
                                  f"curves, ISO 6336-5)")
        if isinstance(s, DutyCycle) and self.life_h is None:
            raise GearDesignError(f"gear stage '{self.name}': a DutyCycle needs life_h, the required life its time "
                                  f"shares divide (h)")
        if isinstance(s, LoadSpectrum) and s.per_tooth:
            raise GearDesignError(f"gear stage '{self.name}': a spectrum counted per tooth belongs to one pair's "
                                  f"teeth; give a stage bins of torque, speed and time")
        if s.reverses and self.mean_stress_factor is None:
            raise GearDesignError(f"gear stage '{self.name}': the spectrum's torque reverses (a negative bin), so the "
                                  f"roots bend both ways: give mean_stress_factor (Y_M in "
                                  f"[{MEAN_STRESS_FACTOR_RANGE[0]:g}, {MEAN_STRESS_FACTOR_RANGE[1]:g}], ISO 6336-3:2019)")

    def spectrum_at(self, torque_nm: float, n_rpm: float):
        """The spectrum on the stage's pinion at the nominal ``torque_nm`` (N·m) and ``n_rpm`` (rpm) the flow brings
        it (a DutyCycle scaled to them over ``life_h``; a LoadSpectrum as given); None without a spectrum."""
        from .duty_cycle import DutyCycle

        if isinstance(self.spectrum, DutyCycle):
            return self.spectrum.at(torque_nm, n_rpm, self.life_h)
        return self.spectrum

    @property
    def free_shifts(self) -> bool:
        return self.x1 is None

    @property
    def sized(self) -> bool:
        """True when the load sizes the stage (no module given)."""
        return self.m is None

    @property
    def housing(self):
        """The centre distance rule in force: "free", a series name or a_w in mm (None: by the stage)."""
        if self.center_distance is None:
            return "gost2185" if self.sized else "free"
        return self.center_distance

    @property
    def bounds(self):
        """The window of x1 and x2 in force (None: optimize_shifts' own)."""
        if self.shift_bounds is None:
            from .housing import REDUCER_SHIFT_BOUNDS
            return REDUCER_SHIFT_BOUNDS if self.sized else None
        return self.shift_bounds

    @property
    def fit(self):
        """The GOST 1643-81 mating type of the manufactured state in force, or None."""
        if self.mating_type is None:
            from ..gears.manufactured import DEFAULT_MATING_TYPE
            return DEFAULT_MATING_TYPE if self.sized else None
        return None if self.mating_type == "none" else self.mating_type

    @property
    def width_mm(self) -> float:
        """Face width of the mass model [mm]: the given one, else 4πm (a stage sized by load has
        none before it is sized)."""
        if self.face_width_mm is not None:
            return self.face_width_mm
        if self.m is None:
            raise GearDesignError(f"gear stage '{self.name}' has no module yet (m=None: sized by its load)")
        return FACE_WIDTH_PITCHES * math.pi * self.m

    @renamed_keywords(speed_rpm="n_rpm")
    def load(self, torque_nm: float, n_rpm: float):
        """The strength checks' load case: ``torque_nm`` on the pinion at ``n_rpm`` (``speed_rpm=`` is its old
        name), with the stage's life and application factor."""
        return Load(torque_nm=float(torque_nm), n_rpm=float(n_rpm), life_h=self.life_h,
                    application_factor=self.application_factor)

    def checks_key(self) -> tuple:
        return tuple(sorted((self.checks or {}).items()))

    def pairs(self, ratio_lo: float, ratio_hi: float):
        """(z1, z2) int arrays of the tooth pairs to consider with z2/z1 in [ratio_lo, ratio_hi]
        (intersected with ``ratio_range``), at most :data:`GEAR_PAIRS_MAX`."""
        lo, hi = max(ratio_lo, self.ratio_range[0]), min(ratio_hi, self.ratio_range[1])
        z1 = np.arange(self.z1_range[0], self.z1_range[1] + 1) if self.z1 is None else np.array([self.z1])
        z2_top = self.z2_max if self.z2 is None else self.z2
        z2 = np.arange(int(z1.min()), z2_top + 1) if self.z2 is None else np.array([self.z2])
        Z1, Z2 = np.meshgrid(z1, z2, indexing="ij")
        u = Z2 / Z1
        ok = (u >= lo * (1 - 1e-12)) & (u <= hi * (1 + 1e-12))
        if ok.sum() > GEAR_PAIRS_MAX:
            raise GearDesignError(f"gear stage '{self.name}' would enumerate {int(ok.sum())} tooth pairs, more than "
                                  f"{GEAR_PAIRS_MAX}: narrow z1_range, z2_max or ratio_range")
        return Z1[ok].astype(np.int64), Z2[ok].astype(np.int64)

    def fixed_pair(self):
        """The GearPair of fixed tooth counts and shifts."""
        return GearPair(self.m, self.z1, self.z2, self.x1, self.x2, beta_deg=self.beta_deg,
                        face_width_mm=self.face_width_mm)


@dataclass(frozen=True)
class ChainStage:
    """A roller-chain drive sized from a catalog by :func:`geardesign.drives.chain.design`.

    Free variables: the catalog row (pitch, strands; ``designation`` fixes it) and the sprocket
    teeth (``z1``/``z2`` None: z1 odd from 13 to the rule 29 − 2u, z2 up to ``z2_max``, z2/z1 in
    ``ratio_range``). The other keywords are chain.design's (operating factors, [p], [s], method,
    centre distance, sag factor); ``objective`` picks the chain in :meth:`Drive.analyse` when the
    row is free (the drive's own objective picks it in :meth:`Drive.optimize`).
    """

    catalog: str = "gost13568"
    z1: int | None = None
    z2: int | None = None
    strands: tuple | None = None
    efficiency: float = 0.96
    designation: str | None = None
    conditions: object = None
    k_e: float | None = None
    allowable_pressure_mpa: float | None = None
    allowable_safety_factor: float | None = None
    method: str = "hinge_pressure"
    center_distance_mm: float | None = None
    sag_factor: float = 6.0
    z2_max: int = 120
    ratio_range: tuple = (1.0, 7.0)
    objective: str = "min_mass"
    name: str = "chain"
    _inputs: object = field(default=None, init=False, repr=False, compare=False)

    kind = "chain"

    __repr__ = compact_repr     # only what differs from the defaults

    def __post_init__(self):
        object.__setattr__(self, "efficiency", _efficiency(self.efficiency))
        object.__setattr__(self, "name", _name(self.name, "chain"))
        if self.strands is not None and ndim(self.strands) not in (0, 1):
            raise GearDesignError(f"strands must be strand counts (1, 2, 3), got {_show(self.strands)}")
        object.__setattr__(self, "strands", (1, 2, 3) if self.strands is None else tuple(np.atleast_1d(self.strands).tolist()))
        object.__setattr__(self, "ratio_range", _range("ratio_range", self.ratio_range, *RATIO_RANGE))
        # chain.design's own validation, once, at a placeholder load (the load comes from the drive)
        inp = validate_inputs(1.0, None, 100.0, 1.0, self.conditions, self.k_e, self.allowable_pressure_mpa,
                              self.allowable_safety_factor, self.catalog, self.strands, self.z1,
                              self.center_distance_mm, self.objective, self.method, self.sag_factor, self.z2_max, 40.0)
        object.__setattr__(self, "_inputs", inp)
        if self.z2 is not None:
            require_count("z2", self.z2, Z1_RANGE[0], self.z2_max)
            if self.z1 is None:
                raise GearDesignError("a fixed z2 needs a fixed z1 (the chain stage's ratio is z2/z1)")
        if self.designation is not None:
            if not isinstance(self.designation, str):
                raise GearDesignError(f"designation must be a chain designation (text), got {_show(self.designation)}")
            rows = self.table().values["designation"]
            if self.designation not in set(np.asarray(rows, dtype=object).tolist()):
                raise GearDesignError(f"designation {self.designation!r} is not in catalog {self.catalog!r}")

    def table(self):
        """The validated chain catalog (read once per file version)."""
        return load_chains(self._inputs, catalog_dir())

    def rows(self) -> np.ndarray:
        """Catalog rows this stage may use (its strand counts, its designation if fixed)."""
        chains = self.table()
        ok = np.isin(chains.strands, self.strands)
        if self.designation is not None:
            ok &= np.asarray(chains.values["designation"], dtype=object) == self.designation
        return np.flatnonzero(ok)

    def pairs(self, ratio_lo: float, ratio_hi: float):
        """(z1, z2) sprocket teeth with z2/z1 in [ratio_lo, ratio_hi] ∩ ``ratio_range``; without a
        given z1, the odd counts 13 … max(29 − 2u, 13) of chain.design's rule for that u."""

        lo, hi = max(ratio_lo, self.ratio_range[0]), min(ratio_hi, self.ratio_range[1])
        z1 = np.arange(13, 28, 2) if self.z1 is None else np.array([int(self.z1)])
        z2 = np.arange(int(z1.min()), self.z2_max + 1) if self.z2 is None else np.array([int(self.z2)])
        Z1, Z2 = np.meshgrid(z1, z2, indexing="ij")
        u = Z2 / Z1
        ok = (u >= lo * (1 - 1e-12)) & (u <= hi * (1 + 1e-12)) & (Z2 <= self.z2_max)
        if self.z1 is None:
            rule = np.maximum(np.vectorize(recommended_z1)(np.where(ok, u, 1.0)), 13)
            ok &= Z1 <= rule
        return Z1[ok].astype(np.int64), Z2[ok].astype(np.int64)

    def design_kwargs(self) -> dict:
        """chain.design's keywords of this stage (the load and ratio are the drive's)."""
        kw = dict(conditions=self.conditions, k_e=self.k_e, allowable_pressure_mpa=self.allowable_pressure_mpa,
                  allowable_safety_factor=self.allowable_safety_factor, catalog=self.catalog, strands=self.strands,
                  center_distance_mm=self.center_distance_mm, objective=self.objective, method=self.method,
                  sag_factor=self.sag_factor, z2_max=self.z2_max)
        return kw


@dataclass(frozen=True)
class Shaft:
    """A keyed hub on shaft ``at`` of the drive (0: input shaft, k: output shaft of stage k).

    Its key is picked by :func:`geardesign.drives.key.select` (the longest standard length that
    fits the hub, one key, else two at 180°) for the torque of that shaft.
    """

    d_mm: float
    hub_length_mm: float
    at: int
    name: str | None = None
    allowable_crush_mpa: float | None = None
    allowable_shear_mpa: float | None = None
    end: str = "rounded"
    max_keys: int = 2

    __repr__ = compact_repr     # only what differs from the defaults

    def __post_init__(self):
        object.__setattr__(self, "at", require_count("at (shaft number)", self.at, 0, 64))
        object.__setattr__(self, "name", _name(self.name, f"shaft {self.at}"))
        if self.allowable_crush_mpa is None:
            object.__setattr__(self, "allowable_crush_mpa", key.DEFAULT_CRUSH_MPA)
        if self.allowable_shear_mpa is None:
            object.__setattr__(self, "allowable_shear_mpa", key.DEFAULT_SHEAR_MPA)
        sel = self.select(1e-6)    # the key table, the hub and the limits are checked here
        if sel.length_mm is None:
            raise GearDesignError(f"shaft '{self.name}': hub_length_mm = {self.hub_length_mm:g}: {sel.message}")

    def select(self, torque_nm):
        """key.select for this hub at ``torque_nm`` [N·m]."""
        return key.select(self.d_mm, torque_nm, self.hub_length_mm, self.allowable_crush_mpa,
                          self.allowable_shear_mpa, self.end, self.max_keys)
