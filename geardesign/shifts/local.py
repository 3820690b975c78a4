"""Local solves shared by the methods: one design's values and gradients cached for a solver,
the search window as linear checks, SLSQP on the max-min form, and the most central point."""
from __future__ import annotations

import numpy as np
from scipy.optimize import minimize

from .problem import Problem

__all__ = ["Evaluator", "window_box", "slsqp", "MinMargin", "central_point", "BIG"]

BIG = 1e3             # stands in for −inf margins inside the smooth solvers


class Evaluator:
    """Caches Problem.evaluate_point at one point for the solvers (w = (v, t)).

    With ``window`` (lo, hi) the window's edges join the margins as linear checks
    v − lo >= 0 and hi − v >= 0 (after the problem's own), so that an optimum on the window
    is a KKT point like any other.
    """

    _CACHE = 16   # points remembered: Newton returns to its iterate after each difference step

    def __init__(self, prob: Problem, window=None):
        self.prob = prob
        self.cache = {}
        self.nfev = 0
        self.missing = 0   # points where the pair's geometry does not exist (a solver walked to its edge)
        self.window = window
        if window is not None:
            eye = np.eye(prob.nvar)
            self._window_rows = np.concatenate((eye, -eye))
            self._lo, self._hi = [float(c) for c in window[0]], [float(c) for c in window[1]]

    def __call__(self, v):
        key = tuple(map(float, v))
        val = self.cache.get(key)
        if val is None:
            P, M, GP, GM = self.prob.evaluate_point(key)
            if self.window is not None:
                M = np.concatenate((M, [a - b for a, b in zip(key, self._lo)] + [b - a for a, b in zip(key, self._hi)]))
                GM = np.concatenate((GM, self._window_rows))
            if not (np.isfinite(M).all() and np.isfinite(P).all()):
                self.missing += 1
                P, M = np.nan_to_num(P, nan=-BIG, neginf=-BIG), np.nan_to_num(M, nan=-BIG, neginf=-BIG)
                GP, GM = np.nan_to_num(GP), np.nan_to_num(GM)
            val = (P, M, GP, GM)
            if len(self.cache) >= self._CACHE:
                self.cache.pop(next(iter(self.cache)))
            self.cache[key] = val
            self.nfev += 1
        return val


def window_box(prob: Problem, bounds):
    """The box of the free variables: (lo, hi) arrays."""
    lo, hi = bounds
    if prob.nvar == 1:
        lo1, hi1 = prob.x1_on_line(lo, hi)
        return np.array([lo1]), np.array([hi1])
    return np.array([lo, lo], dtype=float), np.array([hi, hi], dtype=float)


def slsqp(prob: Problem, v0, bounds, ftol=1e-15, maxiter=200, pieces_only=False):
    """SLSQP on w = (v, t): maximise t s.t. pieces − t >= 0, margins >= 0: (w, iterations, the
    evaluator, whether SLSQP reports success)."""
    ev = Evaluator(prob)
    nv = prob.nvar
    P0, M0, _, _ = ev(v0)
    w0 = np.append(v0, P0.min())

    def cons(w):
        P, M, _, _ = ev(w[:nv])
        return np.concatenate([P - w[nv], [] if pieces_only else M])

    def cons_jac(w):
        _, _, GP, GM = ev(w[:nv])
        top = np.hstack([GP, -np.ones((GP.shape[0], 1))])
        if pieces_only:
            return top
        return np.vstack([top, np.hstack([GM, np.zeros((GM.shape[0], 1))])])

    lo, hi = window_box(prob, bounds)
    res = minimize(lambda w: -w[nv], w0, jac=lambda w: np.append(np.zeros(nv), -1.0),
                   constraints=[{"type": "ineq", "fun": cons, "jac": cons_jac}],
                   bounds=list(zip(lo, hi)) + [(None, None)], method="SLSQP",
                   options={"ftol": ftol, "maxiter": maxiter})
    return res.x, res.nit, ev, bool(res.success)


class MinMargin:
    """A problem seen with pieces = its margins (to maximise the smallest), no hard constraints;
    everything else is the base problem's (a pair's or a planetary set's)."""

    def __init__(self, base: Problem):
        self.base = base

    def __getattr__(self, name):
        return getattr(self.base, name)

    def evaluate(self, V, grads=True):
        out = self.base.evaluate(V, grads)
        if not grads:
            return out[1], out[1][:0]
        P, M, GP, GM = out
        return M, M[:0], GM, GM[:0]

    def evaluate_point(self, v):
        P, M, GP, GM = self.base.evaluate_point(v)
        return M, M[:0], GM, GM[:0]


def central_point(prob: Problem, V, M, bounds) -> np.ndarray:
    """(x, t): the point that maximises the smallest margin t near the least infeasible node of
    V (M its margins), by SLSQP; t >= 0 is a feasible point of a region thinner than the grid."""
    worst = M.min(axis=0) if M.size else np.zeros(V.shape[0])
    i = int(np.argmax(worst))
    w, _, ev, _ = slsqp(MinMargin(prob), V[i], bounds, ftol=1e-12, pieces_only=True)
    if not w[-1] > worst[i] and not (ev(w[:-1])[0] > -BIG).all():
        # SLSQP left for where the design stops existing (margins −BIG): the node it started from
        # is the better answer
        return np.append(V[i], worst[i])
    return w
