"""Tooth counts for a ratio: enumerate the (z1, z2) pairs, solve the shifts for each, rank.

The discrete part (tooth counts, modules, standard centre distances) is enumerated with
vectorised numpy over the whole candidate set; the continuous part (the profile shifts) is
solved per candidate with :func:`geardesign.shifts.optimize.optimize_shifts`.

* Centre distance free (``a_w=None``): for each pair the shifts are optimised for the
  objective over the whole feasible region; the module only scales lengths, so each pair is
  solved once whatever the module.
* Centre distance given (``a_w`` in mm, with a module): for each pair and module the x-sum
  follows from a_w (cos α_w = a cos α / a_w, x1 + x2 = (z1 + z2)(inv α_w − inv α)/(2 tan α),
  ISO 21771:2007 eq. (62)); the objective picks the split. Pairs with a_w <= a cos α, or
  with an x-sum outside ``x_sum_window`` (a pair that needs more shift than any gear
  carries), are skipped before any solve and listed with the reason in ``skipped``.

Ranking (best first): feasible before infeasible; then the smaller |ratio error|; then
modules of the first (preferred) series of ISO 54 / GOST 9563 before the second; then the
better objective (larger for ``max_*``, smaller for ``min_*`` and ``balanced_sliding``);
then the smaller tooth sum (a smaller, lighter pair — or, for a fixed a_w, the larger,
stronger module); finally the smaller module.


Modules and centre distances. Without ``a_w`` the module does not change the shifts or any geometric
check, only the size: ``m="series"`` then lists every (pair, module) with its a and a_w in mm, so the
module can be picked by size or strength from one table (each pair solved once; with a face width, a ring
pair or a load each (pair, module) is solved on its own). With ``a_w`` given, ``m="series"`` keeps the
modules for which some tooth sum fits that centre distance with an x-sum inside ``x_sum_window``;
``a_w="series"`` takes for each pair and module the smallest standard centre distance of GOST 2185-66
(series 1 and 2) >= a = m(z1 + z2)/2, the nearest standard value that needs a non-negative x-sum. The
x-sum follows from a_w; the objective picks the split.
"""
from __future__ import annotations

import functools
import textwrap
import math
import time
from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from .. import catalogs, parallel
from ..results import RankedTable, plain
from ..gears.checks import resolve_checks
from ..errors import GearDesignError
from ..validate import _show, one_number, require_callable, require_count, require_finite, require_positive, require_range
from ..gears.geometry import A_W_RANGE_MM, min_center_distance, require_module, x_sum_from_center_distance
from ..gears.mesh import Z_MAX, Z_MIN, Mesh
from .objectives import default_objective
from .problem import DEFAULT_BOUNDS
from ..gears.rack import BasicRack, require_rack
from .optimize import METHODS, optimize_shifts

__all__ = ["select_teeth", "ratio_pairs", "TeethSelection", "X_SUM_WINDOW", "MAX_SOLVES"]

# x1 + x2 outside this window is not solved: it is the shift window of one gear in
# optimize_shifts (DEFAULT_BOUNDS); a pair that needs more than that in total is absurd.
X_SUM_WINDOW = DEFAULT_BOUNDS
MAX_SOLVES = 3000        # refuse searches that would call the optimiser more often than this (per worker)
# solves per chunk sent to a worker: at ~2-10 ms a solve, 40 outweigh a task's ~2 ms of scheduling
TEETH_CHUNK_MIN, TEETH_CHUNK_MAX = 40, 500
_RATIO_EPS = 1e-12       # relative slack on ratio_tol and for grouping equal ratio errors


