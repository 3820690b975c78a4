"""d(fun)/d(limit) at an optimum from the multipliers of its active checks, one-sided at
degenerate corners (Gauvin & Tolle 1977)."""
from __future__ import annotations

import numpy as np

from ..gears import checks as _checks
from .active_set import active_rows, multipliers
from .local import Evaluator
from .problem import Problem

__all__ = ["sensitivities_at"]


def _limit_factor(check) -> float:
    """d(margin)/d(limit) → converts a multiplier into d(fun)/d(limit)."""
    check = getattr(check, "inner", check)   # a planetary set's check of one mesh
    if isinstance(check, _checks.Jamming):
        return -1.0
    if isinstance(check, _checks.CustomCheck):
        return (1.0 if check.sense == ">=" else -1.0) / check.scale
    return getattr(check, "margin_per_limit", 1.0)   # a margin S/S_min − 1: 1/S_min


def sensitivities_at(prob: Problem, ev: Evaluator, w, act_tol: float):
    """d(fun)/d(limit) of each active check at the optimum w, from the multipliers of the
    constraints active there (within ``act_tol``; window edges have no limit), and none for
    ``max_margin``.

    Where more constraints are active than the multipliers need (a degenerate corner), the
    multipliers are not unique and the optimum is not differentiable in the limit: the
    one-sided derivatives are the extremes of the check's multiplier over the multiplier set
    (Gauvin & Tolle 1977, Theorem 3.3), found by two small linear programs. Those checks get
    both sides in the second dict: {"raised": d fun/d limit as the limit rises, "lowered": ...}.
    Both methods call this one function, so they report the same values.
    """
    if prob.objective.kind == "margin":
        return {}, {}
    nv = prob.nvar
    P, M, GP, GM = ev(w[:nv])
    act_p = [k for k in range(P.size) if P[k] - w[nv] <= act_tol * max(1.0, abs(w[nv]))]
    act_m = [i for i in range(M.size) if abs(M[i]) <= act_tol]
    if not act_m:
        return {}, {}
    lp, lm = multipliers(prob, w, act_p, act_m, ev)
    sens, sides = {}, {}
    checks_of = {}
    for pos, j in enumerate(act_m):
        if j < len(prob.part_check):
            checks_of.setdefault(prob.part_check[j], []).append(pos)
    degenerate = len(act_p) + len(act_m) > nv + 1
    rows = np.array(active_rows(GP, GM, act_p, act_m)) if degenerate else None
    for ci, positions in checks_of.items():
        c = prob.checks[ci]
        f = -prob.objective.sense * _limit_factor(c)
        lam = float(sum(lm[p] for p in positions))
        if degenerate:
            rng = _multiplier_range(rows, nv, [len(act_p) + p for p in positions])
            if rng is not None and rng[1] - rng[0] > 1e-7 * max(1.0, abs(rng[1])):
                lo, hi = rng
                raised = f * (hi if _limit_factor(c) > 0 else lo)
                lowered = f * (lo if _limit_factor(c) > 0 else hi)
                sides[c.name] = {"raised": raised + 0.0, "lowered": lowered + 0.0}
                sens[c.name] = raised + 0.0
                continue
            if rng is not None:
                lam = rng[0]
        sens[c.name] = f * lam + 0.0
    return sens, sides


def _multiplier_range(rows: np.ndarray, nv: int, idx: list):
    """(min, max) of Σ λ[idx] over {λ >= 0 : Rᵀ λ = −e_t}, or None when the LP fails."""
    from scipy.optimize import linprog

    A = rows.T
    b = -np.eye(nv + 1)[nv]
    c = np.zeros(rows.shape[0])
    c[idx] = 1.0
    out = []
    for sign in (1.0, -1.0):
        res = linprog(sign * c, A_eq=A, b_eq=b, bounds=(0, None), method="highs")
        if res.status != 0:
            return None
        out.append(sign * res.fun)
    return out[0], out[1]
