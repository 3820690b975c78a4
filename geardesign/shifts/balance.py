"""The exact method's short cut on a fixed-a_w line with the ``balanced_sliding`` objective: the point where the
specific sliding at the two roots is equal (GOST 16532-70's distribution rule), found by a safeguarded Newton on
the line, is the optimum when every check holds there with room to spare.

Why it is the optimum: along the line x1 + x2 = x_Σ, |ϑ1,root| falls and |ϑ2,root| rises as x1 grows
(:func:`geardesign.gears.pair.balanced_sliding_split` relies on the same monotony), so max(|ϑ1|, |ϑ2|) has one
minimum, at their crossing; where no check is active there, it is a KKT point with both pieces active and the
objective's gradients of opposite sign (checked here: a point where they are not is handed back). A drive sizing
gear stages on a standard housing solves ~600 such lines; the active-set search from a 401-node grid costs ~3 ms
each, this ~0.2 ms. Anything this does not certify (a check within :data:`CLEARANCE` of its limit at the
crossing, no crossing inside the window, a crossing the Newton does not reach) goes to the active-set search."""
from __future__ import annotations

import math

import numpy as np

from ..gears.geometry import mesh_geometry_float
from .local import Evaluator, window_box
from .problem import _FLOAT_FAULTS, Problem
from .result import Outcome
from .sensitivities import sensitivities_at

__all__ = ["serves", "solve", "CLEARANCE"]

CLEARANCE = 1e-6     # the least margin of every check at the crossing for the short cut to certify it
_MAXIT = 60
_GRID_N = 401       # nodes of the line that certify a boundary optimum (the active-set search's start grid)
_MESSAGE = "converged: equal root sliding on the fixed-a_w line (Newton with bisection), no check active there"
_BOUNDED = ("converged: {check} stops the fixed-a_w line short of equal root sliding; its boundary solved by "
            "Newton with bisection")


def serves(prob: Problem) -> bool:
    """True for one pair's (not a planetary set's) ``balanced_sliding`` problem on a fixed-a_w line."""
    return type(prob) is Problem and prob.objective.name == "balanced_sliding" and prob.nvar == 1


def _gap(prob: Problem, x1: float):
    """(ϑ-piece difference, its derivative along the line) at x1 from the geometry alone (the margins are read
    once, at the end); None where the pair does not exist there."""
    try:
        geo = mesh_geometry_float(prob.mesh, prob.m, x1, prob.x_sum - prob.sgn * x1, prob.full)
    except _FLOAT_FAULTS:
        return None
    (p1, p2), ((a1, a2), (b1, b2)) = prob.objective.pieces(geo), prob.objective.piece_gradients(geo)
    d = float(p1 - p2)
    return (d, float((a1 - prob.sgn * a2) - (b1 - prob.sgn * b2))) if math.isfinite(d) else None


def solve(prob: Problem, bounds):
    """The crossing as an :class:`~geardesign.shifts.result.Outcome`, or None where it is not certified (the
    active-set search then solves the problem)."""
    lo, hi = prob.x1_on_line(*bounds)
    if not lo < hi:
        return None
    a, b = _gap(prob, lo), _gap(prob, hi)
    if a is None or b is None or not a[0] * b[0] < 0.0:
        return None        # no crossing inside the window, or the pair does not exist at an end of it
    # pieces are −|ϑ1|, −|ϑ2|: the difference rises with x1 where |ϑ1| falls and |ϑ2| rises
    x_lo, x_hi = (lo, hi) if a[0] < 0.0 else (hi, lo)
    x, it = 0.5 * (lo + hi), 0
    while True:
        it += 1
        if it > _MAXIT:
            return None
        g = _gap(prob, x)
        if g is None:
            return None
        d, slope = g[0], g[1]
        if d == 0.0:
            break
        if d < 0.0:
            x_lo = x
        else:
            x_hi = x
        step = -d / slope if slope != 0.0 else math.nan
        nxt = x + step
        if not (min(x_lo, x_hi) < nxt < max(x_lo, x_hi)):
            nxt = 0.5 * (x_lo + x_hi)            # Newton left the bracket: bisect
        if abs(nxt - x) <= 1e-15 * max(1.0, abs(x)):
            x = nxt
            break
        x = nxt
    P, M, GP, _ = prob.evaluate_point(np.array([x]))
    if not (np.isfinite(P).all() and np.isfinite(M).all()):
        return None
    if not (abs(float(P[0] - P[1])) <= 1e-12 * max(1.0, abs(float(P[0]))) and GP[0, 0] * GP[1, 0] < 0.0):
        return None
    if M.size and M.min() < CLEARANCE:
        return _bounded(prob, bounds, x, M, it, lo, hi)
    return _outcome(prob, bounds, x, P, it, _MESSAGE)


