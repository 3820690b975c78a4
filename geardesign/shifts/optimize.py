"""Optimal profile shifts x1/x2 for given tooth counts: three methods, one answer.

Every objective is written as "maximise t subject to piece_k(x) >= t and margin_i(x) >= 0"
(one piece for a smooth objective, two for balanced sliding, the normalised margins for
``max_margin``), so the three methods share one formulation:

* ``grid``   — all pieces and margins on an N×N grid in one vectorised call; the best feasible
  node. Coarse and fast; the achieved tolerance is half the grid spacing.
* ``convex`` — sequential convex programming in cvxpy with the Clarabel solver: the checks are
  linearised at the iterate and the linear program is solved inside a trust region, repeated.
  The cvxpy problem is built once with Parameters (DPP) and re-solved; its dual values give the
  sensitivities.
* ``exact``  — from the best node of a 31×31 grid, Newton on the KKT system of each candidate
  active set among the checks that pass within ~2 grid spacings (the window's edges count as
  checks): the active checks at zero and, when one fewer is active than free variables, the
  stationarity condition. The first solution that holds every check with multipliers >= 0 is
  the optimum (candidates whose multipliers, linearised at the start, are >= 0 go first).
  When none qualifies, SLSQP from the node and the same Newton polish. Reaches ~1e-12 in x.
  One design is evaluated in Python floats (:meth:`Problem.evaluate_point`), ~20× cheaper
  than a one-element numpy call; a solve takes ~5 evaluations and ~0.9 ms.
  ``max_margin`` with both shifts free goes first to :mod:`~geardesign.shifts.centres` (sequential
  linear programming to the vertex or edge of the smallest normalised margins, with the same KKT
  certificate; the solver a drive runs on hundreds of pairs at once), and to the search above where
  that gives no certificate.

Sensitivities are d(fun)/d(limit) of the active checks: how much the optimum moves per unit
rise of each active limit (for undercut and interference, per unit of extra margin required).
"""
from __future__ import annotations

import math
import time

import numpy as np

from ..errors import GearDesignError
from ..gears.mesh import Mesh, mesh_of
from ..validate import _show, one_number, require_choice, require_count, require_finite, require_range
from .center_distance import reachable_center_distance, x_sum_for_housing
from .conflict import smallest_conflict
from .grid import GRID_N_MAX
from .objectives import OBJECTIVES, default_objective, unlimited_life_note
from .problem import DEFAULT_BOUNDS, Problem, validate_bounds
from .methods import ACCURACY, DEFAULT_TOL, METHOD_TABLE, METHODS
from .result import Outcome, ShiftResult

__all__ = ["optimize_shifts", "ShiftResult", "METHODS", "DEFAULT_TOL", "OBJECTIVES", "GRID_N_MAX",
           "smallest_conflict", "reachable_center_distance", "x_sum_for_housing"]



