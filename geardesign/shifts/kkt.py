"""The exact method: from each start, Newton on the KKT system of each candidate active set among
the checks that pass near it (the window's edges count as checks); SLSQP, then the same polish,
only when none gives a KKT point. Reaches ~1e-12 in x."""
from __future__ import annotations

import itertools
import math

import numpy as np

from ..gears.checks import FEASIBILITY_TOL
from .active_set import active_rows, multipliers, solve_small
from .local import Evaluator, slsqp, window_box
from .problem import Problem
from .result import Outcome
from .sensitivities import sensitivities_at

__all__ = ["solve"]


def _stationarity(rows, nv):
    """det [e_t; rows] / Π‖row‖: zero when e_t lies in the span of the nv active gradients,
    i.e. the Lagrangian is stationary with one active constraint fewer than variables + 1."""
    # a zero row (a check flat at its boundary, a pointed tip) has no direction: NaN, and the
    # Newton on this active set gives up
    if nv == 1:
        norm = math.hypot(rows[0][0], rows[0][1])
        return -rows[0][0] / norm if norm > 0 else math.nan
    (a0, a1, a2), (b0, b1, b2) = rows
    norm = math.sqrt(a0 * a0 + a1 * a1 + a2 * a2) * math.sqrt(b0 * b0 + b1 * b1 + b2 * b2)
    return (a0 * b1 - a1 * b0) / norm if norm > 0 else math.nan


def _kkt_newton(ev: Evaluator, nv: int, act_p, act_m, w0, max_move: float, maxit: int = 30,
                noisy: bool = False):
    """Newton on the KKT system of one active set: active pieces = t, active margins = 0 and,
    with one equation short, :func:`_stationarity`. The active rows of the Jacobian are the
    analytic gradients; the stationarity row starts from forward differences and is then kept
    by Broyden's update (one evaluation per step instead of nv + 1).
    With ``noisy`` gradients (central differences) the stationarity holds to ~1e-9 only, so it
    is accepted at 1e-8 and the steps stop at 1e-10.
    Returns (w, iterations) or None when it diverges, leaves ``max_move`` or stalls."""
    edge = len(act_p) + len(act_m) == nv
    step_tol, stat_tol = (1e-10, 1e-8) if noisy else (1e-13, 1e-10)
    # at a vertex every equation is a margin or piece with an O(1) gradient: a residual at rounding level
    # puts x there too, without the last step's confirmation; the stationarity row of an edge may be
    # flat, so edges stop on the step
    res_tol = 1e-14 if not (edge or noisy) else 0.0
    w0 = [float(c) for c in w0]
    w = w0[:]

    def system(w):
        P, M, GP, GM = ev(w[:nv])
        rows = active_rows(GP, GM, act_p, act_m)
        F = [float(P[k]) - w[nv] for k in act_p] + [float(M[i]) for i in act_m]
        if edge:
            F.append(_stationarity(rows, nv))
        return F, rows

    F, rows = system(w)
    if not all(map(math.isfinite, F)):
        return None
    if edge:
        srow = [0.0] * (nv + 1)
        for j in range(nv):
            step = 1e-5 * max(1.0, abs(w[j]))   # gradients may be differences themselves
            vj = w[:nv]
            vj[j] += step
            _, _, GPj, GMj = ev(vj)
            srow[j] = (_stationarity(active_rows(GPj, GMj, act_p, act_m), nv) - F[-1]) / step
        if not all(map(math.isfinite, srow)):
            return None
    for it in range(1, maxit + 1):   # noqa: B007 (the count is returned after the loop)
        try:
            dw = solve_small(rows + [srow] if edge else rows, [-f for f in F])
        except np.linalg.LinAlgError:
            return None
        small = max(map(abs, dw[:nv])) <= step_tol * max(1.0, max(map(abs, w[:nv])))
        if small and not noisy and max(map(abs, F[:-1] if edge else F), default=0.0) <= 1e-12:
            break   # x within a step below the tolerance, t too: stay where F is known (no confirming evaluation)
        w = [a + d for a, d in zip(w, dw)]
        if not all(map(math.isfinite, w)) or max(abs(a - b) for a, b in zip(w[:nv], w0)) > max_move:
            return None
        F_old = F
        F, rows = system(w)
        if not all(map(math.isfinite, F)):
            return None
        dd = sum(d * d for d in dw)
        if edge and dd > 0:   # Broyden: the row's directional derivative along the step matches the change
            r = (F[-1] - F_old[-1] - sum(a * d for a, d in zip(srow, dw))) / dd
            srow = [a + r * d for a, d in zip(srow, dw)]
        if small or max(map(abs, F)) <= res_tol:
            break
    ok = max(map(abs, F[:-1] if edge else F), default=0.0) <= 1e-10 and (not edge or abs(F[-1]) <= stat_tol)
    return (np.array(w), it) if ok else None