def ratio_pairs(ratio: float, ratio_tol: float = 0.02, z1_range=(8, 40), z_sum_max: int | None = None):
    """Every (z1, z2) with |z2/z1 − ratio|/ratio <= ratio_tol, z1 in z1_range, z1 + z2 <= z_sum_max.

    Returns two int arrays, sorted by z1 then z2.

    >>> z1, z2 = ratio_pairs(2.0, 0.0, (10, 12))
    >>> list(zip(z1.tolist(), z2.tolist()))
    [(10, 20), (11, 22), (12, 24)]
    """
    ratio = one_number("ratio", require_range("ratio", ratio, 1.0, 100.0))
    ratio_tol = one_number("ratio_tol", require_range("ratio_tol", ratio_tol, 0.0, 0.5))
    lo, hi = _z1_range(z1_range)
    z1 = np.arange(lo, hi + 1)
    z2_lo = max(int(math.floor(lo * ratio * (1 - ratio_tol))), Z_MIN)
    z2_hi = int(math.ceil(hi * ratio * (1 + ratio_tol)))
    z2 = np.arange(z2_lo, z2_hi + 1)
    Z1, Z2 = np.meshgrid(z1, z2, indexing="ij")
    ok = np.abs(Z2 / Z1 - ratio) / ratio <= ratio_tol + _RATIO_EPS
    if z_sum_max is not None:
        ok &= Z1 + Z2 <= require_count("z_sum_max", z_sum_max, 2 * Z_MIN, 10**15)
    return Z1[ok].astype(int), Z2[ok].astype(int)


def _z1_range(z1_range):
    try:
        lo, hi = z1_range
    except (TypeError, ValueError):
        raise GearDesignError(f"z1_range must be (min, max), got {z1_range!r}") from None
    lo = require_count("z1_range min", lo, Z_MIN, Z_MAX)
    hi = require_count("z1_range max", hi, Z_MIN, Z_MAX)
    if hi < lo:
        raise GearDesignError(f"z1_range must be (min, max) with min <= max, got {z1_range!r}")
    if hi - lo > 2000:
        raise GearDesignError(f"z1_range must span at most 2000 tooth counts, got {z1_range!r}")
    return lo, hi


