"""The checks of a worm pair as signed, dimensionless margins (>= 0 holds) in the check registry
(:mod:`geardesign.gears.checks.base`, pair kind ``"worm"``): the wheel's undercut, the worm's and the wheel's
tip thickness (pointed teeth), the wheel's shift in its usual range, the worm length and wheel width the mesh
needs, and the mid-plane contact ratio. Each reads the dict of
:func:`~geardesign.gears.worm.geometry.worm_geometry`; lengths are divided by the axial module m_x.

Build them with ``make_checks(kind="worm", ...)``; the options the spur pair has already (``undercut``,
``sa_min``, ``eps_alpha_min``) mean the same here, the worm's own (``x2_abs_max``, ``worm_length_min``,
``wheel_width_max``) are built for worm pairs only.

With a load (``make_checks(kind="worm", worm_load=WormLoad(T2_nm, n1_rpm, casting, application_factor))``) the AGMA load check
``agma_load`` joins them: S_AGMA = T2_all/T2 >= S_AGMAmin, T2_all the wheel torque ANSI/AGMA 6034-B92 allows at
the worm speed (:func:`~geardesign.gears.worm.agma.agma_capacity`), over arrays (the drive's search hands one
torque and speed per design).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...errors import GearDesignError
from ...validate import require_range
from ..checks.base import Check, Option, register, register_context
from ..checks.external import (DEFAULT_EPS_ALPHA_MIN, DEFAULT_SA_MIN, EPS_ALPHA_MIN, EPS_ALPHA_MIN_RANGE, SA_MIN,
                               SA_MIN_RANGE, UNDERCUT)

__all__ = ["WheelUndercut", "WormTipThickness", "WheelTipThickness", "WheelShiftRange", "WormLength", "WheelWidth",
           "WormContactRatio", "X2_ABS_MAX_RANGE", "DEFAULT_X2_ABS_MAX", "worm_options", "WormLoad", "AgmaLoad",
           "AGMA_SAFETY_RANGE"]

DEFAULT_X2_ABS_MAX = 1.0
X2_ABS_MAX_RANGE = (0.0, 3.0)
X2_ABS_MAX = Option("x2_abs_max", "limit", DEFAULT_X2_ABS_MAX, "largest |x2| of a worm wheel",
                    source="|x2| <= 1: the range a GOST-based worm generator accepts (Dmitry-Lisitsyn/"
                           "WormGearGenerator, Helpers/DataValidation.cs); GOST 19650's own clause not retrieved",
                    range=X2_ABS_MAX_RANGE, cli=False)
WORM_LENGTH = Option("worm_length_min", "flag", True,
                     "the worm's threaded length b_1 >= pi m_x (4.5 + 0.02 z2) (a worm pair)",
                     source="SDP/SI-KHK, Elements of Metric Gear Technology (D785), worm gear mesh geometry",
                     cli=False)
WHEEL_WIDTH = Option("wheel_width_max", "flag", True, "the wheel's face width b_2 <= 0.75 d_a1 (a worm pair)",
                     source="the GOST-based course-design rule b_2 <= 0.75 d_a1 (course project 'Proektuvannya "
                            "cherv'yachnoyi peredachi reduktora', ukrbukva.net)", cli=False)


@register
@dataclass(frozen=True)
class WheelUndercut(Check):
    """No undercut of the wheel by its hob: x2 >= x_min2 (margin x2 − x_min2)."""

    option, pair_kinds, colour, order = UNDERCUT, ("worm",), "tab:blue", 10

    def __post_init__(self):
        object.__setattr__(self, "name", self.name or "undercut2")
        object.__setattr__(self, "label", self.label or "no undercut of the wheel (x2 >= x_min2)")

    def value(self, geo):
        return geo["x2"]

    def limit_value(self, geo):
        return geo["x_min2"]


@dataclass(frozen=True)
class _TipThickness(Check):
    """Tip thickness >= sa_min·m_x (margin s/m_x − sa_min)."""

    limit: float = DEFAULT_SA_MIN
    field = ""

    def __post_init__(self):
        require_range("sa_min", self.limit, *SA_MIN_RANGE)

    def value(self, geo):
        return geo[self.field] / geo["m_x"]


@register
@dataclass(frozen=True)
class WormTipThickness(_TipThickness):
    """The worm's thread on its tip cylinder, normal section: s_an1/m_x >= sa_min."""

    option, pair_kinds, colour, order, field = SA_MIN, ("worm",), "tab:orange", 50, "san1"

    def __post_init__(self):
        super().__post_init__()
        object.__setattr__(self, "name", self.name or "tip_thickness1")
        object.__setattr__(self, "label", self.label or "worm tip thickness: s_an1/m_x >= sa_min (normal section)")