def _active_sets(near_p, near_m, nv):
    """Candidate active sets (>= 1 piece; nv + 1 constraints, or nv with stationarity),
    the fully determined ones (vertices) first."""
    need = nv + 1
    out = []
    for n_m in range(len(near_m), -1, -1):
        for sub_m in itertools.combinations(near_m, n_m):
            for n_p in range(len(near_p), 0, -1):
                for sub_p in itertools.combinations(near_p, n_p):
                    if n_m + n_p in (need, need - 1):
                        out.append((list(sub_p), list(sub_m)))
    out.sort(key=lambda o: -(len(o[0]) + len(o[1])))
    return out


def _promising_first(prob: Problem, ev: Evaluator, w0, cands):
    """The candidate sets whose multipliers, linearised at w0, are >= 0 first, then the others, each
    group in its order (a stable sort on that test, its multipliers computed only as far as the
    candidates are tried)."""
    if len(cands) <= 1:
        yield from cands
        return
    later = []
    for c in cands:
        if min(np.concatenate(multipliers(prob, w0, *c, ev)), default=0.0) < 0:
            later.append(c)
        else:
            yield c
    yield from later


def _first_kkt_point(prob: Problem, ev: Evaluator, w0, near_p, near_m, max_move: float, limit: int = 24):
    """The first candidate active set whose Newton solution is a KKT point: it holds every
    check, no piece is below t, the multipliers are >= 0, and t is no worse than at w0.

    Returns (w, act_p, act_m, newton iterations) or None.
    """
    nv = prob.nvar
    # no worse than the start, when the start holds every check: a start node that misses one (a region's piece
    # seen on the coarse grid) may score above the optimum, which would then be refused here for SLSQP to find
    M0 = ev(w0[:nv])[1]
    t0 = w0[nv] if not (M0.size and M0.min() < -FEASIBILITY_TOL) else -math.inf
    nit = 0
    # Newton reads the active rows alone: where no costly check is active it walks without them, and the
    # point it reaches is checked against every check below
    light, costly = ev.light(), getattr(prob, "costly_parts", set())
    for act_p, act_m in itertools.islice(_promising_first(prob, ev, w0, _active_sets(near_p, near_m, nv)), limit):
        walk = light if light is not None and costly.isdisjoint(act_m) else ev
        # on the active rows' checks alone (the same iterates: the rows are all it reads), the start and the end
        # point in full (multipliers, feasibility)
        out = _kkt_newton(walk.reading_only(act_m), nv, act_p, act_m, w0, max_move, noisy=walk.prob.fd_gradients)
        if out is None:
            continue
        w, it = out
        nit += it
        P, M, _, _ = ev(w[:nv])
        if (M.size and M.min() < -FEASIBILITY_TOL) or P.min() < w[nv] - 1e-10 or w[nv] < t0 - 1e-9:
            continue
        lp, lm = multipliers(prob, w, act_p, act_m, ev)
        if (lp.size and lp.min() < -1e-7) or (lm.size and lm.min() < -1e-7):
            continue
        return w, act_p, act_m, nit
    return None


