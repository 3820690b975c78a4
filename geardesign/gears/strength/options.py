"""The options of :func:`~geardesign.gears.strength.chain.pair_strength` that are numbers, or a pair of them (one per
gear), checked by name against their ranges before any work."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...errors import GearDesignError
from ...validate import one_number
from . import accuracy as acc
from . import defaults as dflt
from .factors import TRANSVERSE_DEVIATIONS, gear_blank_factor
from .ops import checked

__all__ = ["validate_options", "shaft_option", "blank_option", "transverse_option", "TIP_RELIEF_RANGE_UM",
           "SHAFT_RANGES", "BLANK_RANGES", "StrengthOptions", "GROUPED", "DEFAULT_OPTIONS",
           "gathered"]

TIP_RELIEF_RANGE_UM = (0.0, 1000.0)    # C_a given: from none to a millimetre (a relief of module size)
# the pinion shaft of ISO 6336-1:2006 7.6.2.2, eq. (44) (factors.shaft_misalignment's keywords): K' is one of the
# standard's ±0.48, ±0.8, ±1.33, -0.36, -0.6 (Fig. 13); l the bearing span, s the pinion's offset from its middle,
# d_sh the shaft's diameter (mm)
# a webbed wheel's (b_s/b, s_R/m_n) for C_R: open below; beyond the standard's 0.2..1.2 and >= 1 C_R takes the ends
BLANK_RANGES = ((0.0, 100.0), (0.0, 1000.0))
SHAFT_RANGES = {"K_prime": (-2.0, 2.0), "l_mm": (0.0, 1e5), "s_mm": (0.0, 1e5), "d_sh_mm": (0.0, 1e5)}


def _not_bool(name, value):
    if isinstance(value, (bool, np.bool_)):
        raise GearDesignError(f"{name} must be a number, got {value!r}")
    return value


def _pair_option(name, value, check) -> tuple:
    """An option with a value per gear, (gear 1, gear 2): a tuple or list of two, each ``check``-ed."""
    if not isinstance(value, (tuple, list)) or len(value) != 2:
        raise GearDesignError(f"{name} must be a pair (gear 1, gear 2), got {value!r}")
    return tuple(check(_not_bool(name, v)) for v in value)


def _per_gear_options(cycles_per_rev, rim_mm, bore_ratio, tip_relief_um) -> tuple:
    """The options of the two gears (pairs) and the tip relief, checked."""
    cpr = _pair_option("cycles_per_rev", cycles_per_rev, lambda c: _number("cycles_per_rev", c, 1, 1000))
    rim_mm = _pair_option("rim_mm", rim_mm, lambda r: None if r is None else _number(
        "rim_mm", r, *dflt.FACE_WIDTH_RANGE_MM, lo_open=True, unit="mm"))
    bore_ratio = _pair_option("bore_ratio", bore_ratio, lambda q: _number("bore_ratio", q, 0.0, 1.0, hi_open=True))
    if tip_relief_um is not None:
        tip_relief_um = _number("tip_relief_um", _not_bool("tip_relief_um", tip_relief_um), *TIP_RELIEF_RANGE_UM,
                                unit="µm")
    return cpr, rim_mm, bore_ratio, tip_relief_um


def validate_options(accuracy_grade, nu40, Rz_flank_um, Rz_root_um, K_gamma, root_method, S_Hmin, S_Fmin,
                      cycles_per_rev, rim_mm, bore_ratio, tip_relief_um) -> tuple:
    """The options of :func:`pair_strength` that are numbers (or pairs of them), checked: (grade, nu40, Rz, Rz_root,
    K_gamma, root_method, (S_Hmin, S_Fmin), cycles_per_rev, rim_mm, bore_ratio, tip_relief_um)."""
    grade = checked("accuracy_grade", accuracy_grade, *acc.GRADE_RANGE)
    grade = grade if type(grade) is float else float(grade) if np.ndim(grade) == 0 else grade
    return (grade, _number("nu40", nu40, *dflt.NU40_RANGE, unit="mm²/s"),
            _number("Rz_flank_um", Rz_flank_um, *dflt.RZ_RANGE_UM, unit="µm"),
            _number("Rz_root_um", Rz_root_um, dflt.RZ_RANGE_UM[0], dflt.RZ_ROOT_MAX_UM, unit="µm"),
            _number("K_gamma", K_gamma, *dflt.K_GAMMA_RANGE),
            root_method if root_method in ("B", "C") else _bad_method(root_method),
            (_number("S_Hmin", S_Hmin, 0.5, 10.0), _number("S_Fmin", S_Fmin, 0.5, 10.0)),
            *_per_gear_options(cycles_per_rev, rim_mm, bore_ratio, tip_relief_um))


def _number(name, value, lo, hi, **kw):
    """One number in [lo, hi] as a Python float (refused by name otherwise)."""
    value = checked(name, value, lo, hi, **kw)
    return value if type(value) is float else one_number(name, value)


def _bad_method(root_method):
    raise GearDesignError(f"root_method must be 'B' (ISO 6336-3:2019, load at the outer point of single pair "
                          f"contact) or 'C' (tip load with Y_eps, ISO 6336-3:1996), got {root_method!r}")


def shaft_option(shaft) -> dict:
    """``shaft`` (None or a dict of :data:`SHAFT_RANGES`' keywords) as a dict of checked numbers."""
    if shaft is None:
        return {}
    if not isinstance(shaft, dict):
        raise GearDesignError(f"shaft must be a dict of {', '.join(SHAFT_RANGES)} (ISO 6336-1 eq. (44)), got "
                              f"{type(shaft).__name__}")
    unknown = sorted(set(shaft) - set(SHAFT_RANGES), key=str)
    if unknown:
        raise GearDesignError(f"shaft: unknown key {', '.join(map(repr, unknown))}; allowed: {', '.join(SHAFT_RANGES)}")
    return {k: _number(f"shaft[{k!r}]", _not_bool(f"shaft[{k!r}]", v), *SHAFT_RANGES[k],
                       lo_open=k in ("l_mm", "d_sh_mm"), unit="" if k == "K_prime" else "mm")
            for k, v in shaft.items()}


def _one_blank(value):
    """One gear's (b_s/b, s_R/m_n), checked; None: a solid disc gear."""
    if value is None:
        return None
    if not isinstance(value, (tuple, list)) or len(value) != 2:
        raise GearDesignError(f"gear_blank must be None (solid gears), (b_s/b, s_R/m_n) or one such pair or None per "
                              f"gear, got {value!r}")
    return tuple(_number(name, _not_bool(name, v), lo, hi, lo_open=True)
                 for name, v, (lo, hi) in zip(("gear_blank b_s/b", "gear_blank s_R/m_n"), value, BLANK_RANGES))


def blank_option(gear_blank) -> float:
    """C_R of ``gear_blank`` (see :func:`~geardesign.gears.strength.chain.pair_strength`): 1.0 for None (solid
    gears), the factor of one (b_s/b, s_R/m_n) for both gears, or the mean of the two gears' factors (a solid gear's
    1.0) for a pair of them.

    >>> blank_option(None), round(blank_option((0.25, 5.0)), 4), round(blank_option((None, (0.25, 5.0))), 4)
    (1.0, 0.898, 0.949)
    """
    if gear_blank is None:
        return 1.0
    if (isinstance(gear_blank, (tuple, list)) and len(gear_blank) == 2
            and all(g is None or isinstance(g, (tuple, list)) for g in gear_blank)):
        per_gear = [_one_blank(g) for g in gear_blank]
        return sum(1.0 if g is None else float(gear_blank_factor(*g)) for g in per_gear) / 2.0
    return float(gear_blank_factor(*_one_blank(gear_blank)))


def transverse_option(which) -> str:
    """``transverse_deviation`` checked: one of :data:`~.factors.TRANSVERSE_DEVIATIONS`."""
    if isinstance(which, str) and which in TRANSVERSE_DEVIATIONS:
        return which
    raise GearDesignError(f"transverse_deviation must be 'larger' (the larger of f_pb and f_falpha, ISO 6336-1:2006 "
                          f"8.3.2) or 'f_pb', got {which!r}")
# The options of pair_strength that describe the gears' making, lubrication and rating (not the design or its
# load), grouped in one object: ``pair_strength(..., options=StrengthOptions(accuracy_grade=6, nu40=320))``.
GROUPED = ("accuracy_grade", "nu40", "Rz_flank_um", "Rz_root_um", "root_method", "factors", "K_gamma", "tip_relief_um",
           "bore_ratio", "shaft", "pitting_permitted", "optimum_life", "S_Hmin", "S_Fmin", "cycles_per_rev", "rim_mm",
           "gear_blank", "transverse_deviation")


@dataclass(frozen=True)
class StrengthOptions:
    """The options of :func:`~geardesign.gears.strength.chain.pair_strength` in one object (their meaning, units and
    ranges: its docstring and docs/glossary.md), checked by name when made. Passed as ``options=``, instead of
    the same keywords one by one (giving both is refused).

    >>> StrengthOptions(accuracy_grade=6, nu40=320).nu40
    320
    >>> StrengthOptions(root_method="A")
    Traceback (most recent call last):
    ...
    geardesign.errors.GearDesignError: root_method must be 'B' (ISO 6336-3:2019, load at the outer point of single pair contact) or 'C' (tip load with Y_eps, ISO 6336-3:1996), got 'A'
    """

    accuracy_grade: float = dflt.ACCURACY_GRADE
    nu40: float = dflt.NU40_MM2_S
    Rz_flank_um: float = dflt.RZ_FLANK_UM
    Rz_root_um: float = dflt.RZ_ROOT_UM
    root_method: str = "B"
    factors: dict | None = None
    K_gamma: float = 1.0
    tip_relief_um: float | None = None
    bore_ratio: tuple = (0.0, 0.0)
    shaft: dict | None = None
    pitting_permitted: bool = False
    optimum_life: bool = False
    S_Hmin: float = dflt.S_HMIN
    S_Fmin: float = dflt.S_FMIN
    cycles_per_rev: tuple = (1, 1)
    rim_mm: tuple = (None, None)
    gear_blank: object = None
    transverse_deviation: str = dflt.TRANSVERSE_DEVIATION

    def __post_init__(self):
        blank_option(self.gear_blank)
        transverse_option(self.transverse_deviation)
        validate_options(self.accuracy_grade, self.nu40, self.Rz_flank_um, self.Rz_root_um, self.K_gamma,
                         self.root_method, self.S_Hmin, self.S_Fmin, self.cycles_per_rev, self.rim_mm,
                         self.bore_ratio, self.tip_relief_um)
        shaft_option(self.shaft)
        if self.factors is not None and not isinstance(self.factors, dict):
            raise GearDesignError(f"factors must be a dict of factor values, got {type(self.factors).__name__}")


def gathered(keywords: dict) -> dict:
    """``keywords`` (of :func:`~geardesign.gears.strength.chain.pair_strength`) with the options among them
    (:data:`GROUPED`, given one by one) gathered into ``options=`` one :class:`StrengthOptions`: how the callers
    inside the package, which carry the options as a dict (a checks dict's ``strength``, a scene's, the command
    line's), call it the one way. Both at once are refused by name."""
    loose = [k for k in GROUPED if k in keywords]
    if not loose:
        return keywords
    if keywords.get("options") is not None:
        raise GearDesignError(f"give the strength options either as options= or as keywords, not both: "
                              f"{', '.join(loose)}")
    out = {k: v for k, v in keywords.items() if k not in GROUPED}
    out["options"] = StrengthOptions(**{k: keywords[k] for k in loose})
    return out


# every option at its default: what pair_strength uses without options= (its default objects are those of any
# StrengthOptions() made elsewhere, which lets the chain skip checking them again)
DEFAULT_OPTIONS = StrengthOptions()