@dataclass
class TeethSelection(RankedTable):
    """The ranked result of :func:`select_teeth`.

    ``table`` — one row per solved candidate, best first (see the module docstring for the
    ranking); ``skipped`` — candidates dropped before solving, with ``reason``;
    ``best`` — the first row if it is feasible, else None; ``choice`` — why it was chosen.
    """

    table: pd.DataFrame
    skipped: pd.DataFrame
    ratio: float
    ratio_tol: float
    objective: str
    m: object
    a_w: object
    method: str
    checks: list = field(default_factory=list)
    n_solved: int = 0
    time_s: float = 0.0
    objective_sense: int = 1     # +1: larger is better, −1: smaller

    @property
    def feasible(self) -> pd.DataFrame:
        return self.table[self.table["feasible"]]

    @property
    def choice(self) -> str:
        """One paragraph: which row is chosen and why, in the terms of the ranking."""
        b = self.best
        if b is None:
            n = len(self.table)
            return (f"no feasible candidate among {n} solved (and {len(self.skipped)} skipped); "
                    "see the reason column: the checks that conflict for each pair")
        feas = self.feasible
        same_err = feas[np.isclose(feas["ratio_error"].abs(), abs(b["ratio_error"]), rtol=0, atol=_RATIO_EPS)]
        word = "largest" if self.objective_sense > 0 else "smallest"
        err = "exact" if abs(b["ratio_error"]) <= _RATIO_EPS else f"error {100 * b['ratio_error']:+.3g} %"
        text = (f"z1/z2 = {b['z1']:d}/{b['z2']:d} (ratio {b['ratio']:.6g}, {err}), m = {b['module_mm']:g} mm, "
                f"x1 = {b['x1']:.4f}, x2 = {b['x2']:.4f}, a_w = {b['a_w_mm']:.6g} mm: "
                f"{len(feas)} of {len(self.table)} solved candidates are feasible; ")
        if len(feas) == 1:
            return text + "it is the only feasible one."
        text += (f"{len(same_err)} feasible candidate(s) share the smallest ratio error, and among them it has the "
                 f"{word} {self.objective} = {b['objective']:.6g}")
        ties = same_err[np.isclose(same_err["objective"], b["objective"], rtol=1e-9, atol=1e-12)]
        if len(ties) > 1:
            text += f" (tied with {len(ties) - 1} other(s); the smaller tooth sum wins)"
        text += "."
        zsum = same_err["z1"] + same_err["z2"]
        if self.a_w is None and self.objective == "max_x_sum" and len(same_err) > 1 and b["z1"] + b["z2"] == zsum.max():
            # with a free centre distance the x-sum the checks allow grows with the tooth counts
            text += (" With a_w free, max_x_sum grows with the tooth count, so the largest pair in the range wins; "
                     "for a compact pair fix the housing (a_w=...), cap z1 + z2 (z_sum_max=...) or narrow z1_range.")
        return text

    def best_per_module(self) -> pd.DataFrame:
        """The best feasible row of each module, in ranking order (read with ``m="series"``)."""
        feas = self.feasible
        return feas.drop_duplicates("module_mm").reset_index(drop=True)

    def to_dict(self) -> dict:
        best = self.best
        return plain({
            "status": self.status,
            "input": {"ratio": self.ratio, "ratio_tol": self.ratio_tol, "objective": self.objective,
                      "m": self.m, "a_w": self.a_w, "method": self.method, "checks": list(self.checks)},
            "best": None if best is None else best.to_dict(),
            "choice": self.choice,
            "n_solved": self.n_solved,
            "time_s": self.time_s,
            "table": self.table.to_dict(orient="records"),
            "skipped": self.skipped.to_dict(orient="records"),
        })

    def __repr__(self) -> str:
        cols = ["z1", "z2", "ratio", "module_mm", "a_w_mm", "x1", "x2", "eps_alpha", "objective", "feasible"]
        head = self.table[cols].head(5)
        with pd.option_context("display.width", 160, "display.max_columns", 20):
            body = head.to_string(index=False, float_format=lambda v: f"{v:.5g}")
        return "\n".join([
            f"TeethSelection(ratio {self.ratio:g} ± {100 * self.ratio_tol:g} %, objective {self.objective}, "
            f"m = {self.m}, a_w = {self.a_w}, method {self.method})",
            f"  {len(self.table)} candidates solved ({int(self.table['feasible'].sum()) if len(self.table) else 0} "
            f"feasible), {len(self.skipped)} skipped, {self.time_s:.2f} s",
            textwrap.fill(f"choice: {self.choice}", 110, initial_indent="  ", subsequent_indent="    "),
            body,
        ])


def _modules(m, m_range):
    """(module values, series) to search."""
    if isinstance(m, str):
        if m != "series":
            raise GearDesignError(f"m must be a module in mm, 'series' or None, got {m!r}")
        try:
            lo, hi = (1.0, 50.0) if m_range is None else m_range
        except (TypeError, ValueError):
            raise GearDesignError(f"m_range must be (min, max) in mm, got {_show(m_range)}") from None
        lo = one_number("m_range min", require_positive("m_range min", lo, unit="mm"))
        hi = one_number("m_range max", require_positive("m_range max", hi, unit="mm"))
        frame = catalogs.load_catalog("modules")
        frame = frame[(frame["module_mm"] >= lo) & (frame["module_mm"] <= hi)]
        if frame.empty:
            raise GearDesignError(f"m_range must hold at least one standard module, got {m_range!r}")
        return frame["module_mm"].to_numpy(float), frame["series"].to_numpy(int)
    mm = one_number("m (module)", require_module(m))
    std = catalogs.load_catalog("modules")
    hit = std.loc[np.isclose(std["module_mm"], mm, rtol=1e-12), "series"]
    return np.array([mm]), np.array([int(hit.iloc[0]) if len(hit) else 0])


def _standard_center_distance(a):
    """The smallest GOST 2185-66 centre distance (series 1 and 2) >= a; NaN above the table."""
    values = catalogs.center_distance_series((1, 2))
    i = np.searchsorted(values, np.asarray(a) * (1 - 1e-12), side="left")
    return np.where(i < values.size, values[np.minimum(i, values.size - 1)], np.nan)