def _near(ev: Evaluator, nv: int, w, reach: float, most: int = 4):
    """Pieces and margins whose boundary (to first order) lies within ``reach`` of w in x."""
    P, M, GP, GM = ev(w[:nv])
    k0 = int(np.argmin(P))
    with np.errstate(divide="ignore", invalid="ignore"):
        dist_p = (P - w[nv]) / np.sqrt(((GP - GP[k0]) ** 2).sum(axis=1))
        dist_m = M / np.sqrt((GM ** 2).sum(axis=1))
    dist_p[k0] = 0.0
    near_p = [int(k) for k in np.argsort(dist_p)[:most] if dist_p[k] <= reach]
    near_m = [int(i) for i in np.argsort(dist_m)[:most] if dist_m[i] <= reach]
    return sorted(near_p), sorted(near_m)


def _polish(prob: Problem, w, ev: Evaluator, tol: float, act_tol=1e-5):
    """Newton on the active set of a converged SLSQP point: (w, act_p, act_m) or None."""
    nv = prob.nvar
    P, M, _, _ = ev(w[:nv])
    near_p = [k for k in range(P.size) if P[k] - w[nv] < act_tol]
    near_m = [i for i in range(M.size) if M[i] < act_tol]
    found = _first_kkt_point(prob, ev, w, near_p, near_m, max_move=1e-3)
    return None if found is None else found[:3]


_SLSQP_KKT = "converged: SLSQP, then Newton on the KKT system of its active set"
# the accuracy of a point SLSQP ends on when no KKT point is found near it (exact_from's kind "slsqp")
SLSQP_ACCURACY = ("SLSQP's point (no KKT point of the active set found near it): fun to SLSQP's ftol, x not "
                  "certified; checks hold to {tol:g}")


def exact_from(prob: Problem, ev: Evaluator, v0, bounds, tol, h):
    """One local exact solve from the feasible point v0: (w, iterations, message, kind), kind
    "kkt" for a KKT point, "slsqp" for SLSQP's point where no KKT point was found near it, "edge"
    when SLSQP failed after walking to where the pair stops existing."""
    nv = prob.nvar
    w0 = np.append(v0, ev(v0)[0].min())
    found = _first_kkt_point(prob, ev, w0, *_near(ev, nv, w0, reach=2.2 * h), max_move=3 * h)
    if found is not None:
        return found[0], found[3], "converged: KKT system of the active set solved by Newton from a grid node", "kkt"
    if getattr(prob, "costly_parts", None):
        # SLSQP on the costly checks' quadratic model around v0 (one call of the chain), then the polish on the
        # checks themselves; where that finds no KKT point, SLSQP on the checks themselves
        w, nit, _, _ = slsqp(prob.modelled_at(v0), v0, bounds)
        polished = _polish(prob, w, Evaluator(prob), tol)
        if polished is not None:
            return polished[0], nit, _SLSQP_KKT, "kkt"
    # with central-difference gradients (~1e-10 noise) SLSQP cannot meet 1e-15; it would run to maxiter
    w, nit, ev_s, ok = slsqp(prob, v0, bounds, ftol=1e-10 if prob.fd_gradients else 1e-15)
    polished = _polish(prob, w, ev_s, tol)
    if polished is not None:
        return polished[0], nit, _SLSQP_KKT, "kkt"
    # Where SLSQP stops after a failed line search depends on the last digits of the margins
    # near the edge (on it or just inside): the edge is recognised by SLSQP having reached it.
    kind = "edge" if not ok and ev_s.missing > 0 else "slsqp"
    return _inside(ev_s, w, nv, tol), nit, "converged (SLSQP; active-set polish not applicable)", kind


def _inside(ev, w, nv: int, tol: float):
    """SLSQP's point w moved the least that makes the margins it misses by less than ``tol`` hold (one
    Gauss-Newton step on those margins, to a hair inside): SLSQP meets its constraints to its own tolerance,
    a returned optimum must hold every check (FEASIBILITY_TOL). w itself where no such step does it."""
    _, M, _, GM = ev(w[:nv])
    miss = M < 0.0
    if not miss.any() or (M < -tol).any():
        return w
    step = np.linalg.lstsq(GM[miss], FEASIBILITY_TOL - M[miss], rcond=None)[0]
    v = w[:nv] + step
    P2, M2, _, _ = ev(v)
    if M2.min() >= 0.0 and np.isfinite(P2).all():
        return np.append(v, P2.min())
    return w


