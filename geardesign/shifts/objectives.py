"""Objectives of the shift problem, as objects like the checks: a registry by name, and a user's own.

Every objective is "maximise the smallest piece": F = min_k piece_k(geo) = sense · fun, with one
piece for a smooth objective and two for balanced sliding (max |ϑ| is the larger of two).
``max_margin`` is the exception: its pieces are the checks' normalised margins, which the
problem builds itself (``kind = "margin"``).

>>> sorted(OBJECTIVES)[:5]
['balanced_root_strength', 'balanced_sliding', 'max_eps_alpha', 'max_life', 'max_margin']
>>> OBJECTIVES["max_x_sum"].pieces({"_x1": 0.5, "_x2": 0.25})
(0.75,)
"""
from __future__ import annotations

import math
from typing import Callable

import numpy as np

from ..errors import GearDesignError
from ..gears.checks import ContactRatio, sliding_root_gradient
from ..gears.checks.damage import PittingDamage, RootDamage
from ..validate import _short

__all__ = ["Objective", "CustomObjective", "MaxLife", "DAMAGE_FLOOR", "unlimited_life_note", "OBJECTIVES", "register_objective", "unregister_objective",
           "resolve_objective", "default_objective"]


class Objective:
    """What a solve optimises. ``sense`` is +1 for "max_*" goals and −1 for "min_*" goals;
    ``x_sum_only`` marks goals that depend on x1 + x2 alone (constant on a fixed-a_w line)."""

    name = ""
    sense = +1
    kind = "smooth"            # "smooth", "minimax" (min of pieces) or "margin" (Chebyshev centre)
    description = ""
    x_sum_only = False
    needs_report_fields = False   # see Check.needs_report_fields
    needs_load = False            # True: reads the safety factors of the strength checks (a load case)

    def pieces(self, geo) -> tuple:
        """Values whose minimum is sense · fun (floats or arrays, as ``geo`` holds)."""
        raise NotImplementedError

    def piece_gradients(self, geo) -> list | None:
        """[(∂piece/∂x1, ∂piece/∂x2)] per piece, or None for central differences."""
        return None

    def bound(self, checks) -> "Objective":
        """This objective for a problem with ``checks`` (an objective that reads a load case takes it from
        the strength checks); most objectives need nothing and return themselves."""
        return self

    def __repr__(self) -> str:
        return f"<objective {self.name}: {self.description}>"


class MaxXSum(Objective):
    name, sense, x_sum_only = "max_x_sum", +1, True
    description = "largest x_Σ = x1 + x2 (x2 − x1 for a ring pair): the largest α_w, contact strength"

    def pieces(self, geo):
        return (geo["_x2"] + geo.get("_sgn", 1.0) * geo["_x1"],)

    def piece_gradients(self, geo):
        return [(geo.get("_sgn", 1.0), 1.0)]


class MaxEpsAlpha(Objective):
    name, sense, description = "max_eps_alpha", +1, "largest transverse contact ratio ε_α"

    def pieces(self, geo):
        return (geo["eps_alpha"],)

    def piece_gradients(self, geo):
        return [ContactRatio().gradient(geo)]


class BalancedSliding(Objective):
    name, sense, kind = "balanced_sliding", -1, "minimax"
    description = "smallest max(|ϑ1|, |ϑ2|) at the roots; equal sliding at both ends where no check stops it"

    def pieces(self, geo):
        return (-abs(geo["sliding1_root"]), -abs(geo["sliding2_root"]))

    def piece_gradients(self, geo):
        out = []
        for gear in (1, 2):
            sign = np.sign(geo[f"sliding{gear}_root"])
            d1, d2 = sliding_root_gradient(geo, gear)
            out.append((-sign * d1, -sign * d2))
        return out


class MinSpecificPressure(Objective):
    name, sense, x_sum_only = "min_specific_pressure", -1, True
    description = "smallest specific pressure coefficient at the pitch point"

    def pieces(self, geo):
        return (-geo["spec_pressure_pitch"],)

    def piece_gradients(self, geo):
        # Γ ∝ 1/tan α_w depends on x_Σ only: ∂(−Γ)/∂x_Σ = Γ · 2 tan α_n / (z_Σ tan³α_w cos²α_w), with
        # x_Σ, z_Σ = x2 − x1, z2 − z1 for a ring pair (∂x_Σ/∂x1 = −1)
        zs = geo["_z2"] - geo["_z1"] if geo["_sgn"] < 0 else geo["_z1"] + geo["_z2"]
        g = (geo["spec_pressure_pitch"] * 2.0 * geo["_tn"]
             / (zs * geo["_t_w"] ** 3 * geo["_cos_w"] ** 2))
        return [(geo["_sgn"] * g, g)]


