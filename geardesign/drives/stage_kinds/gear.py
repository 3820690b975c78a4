"""The external gear pair (:class:`~geardesign.drives.stages.GearStage`) as a stage kind: tooth pairs
as options, each solved for its shifts in the branch and bound (kept in a cache between calls),
base circles as the bound below its cost; drawn as two meshing circles.

By load: a stage with a ``material`` gets the ISO 6336 strength checks at the torque and speed
flowing into it (:mod:`.gear_strength`: ``contact_strength``, ``root_strength1``, ``root_strength2``);
a stage whose module is None has its module (and face width, when not given) chosen per design
from the ISO 54 series so that they hold. Another sizing rule can be installed, ``set_sizing(fn)``::

    fn(torque_nm, n_rpm, z1, z2, *, modules, stage) -> [(m_mm, face_width_mm or None), ...]

``modules`` is the ISO 54 series (``catalogs/modules_iso54.csv``, both series) the module must be
taken from; the candidates come smallest (preferred) first, and the stage takes the first whose
checks hold. A stage with ``m=None`` needs a material or such a function.
"""
from __future__ import annotations

import math
import threading
from pathlib import Path
from dataclasses import replace
from collections import OrderedDict
from functools import lru_cache

import numpy as np

from ...errors import GearDesignError
from ...gears.geometry import M_RANGE_MM, X_ABS_MAX, require_module
from ...gears.mesh import BETA_RANGE_DEG, FACE_WIDTH_RANGE_MM, Z_MAX, Z_MIN
from ...validate import one_number, require_range
from ...catalogs.tables import module_series
from ...gears.checks import resolve_checks
from ...gears.pair import GearPair
from ...shifts.centres import margin_centres
from ...shifts.objectives import OBJECTIVES
from ...shifts.optimize import optimize_shifts
from ..limits import LOOK_AHEAD, MARGIN_AHEAD, MARGIN_TOL, SHIFT_CACHE, SIZING_TRIES
from ..stages import (EFFICIENCY_RANGE, FACE_WIDTH_PITCHES, MODULE_SERIES_RULES, GearStage, disc_mass_kg,
                      stage_area_mm2, stage_material)
from .base import ToothedKind
from .gear_strength import _widths, check_names, life_options, safety_limits, strength_margins, strength_sizes, strength_sizes_many, widest_width
from ...gears.center_distance import x_sum_from_center_distance

__all__ = ["GearKind", "set_sizing", "shift_solution", "gear_solution", "margin_solutions", "clear_shift_cache"]


class _Solved:
    """Solved tooth pairs by their key (m, z1, z2, checks, β, b, shift objective), the last SHIFT_CACHE kept
    between calls; ``misses`` counts the solves (one by one or in a batch). On a Dask worker, what a chunk
    solves is also noted in its thread's ``journal`` (sent back to the caller's cache: :meth:`GearKind.absorb`)."""

    def __init__(self, size: int):
        self.size, self.data, self.misses = size, OrderedDict(), 0
        self.local = threading.local()     # a worker may run chunks side by side in its threads

    def get(self, key):
        sol = self.data.get(key)
        if sol is not None:
            self.data.move_to_end(key)
        return sol

    def put(self, key, sol: dict) -> dict:
        self.misses += 1
        self.keep(key, sol)
        journal = getattr(self.local, "journal", None)
        if journal is not None:
            journal[key] = sol
        return sol

    def keep(self, key, sol: dict) -> None:
        """``sol`` remembered, not counted as a solve (one made elsewhere)."""
        self.data[key] = sol
        if len(self.data) > self.size:
            self.data.popitem(last=False)

    def clear(self) -> None:
        self.data.clear()
        self.misses = 0


_SOLVED = _Solved(SHIFT_CACHE)


def clear_shift_cache() -> None:
    """Forget every solved tooth pair (a benchmark's first call)."""
    _SOLVED.clear()


def _pair_key(stage: GearStage, z1: int, z2: int, objective: str) -> tuple:
    """What a tooth pair's shift solution depends on: (m, z1, z2, checks, β, b, shift objective, a_w of the
    housing or None, the shift window or None, the mating type of the manufactured state or None)."""
    return _solution_key(stage, stage.m, z1, z2, housing_center_distance(stage, z1, z2), objective,
                         stage.face_width_mm)


def _solution_key(stage: GearStage, m, z1: int, z2: int, a_w, objective: str, face_width_mm) -> tuple:
    """:func:`_pair_key` at module m and housing a_w (a sized stage's candidates, without building each stage)."""
    if a_w is not None and objective in ("max_x_sum", "min_specific_pressure"):
        objective = "balanced_sliding"     # a housing fixes the x-sum: the objective splits it (optimize_shifts)
    return (m, int(z1), int(z2), stage.checks_key(), stage.beta_deg, face_width_mm, objective, a_w, stage.bounds,
            stage.fit)


def housing_center_distance(stage: GearStage, z1: int, z2: int):
    """The a_w [mm] a stage of known module puts the pair at: None (free), the housing's, or the smallest
    standard one of its series whose x-sum lies in the reducer window (NaN: none does)."""
    rule = stage.housing
    if rule == "free":
        return None
    if not isinstance(rule, str):
        return float(rule)
    from ..housing import standard_center_distance
    return float(standard_center_distance(stage.m, int(z1), int(z2), rule, stage.beta_deg))


def shift_solution(key: tuple) -> dict:
    """The shifts of one tooth pair (its :func:`_pair_key`) by optimize_shifts (exact), with the pair's geometry
    and margins."""
    sol = _SOLVED.get(key)
    return sol if sol is not None else _SOLVED.put(key, _solve_shifts(*key))


def _solve_shifts(m, z1, z2, checks_key, beta_deg, face_width_mm, objective, a_w=None, bounds=None,
                  fit=None) -> dict:
    from ...shifts.problem import DEFAULT_BOUNDS

    checks = dict(checks_key) or None
    if a_w is not None and not math.isfinite(a_w):
        return dict(feasible=False, reason="no standard centre distance gives a shift sum in the reducer window "
                                           "(geardesign.drives.housing.REDUCER_X_SUM_WINDOW)", margins={})
    try:
        r = optimize_shifts(int(z1), int(z2), objective, checks, "exact", m=m, beta_deg=beta_deg,
                            face_width_mm=face_width_mm, a_w=a_w, bounds=DEFAULT_BOUNDS if bounds is None else bounds)
    except GearDesignError as exc:
        return dict(feasible=False, reason=str(exc), margins={})
    if not (r.success and not r.conflict):
        why = "conflict: " + ", ".join(r.conflict) if r.conflict else r.message
        return dict(feasible=False, reason=why, margins=dict(r.margins))
    pair = GearPair(m, int(z1), int(z2), r.x1, r.x2, beta_deg=beta_deg, face_width_mm=face_width_mm)
    geo = pair.geometry()
    sol = dict(feasible=True, reason="", x1=r.x1, x2=r.x2, margins=dict(r.margins), a_w=geo.a_w, da1=geo.da1,
               da2=geo.da2, a_w_housing=a_w)
    return _with_shop(sol, pair, checks, fit) if fit is not None else sol


