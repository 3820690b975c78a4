"""The convex method: sequential convex programming in cvxpy with Clarabel. The subproblem is
built once per shape with Parameters (DPP) and re-solved; its duals feed the curvature."""
from __future__ import annotations

import warnings

import numpy as np

from .local import Evaluator, window_box
from .problem import Problem
from .result import Outcome
from .sensitivities import sensitivities_at

__all__ = ["solve"]

_SCP_CACHE: dict = {}
# Clarabel's gap and feasibility tolerances: 1e-12 asked more than an interior-point method reaches
# on the normalised-margin subproblems (cvxpy then warned "Solution may be inaccurate" on ~1 in 20 of
# them); 1e-10 is reached and is still far below the method's tolerance in x (1e-7)
_SUBPROBLEM_TOL = 1e-10
# a dual value of the subproblem below this is an inactive check's (Clarabel leaves ~1e-10 there)
_NO_MULTIPLIER = 1e-8
# weight of the checks' violation against the objective in the merit that accepts or refuses a step
_PENALTY = 10.0


def _scp_problem(P: int, K: int, nv: int):
    """The convex subproblem, built once per shape and re-solved with new Parameters (DPP):
    maximise t − ½‖L d‖² s.t. pieces + GP d >= t, margins + GM d >= 0, lo <= d <= hi,
    with LᵀL the PSD part of the Lagrangian's curvature (so the steps are SQP steps)."""
    key = (P, K, nv)
    if key not in _SCP_CACHE:
        import cvxpy as cp

        d = cp.Variable(nv)
        t = cp.Variable()
        Pp, GPp = cp.Parameter(P), cp.Parameter((P, nv))
        Mp, GMp = cp.Parameter(K), cp.Parameter((K, nv))
        lo, hi, Lp = cp.Parameter(nv), cp.Parameter(nv), cp.Parameter((nv, nv))
        cons = [Pp + GPp @ d >= t, d >= lo, d <= hi]
        if K:
            cons.append(Mp + GMp @ d >= 0)
        problem = cp.Problem(cp.Maximize(t - 0.5 * cp.sum_squares(Lp @ d)), cons)
        _SCP_CACHE[key] = (problem, d, t, Pp, GPp, Mp, GMp, lo, hi, Lp, cons)
    return _SCP_CACHE[key]


def _curvature(ev: Evaluator, v, lam_p, lam_m, h=1e-5):
    """L with LᵀL = PSD part of −∇²(Σ λ_p p + Σ λ_m m), second derivatives by central
    differences of the analytic gradients."""
    nv = v.size
    H = np.zeros((nv, nv))
    # checks without a multiplier add no curvature: where the costly ones (the strength chain) have none,
    # the differences are taken without evaluating them
    costly = sorted(getattr(ev.prob, "costly_parts", ()))
    light = ev.light() if costly and np.all(np.abs(lam_m[costly]) <= _NO_MULTIPLIER) else None
    at = ev if light is None else light
    for j in range(nv):
        e = np.zeros(nv)
        e[j] = h
        _, _, GPu, GMu = at(v + e)
        _, _, GPd, GMd = at(v - e)
        H[:, j] = lam_p @ (GPu - GPd) / (2 * h) + (lam_m @ (GMu - GMd) / (2 * h) if lam_m.size else 0.0)
    B = -(H + H.T) / 2
    vals, vecs = np.linalg.eigh(B)
    vals = np.clip(vals, 1e-8, None)
    return (vecs * np.sqrt(vals)).T