def _validated(method, rack, progress, x_sum_window, tip_shortening, beta_deg, internal, face_width_mm, checks):
    """The search's inputs checked once: (rack, x-sum window, the kind of pair, the checks' names)."""
    if method not in METHODS:
        raise GearDesignError(f"method must be one of {list(METHODS)}, got {method!r}")
    rack = require_rack(rack)
    require_callable("progress", progress)
    # the kind is validated once, on a proto mesh; every candidate shares it
    proto = Mesh(20, 60, rack, tip_shortening, beta_deg, internal, face_width_mm)
    kind = dict(beta_deg=proto.beta_deg, internal=proto.internal, face_width_mm=proto.face_width_mm)
    check_names = [c.name for c in resolve_checks(checks, internal=kind["internal"])]
    return rack, _x_sum_window(x_sum_window), kind, check_names


def select_teeth(ratio, ratio_tol=0.02, m=None, a_w=None, z1_range=(8, 40), z_sum_max=None,
                 objective=None, checks=None, rack=None, method="exact", *, m_range=None,
                 x_sum_window=X_SUM_WINDOW, tip_shortening=True, progress=None, beta_deg: float = 0.0,
                 internal: bool = False, face_width_mm: float | None = None, client=None,
                 workers=None) -> TeethSelection:
    """Tooth counts z1/z2 for a gear ratio u = z2/z1, with the best profile shifts for each, ranked.

    Parameters
    ----------
    ratio : the wanted ratio u = z2/z1 >= 1 (z1 the pinion).
    ratio_tol : the relative ratio error allowed, |z2/z1 − u|/u <= ratio_tol (0.02 = 2 %).
    m : module in mm, ``"series"`` (ISO 54 / GOST 9563 within ``m_range``, default 1..50 mm) or
        ``None`` (the series with ``a_w``, else m = 1); see "Modules and centre distances" above.
    a_w : operating centre distance in mm (in :data:`~geardesign.gears.inputs.A_W_RANGE_MM`), or ``"standard"``
        (alias ``"series"``: GOST 2185-66, the nearest >= a).
    z1_range : (min, max) teeth of the pinion, inclusive.  z_sum_max : largest z1 + z2.
    objective : a name in :data:`geardesign.shifts.objectives.OBJECTIVES` or an Objective; default ``"max_x_sum"`` with the
        centre distance free, ``"balanced_sliding"`` with ``a_w`` given (the x-sum is then
        fixed, so "max_x_sum" could not choose the split; equal specific sliding at both
        roots is the classic rule, GOST 16532-70 appendix).  checks : as for
        :func:`geardesign.shifts.optimize.optimize_shifts` (None: no undercut, no interference,
        s_a >= 0.25 m, ε_α >= 1.2).  rack : :class:`BasicRack` (standard by default).
    method : "grid", "convex" or "exact" (see :mod:`geardesign.shifts.optimize`).
    x_sum_window : (lo, hi) of x1 + x2 worth solving when a_w fixes it.  progress : callable(done, total).
    beta_deg, internal, face_width_mm : helical (``m`` the normal module), internal (z2 the ring,
        u = z2/z1, x_Σ = x2 − x1, a = m (z2 − z1)/2) and the face width in mm for ε_β, as for
        :class:`~geardesign.gears.mesh.Mesh`. With a face width each (pair, module) is solved
        on its own: ε_β = b sin β/(π m) depends on the module.
    client, workers : the solves on a ``dask.distributed.Client`` or a local cluster of ``workers``
        processes (:mod:`geardesign.parallel`): the serial table bit for bit, MAX_SOLVES × workers.

    Returns
    -------
    TeethSelection
        ``table`` columns: z1, z2, z_sum, ratio, ratio_error (signed, relative), module_mm,
        module_series (1, 2, or 0 for a non-standard module), a_mm, a_w_mm, x_sum, x1, x2,
        eps_alpha, objective (its value, in its own sense), feasible, active, reason (the
        conflicting checks of an infeasible row), one ``margin_<check>`` per check, rank.
        Ranked as described in :mod:`geardesign.shifts.teeth`.

    >>> sel = select_teeth(2.0, ratio_tol=0.0, m=2, z1_range=(20, 21))
    >>> sel.table[["z1", "z2"]].values.tolist()
    [[21, 42], [20, 40]]
    """
    t0 = time.perf_counter()
    objective = default_objective(objective, x_sum_fixed=a_w is not None)
    rack, x_sum_window, kind, check_names = _validated(method, rack, progress, x_sum_window, tip_shortening,
                                                       beta_deg, internal, face_width_mm, checks)
    z1, z2 = ratio_pairs(ratio, ratio_tol, z1_range, z_sum_max)
    ratio = float(ratio)
    a_w = _housing(a_w)
    m_used = m if m is not None else ("series" if a_w is not None else 1.0)

    cands = _candidates(z1, z2, ratio, *_modules(m_used, m_range), kind)
    cands, skipped = _within_reach(cands, a_w, rack, x_sum_window, kind)
    keys, solved = _solve(cands, a_w, objective, checks, method, rack, tip_shortening, progress, kind,
                          dict(client=client, workers=workers))
    table = _rank(_table(cands, keys, solved, a_w, check_names), objective.sense)
    return TeethSelection(table=table, skipped=skipped, ratio=ratio, ratio_tol=float(ratio_tol),
                          objective=objective.name, objective_sense=objective.sense, m=m_used, a_w=a_w,
                          method=method, checks=check_names, n_solved=len(solved), time_s=time.perf_counter() - t0)