def _outcome(prob: Problem, bounds, x: float, P, it: int, message: str) -> Outcome:
    w = np.array([x, float(P.min())])
    sens, sides = sensitivities_at(prob, Evaluator(prob, window=window_box(prob, bounds)), w, act_tol=1e-9)
    return Outcome(w[:1], it, True, message, sens, sides)


def _bounded(prob: Problem, bounds, c: float, M, it: int, lo: float, hi: float):
    """The optimum when one check stops the line short of the crossing c: that check's boundary on the side
    where it holds (the objective is unimodal: the nearest feasible point to c is the best on its side),
    certified against every feasible node of a 401-node grid of the line; None where it is not."""
    bad = np.flatnonzero(M < CLEARANCE)
    if bad.size != 1 or not M[bad[0]] < 0.0:
        return None
    j = int(bad[0])
    slope = float(prob.evaluate_point(np.array([c]))[3][j, 0])
    if not math.isfinite(slope) or slope == 0.0:
        return None
    r = _margin_root(prob, j, c, hi if slope > 0.0 else lo)
    if r is None:
        return None
    x, n = r
    P, Mr, _, _ = prob.evaluate_point(np.array([x]))
    others = np.delete(Mr, j)
    if not (abs(Mr[j]) <= 1e-12 and (others.size == 0 or others.min() >= CLEARANCE) and np.isfinite(P).all()):
        return None
    grid = np.linspace(lo, hi, _GRID_N)
    Pg, Mg = prob.evaluate(grid[:, None], grads=False)
    held = Mg.min(axis=0) >= 0.0 if Mg.size else np.ones(grid.size, dtype=bool)
    if (Pg.min(axis=0)[held] > float(P.min()) + 1e-12).any():
        return None          # a feasible node beats the boundary point: another piece of the line (the search's)
    return _outcome(prob, bounds, x, P, it + n, _BOUNDED.format(check=prob.checks[prob.part_check[j]].name))


def _margin_root(prob: Problem, j: int, a: float, b: float):
    """(x, steps) where the margin part j (negative at a, positive at b) is zero, by Newton kept inside the
    bracket by bisection; None where it is not positive at b or the pair does not exist on the way."""
    def at(x):
        _, M, _, GM = prob.evaluate_point(np.array([x]))
        return float(M[j]), float(GM[j, 0])
    fb = at(b)[0]
    if not fb > 0.0:
        return None
    x_neg, x_pos, x = a, b, a
    for n in range(1, _MAXIT + 1):
        f, d = at(x)
        if not math.isfinite(f):
            return None
        if f == 0.0:
            return x, n
        if f < 0.0:
            x_neg = x
        else:
            x_pos = x
        nxt = x - f / d if d != 0.0 else math.nan
        if not (min(x_neg, x_pos) < nxt < max(x_neg, x_pos)):
            nxt = 0.5 * (x_neg + x_pos)
        if abs(nxt - x) <= 1e-15 * max(1.0, abs(x)):
            return (nxt, n) if at(nxt)[0] >= 0.0 else (x_pos, n)
        x = nxt
    return None