def optimize_shifts(z1=None, z2=None, objective=None, checks=None, method: str = "exact",
                    tol: float | None = None, a_w: float | None = None, m: float | None = None, rack=None,
                    tip_shortening: bool = True, bounds=DEFAULT_BOUNDS, grid_n: int | None = None,
                    start=None, beta_deg: float = 0.0, internal: bool = False,
                    face_width_mm: float | None = None, *, mesh: Mesh | None = None) -> ShiftResult:
    """The best profile shifts x1, x2 for tooth counts z1, z2 under the chosen checks.

    Parameters
    ----------
    z1, z2 : tooth counts.
    objective : a name in :data:`geardesign.shifts.objectives.OBJECTIVES` or an
        :class:`~geardesign.shifts.objectives.Objective` (e.g. a ``CustomObjective``); default ``max_x_sum``, or
        ``balanced_sliding`` when ``a_w`` fixes the x-sum (objectives that depend on the x-sum
        alone, ``max_x_sum`` and ``min_specific_pressure``, are refused then: they are constant).
    checks : None (no undercut, no interference, s_a >= 0.25 m, ε_α >= 1.2), a dict of
        :func:`geardesign.gears.checks.make_checks` options (``{"sa_min": 0.4, "undercut": False}``),
        or a list of :class:`geardesign.gears.checks.Check`. Whatever is dropped, the gears must mesh
        (ε_α >= :data:`~geardesign.shifts.problem.MESHING_EPS_ALPHA_MIN`, the ``meshing`` check, added
        when no contact-ratio check implies it): a pair that does not mesh is no design.
    method : "grid" (fastest, x within half a node spacing), "convex" (SQP in cvxpy/Clarabel,
        ~1e-7 in x, dual sensitivities) or "exact" (active-set Newton, ~1e-12 in x; default).
    tol : tolerance in x (defaults: grid 0.01, convex 1e-7, exact 1e-9); every returned point
        satisfies the checks to within it.
    a_w : operating centre distance of the housing, mm; needs ``m``. It fixes x_Σ and the
        objective picks the split; an a_w the window cannot reach is refused with the reachable range.
    m : module, mm (scales a_w only; the shifts do not depend on it). Default 1 without ``a_w``.
    bounds : the window (lo, hi) searched for each of x1, x2.
    grid_n : nodes per axis of the grid method (default from ``tol``; at most GRID_N_MAX).
    start : a feasible (x1, x2) to start convex/exact from instead of their own coarse grid
        (the atlas passes the best node of its batched grid).
    beta_deg, internal, face_width_mm : a helical pair (normal module and shifts), an internal pair
        (gear 2 a ring; its x_Σ, which a_w fixes and ``max_x_sum`` maximises, is x2 − x1), and the
        face width for ε_β (see :class:`~geardesign.gears.mesh.Mesh`).
    mesh : a :class:`~geardesign.gears.mesh.Mesh` instead of z1, z2, rack, tip_shortening, beta_deg, internal
        and face_width_mm (giving both is refused).

    >>> r = optimize_shifts(17, 26)          # seed 000's tooth counts: ε_α >= 1.2 caps x1 + x2
    >>> r.success, r.active, round(r.fun, 6)
    (True, ['contact_ratio'], 1.337093)
    """
    t0 = time.perf_counter()
    method = require_choice("method", method, METHODS)
    if a_w is not None and m is None:
        raise GearDesignError(f"a_w (center distance) = {a_w!r} mm needs the module m: give m (mm) too")
    objective = default_objective(objective, x_sum_fixed=a_w is not None)
    tol = DEFAULT_TOL[method] if tol is None else one_number("tol", require_range("tol", tol, 1e-14, 1.0))
    bounds = validate_bounds(bounds)
    if grid_n is not None:
        grid_n = require_count("grid_n", grid_n, 2, GRID_N_MAX)
    if start is not None and np.shape(require_finite("start", start)) != (2,):
        raise GearDesignError(f"start must be a point (x1, x2), got {_show(start)}")
    prob = Problem(mesh_of(mesh, z1, z2, rack, tip_shortening, beta_deg, internal, face_width_mm), checks, objective,
                   1.0 if m is None else m)
    if prob.objective.kind == "margin" and not prob.asked:
        raise GearDesignError("objective 'max_margin' (the point farthest from every check's boundary) needs at "
                              "least one check, got checks=[]")
    if a_w is not None:
        prob.x_sum = x_sum_for_housing(prob, a_w, bounds)

    outcome = solve_problem(prob, method, bounds, tol, grid_n, start)
    return _result(prob, outcome, method, outcome.tol or tol, a_w, t0)


def solve_problem(prob: Problem, method: str, bounds, tol: float, grid_n=None, start=None) -> Outcome:
    """Hand a built problem to its method (:data:`~geardesign.shifts.methods.METHOD_TABLE`); the Outcome
    at the method's point. A problem with costly checks (the strength chain) is solved first without them:
    where that optimum holds them as well it is this problem's too, and the chain is read once, there."""
    solve = METHOD_TABLE[method].solve
    relaxed = prob.relaxed()
    if relaxed is not None:
        out = solve(relaxed, bounds, tol, grid_n, start)
        if out.success and prob.holds_costly(out.v):
            return out
    return solve(prob, bounds, tol, grid_n, start)


SLIDING_IMBALANCE = 2.0   # the larger root sliding over the smaller one above which the message names balanced_sliding


def _sliding_hint(prob: Problem, geo, success: bool) -> str:
    """A pointer to ``balanced_sliding`` when the optimum's specific sliding at the two roots is badly
    unbalanced (wear concentrates on one gear's root), unless that is the objective already."""
    if not success or prob.objective.name == "balanced_sliding":
        return ""
    try:
        s1, s2 = float(geo["sliding1_root"]), float(geo["sliding2_root"])
    except (KeyError, TypeError):
        return ""
    lo, hi = sorted((abs(s1), abs(s2)))
    if not (math.isfinite(lo) and math.isfinite(hi)) or hi <= SLIDING_IMBALANCE * lo:
        return ""
    return (f"; root sliding is unbalanced (ϑ1 = {_sliding_text(s1)}, ϑ2 = {_sliding_text(s2)}): "
            "objective='balanced_sliding' equalises it" + (" on this a_w" if prob.x_sum is not None else ""))