class MaxMargin(Objective):
    name, sense, kind = "max_margin", +1, "margin"
    description = "the point farthest (in x) from every check's boundary (robust design)"

    def pieces(self, geo):
        return (0.0 * geo["_x1"],)

    def piece_gradients(self, geo):
        return [(0.0, 0.0)]


class _StrengthObjective(Objective):
    """An objective over the safety factors of the problem's strength checks (ISO 6336): the load case
    and the minimum safety factors are theirs, so a problem has them only with a load."""

    kind, needs_load = "minimax", True
    checks: tuple = ()

    def bound(self, checks):
        found = tuple(c for c in checks if c.name in ("contact_strength", "root_strength1", "root_strength2"))
        if not found:
            raise GearDesignError(f"objective {self.name!r} needs a load: give the checks load=, material= and "
                                  f"face_width_mm= (e.g. checks={{'load': gd.Load(...), 'material': '42CrMo4'}})")
        out = type(self)()
        out.checks = found
        return out

    def pieces(self, geo):
        """S/S_min of the bound checks called ``_names``."""
        return tuple(c.value(geo) / c.limit for c in self.checks if c.name in self._names)

    def piece_gradients(self, geo):
        return [tuple(c.gradient(geo)) for c in self.checks if c.name in self._names]


class BalancedRootStrength(_StrengthObjective):
    name, sense = "balanced_root_strength", +1
    description = "largest min(S_F1, S_F2): equal root safety of both gears where no check stops it"
    _names = ("root_strength1", "root_strength2")


class MaxMinSafety(_StrengthObjective):
    name, sense = "max_min_safety", +1
    description = "largest smallest safety factor, each relative to its minimum (S_H/S_Hmin, S_F/S_Fmin)"
    _names = ("contact_strength", "root_strength1", "root_strength2")


# D below this counts as no damage: ln D stays finite (a piece of ~690, never the smallest where some gear is
# damaged) and its gradient is taken as 0 (the S-N curve's horizontal end, where the life is unbounded)
DAMAGE_FLOOR = 1e-300
# max_life's fun where no gear takes damage: −ln DAMAGE_FLOOR
UNLIMITED_LIFE_FUN = -math.log(DAMAGE_FLOOR)


def unlimited_life_note(objective: str, fun: float) -> str:
    """What a ``max_life`` result whose every damage sum is 0 means, appended to its message ("" otherwise): every bin
    lies below each S-N curve's endurance, so the life is unlimited there and max_life cannot rank such designs.

    >>> unlimited_life_note("max_life", UNLIMITED_LIFE_FUN)[:41]
    '; no gear takes damage at this point (the'
    >>> unlimited_life_note("max_life", 2.0), unlimited_life_note("max_x_sum", UNLIMITED_LIFE_FUN)
    ('', '')
    """
    if objective != "max_life" or fun < UNLIMITED_LIFE_FUN * (1 - 1e-12):
        return ""
    return ("; no gear takes damage at this point (the spectrum's every bin below the S-N curves' endurance: the life "
            f"is unlimited, and fun is its cap ln(1/{DAMAGE_FLOOR:g})): max_life cannot rank designs that all live "
            "for ever, so the point is one corner of the other checks among equally good ones; another objective "
            "chooses among them")


class MaxLife(Objective):
    """The longest service life under the load spectrum (ISO 6336-6): the largest smallest
    ln(L_k/L_req) = −ln D_k over the damage checks (pitting and root of both gears, every load case; D_k
    Miner's sum over the required life L_req), so fun = ln(L/L_req) of the governing gear and mode and the life
    is L = L_req·e^fun; a problem has it only with a spectrum (the damage checks,
    :mod:`geardesign.gears.checks.damage`, whose D <= D_max still hold)."""

    name, sense, kind, needs_load = "max_life", +1, "minimax", True
    description = ("longest service life under the spectrum: largest min ln(L/L_req) = −ln D over the "
                   "damage checks (ISO 6336-6)")
    checks: tuple = ()

    def bound(self, checks):
        found = tuple(c for c in checks if isinstance(c, (PittingDamage, RootDamage)))
        if not found:
            raise GearDesignError(f"objective {self.name!r} needs a load spectrum: give the checks spectrum=, "
                                  f"material= and face_width_mm= (e.g. checks={{'spectrum': gd.LoadSpectrum(...), "
                                  f"'material': '42CrMo4', 'face_width_mm': 40}})")
        out = type(self)()
        out.checks = found
        return out

    def pieces(self, geo):
        return tuple(life_piece(c.value(geo)) for c in self.checks)

    def piece_gradients(self, geo):
        out = [life_piece_gradient(c.value(geo), c.spec.damage(geo, gradients=True)[f"dD_{c.mode}{c.gear}"])
               for c in self.checks]
        return [tuple(float(v) if np.ndim(v) == 0 else v for v in g) for g in out]