@register
@dataclass(frozen=True)
class WheelTipThickness(_TipThickness):
    """The wheel's tooth on its throat circle in the mid-plane: s_a2/m_x >= sa_min (0: not pointed)."""

    option, pair_kinds, colour, order, field = SA_MIN, ("worm",), "tab:orange", 51, "sa2"

    def __post_init__(self):
        super().__post_init__()
        object.__setattr__(self, "name", self.name or "tip_thickness2")
        object.__setattr__(self, "label", self.label or "wheel tip thickness (pointed teeth): s_a2/m_x >= sa_min")


@register
@dataclass(frozen=True)
class WheelShiftRange(Check):
    """The wheel's shift in its usual range, |x2| <= x2_abs_max (margin x2_abs_max − |x2|)."""

    option, pair_kinds, colour, order = X2_ABS_MAX, ("worm",), "tab:gray", 55

    limit: float = DEFAULT_X2_ABS_MAX

    def __post_init__(self):
        require_range("x2_abs_max", self.limit, *X2_ABS_MAX_RANGE)
        object.__setattr__(self, "name", self.name or "x2_range")
        object.__setattr__(self, "label", self.label or "|x2| <= x2_abs_max")

    def value(self, geo):
        return np.abs(geo["x2"])

    def margin(self, geo):
        return self.limit - self.value(geo)


@register
@dataclass(frozen=True)
class WormLength(Check):
    """The threaded worm length covers the mesh: (b_1 − b_1,min)/m_x >= 0."""

    option, pair_kinds, colour, order = WORM_LENGTH, ("worm",), "tab:green", 56

    def __post_init__(self):
        object.__setattr__(self, "name", self.name or "worm_length")
        object.__setattr__(self, "label", self.label or "worm length b_1 >= pi m_x (4.5 + 0.02 z2)")

    def value(self, geo):
        return geo["b_1"] / geo["m_x"]

    def limit_value(self, geo):
        return geo["b_1_min"] / geo["m_x"]


@register
@dataclass(frozen=True)
class WheelWidth(Check):
    """The wheel's face stays within what the worm embraces: (0.75 d_a1 − b_2)/m_x >= 0."""

    option, pair_kinds, colour, order = WHEEL_WIDTH, ("worm",), "olive", 57

    def __post_init__(self):
        object.__setattr__(self, "name", self.name or "wheel_width")
        object.__setattr__(self, "label", self.label or "wheel width b_2 <= 0.75 d_a1")

    def value(self, geo):
        return geo["b_2"] / geo["m_x"]

    def limit_value(self, geo):
        return geo["b_2_max"] / geo["m_x"]

    def margin(self, geo):
        return self.limit_value(geo) - self.value(geo)