@lru_cache(maxsize=64)
def _geometric_checks(checks_key: tuple) -> tuple:
    return resolve_checks({"jamming": False, **dict(checks_key)})


def _with_shop(sol: dict, pair, checks, fit: str) -> dict:
    """``sol`` with the margins of its manufactured state (``<check>_manufactured``, GOST 1643-81 mating type
    ``fit``), failing when one of them fails."""
    from ...gears.manufactured import MANUFACTURED_CHECKS, manufactured_margins, shop_allowances

    allow = shop_allowances(pair, fit)
    limits = {c.name: (sol["margins"][c.name], c.limit) for c in _geometric_checks(tuple(sorted((checks or {}).items())))
              if c.name in MANUFACTURED_CHECKS and c.name in sol["margins"]}
    shop = {f"{k}_manufactured": v for k, v in manufactured_margins(pair, limits, allow).items()
            if v != sol["margins"].get(k)}
    failing = [k for k, v in shop.items() if not v >= -MARGIN_TOL]
    out = dict(sol, margins={**sol["margins"], **shop}, allowances=allow)
    if failing:
        why = "fails at the manufactured state: " + ", ".join(failing)
        out.update(feasible=False, reason=f"{sol['reason']}; {why}" if sol["reason"] else why)
    return out


def margin_solutions(stage: GearStage, pairs: list) -> None:
    """The ``max_margin`` shifts of many tooth pairs of a stage of known module solved together
    (:func:`geardesign.shifts.centres.margin_centres`: each pair's solution bit for bit the one
    :func:`shift_solution` gives alone) into the cache; a pair the batch does not certify is left for
    :func:`shift_solution` to solve alone."""
    if stage.housing != "free" or stage.bounds is not None or stage.fit is not None:
        return    # the batch solves free shifts in the default window: these pairs are solved one by one
    todo = list(dict.fromkeys(k for k in (_pair_key(stage, z1, z2, "max_margin") for z1, z2 in pairs)
                              if _SOLVED.get(k) is None))
    if len(todo) < 2:
        return
    z1, z2 = np.array([k[1:3] for k in todo]).T
    try:
        r = margin_centres(z1, z2, stage.m, dict(stage.checks_key()) or None, stage.beta_deg, stage.face_width_mm)
    except GearDesignError:    # one by one, each with its own reason
        return
    for j in np.flatnonzero(r["ok"]):
        _SOLVED.put(todo[j], dict(
            feasible=True, reason="", x1=float(r["x1"][j]), x2=float(r["x2"][j]),
            margins={k: float(v[j]) for k, v in r["margins"].items()},
            a_w=float(r["a_w"][j]), da1=float(r["da1"][j]), da2=float(r["da2"][j])))


def _shift_objective(stage: GearStage, objective: str) -> str:
    """The objective a stage's free shifts are solved for: its own, else max_margin for a max_margin drive or a
    stage checked at its manufactured state in a free housing (max_x_sum puts such a pair on its ε_α boundary,
    which the shop's thinner teeth then cross: every design failed contact_ratio_manufactured), and max_x_sum
    (the contact-strength choice) for the others."""
    if stage.shift_objective:
        return stage.shift_objective
    robust = objective == "max_margin" or (stage.fit is not None and stage.housing == "free")
    return "max_margin" if robust else "max_x_sum"


def gear_solution(stage: GearStage, z1: int, z2: int, objective: str) -> dict:
    """Shifts, geometry and margins of one tooth pair of a gear stage of known module (fixed or
    solved shifts)."""
    if not stage.free_shifts:
        pair = stage.fixed_pair()
        table = pair.checks(**{"jamming": False, **(stage.checks or {})})
        geo = pair.geometry()
        margins = dict(zip(table["check"], table["margin"].astype(float)))
        failing = [k for k, v in margins.items() if v < -MARGIN_TOL]
        sol = dict(feasible=not failing, reason=("fails " + ", ".join(failing)) if failing else "", x1=pair.x1,
                   x2=pair.x2, margins=margins, a_w=geo.a_w, da1=geo.da1, da2=geo.da2)
        return _with_shop(sol, pair, stage.checks, stage.fit) if stage.fit is not None else sol
    return shift_solution(_pair_key(stage, z1, z2, _shift_objective(stage, objective)))


def _base_circle_bounds(stage: GearStage, m: float, z1, z2):
    """Lower bounds of a gear stage's size [mm²] whatever its shifts: base circles (below every tip
    circle) at the centre distance a·cos α_t (below every operating one); and the blank discs'
    mass on those circles at the stage's face width [kg]."""
    alpha_t = math.atan(math.tan(math.radians(20.0)) / math.cos(math.radians(stage.beta_deg)))
    scale = m / math.cos(math.radians(stage.beta_deg))
    db1, db2 = scale * z1 * math.cos(alpha_t), scale * z2 * math.cos(alpha_t)
    a_cos = 0.5 * scale * (z1 + z2) * math.cos(alpha_t)
    return stage_area_mm2(a_cos, db1, db2), db1, db2


_SIZING = [None]


def set_sizing(fn):
    """Install the function that sizes gear stages given without a module (None removes it);
    returns the one installed before."""
    if fn is not None and not callable(fn):
        raise GearDesignError(f"the gear sizing function must be callable, got {type(fn).__name__}")
    before, _SIZING[0] = _SIZING[0], fn
    return before


@lru_cache(maxsize=2)
def _series(which=(1, 2)) -> np.ndarray:
    """The ISO 54 modules of series ``which`` (read once: the catalog lookup costs ~3 ms, the search asks per tooth
    pair), sorted."""
    series = np.array(module_series(which), dtype=float)
    series.flags.writeable = False
    return series


def _series_rounds(stage: GearStage) -> tuple:
    """The module lists a stage sized by its strength tries in turn (``GearStage.module_series``): "preferred"
    series I, then both series (a tooth pair none of whose series I modules holds its checks takes the smallest
    module of either that does: one of series II); "both" both at once."""
    return (_series(1), _series()) if stage.module_series == "preferred" else (_series(),)