def life_piece(D):
    """max_life's piece of a damage sum D: −ln D = ln(L/L_req), D floored at :data:`DAMAGE_FLOOR` (no damage)."""
    return -np.log(np.maximum(np.asarray(D, dtype=float)[()], DAMAGE_FLOOR))


def life_piece_gradient(D, grad) -> tuple:
    """∂(−ln D)/∂x = −(∂D/∂x)/D of :func:`life_piece` for ``grad`` = (∂D/∂x1, ∂D/∂x2); 0 where there is no damage."""
    D = np.asarray(D, dtype=float)[()]
    with np.errstate(divide="ignore", invalid="ignore"):
        return tuple(np.where(D > DAMAGE_FLOOR, -np.asarray(g) / D, 0.0)[()] for g in grad)


class CustomObjective(Objective):
    """A user's own goal: ``func(geo) -> value`` (geo holds the
    :data:`~geardesign.gears.geometry.GEOMETRY_FIELDS` names, floats or arrays), maximised with
    ``sense="max"`` or minimised with ``sense="min"``; gradients by central differences.

    >>> o = CustomObjective("min_da1", lambda g: g["da1"], sense="min")
    >>> o.sense, float(o.pieces({"da1": 40.0})[0])
    (-1, -40.0)
    """

    def __init__(self, name: str, func: Callable, sense: str = "max", description: str = ""):
        if not isinstance(name, str) or not name:
            raise GearDesignError(f"CustomObjective needs a name (a non-empty string), got {_short(name)}")
        if not callable(func):
            raise GearDesignError(f"CustomObjective {name!r}: func must be callable, got {_short(func)}")
        if sense not in ("max", "min"):
            raise GearDesignError(f"CustomObjective {name!r}: sense must be 'max' or 'min', got {_short(sense)}")
        self.name, self.func = name, func
        self.sense = +1 if sense == "max" else -1
        self.description = description or f"{sense}imise {name}"
        self.needs_report_fields = True

    def pieces(self, geo):
        return (self.sense * np.asarray(self.func(geo), dtype=float)[()],)


OBJECTIVES: dict[str, Objective] = {o.name: o for o in (MaxXSum(), MaxEpsAlpha(), BalancedSliding(),
                                                          MinSpecificPressure(), MaxMargin(), BalancedRootStrength(),
                                                          MaxMinSafety(), MaxLife())}


def register_objective(objective: Objective) -> Objective:
    """Add an :class:`Objective` object to :data:`OBJECTIVES` under its name: every method, the CLI's
    ``--objective`` and the scenes then offer it (docs/extending.md)."""
    if not isinstance(objective, Objective) or not objective.name:
        raise GearDesignError(f"register_objective takes a named geardesign Objective, got {_short(objective)}")
    if objective.name in OBJECTIVES:
        raise GearDesignError(f"an objective called {objective.name!r} exists already")
    OBJECTIVES[objective.name] = objective
    return objective


def unregister_objective(name: str) -> None:
    """Remove a registered objective (tests and examples clean up with it)."""
    OBJECTIVES.pop(name, None)


def resolve_objective(objective) -> Objective:
    """A registered name or an :class:`Objective` object."""
    if isinstance(objective, Objective):
        return objective
    if isinstance(objective, str) and objective in OBJECTIVES:
        return OBJECTIVES[objective]
    raise GearDesignError(f"objective must be one of {list(OBJECTIVES)} or an Objective object, "
                          f"got {_short(objective)}")


def default_objective(objective, x_sum_fixed: bool) -> Objective:
    """``max_x_sum`` on the plane; ``balanced_sliding`` on a fixed-a_w line, where objectives of
    the x-sum alone are constant and refused."""
    if objective is None:
        return OBJECTIVES["balanced_sliding" if x_sum_fixed else "max_x_sum"]
    objective = resolve_objective(objective)
    if x_sum_fixed and objective.x_sum_only:
        others = [o for o, obj in OBJECTIVES.items() if not obj.x_sum_only]
        raise GearDesignError(
            f"objective {objective.name!r} depends on x1 + x2 alone, which a_w fixes: nothing to optimise; "
            f"with a fixed center distance choose one of {others}")
    return objective
