"""Local solves shared by the methods: one design's values and gradients cached for a solver,
the search window as linear checks, SLSQP on the max-min form, and the most central point."""
from __future__ import annotations

import numpy as np

from .problem import Problem

__all__ = ["Evaluator", "window_box", "slsqp", "MinMargin", "central_point", "maximin", "BIG"]

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

    def reading_only(self, parts) -> "Evaluator":
        """An evaluator of :meth:`Problem.reading_only` (only the checks of the margin ``parts`` evaluated), with the
        same window, one per set of parts; itself where the problem has no such view."""
        key = frozenset(parts)
        views = self.__dict__.setdefault("_views", {})
        if key not in views:
            prob = self.prob.reading_only(key)
            views[key] = self if prob is self.prob else Evaluator(prob, self.window)
        return views[key]

    def light(self):
        """An evaluator of the problem without its costly checks (their margins −BIG: see Problem.light), with
        the same window, for steps that read only the others; None when the problem has no such view."""
        if not hasattr(self, "_light"):
            light = getattr(self.prob, "light", lambda: None)()
            self._light = None if light is None else Evaluator(light, self.window)
        return self._light

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
                P, M = _nan_to_num(P, nan=-BIG, neginf=-BIG), _nan_to_num(M, nan=-BIG, neginf=-BIG)
                GP, GM = _nan_to_num(GP), _nan_to_num(GM)
            val = (P, M, GP, GM)
            if len(self.cache) >= self._CACHE:
                self.cache.pop(next(iter(self.cache)))
            self.cache[key] = val
            self.nfev += 1
        return val


_FLOAT_MAX = float(np.finfo(float).max)


def _nan_to_num(a, nan: float = 0.0, neginf: float = -_FLOAT_MAX):
    """``np.nan_to_num(a, nan=nan, neginf=neginf)`` of a float array, the same values: NaN → ``nan``, +inf → the
    largest float, −inf → ``neginf``. numpy's general function costs ~10 µs on the few values of one design, and a
    ring pair's solve calls it four times at every point where its cutter trimming is undefined (a quarter of them)."""
    out = np.array(a, dtype=float)
    out[np.isnan(out)] = nan
    inf = np.isinf(out)
    if inf.any():
        out[inf] = np.where(out[inf] > 0, _FLOAT_MAX, neginf)
    return out


def window_box(prob: Problem, bounds):
    """The box of the free variables: (lo, hi) arrays."""
    lo, hi = bounds
    if prob.nvar == 1:
        lo1, hi1 = prob.x1_on_line(lo, hi)
        return np.array([lo1]), np.array([hi1])
    return np.array([lo, lo], dtype=float), np.array([hi, hi], dtype=float)


def slsqp(prob: Problem, v0, bounds, ftol=1e-15, maxiter=200, pieces_only=False, box=None):
    """SLSQP on w = (v, t): maximise t s.t. pieces − t >= 0, margins >= 0, v in the window (or in ``box``, a
    (lo, hi) pair of arrays inside it): (w, iterations, the evaluator, whether SLSQP reports success)."""
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

    from scipy.optimize import minimize   # here: scipy.optimize costs ~0.3 s to import; the CLI's help and pair never solve

    lo, hi = window_box(prob, bounds) if box is None else box
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


_MODEL_ROUNDS = 40       # trust-region rounds on the costly checks' models before SLSQP runs on the checks themselves
_MODEL_RADIUS = 0.1      # the first trust region, in x (under a start-grid spacing)
_MODEL_SETTLED = 1e-10   # in x: a round that moves less has reached the point


def maximin(prob: Problem, v0, bounds, ftol: float = 1e-12):
    """(w, ev): w = (x, t) with the largest smallest margin t of ``prob`` near v0 by SLSQP, and an evaluator
    of the smallest-margin problem that holds the margins at w.

    With costly checks (the strength chain, whose central-difference gradients make SLSQP wander for
    hundreds of evaluations) SLSQP walks on their quadratic models (:func:`_maximin_on_models`); where that
    does not settle, SLSQP on the checks themselves."""
    if getattr(prob, "costly_parts", None):
        found = _maximin_on_models(prob, v0, bounds, ftol)
        if found is not None:
            return found
    w, _, ev, _ = slsqp(MinMargin(prob), v0, bounds, ftol=ftol, pieces_only=True)
    return w, ev