def _sliding_text(value: float) -> str:
    """A root's specific sliding as a message shows it: where the contact starts at the base circle (the
    interference limit active) the flank's rolling speed is 0 and ϑ = −∞, which rounding turns into ±1e15 (either
    sign): said as the limit rather than as that number.

    >>> _sliding_text(-1.4412), _sliding_text(-8.9e15), _sliding_text(3.1e15)
    ('-1.44', '-∞ (the contact starts at the base circle)', '-∞ (the contact starts at the base circle)')
    """
    if abs(value) < 1e9:
        return f"{value:.3g}"
    return "-∞ (the contact starts at the base circle)"


# The stationarity of an edge is read from central differences of gradients that are central differences
# themselves (max_margin's pieces): it holds to ~1e-8, and so does x along the edge.
_EDGE_ACCURACY = ("KKT point on an edge of two normalised margins, solved by Newton: x to ~1e-8 along the edge (its "
                  "stationarity is read from central-difference gradients), fun to ~1e-14, checks hold to {tol:g}")


def _edge_accuracy(prob: Problem, P, method: str, tol: float) -> str:
    """What an exact max_margin optimum on an edge (two pieces active, not a vertex's three) is accurate to;
    '' for any other result."""
    if method != "exact" or prob.objective.kind != "margin" or prob.nvar != 2 or not np.isfinite(P).all():
        return ""
    edge = int(np.sum(P - P.min() <= 1e-9 * max(1.0, abs(P.min())))) == 2
    return _EDGE_ACCURACY.format(tol=tol) if edge else ""


def _result(prob: Problem, out: Outcome, method: str, tol: float, a_w, t0: float) -> ShiftResult:
    """The design at the method's point, evaluated once more on the float path, as a ShiftResult."""
    x1, x2 = (float(c[0]) for c in prob.xy(np.asarray(out.v)[None, :]))
    geo, (P, M, _, _) = prob.evaluate_design(x1, x2, grads=False)
    # a margin the solver cannot tell from zero is zero (no -2.8e-16 in reports)
    zero = tol if method != "grid" else 1e-12
    mg = {name: (0.0 if abs(v) <= zero else float(v)) for name, v in zip(prob.names, M)}
    fun = float(prob.objective.sense * P.min()) if prob.objective.kind != "margin" else float(P.min())
    # a check undefined at an infeasible point (the ISO 6336 chain where ε_α < 1) fails there: −inf, not an error
    margins_ok = all(map(math.isfinite, mg.values())) or not out.success and not any(map(math.isnan, mg.values()))
    if not (margins_ok and all(map(math.isfinite, [fun, float(geo["a_w"]), float(geo["eps_alpha"])]))):
        raise GearDesignError(
            f"no finite result for z1/z2 = {prob.z1}/{prob.z2} ({prob.objective.name}, {method}): the pair's "
            f"geometry or a check is undefined at the point the solver reached ({x1:.6g}, {x2:.6g}); "
            f"check the rack and the window")
    message, success = out.message, out.success
    undefined = [name for name, v in mg.items() if v == -math.inf]
    if undefined:
        message += (f"; {', '.join(undefined)} undefined at the point shown (margin -inf, failing: e.g. ISO 6336 "
                    f"needs eps_alpha >= 1, here {float(geo['eps_alpha']):.4g})")
    if success and not float(geo["eps_alpha"]) > 0:   # a tolerance asked too coarse to hold the meshing
        message, success = (f"the gears do not mesh at the point reached (eps_alpha {float(geo['eps_alpha']):.4g}): "
                            f"no design; a finer tol finds one"), False
    if prob.x_sum is not None:
        xs_name = "x2 - x1" if prob.mesh.internal else "x1 + x2"
        message += f"; {xs_name} = {prob.x_sum:.10g} fixed by a_w = {a_w:.10g} mm, objective {prob.objective.name}"
    message += _sliding_hint(prob, geo, out.success) + unlimited_life_note(prob.objective.name, fun)
    active = [k for k, v in mg.items() if abs(v) <= max(tol, 1e-9) * 10]
    return ShiftResult(
        x1=x1, x2=x2, fun=fun, objective=prob.objective.name, success=success, message=message,
        method=method, tol=tol, nit=out.nit, time_s=time.perf_counter() - t0, margins=mg, active=active,
        sensitivity=out.sensitivity, conflict=out.conflict, z1=prob.z1, z2=prob.z2, m=prob.m,
        x_sum_fixed=prob.x_sum, a_w=float(geo["a_w"]), eps_alpha=float(geo["eps_alpha"]),
        sensitivity_sides=out.sides, accuracy=out.accuracy or _edge_accuracy(prob, P, method, tol)
        or ACCURACY[method].format(tol=tol),
        beta_deg=prob.mesh.beta_deg,
        internal=prob.mesh.internal)