def _series_one_above(stage: GearStage, modules: np.ndarray, m: float):
    """On a standard centre distance, where a tooth pair's fit depends on each module's standard a_w: the index in
    ``modules`` of the series I module next above ``m`` when ``m`` is a series II module the stage would take
    (``module_series`` "preferred": it takes that series I module instead wherever it holds), else None. Only the
    next one: each module tried costs a shift solve, and the one after is 25-45 % larger than the series II one."""
    first = _series(1)
    if stage.module_series != "preferred" or np.any(first == m):
        return None
    above = first[first > m]
    at = np.flatnonzero(modules == above[0]) if above.size else ()
    return int(at[0]) if len(at) else None


def _shifts_scale_free(stage: GearStage) -> bool:
    """True when the pair's shift solution does not depend on its module and face width: each of its
    checks is a built-in geometric one, a margin in units of the module; the face width enters only
    ε_β, i.e. the ε_γ check of a helical pair. (A registered check or a strength check in ``checks``
    may depend on lengths in mm: such a stage is solved at each module. So is a stage checked at its manufactured
    state, ``fit``: GOST 1643's thickness allowances are µm that grow slower than m, so a design holding at m = 1
    may fail at its own module: a sized stage in a free housing was returned failing interference2_manufactured.)"""
    return stage.fit is None and _scale_free_checks(stage.checks_key(), stage.beta_deg != 0.0)


@lru_cache(maxsize=64)
def _scale_free_checks(checks_key: tuple, helical: bool) -> bool:
    from ...gears.checks.external import (ContactRatio, Interference, Jamming, TipThickness, TotalContactRatio,
                                          Undercut)

    free = (Undercut, Interference, Jamming, TipThickness, ContactRatio) + (() if helical else (TotalContactRatio,))
    return all(type(c) in free for c in resolve_checks(dict(checks_key) or None))


# a drive with a sized series II module ranks as this much larger (or heavier) than it is: it wins over drives of
# series I modules only when more than 5 % smaller (ISO 54, DIN 780-1: series I preferred); a neighbouring module
# of the other series is 9-14 % larger or smaller, its stage about twice that in area
SERIES_II_MARGIN = 0.05
CONTACT_SCREEN = 0.1   # a module whose contact margin at the even split is below −0.1 is not solved
STANDARD_TRIES = 1     # modules per pair and round of the standard-housing sizing
RESIZE_FIXED_POINT = 6  # sizings of a stage re-sized for its shafts' f_sh (GearKind.resize) before it gives up


_STANDARD_CACHE: dict = {}


def _standard_modules(stage: GearStage, z1: int, z2: int) -> tuple:
    """(modules, a_w, b for the shifts' ε_β or None, widest width, x_Σ) of the series modules that put z1/z2 on a
    standard centre distance of the stage's series (arrays; kept, they do not depend on the load)."""
    key = (stage.housing, stage.beta_deg, stage.face_width_mm, stage.z1_range, int(z1), int(z2))
    hit = _STANDARD_CACHE.get(key)
    if hit is None:
        from ..housing import standard_center_distance

        series = _series()
        a_w = np.asarray(standard_center_distance(series, z1, z2, stage.housing, stage.beta_deg), dtype=float)
        have = np.isfinite(a_w)
        ms, a_w = series[have], a_w[have]
        b_max = np.array([widest_width(stage, z1, m) for m in ms])
        b_ref = ([stage.face_width_mm] * ms.size if stage.face_width_mm is not None or stage.beta_deg == 0.0
                 else list(b_max))          # a helical stage's ε_β: the widest width's
        x_sum = np.asarray(x_sum_from_center_distance(ms, z1, z2, a_w, beta_deg=stage.beta_deg), dtype=float)
        hit = _STANDARD_CACHE.setdefault(key, (ms, a_w, b_ref, b_max, np.atleast_1d(x_sum)))
    return hit


def _strength_first_fits(stage, pairs, batch, flows):
    """(pair index, m, solution, b, {check: margin}) of each batch item's first width holding every strength
    check (else its closest) at its pair's flow, all items' widths in one strength call."""
    grids = [_widths(stage, np.array([m]), pairs[i][0])[1].ravel() for i, m, _ in batch]
    sizes = [g.size for g in grids]
    def rep(f):      # one value per batch item, repeated over its widths
        return np.concatenate([np.full(n, f(item)) for n, item in zip(sizes, batch)])

    B = np.concatenate(grids)
    M = rep(lambda it: it[1])
    Z1, Z2 = rep(lambda it: pairs[it[0]][0]), rep(lambda it: pairs[it[0]][1])
    X1, X2 = rep(lambda it: it[2]["x1"]), rep(lambda it: it[2]["x2"])
    T, N = rep(lambda it: flows[it[0]].torque_in_nm), rep(lambda it: flows[it[0]].n_in_rpm)
    margins = strength_margins(stage, M, B, Z1, Z2, X1, X2, T, N)
    worst = np.minimum.reduce(list(margins.values()))
    worst = np.where(np.isnan(worst), -np.inf, worst)
    start = 0
    for (i, m, sol), n in zip(batch, sizes):
        w = worst[start:start + n]
        ok = np.flatnonzero(w >= -MARGIN_TOL)
        j = start + (ok[0] if ok.size else int(np.argmax(w)))
        yield i, m, sol, float(B[j]), {k: float(v[j]) for k, v in margins.items()}
        start += n


def _at_module(stage: GearStage, m: float, face_width_mm) -> GearStage:
    """A sized stage at module m and width b with the rules it is sized under kept (its housing, shift window and
    mating type): a stage given m falls back to a free housing, the default window and no manufactured state,
    so ``replace(stage, m=m)`` alone solved a sized stage's candidates by other rules than the stage's (a free
    housing's sized stage came out with x2 = 2.18 and failed its manufactured state when analysed)."""
    return replace(stage, m=m, face_width_mm=face_width_mm, center_distance=stage.housing, shift_bounds=stage.bounds,
                   mating_type=stage.fit or "none")


def _sized_stage(stage: GearStage, sol: dict) -> GearStage:
    """The stage at the module and width its sizing chose, with the rules it was sized under made explicit (the
    housing's a_w as a number, the shift window, the mating type): the same shifts when solved again."""
    st = replace(stage, m=sol["m"], face_width_mm=sol["face_width_mm"], shift_bounds=stage.bounds,
                 mating_type=stage.fit or "none")
    if stage.housing != "free" and sol.get("a_w_housing") is not None:
        st = replace(st, center_distance=sol["a_w_housing"])    # the series value itself: the same key, shifts
    else:
        st = replace(st, center_distance="free")
    return st