def _maximin_on_models(prob: Problem, v0, bounds, ftol: float):
    """:func:`maximin` as a trust-region method: SLSQP on the problem with its costly checks replaced by their
    quadratic models around v (Problem.modelled_at) inside a box of half-width ``radius`` around v; its point
    replaces v where the smallest margin, the costly checks evaluated there, gains at least a tenth of what
    the models promised, and the box shrinks where not. A refused point's models stay on as further pieces
    for the next round (a cut, as bundle methods keep them): the chain has kinks (Z_B's switch at M1 = 1,
    clamped factors), and the smaller of the models on either side of one holds it. One evaluation of the costly
    checks per round (a model's anchor holds their values); None when the rounds do not settle."""
    lo, hi = window_box(prob, bounds)
    v = np.asarray(v0, dtype=float)
    model = MinMargin(prob.modelled_at(v))
    t = model.evaluate_point(v)[0].min()
    radius, grow, cut, costly = _MODEL_RADIUS, True, [], sorted(prob.costly_parts)
    for _ in range(_MODEL_ROUNDS):
        box = (np.maximum(lo, v - radius), np.minimum(hi, v + radius))
        w, _, _, _ = slsqp(_Bundle(model, cut, costly), v, bounds, ftol=ftol, pieces_only=True, box=box)
        step, predicted = float(np.max(np.abs(w[:-1] - v))), w[-1] - t
        if step <= _MODEL_SETTLED or predicted <= ftol:
            # no gain left that SLSQP itself would pursue (near a maximin along an edge t is flat to second
            # order: x is fixed there only to ~√ftol, by any method)
            return np.append(v, t), Evaluator(model)
        trial = MinMargin(prob.modelled_at(w[:-1]))
        t_new = trial.evaluate_point(w[:-1])[0].min()
        if t_new > -BIG and t_new - t >= 0.1 * predicted:
            if grow and t_new - t > 0.75 * predicted and step > 0.9 * radius:
                radius *= 2
            v, model, t, cut = w[:-1], trial, t_new, []
        else:
            # past a kink of the costly checks the models overshoot: the box only shrinks from then on
            radius, grow, cut = step / 4, False, [trial] if t_new > -BIG else []
            if radius <= _MODEL_SETTLED:
                return np.append(v, t), Evaluator(model)
    return None


class _Bundle(MinMargin):
    """The smallest-margin problem of ``model`` (a MinMargin of a modelled problem) with the models of the
    costly parts (indices ``costly``) of ``cuts`` (others, anchored elsewhere) as further pieces."""

    def __init__(self, model: MinMargin, cuts: list, costly: list):
        super().__init__(model.base)
        self.model, self.cuts, self.costly = model, cuts, costly

    def evaluate_point(self, v):
        P, _, GP, _ = self.model.evaluate_point(v)
        if self.cuts:
            more = [c.evaluate_point(v) for c in self.cuts]
            P = np.concatenate([P] + [o[0][self.costly] for o in more])
            GP = np.concatenate([GP] + [o[2][self.costly] for o in more])
        return P, P[:0], GP, GP[:0]


def central_point(prob: Problem, V, M, bounds) -> np.ndarray:
    """(x, t): the point that maximises the smallest margin t near the least infeasible node of
    V (M its margins), by SLSQP (:func:`maximin`); t >= 0 is a feasible point of a region thinner than the grid."""
    worst = M.min(axis=0) if M.size else np.zeros(V.shape[0])
    i = int(np.argmax(worst))
    w, ev = maximin(prob, V[i], bounds)
    if not w[-1] > worst[i] and not (ev(w[:-1])[0] > -BIG).all():
        # SLSQP left for where the design stops existing (margins −BIG): the node it started from
        # is the better answer
        return np.append(V[i], worst[i])
    return w