def _x_sum_window(window) -> tuple[float, float]:
    """(lo, hi) of the x-sums worth solving: two finite numbers, lo < hi."""
    try:
        lo, hi = window
    except (TypeError, ValueError):
        raise GearDesignError(f"x_sum_window must be (lo, hi), got {_show(window)}") from None
    lo = one_number("x_sum_window lo", require_finite("x_sum_window lo", lo))
    hi = one_number("x_sum_window hi", require_finite("x_sum_window hi", hi))
    if not lo < hi:
        raise GearDesignError(f"x_sum_window must be (lo, hi) with lo < hi, got {_show(window)}")
    return lo, hi


def _housing(a_w):
    """The housing centre distance: None, "series" or "standard" (the GOST 2185 value above a) or a length in mm."""
    if isinstance(a_w, str):
        if a_w not in ("series", "standard"):
            raise GearDesignError(f"a_w must be a centre distance in mm, 'standard' ('series') or None, got {a_w!r}")
        return "series"
    if a_w is None:
        return None
    return one_number("a_w (center distance)", require_range("a_w (center distance)", a_w, *A_W_RANGE_MM,
                                                             lo_open=True, unit="mm"))


def _candidates(z1, z2, ratio: float, mods, series, kind) -> pd.DataFrame:
    """Every (tooth pair, module) candidate, vectorised: counts, ratio error, module and a
    (m (z2 ± z1)/(2 cos β))."""
    P, M = np.meshgrid(np.arange(z1.size), np.arange(mods.size), indexing="ij")
    P, M = P.ravel(), M.ravel()
    c = pd.DataFrame({"z1": z1[P], "z2": z2[P]})
    c["z_sum"] = c["z1"] + c["z2"]
    c["ratio"] = c["z2"] / c["z1"]
    c["ratio_error"] = (c["ratio"] - ratio) / ratio
    c["module_mm"] = mods[M]
    c["module_series"] = series[M]
    zs = c["z2"] - c["z1"] if kind["internal"] else c["z_sum"]
    c["a_mm"] = c["module_mm"] * zs / (2.0 * math.cos(math.radians(kind["beta_deg"])))
    return c