_NO_OPTIMUM = ("no optimum: {objective} keeps improving toward the edge where the pair stops existing "
               "(inv alpha_w -> 0 or a tip circle at its base circle); the checks asked for do not bound it "
               "(keep the interference checks, or narrow the window); returned the best start node")


def _exists(prob: Problem, v) -> bool:
    """True when the pair's geometry exists (every margin and piece finite) at v."""
    P, M, _, _ = prob.evaluate_point(v)
    return bool(np.isfinite(P).all() and np.isfinite(M).all())


def _settled(ceiling: float, v0, best, solved, h: float) -> bool:
    """True when the start v0 cannot beat the best point found, a point that holds every check: its piece's
    ceiling (the first-order most of its grid piece) is below it, or, for a near node (ceiling NaN: a piece
    too thin for the grid was looked for there), a point already solved that holds every check lies within
    two node spacings of it: a near node is looked at only beyond two nodes of every feasible node
    (:func:`~geardesign.shifts.nodes.grid_starts`), and a feasible point found that close is such a node's
    stand-in."""
    if best is None or not best[0]:
        return False
    if math.isnan(ceiling):
        return any(np.abs(np.asarray(v0) - x).max() <= 2 * h * (1 + 1e-9) for x in solved)
    return ceiling < best[1] - 1e-12


def solve(prob: Problem, starts: list, bounds, tol: float, h: float, ceilings=None) -> Outcome:
    """The best of the local optima from each start (a region may have several pieces and corners);
    ``h`` is the start grid's spacing, which bounds how far Newton may move. A start whose ``ceilings``
    entry shows it cannot beat the best point found is not solved (:func:`_settled`)."""
    ev = Evaluator(prob, window=window_box(prob, bounds))
    nv = prob.nvar
    best, nit, solved, skipped = None, 0, [], 0
    for v0, ceiling in zip(starts, ceilings if ceilings is not None else [math.inf] * len(starts)):
        if _settled(ceiling, v0, best, solved, h):
            skipped += 1
            continue
        w, it, msg, kind = exact_from(prob, ev, v0, bounds, tol, h)
        nit += it
        Mw = ev(w[:nv])[1]
        score = w[-1] if not (kind == "edge" or (Mw.size and Mw.min() < -tol)) else -math.inf
        # a point that holds every check ranks above one that misses a check by less than tol (SLSQP's
        # own points do, and gain ~multiplier × tol in the objective by it)
        holds = score > -math.inf and not (Mw.size and Mw.min() < -FEASIBILITY_TOL)
        if holds:
            solved.append(w[:nv])
        if best is None or (holds, score) > (best[0], best[1] + 1e-12):
            best = (holds, score, w, msg, kind)
    _, score, w, msg, kind = best
    if score == -math.inf and (kind == "edge" or not _exists(prob, w[:nv])):
        return Outcome(starts[0], nit, False, _NO_OPTIMUM.format(objective=prob.objective.name))
    Mv = ev(w[:nv])[1][:len(prob.part_check)]
    ok = not (Mv.size and Mv.min() < -tol)
    if len(starts) - skipped > 1:
        msg += f" (best of {len(starts) - skipped} starts)"
    if skipped:
        msg += (f" ({skipped} other start{'s' if skipped > 1 else ''} not solved: a piece whose first-order "
                "ceiling is below it, or a near node beside a point solved)")
    sens, sides = sensitivities_at(prob, ev, w, act_tol=1e-9)
    # SLSQP's own point (no KKT point found near it) is not the Newton-polished one the method's table describes
    accuracy = None if kind == "kkt" else SLSQP_ACCURACY.format(tol=tol)
    return Outcome(w[:nv], nit, ok, msg if ok else "a check is violated beyond tol", sens, sides, accuracy=accuracy)