class GearKind(ToothedKind):
    name = "gear"
    stage_class = GearStage
    colour = "#9ecae1"
    solved = True
    unsolved_label = "shifts"

    # -- by load
    def load_dependent(self, stage) -> bool:
        return stage.m is None or stage.material is not None

    def cost_grows_with_load(self, stage) -> bool:
        """A stage sized by the ISO 6336 strength (σ_H ∝ √T, σ_F ∝ T at a given module and width)."""
        return stage.m is None and _SIZING[0] is None and stage.material is not None

    def sizes(self, stage, torque_nm: float, speed_rpm: float, z1: int, z2: int) -> list:
        """The installed sizing function's (m, face width) candidates for one tooth pair at its load, checked."""
        fn = _SIZING[0]
        if fn is None:
            raise GearDesignError(f"gear stage '{stage.name}' has no module (m=None): its module is chosen by its "
                                  f"load, which needs a material (the ISO 6336 sizing) or a sizing function "
                                  f"(geardesign.drives.stage_kinds.gear.set_sizing); none is installed")
        series = _series()
        out = []
        for m, b in fn(float(torque_nm), float(speed_rpm), int(z1), int(z2), modules=series, stage=stage):
            m = one_number("m (module)", require_module(m))
            if not np.any(np.isclose(series, m, rtol=1e-12, atol=0)):
                raise GearDesignError(f"gear stage '{stage.name}': the sizing function gave m = {m:g} mm, not a "
                                      f"module of the ISO 54 series")
            if b is not None:
                b = one_number("face_width_mm", require_range("face_width_mm", b, 0.0, 1e4, lo_open=True, unit="mm"))
            out.append((m, b))
        if not out:
            raise GearDesignError(f"gear stage '{stage.name}': the sizing function gave no module for z1/z2 = "
                                  f"{z1}/{z2} at {torque_nm:.6g} N·m, {speed_rpm:.6g} rpm")
        return out

    @staticmethod
    def _with_strength(stage, sol: dict, z1: int, z2: int, flow) -> dict:
        """``sol`` with the stage's strength checks at ``flow`` (a stage of known module with a material)."""
        if stage.material is None or "x1" not in sol:
            return sol
        sm = strength_margins(stage, stage.m, stage.width_mm, z1, z2, sol["x1"], sol["x2"], flow.torque_in_nm,
                              flow.n_in_rpm)
        sm = {k: float(v) for k, v in sm.items()}
        out = dict(sol, margins={**sol["margins"], **sm})
        failing = [k for k, v in sm.items() if not v >= -MARGIN_TOL]
        if failing:
            why = "fails " + ", ".join(failing)
            out.update(feasible=False, reason=f"{sol['reason']}; {why}" if sol["reason"] else why)
        return out

    def _candidate(self, stage, m, b, z1, z2, objective, flow) -> dict:
        st = _at_module(stage, m, b)
        return dict(self._with_strength(st, gear_solution(st, z1, z2, objective), z1, z2, flow), m=m, face_width_mm=b)

    def _sized(self, stage, z1, z2, objective, flow) -> dict:
        """The first sized candidate whose checks hold (else the last tried, or the closest)."""
        if _SIZING[0] is None and stage.material is not None:
            return self._strength_sized(stage, z1, z2, objective, flow)
        for m, b in self.sizes(stage, flow.torque_in_nm, flow.n_in_rpm, z1, z2):
            sol = self._candidate(stage, m, b, z1, z2, objective, flow)
            if sol["feasible"]:
                break
        return sol

    def _strength_sized(self, stage, z1, z2, objective, flow) -> dict:
        """Module and width by the strength checks: shifts of the pair at m = 1, every series module × width
        checked at once at those shifts; the smallest candidate then holds every check when the shift
        solution does not depend on the module and width (``_shifts_scale_free``), else the smallest
        candidates are re-solved at their own module until one holds every check. Such a stage without a
        face width is solved at m = 1 with the widest width of the sizing range (ε_γ needs one: the
        widest ε_β, the most permissive reference)."""
        if stage.housing != "free":
            return self._standard_sized(stage, z1, z2, objective, flow)
        free = _shifts_scale_free(stage)
        b_ref = stage.face_width_mm if free or stage.face_width_mm is not None else widest_width(stage, z1)
        ref = gear_solution(_at_module(stage, 1.0, b_ref), z1, z2, objective)
        if "x1" not in ref:
            return dict(ref, m=math.nan, face_width_mm=None)
        for series in _series_rounds(stage):    # series I first: series II only where no series I module holds
            cands, best = strength_sizes(stage, flow.torque_in_nm, flow.n_in_rpm, z1, z2, ref["x1"], ref["x2"],
                                         series, MARGIN_TOL, 1 if free else SIZING_TRIES)
            if free and cands:   # the reference shifts are those of the first candidate (or the closest)
                return self._scaled(ref, *best)
            for m, b in ([] if free else cands):
                sol = self._candidate(stage, m, b, z1, z2, objective, flow)
                if sol["feasible"]:
                    return sol
        if free:
            return self._unsized(ref, *best)
        if cands:
            return sol
        sol = self._candidate(stage, best[0], best[1], z1, z2, objective, flow)
        return dict(sol, reason=f"no module of the ISO 54 series carries the load (closest m = {best[0]:g} mm, "
                                f"b = {best[1]:g} mm: {sol['reason']})")

    def _standard_sized(self, stage, z1, z2, objective, flow) -> dict:
        """:meth:`_standard_sized_many` of one tooth pair."""
        return self._standard_sized_many(stage, [(z1, z2)], objective, [flow])[0]

    def _standard_sized_many(self, stage, pairs: list, objective: str, flows: list) -> list:
        """Module and width of tooth pairs of a stage whose housing is standard, each at its flow (``flows``, one
        per pair; the strength calls take a load per design, so pairs at different flows share them: a search
        walking a drive meets most flows with one new pair each): for each module of
        the series (smallest first) the smallest standard a_w whose x-sum lies in the reducer window, the shifts
        that split it (with the manufactured state), then every width checked by the strength checks; each
        pair's first (m, b) holding every check. The shifts depend on the module (x_Σ follows from a_w/m), so
        each module's are solved (and kept); a module whose contact safety at the widest width falls more than
        :data:`CONTACT_SCREEN` short at the even split of x_Σ is passed over unsolved (the split moves S_H far
        less). The strength checks run in one vectorised call per round over all pairs, each round taking every
        unsettled pair's next :data:`STANDARD_TRIES` modules."""
        cands = [_standard_modules(stage, z1, z2) for z1, z2 in pairs]
        screen = self._contact_screen(stage, pairs, cands, flows)
        todo = [list(np.flatnonzero(ok)) for ok in screen]
        out: list = [None] * len(pairs)
        closest: list = [None] * len(pairs)
        held: list = [None] * len(pairs)      # a series II design, while the series I module above it is tried
        while True:
            batch = []          # (pair index, module, solution)
            for i, (z1, z2) in enumerate(pairs):
                took = 0
                while out[i] is None and todo[i] and took < STANDARD_TRIES:
                    k = todo[i].pop(0)
                    m, a_w, b_ref = cands[i][0][k], cands[i][1][k], cands[i][2][k]
                    sol = shift_solution(_solution_key(stage, float(m), z1, z2, float(a_w), _shift_objective(stage, objective),
                                                      b_ref))
                    if "x1" in sol and sol["feasible"]:
                        batch.append((i, float(m), sol))
                        took += 1
            if not batch:
                break
            for i, m, sol, b, margins in _strength_first_fits(stage, pairs, batch, flows):
                if out[i] is not None:
                    continue
                full = dict(sol, margins={**sol["margins"], **margins}, m=m, face_width_mm=b)
                worst = min(margins.values())
                if worst >= -MARGIN_TOL:
                    k = _series_one_above(stage, cands[i][0], m) if held[i] is None else None
                    if k is None:
                        out[i] = full
                    else:
                        held[i], todo[i] = full, [k]
                elif closest[i] is None or worst > closest[i][0]:
                    closest[i] = (worst, full)
        for i, (z1, z2) in enumerate(pairs):
            if out[i] is None and held[i] is not None:     # the series I module above holds no design
                out[i] = held[i]
            if out[i] is not None:
                continue
            if closest[i] is None:
                out[i] = dict(feasible=False, reason=f"no module of the ISO 54 series puts z1/z2 = {z1}/{z2} on a "
                                                     f"standard centre distance ({stage.housing}) that holds its "
                                                     f"checks", margins={}, m=math.nan, face_width_mm=None)
                continue
            sol = closest[i][1]
            failing = ", ".join(k for k, v in sol["margins"].items() if not v >= -MARGIN_TOL)
            out[i] = dict(sol, feasible=False, reason=f"no module of the ISO 54 series carries the load on a standard "
                                                     f"centre distance (closest m = {sol['m']:g} mm, b = "
                                                     f"{sol['face_width_mm']:g} mm: fails {failing})")
        return out

    @staticmethod
    def _contact_screen(stage, pairs, cands, flows) -> list:
        """Per pair, which of its modules pass the contact screen: one strength call for every module of every pair
        at its widest width. (An estimate from each pair's middle module, S_H scaled by (m/m_ref)^1.5, once chose the
        modules worth screening; K_Hβ grows with the width, so S_H falls more slowly than that towards the small
        modules, and a pair 20/71 at 7.5 kW was sized m 5.5 where m 3.5 holds every check:
        tests/drives/stage_kinds/test_gear.py.)"""
        sizes = [c[0].size for c in cands]
        if not sum(sizes):
            return [np.zeros(0, dtype=bool) for _ in pairs]
        if "contact_strength" not in check_names(stage):     # sized by its spectrum alone: nothing to screen by
            return [np.ones(n, dtype=bool) for n in sizes]
        worth = [np.ones(n, dtype=bool) for n in sizes]
        at = [np.flatnonzero(w) for w in worth]
        n_at = [a.size for a in at]
        out = [np.zeros(n, dtype=bool) for n in sizes]
        if not sum(n_at):
            return out
        M = np.concatenate([cands[i][0][a] for i, a in enumerate(at)])
        B = np.concatenate([cands[i][3][a] for i, a in enumerate(at)])
        X = np.concatenate([cands[i][4][a] for i, a in enumerate(at)]) / 2
        Z1 = np.concatenate([np.full(a.size, pairs[i][0]) for i, a in enumerate(at)])
        Z2 = np.concatenate([np.full(a.size, pairs[i][1]) for i, a in enumerate(at)])
        T = np.concatenate([np.full(a.size, flows[i].torque_in_nm) for i, a in enumerate(at)])
        N = np.concatenate([np.full(a.size, flows[i].n_in_rpm) for i, a in enumerate(at)])
        contact = strength_margins(stage, M, B, Z1, Z2, X, X, T, N, root=False)["contact_strength"]
        for i, (a, ok) in enumerate(zip(at, np.split(contact >= -CONTACT_SCREEN, np.cumsum(n_at)[:-1]))):
            out[i][a] = ok
        return out

    @classmethod
    def _unsized(cls, ref: dict, m: float, b: float, strength: dict) -> dict:
        """The failing solution of a tooth pair no module carries: :meth:`_scaled` to the closest (m, b) with the
        strength checks it fails named (as a solve at that module would name them)."""
        sol = cls._scaled(ref, m, b, strength)
        why = "fails " + ", ".join(k for k, v in strength.items() if not v >= -MARGIN_TOL)
        why = f"{ref['reason']}; {why}" if ref["reason"] else why
        return dict(sol, feasible=False, reason=f"no module of the ISO 54 series carries the load (closest "
                                                f"m = {m:g} mm, b = {b:g} mm: {why})")

    @staticmethod
    def _scaled(ref: dict, m: float, b: float, strength: dict) -> dict:
        """The solution at module m, face width b from the shifts solved at m = 1 (``_shifts_scale_free``):
        the same shifts and geometric margins, lengths scaled by m, and the ``strength`` margins (all
        holding) the sizing computed at (m, b)."""
        return dict(ref, a_w=ref["a_w"] * m, da1=ref["da1"] * m, da2=ref["da2"] * m,
                    margins={**ref["margins"], **strength}, m=m, face_width_mm=b)

    # -- the branch and bound
    def solve(self, stage, option: dict, objective: str, flow=None) -> dict:
        z1, z2 = int(option["z1"]), int(option["z2"])
        if stage.m is None:
            return self._sized(stage, z1, z2, objective, flow)
        return self._with_strength(stage, gear_solution(stage, z1, z2, objective), z1, z2, flow)

    def _standard_together(self, stage) -> bool:
        """A stage sized by the strength checks on a standard housing (:meth:`_standard_sized_many`)."""
        return stage.m is None and _SIZING[0] is None and stage.material is not None and stage.housing != "free"

    def _sized_together(self, stage) -> bool:
        """A stage sized by the strength checks whose shifts do not depend on the module (a free housing)."""
        return (stage.m is None and _SIZING[0] is None and stage.material is not None and stage.housing == "free"
                and _shifts_scale_free(stage))

    def solve_ahead(self, stage, objective: str) -> int:
        """Groups whose tooth pairs :meth:`solve_many` takes at once: a stage sized by its strength (one
        vectorised sizing call per flow), a stage whose shifts follow ``max_margin`` (one batch of Chebyshev
        centres, ~3 ms of fixed cost and ~0.07 ms a pair); else none."""
        if self._sized_together(stage) or self._standard_together(stage):
            return LOOK_AHEAD
        margin = stage.m is not None and stage.free_shifts and _shift_objective(stage, objective) == "max_margin"
        return MARGIN_AHEAD if margin else 0

    def solve_many(self, stage, options: list, objective: str, flows: list) -> list:
        """Tooth pairs solved together (:meth:`solve_ahead`): the ``max_margin`` shifts in one batch, the
        strength sizing in one vectorised call per input flow; the same solutions as one by one."""
        pairs = [(int(o["z1"]), int(o["z2"])) for o in options]
        if self._standard_together(stage):
            return self._standard_sized_many(stage, pairs, objective, list(flows))
        margin = _shift_objective(stage, objective) == "max_margin" and stage.free_shifts
        if not self._sized_together(stage):
            if margin and stage.m is not None:
                margin_solutions(stage, pairs)
            return super().solve_many(stage, options, objective, flows)
        unit = _at_module(stage, 1.0, stage.face_width_mm)   # one stage for all (building one validates it: ~50 µs)
        if margin:
            margin_solutions(unit, pairs)
        refs = [gear_solution(unit, z1, z2, objective) for z1, z2 in pairs]
        out = [None] * len(options)
        by_flow: dict = {}
        for i, (ref, flow) in enumerate(zip(refs, flows)):
            if "x1" in ref:
                by_flow.setdefault((flow.torque_in_nm, flow.n_in_rpm), []).append(i)
        for (torque, speed), idx in by_flow.items():
            for series in _series_rounds(stage):    # series I first: the pairs no series I module carries again
                sizes = strength_sizes_many(stage, torque, speed,
                                            [(*pairs[i], refs[i]["x1"], refs[i]["x2"]) for i in idx], series,
                                            MARGIN_TOL)
                for i, (cands, best) in zip(idx, sizes):
                    out[i] = self._scaled(refs[i], *best) if cands else self._unsized(refs[i], *best)
                idx = [i for i, (cands, _) in zip(idx, sizes) if not cands]
                if not idx:
                    break
        return [sol if sol is not None else self.solve(stage, o, objective, f)      # unsized: as one by one
                for sol, o, f in zip(out, options, flows)]

    def solve_count(self) -> int:
        return _SOLVED.misses

    def solved_for(self, options: list) -> dict:
        pairs = {(int(o["z1"]), int(o["z2"])) for o in options}
        return {key: sol for key, sol in _SOLVED.data.items() if key[1:3] in pairs}

    def shared_by(self, option: dict):
        return int(option["z1"]), int(option["z2"])      # every module and flow of a tooth pair

    def solve_shared(self, stage, options: list, objective: str, flows: list, known: dict) -> tuple:
        for key, sol in known.items():
            _SOLVED.keep(key, sol)
        _SOLVED.local.journal = journal = {}
        try:
            return self.solve_many(stage, options, objective, flows), journal
        finally:
            _SOLVED.local.journal = None

    def absorb(self, solved: dict) -> None:
        for key, sol in solved.items():     # each one a solve made on a worker: counted here
            _SOLVED.put(key, sol)

    @staticmethod
    def _width(stage, sol) -> float:
        if stage.m is not None:
            return stage.width_mm
        b = sol.get("face_width_mm")
        return b if b is not None else FACE_WIDTH_PITCHES * math.pi * sol["m"]

    def rank_factor(self, stage, sol: dict) -> float:
        """1 + :data:`SERIES_II_MARGIN` for a module of ISO 54 series II that the stage's strength sized
        (``module_series`` "preferred"; an installed sizing function's modules are its own choice): a drive with one
        ranks behind a drive of series I modules unless it is more than that much smaller (or lighter)."""
        if (stage.m is not None or _SIZING[0] is not None or stage.module_series != "preferred"
                or np.any(_series(1) == sol.get("m"))):
            return 1.0
        return 1.0 + SERIES_II_MARGIN

    def solved_cost(self, stage, sol: dict) -> tuple:
        w = self._width(stage, sol)
        return (float(stage_area_mm2(sol["a_w"], sol["da1"], sol["da2"])),
                float(disc_mass_kg(sol["da1"], w) + disc_mass_kg(sol["da2"], w)))

    def bound(self, stage, options: dict) -> tuple:
        z1, z2 = options["z1"].astype(float), options["z2"].astype(float)
        if stage.m is None:     # sized by load, whatever the load: the series' smallest module, no mass
            size, _, _ = _base_circle_bounds(stage, float(_series().min()), z1, z2)
            return size, np.zeros(z1.shape)
        size, db1, db2 = _base_circle_bounds(stage, stage.m, z1, z2)
        return size, disc_mass_kg(db1, stage.width_mm) + disc_mass_kg(db2, stage.width_mm)

    def bound_at(self, stage, option: dict, flow) -> tuple:
        """A stage sized by load at one flow: base circles of the smallest module the sizing function
        offers, blanks of its narrowest face width (the solve takes one of those candidates)."""
        if stage.m is not None or _SIZING[0] is None:   # the strength sizing's candidates cost a solve
            return super().bound_at(stage, option, flow)
        z1, z2 = int(option["z1"]), int(option["z2"])
        cands = self.sizes(stage, flow.torque_in_nm, flow.n_in_rpm, z1, z2)
        m = min(c[0] for c in cands)
        w = min(b if b is not None else FACE_WIDTH_PITCHES * math.pi * mc for mc, b in cands)
        size, db1, db2 = _base_circle_bounds(stage, m, float(z1), float(z2))
        return float(size), float(disc_mass_kg(db1, w) + disc_mass_kg(db2, w))

    def design_columns(self, stage, option: dict, info, c: int) -> dict:
        return {f"{stage.name}.z1": int(option["z1"]), f"{stage.name}.z2": int(option["z2"])}

    def solved_columns(self, stage, sol) -> dict:
        ok = sol is not None and sol["feasible"]
        out = {f"{stage.name}.x1": sol["x1"] if ok else np.nan, f"{stage.name}.x2": sol["x2"] if ok else np.nan,
               f"{stage.name}.a_w_mm": sol["a_w"] if ok else np.nan}
        if stage.m is None:
            out[f"{stage.name}.m"] = sol["m"] if ok else np.nan
            out[f"{stage.name}.face_width_mm"] = self._width(stage, sol) if ok else np.nan
        return out

    def fix(self, stage, option: dict, info, c: int, objective: str, flow=None):
        z1, z2 = int(option["z1"]), int(option["z2"])
        sol = self.solve(stage, option, objective, flow)
        if stage.m is None:
            stage = _sized_stage(stage, sol)
        return replace(stage, z1=z1, z2=z2, x1=sol["x1"], x2=sol["x2"])

    def resize(self, stage, fixed, option: dict, objective: str, flow, f_sh_um: float):
        """A stage sized by its load (no module given, a material) sized again for the misalignment f_sh its shafts
        give it at the size ``fixed`` (ISO 6336-1 method C then takes K_Hβ from it): the first module and width of
        its sizing's order that holds every check with f_sh scaled to that size as f_sh·(b/b_0)·(m_0/m) (the shafts'
        tilt under a tooth force ∝ 1/m, over the face width b: our estimate, which the analysis on the shafts
        checks), found as a fixed point (size for an f_sh, scale it to the size found, again while it grew); the
        stage returned without the f_sh (the analysis computes it). None: a module was given, the stage's options
        give f_sh or K_Hβ, or nothing larger than ``fixed`` holds."""
        own = dict((stage.strength or {}).get("factors") or {})
        if stage.m is not None or stage.material is None or "f_sh" in own or "K_Hbeta" in own:
            return None
        m0, b0 = float(fixed.m), float(fixed.width_mm)
        per = float(f_sh_um) * m0 / b0            # f_sh per b/m at the fixed size
        f = float(f_sh_um)
        for _ in range(RESIZE_FIXED_POINT):
            st = replace(stage, strength={**(stage.strength or {}), "factors": {**own, "f_sh": f}})
            sol = self.solve(st, option, objective, flow)
            if not sol["feasible"] or not math.isfinite(sol["m"]):
                return None
            m, b = float(sol["m"]), float(self._width(st, sol))
            if per * b / m <= f * (1.0 + 1e-12):      # it holds at its own (smaller or equal) f_sh
                break
            f = per * b / m
        else:
            return None
        if (m, b) <= (m0, b0):
            return None
        return replace(_sized_stage(st, sol), z1=int(option["z1"]), z2=int(option["z2"]), x1=sol["x1"],
                       x2=sol["x2"], strength=stage.strength)

    # -- analyse
    def analyse(self, stage, flow, objective: str) -> dict:
        """A gear stage at its tooth counts (free shifts solved; a free module sized at the flow): its
        checks (at the manufactured state too, with a mating type; with a material, its load checks at the
        flow, through the check registry), size and mass."""
        st = stage
        if st.m is None:
            sol = self._sized(st, st.z1, st.z2, objective, flow)
            if not math.isfinite(sol["m"]):
                raise GearDesignError(f"stage '{st.name}': z1/z2 = {st.z1}/{st.z2} has no feasible shifts "
                                      f"({sol['reason']})")
            st = _sized_stage(st, sol)
        sol = gear_solution(st, st.z1, st.z2, objective)
        if not sol["feasible"] and "x1" not in sol:
            raise GearDesignError(f"stage '{st.name}': z1/z2 = {st.z1}/{st.z2} has no feasible shifts ({sol['reason']})")
        pair = GearPair(st.m, st.z1, st.z2, sol["x1"], sol["x2"], beta_deg=st.beta_deg, face_width_mm=st.face_width_mm)
        load = {} if st.material is None else self._load_context(st, flow)
        table = pair.checks(**{"jamming": False, **(st.checks or {}), **load, **self._life_context(st, flow)})
        margins = dict(zip(table["check"], table["margin"].astype(float)))
        margins.update({k: v for k, v in sol["margins"].items() if k.endswith("_manufactured")})
        geo = pair.geometry()
        out = dict(stage=st, pair=pair, checks=table, margins=margins,
                   size=float(stage_area_mm2(geo.a_w, geo.da1, geo.da2)),
                   mass=float(disc_mass_kg(geo.da1, st.width_mm) + disc_mass_kg(geo.da2, st.width_mm)),
                   summary=dict(name=st.name, kind="gear", m=st.m, z1=st.z1, z2=st.z2, x1=pair.x1, x2=pair.x2,
                                # to 1e-9 mm: a standard a_w the shifts were solved for reads 355, not
                                # 354.99999999999994 (the solve's last bit), in tables and JSON
                                a_w_mm=round(float(geo.a_w), 9), da1_mm=geo.da1, da2_mm=geo.da2, ratio=st.z2 / st.z1,
                                efficiency=st.efficiency))
        if "allowances" in sol:
            out["allowances"] = sol["allowances"]
            out["summary"]["manufactured_state"] = sol["allowances"].describe()
        if st.housing != "free":
            out["summary"]["housing"] = st.housing if isinstance(st.housing, str) else f"a_w {st.housing:g} mm"
        if st.material is not None:
            if st.single_load:
                out["strength"] = self._strength_result(st, pair, load)
            out["summary"]["face_width_mm"] = st.width_mm
        if st.spectrum is not None:
            out["life"] = self._life_result(st, pair, flow)
            out["summary"].update(damage=out["life"].governing[1], life_h=out["life"].life_h,
                                  required_life_h=out["life"].required_life_h)
        return out

    @staticmethod
    def _load_context(st, flow) -> dict:
        """The single-load case of the stage's checks at ``flow``, as make_checks takes it (the single route); {}
        for a stage sized by its spectrum alone (``single_load=False``)."""
        if not st.single_load:
            return {}
        opts = dict(st.strength or {})
        return dict(load=st.load(flow.torque_in_nm, flow.n_in_rpm), material=stage_material(st.material),
                    face_width_mm=st.width_mm, strength=opts or None, **safety_limits(opts))

    @staticmethod
    def _life_context(st, flow) -> dict:
        """The damage checks' case of a stage with a spectrum at ``flow`` (make_checks' context: the same damage
        checks as the sizing's, :func:`.gear_strength.damage_checks`), {} without one."""
        if st.spectrum is None:
            return {}
        opts = life_options(dict(st.strength or {}))
        return dict(spectrum=st.spectrum_at(flow.torque_in_nm, flow.n_in_rpm), material=stage_material(st.material),
                    face_width_mm=st.width_mm, strength=opts or None, life_h=st.life_h, sn_curve=st.sn_curve,
                    mean_stress_factor=st.mean_stress_factor)

    @staticmethod
    def _life_result(st, pair, flow):
        """The stage's ISO 6336-6 service life (:meth:`GearPair.life`: damage sums, lives, safety factors for the
        required life and the per-bin table) under its spectrum at ``flow``."""
        spectrum = st.spectrum_at(flow.torque_in_nm, flow.n_in_rpm)
        return pair.life(spectrum, stage_material(st.material), face_width_mm=st.width_mm, life_h=st.life_h,
                         sn_curve=st.sn_curve, mean_stress_factor=st.mean_stress_factor,
                         **life_options(dict(st.strength or {})))

    @staticmethod
    def _strength_result(st, pair, load: dict):
        """The StrengthResult (the factor table) of the design whose checks were just evaluated on ``pair``: from
        the chain's output the strength checks kept, not a second run of the chain."""
        from ...gears.checks import make_checks
        from ...gears.strength.chain import strength_case
        from ...gears.strength.result import from_chain

        for c in make_checks(**load):
            raw = c.spec.chain_output(pair._geo) if c.costly else None   # the pair's own geometry memo
            if raw is not None:
                return from_chain(raw, title=f"{pair.z1}/{pair.z2} m={pair.m:g}",
                                  case=strength_case(load["material"], **(load.get("strength") or {})))
        raise GearDesignError(f"stage '{st.name}': the strength of z1/z2 = {pair.z1}/{pair.z2} is undefined at its "
                              f"shifts (outside ISO 6336's range)")

    # -- scenes
    def scene_keys(self) -> dict:
        f, i = "float", "int"
        from ...gears.strength.load import APPLICATION_FACTOR_RANGE, LIFE_RANGE_H
        from ...gears.backlash import GOST1643_TYPES
        from ..housing import CENTER_DISTANCE_RANGE_MM, CENTER_DISTANCE_SERIES
        from ...gears.strength.user_options import scene_keys as strength_scene_keys
        from ...gears.spectrum import MEAN_STRESS_FACTOR_RANGE, SN_CURVES, SPEED_RANGE_RPM, TIME_RANGE_H

        # no module: sized by the stage's load (needs a material); see GearStage
        return {"module": dict(kind=f, lo=M_RANGE_MM[0], hi=M_RANGE_MM[1]),
                "material": dict(kind="str"),
                "life_h": dict(kind=f, lo=LIFE_RANGE_H[0], hi=LIFE_RANGE_H[1], lo_open=True),
                "application_factor": dict(kind=f, lo=APPLICATION_FACTOR_RANGE[0], hi=APPLICATION_FACTOR_RANGE[1]),
                "z1": dict(kind=i, lo=Z_MIN, hi=Z_MAX), "z2": dict(kind=i, lo=Z_MIN, hi=Z_MAX),
                "x1": dict(kind=f, lo=-X_ABS_MAX, hi=X_ABS_MAX), "x2": dict(kind=f, lo=-X_ABS_MAX, hi=X_ABS_MAX),
                "efficiency": dict(kind=f, lo=EFFICIENCY_RANGE[0], hi=EFFICIENCY_RANGE[1], lo_open=True),
                "beta_deg": dict(kind=f, default=0.0, lo=BETA_RANGE_DEG[0], hi=BETA_RANGE_DEG[1]),
                "face_width_mm": dict(kind=f, lo=FACE_WIDTH_RANGE_MM[0], hi=FACE_WIDTH_RANGE_MM[1], lo_open=True),
                "z1_range": dict(kind="ints", lo=Z_MIN, hi=Z_MAX, length=2), "z2_max": dict(kind=i, lo=Z_MIN, hi=Z_MAX),
                "ratio_range": dict(kind="floats", lo=1.0, hi=100.0, length=2),
                "shift_objective": dict(kind="choice", choices=tuple(OBJECTIVES)),
                # the housing and the shop (GearStage): a series name or a_w in mm; the x window; GOST 1643 type
                "center_distance": dict(kind="float_or_str", lo=CENTER_DISTANCE_RANGE_MM[0],
                                        hi=CENTER_DISTANCE_RANGE_MM[1], choices=("free",) + tuple(CENTER_DISTANCE_SERIES)),
                "shift_bounds": dict(kind="floats", lo=-3.0, hi=3.0, length=2),
                "mating_type": dict(kind="choice", choices=GOST1643_TYPES + ("none",)),
                "module_series": dict(kind="choice", choices=MODULE_SERIES_RULES),
                "checks": dict(table="checks", without=("jamming",)),
                # the service life (GearStage: spectrum): the stage's own [drive.stage.spectrum], its pinion's loads
                # (a CSV beside the scene, as [gear.spectrum] reads it), or the drive's [drive.spectrum]
                "spectrum": {"file": dict(kind="str", required=True),
                             "n_rpm": dict(kind=f, lo=SPEED_RANGE_RPM[0], hi=SPEED_RANGE_RPM[1], lo_open=True),
                             "duration_h": dict(kind=f, lo=TIME_RANGE_H[0], hi=TIME_RANGE_H[1], lo_open=True)},
                "single_load": dict(kind="bool"), "sn_curve": dict(kind="choice", choices=SN_CURVES),
                "mean_stress_factor": dict(kind=f, lo=MEAN_STRESS_FACTOR_RANGE[0], hi=MEAN_STRESS_FACTOR_RANGE[1]),
                **strength_scene_keys()}

    def scene_spec(self, spec: dict, folder) -> dict:
        sp = spec.get("spectrum")
        if isinstance(sp, dict) and not Path(sp["file"]).is_absolute():    # a stage's spectrum beside the scene
            spec["spectrum"] = dict(sp, file=str(Path(folder) / sp["file"]))
        return spec

    def from_scene(self, spec: dict):
        from ...gears.strength.user_options import options_from_table

        strength, kw = options_from_table(spec)     # the strength options' keys: the stage's strength dict
        if isinstance(kw.get("spectrum"), dict):    # [drive.stage.spectrum]: the pinion's loads, as they are
            from ...gears.spectrum import LoadSpectrum

            sp = kw["spectrum"]
            try:
                kw["spectrum"] = LoadSpectrum.from_csv(sp["file"], n_rpm=sp.get("n_rpm"),
                                                       duration_h=sp.get("duration_h", kw.get("life_h")))
            except GearDesignError as exc:
                raise GearDesignError(f"[drive.stage.spectrum] file: {exc}") from None
        kw["strength"] = strength or None
        kw["m"] = kw.pop("module", None)
        kw["checks"] = dict(kw["checks"]) if kw.get("checks") else None
        for k in ("z1_range", "ratio_range", "shift_bounds"):
            if k in kw:
                kw[k] = tuple(kw[k])
        return GearStage(**kw)

    # -- diagram
    wheels = True

    @staticmethod
    def _radii(summary: dict) -> tuple:
        """The two circles' radii: in the ratio of the teeth, the larger 0.9."""
        r1 = 0.9 / max(1.0, summary["ratio"])
        r2 = r1 * summary["ratio"]
        return 0.9 * r1 / max(r1, r2), 0.9 * r2 / max(r1, r2)

    def first_offset(self, summary: dict) -> float:
        return self._radii(summary)[0]

    def last_offset(self, summary: dict) -> float:
        return self._radii(summary)[1]

    def draw(self, canvas, x: float, summary: dict) -> tuple:
        """Two meshing circles, radii in the ratio of the teeth."""
        s = summary
        r1, r2 = self._radii(s)
        for xc, r in ((x, r1), (x + r1 + r2, r2)):
            canvas.circle(xc, r, self.colour, alpha=0.9)
        width = f", b {s['face_width_mm']:g}" if s.get("face_width_mm") is not None else ""   # a stage with a load
        text = (f"{s['name']}: z {s['z1']}/{s['z2']}, m {s['m']:g}{width}\n"
                f"x {s['x1']:.3f}/{s['x2']:.3f}, a_w {s['a_w_mm']:.1f} mm")
        return x + r1 + r2, text