def _within_reach(c: pd.DataFrame, a_w, rack: BasicRack, x_sum_window, kind):
    """(candidates to solve, skipped with reason): with a housing a_w, the pairs it can hold — a_w
    above a·cos α_t (ISO 21771:2007 eq. (62) needs inv α_w > 0) and an x-sum inside the window."""
    section = dict(beta_deg=kind["beta_deg"], internal=kind["internal"])
    xs_lo, xs_hi = x_sum_window
    reason = np.full(len(c), "", dtype=object)
    # a ratio tolerance reaching below 1 brings z2 <= z1, which no ring pair has (a = 0 or less)
    no_ring = (c["z2"] <= c["z1"]).to_numpy() if kind["internal"] else np.zeros(len(c), bool)
    if a_w is None:
        c["a_w_target_mm"] = np.nan
    else:
        target = _standard_center_distance(c["a_mm"].to_numpy()) if a_w == "series" else np.full(len(c), a_w)
        c["a_w_target_mm"] = target
        a_cos = min_center_distance(c["module_mm"].to_numpy(), c["z1"].to_numpy(), c["z2"].to_numpy(), rack,
                                    **section)
        above = np.isnan(target)
        reason[above] = "a is above the largest GOST 2185 centre distance"
        small = ~above & (target <= a_cos)
        for i in np.flatnonzero(small):
            reason[i] = f"a_w = {target[i]:g} mm <= a·cos(alpha) = {a_cos[i]:.6g} mm"
        okw = ~above & ~small & ~no_ring
        xs = np.full(len(c), np.nan)
        xs[okw] = x_sum_from_center_distance(c["module_mm"].to_numpy()[okw], c["z1"].to_numpy()[okw],
                                             c["z2"].to_numpy()[okw], target[okw], rack, **section)
        c["x_sum_target"] = xs
        out = okw & ((xs < xs_lo) | (xs > xs_hi))
        name = "x2 − x1" if kind["internal"] else "x1 + x2"
        for i in np.flatnonzero(out):
            reason[i] = f"{name} = {xs[i]:.4g} outside [{xs_lo:g}, {xs_hi:g}]"
    reason[no_ring] = "an internal pair needs more teeth on the ring: z2 <= z1"
    keep = reason == ""
    skipped = c.loc[~keep, ["z1", "z2", "ratio", "ratio_error", "module_mm", "a_mm", "a_w_target_mm"]].copy()
    skipped["reason"] = reason[~keep]
    skipped = skipped.rename(columns={"a_w_target_mm": "a_w_mm"}).reset_index(drop=True)
    return c[keep].reset_index(drop=True), skipped


def _solve(c: pd.DataFrame, a_w, objective, checks, method, rack, tip_shortening, progress, kind, where):
    """One shift solve per distinct problem (without a_w and face width the module only scales
    lengths): (each candidate's key, {key: ShiftResult or the GearDesignError it raised}).
    ``where``: client= / workers= of :func:`geardesign.parallel.map_chunks` (empty: here)."""
    if a_w is None:
        # the module changes the problem when ε_β (face width) or the ring's shaper cutter (its standard
        # size depends on the module) enters the checks: then each (pair, module) is solved on its own
        per_module = (kind["face_width_mm"] is not None or kind["internal"]
                      or (isinstance(checks, dict) and (checks.get("load") is not None
                                                        or checks.get("spectrum") is not None)))   # strength scales with m
        keys = list(zip(c["z1"], c["z2"], *([c["module_mm"]] if per_module else [])))
    else:
        keys = list(zip(c["z1"], c["z2"], c["module_mm"], c["a_w_target_mm"]))
    unique = list(dict.fromkeys(keys))
    n_workers = parallel.slots(**where)
    if len(unique) > MAX_SOLVES * n_workers:
        per = "" if n_workers == 1 else f" ({MAX_SOLVES} per worker x {n_workers})"
        raise GearDesignError(
            f"the search needs {len(unique)} shift solves, more than the limit {MAX_SOLVES * n_workers}{per}: narrow "
            f"z1_range, ratio_tol, z_sum_max or m_range")
    setup = dict(objective=objective, checks=checks, method=method, rack=rack, tip_shortening=tip_shortening,
                 kind=kind)
    if not parallel.requested(**where):
        solved = {}
        for k, key in enumerate(unique):
            solved[key] = _solve_one(key, setup)
            if progress is not None:
                progress(k + 1, len(unique))
        return keys, solved
    parts = parallel.map_chunks(functools.partial(_solve_chunk, setup),
                                [unique[s] for s in parallel.chunk_slices(len(unique), n_workers, TEETH_CHUNK_MIN,
                                                                          TEETH_CHUNK_MAX)],
                                progress=progress, **where)
    return keys, dict(zip(unique, [r for part in parts for r in part]))