@register
@dataclass(frozen=True)
class WormContactRatio(Check):
    """Contact ratio of the mid-plane mesh ε_α >= eps_alpha_min (margin ε_α − limit)."""

    option, pair_kinds, colour, order = EPS_ALPHA_MIN, ("worm",), "tab:purple", 60

    limit: float = DEFAULT_EPS_ALPHA_MIN

    def __post_init__(self):
        require_range("eps_alpha_min", self.limit, *EPS_ALPHA_MIN_RANGE)
        object.__setattr__(self, "name", self.name or "contact_ratio")
        object.__setattr__(self, "label", self.label or "mid-plane contact ratio eps_alpha >= eps_alpha_min")

    def value(self, geo):
        return geo["eps_alpha"]


AGMA_SAFETY_RANGE = (0.5, 10.0)
AGMA_SAFETY = Option("S_AGMAmin", "limit", 1.0, "smallest AGMA 6034 load safety W_t,all/W_t of a worm pair, with a load",
                     source="Shigley ch. 15: W_t,all >= W_t with the design factor n_d in the load (n_d = 1.2 in "
                            "Example 15-4); 1.0 leaves n_d to the user", range=AGMA_SAFETY_RANGE, cli=False)


@dataclass(frozen=True, eq=False)
class WormLoad:
    """The load case of the worm's AGMA check: the wheel (output) torque ``T2_nm`` (N·m) at the worm speed
    ``n1_rpm`` (rpm), the bronze wheel's ``casting`` ("sand", "chill", "centrifugal") and the application factor
    ``application_factor`` (K_A). The torque and speed may be arrays (one per design, broadcast with the geometry)."""

    T2_nm: object
    n1_rpm: object
    casting: str = "sand"
    application_factor: float = 1.0

    def __post_init__(self):
        from .agma import _casting
        object.__setattr__(self, "T2_nm", require_range("T2_nm", self.T2_nm, 0.0, 1e9, lo_open=True, unit="N·m"))
        object.__setattr__(self, "n1_rpm", require_range("n1_rpm", self.n1_rpm, 0.0, 1e6, lo_open=True, unit="rpm"))
        _casting(self.casting)
        require_range("application_factor", self.application_factor, 1.0, 10.0)


@register
@dataclass(frozen=True)
class AgmaLoad(Check):
    """The load a worm pair carries by ANSI/AGMA 6034-B92 (Shigley ch. 15): S_AGMA = T2_all/T2 >= S_AGMAmin,
    margin S_AGMA/S_AGMAmin − 1. Built only with a ``worm_load`` (:class:`WormLoad`)."""

    option, pair_kinds, colour, order = AGMA_SAFETY, ("worm",), "deeppink", 80

    limit: float = 1.0
    load: WormLoad | None = None

    @classmethod
    def build(cls, value, context: dict) -> list:
        load = context.get("worm_load")
        if load is None:
            return []
        if not isinstance(load, WormLoad):
            raise GearDesignError(f"worm_load must be a geardesign.gears.worm.checks.WormLoad, got {type(load).__name__}")
        return [cls(limit=value, load=load)]

    def __post_init__(self):
        require_range("S_AGMAmin", self.limit, *AGMA_SAFETY_RANGE)
        object.__setattr__(self, "name", self.name or "agma_load")
        object.__setattr__(self, "label", self.label or "AGMA 6034 load: T2_all/T2 >= S_AGMAmin (Shigley ch. 15)")

    def value(self, geo):
        from .agma import agma_capacity   # here: the rating's formulas load only with a load
        return agma_capacity(geo, self.load.n1_rpm, self.load.casting, self.load.application_factor)["T2_all"] / self.load.T2_nm

    def margin(self, geo):
        return self.value(geo) / self.limit - 1.0


register_context(("worm_load",), lambda context: {})


def worm_options() -> dict:
    """The registered options that build checks of a worm pair from its geometry alone, by name (the worm command's
    check options; the AGMA load check's ``S_AGMAmin`` goes with a load: the rating's and the drive stage's)."""
    from ..checks.base import registered

    out = {}
    for cls in registered():
        if "worm" in cls.pair_kinds and cls is not AgmaLoad:
            out.setdefault(cls.option.name, cls.option)
    return out