def solve_convex(prob: Problem, v0, bounds, tol, maxit=100):
    """SQP in a trust region from ``v0``: each step solves the convex subproblem (:func:`_scp_problem`),
    is kept when the merit (:func:`_merit`) gains at least a tenth of the predicted gain, and then sets
    the curvature from the subproblem's duals. Returns the point, the iterations, the checks'
    multipliers and the evaluator (with the count of inaccurately solved subproblems)."""
    nv = prob.nvar
    ev = Evaluator(prob)
    P, M, GP, GM = ev(v0)
    sub = _scp_problem(P.size, M.size, nv)
    cons = sub[-1]
    box_lo, box_hi = _window(prob, bounds)
    v = np.asarray(v0, dtype=float)
    radius = 0.25
    lam_p = np.full(P.size, 1.0 / P.size)
    lam_m = np.zeros(M.size)
    L = np.eye(nv) * 1e-4
    nit = inaccurate = 0
    for nit in range(1, maxit + 1):   # noqa: B007 (the count is returned after the loop)
        step, value, rough = _subproblem_step(sub, P, M, GP, GM, L, np.maximum(-radius, box_lo - v),
                                              np.minimum(radius, box_hi - v))
        inaccurate += rough
        if step is None:
            radius /= 4
            if radius < tol:
                break
            continue
        now = _merit(P, M)
        predicted = value - now
        step, (P1, M1, GP1, GM1), actual = _corrected(ev, v, step, M, GM, now, predicted, ev(v + step))
        if predicted <= 1e-15 or actual >= 0.1 * predicted:
            v, P, M, GP, GM = v + step, P1, M1, GP1, GM1
            lam_p = np.asarray(cons[0].dual_value, dtype=float)
            if M.size:
                lam_m = np.asarray(cons[3].dual_value, dtype=float)
            L = _curvature(ev, v, lam_p, lam_m)
            if predicted > 0 and actual > 0.75 * predicted and np.max(np.abs(step)) > 0.9 * radius:
                radius = min(2 * radius, 1.0)
            if np.max(np.abs(step)) < 0.01 * tol:   # the next SQP step would be ~(tol/100)²
                break
        else:
            radius = min(radius, np.max(np.abs(step))) / 4
            if radius < 0.01 * tol:
                break
    ev.inaccurate = inaccurate
    return v, nit, lam_m, ev


def _merit(P, M):
    """The merit of a point: its smallest objective piece less _PENALTY times the checks' violation."""
    return P.min() - _PENALTY * np.clip(-M, 0, None).sum()


def _window(prob: Problem, bounds):
    """The window (lo, hi) in the solver's variables: x1 along the line of fixed x_Σ, or the (x1, x2) box."""
    blo, bhi = bounds
    if prob.nvar == 1:
        box_lo, box_hi = (np.array([v]) for v in prob.x1_on_line(blo, bhi))
        return box_lo, box_hi
    return np.array([blo, blo]), np.array([bhi, bhi])


def _subproblem_step(sub, P, M, GP, GM, L, lo_d, hi_d):
    """The subproblem's step d within lo_d <= d <= hi_d (None where the solver found none), its optimal
    value, and whether the solver called its solution inaccurate."""
    import cvxpy as cp

    problem, d, _, Pp, GPp, Mp, GMp, lo, hi, Lp, _ = sub
    Pp.value, GPp.value, Lp.value = P, GP, L
    if M.size:
        Mp.value, GMp.value = M, GM
    lo.value = lo_d
    hi.value = hi_d
    with warnings.catch_warnings():
        # read from problem.status below and reported in the result's message, not on stderr
        warnings.filterwarnings("ignore", message="Solution may be inaccurate")
        problem.solve(solver=cp.CLARABEL, warm_start=False, tol_gap_abs=_SUBPROBLEM_TOL, tol_gap_rel=_SUBPROBLEM_TOL,
                      tol_feas=_SUBPROBLEM_TOL)
    rough = problem.status == "optimal_inaccurate"
    if d.value is None:
        return None, None, rough
    return np.asarray(d.value, dtype=float), float(problem.value), rough


def _corrected(ev: Evaluator, v, step, M, GM, now, predicted, trial):
    """The step, the evaluation at its end and the merit's gain, with a second-order correction where the
    plain step gains less than a tenth of the prediction and leaves checks violated."""
    P1, M1, GP1, GM1 = trial
    actual = _merit(P1, M1) - now
    if actual < 0.1 * predicted and M.size and (M1 < 0).any():
        # second-order correction (Maratos effect): pull the violated checks back to zero
        bad = M1 < 0
        corr = -np.linalg.pinv(GM[bad]) @ M1[bad]
        P2, M2, GP2, GM2 = ev(v + step + corr)
        if _merit(P2, M2) - now >= 0.1 * predicted:
            return step + corr, (P2, M2, GP2, GM2), _merit(P2, M2) - now
    return step, trial, actual


def solve(prob: Problem, starts: list, bounds, tol: float) -> Outcome:
    """SQP from the best start; sensitivities from the same active-set multipliers as ``exact``."""
    v, nit, _, ev = solve_convex(prob, starts[0], bounds, tol)
    Pv, Mv, _, _ = ev(v)
    ok = not (Mv.size and Mv.min() < -tol)
    msg = "converged: trust region below tol" if ok else "stopped with a check violated beyond tol"
    if ev.inaccurate:
        msg += (f" ({ev.inaccurate} of {nit} convex subproblems solved only inaccurately by the solver; "
                "the point is checked against every check all the same)")
    w = np.append(v, Pv.min())
    sens, sides = sensitivities_at(prob, Evaluator(prob, window=window_box(prob, bounds)), w, act_tol=10 * tol)
    return Outcome(v, nit, ok, msg, sens, sides)