def _solve_one(key, setup):
    """The ShiftResult of one candidate key (z1, z2[, m[, a_w]]), or the GearDesignError it raised."""
    housing = {"a_w": key[3] if len(key) == 4 else None, "m": key[2] if len(key) > 2 else 1.0}
    try:
        return optimize_shifts(key[0], key[1], setup["objective"], setup["checks"], setup["method"],
                               rack=setup["rack"], tip_shortening=setup["tip_shortening"], **housing,
                               **setup["kind"])
    except GearDesignError as exc:
        return exc


def _solve_chunk(setup, keys) -> list:
    """A chunk of candidate keys solved on a worker."""
    return [_solve_one(key, setup) for key in keys]


def _table(c: pd.DataFrame, keys, solved, a_w, check_names) -> pd.DataFrame:
    """The candidates with their solutions: a_w, shifts, ε_α, objective, feasibility, margins."""
    rows = []
    for key, mod in zip(keys, c["module_mm"]):
        r = solved[key]
        if isinstance(r, GearDesignError):
            rows.append(dict(a_w_mm=np.nan, x_sum=np.nan, x1=np.nan, x2=np.nan, eps_alpha=np.nan,
                             objective=np.nan, feasible=False, active="", reason=str(r),
                             **{f"margin_{n}": np.nan for n in check_names}))
            continue
        feasible = bool(r.success and not r.conflict)
        why = "" if feasible else ("conflict: " + ", ".join(r.conflict) if r.conflict else r.message)
        rows.append(dict(
            a_w_mm=r.a_w * (mod if len(key) == 2 else 1.0), x_sum=r.x_sum,
            x1=r.x1, x2=r.x2,
            eps_alpha=r.eps_alpha, objective=r.fun, feasible=feasible, active=", ".join(r.active), reason=why,
            **{f"margin_{n}": r.margins.get(n, np.nan) for n in check_names}))
    sol = pd.DataFrame(rows, index=c.index, columns=["a_w_mm", "x_sum", "x1", "x2", "eps_alpha", "objective",
                                                     "feasible", "active", "reason"]
                       + [f"margin_{n}" for n in check_names])
    table = pd.concat([c.drop(columns=[k for k in ("a_w_target_mm", "x_sum_target") if k in c]), sol], axis=1)
    table["feasible"] = table["feasible"].astype(bool)
    return table


def _rank(table: pd.DataFrame, sense: int) -> pd.DataFrame:
    """Feasible first, |ratio error|, first-series module, objective in its sense, z-sum, module."""
    if table.empty:
        table["rank"] = pd.Series(dtype=int)
        return table
    key = pd.DataFrame({
        "infeasible": ~table["feasible"],
        # round so that equal ratios (16/24, 18/27) compare equal despite float noise
        "err": np.round(table["ratio_error"].abs().to_numpy() / _RATIO_EPS) * _RATIO_EPS,
        "series": np.where(table["module_series"] == 1, 0, 1),
        # rounded: with a fixed a_w, max_x_sum values differ only by rounding noise
        "obj": np.round(np.nan_to_num(-sense * table["objective"].to_numpy(float), nan=np.inf), 9),
        "z_sum": table["z_sum"],
        "m": table["module_mm"],
    }, index=table.index)
    order = key.sort_values(list(key.columns), kind="stable").index
    out = table.loc[order].reset_index(drop=True)
    out["rank"] = np.arange(1, len(out) + 1)
    return out
