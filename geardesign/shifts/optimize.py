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
  than a one-element numpy call; a solve takes ~6 evaluations and ~1.6 ms.

Sensitivities are d(fun)/d(limit) of the active checks: how much the optimum moves per unit
rise of each active limit (for undercut and interference, per unit of extra margin required).
"""
from __future__ import annotations

import functools
import itertools
import math
import time
from dataclasses import dataclass, field

import numpy as np
import pandas as pd
from scipy.optimize import minimize

from ..gears import checks as _checks
from ..errors import GearDesignError
from ..validate import one_number, require_choice, require_count, require_positive, require_range
from ..gears.geometry import center_distance_from_x_sum, min_center_distance, x_sum_from_center_distance
from ..gears.involute import inv
from .problem import DEFAULT_BOUNDS, OBJECTIVES, Problem, validate_bounds

__all__ = ["optimize_shifts", "ShiftResult", "METHODS", "smallest_conflict", "reachable_center_distance",
           "x_sum_for_housing", "GRID_N_MAX"]

METHODS = ("grid", "convex", "exact")
DEFAULT_TOL = {"grid": 1e-2, "convex": 1e-7, "exact": 1e-9}
_START_N = 31          # grid nodes per axis for the start of convex and exact (spacing 0.15)
_BIG = 1e3             # stands in for −inf margins inside the smooth solvers
_ACCURACY = {
    "exact": "KKT point solved by Newton: x to ~1e-12, checks hold to {tol:g}",
    "convex": "SQP stopped when its step fell below tol: x within ~{tol:g} of the optimum",
    "grid": ("best grid node: fun within one node spacing's change of the optimum; x within "
             "{tol:g} of it unless the optimum slides along a boundary nearly level with fun"),
}


@dataclass
class ShiftResult:
    """The optimum of :func:`optimize_shifts`, in the manner of ``scipy.optimize.OptimizeResult``.

    ``fun`` is the objective in its natural sense (x1 + x2 for ``max_x_sum``, ε_α for
    ``max_eps_alpha``, max |ϑ| for ``balanced_sliding``, the specific pressure coefficient for
    ``min_specific_pressure``, the distance in x to the nearest check boundary for ``max_margin``).
    """

    x1: float
    x2: float
    fun: float
    objective: str
    success: bool
    message: str
    method: str
    tol: float
    nit: int
    time_s: float
    margins: dict = field(default_factory=dict)
    active: list = field(default_factory=list)
    sensitivity: dict = field(default_factory=dict)
    conflict: list = field(default_factory=list)
    z1: int = 0
    z2: int = 0
    m: float = 1.0
    x_sum_fixed: float | None = None
    a_w: float = math.nan
    eps_alpha: float = math.nan
    sensitivity_sides: dict = field(default_factory=dict)
    accuracy: str = ""

    @property
    def x(self) -> np.ndarray:
        return np.array([self.x1, self.x2])

    def to_dict(self) -> dict:
        d = {k: getattr(self, k) for k in self.__dataclass_fields__}
        d["margins"] = dict(self.margins)
        return d

    def to_frame(self) -> pd.DataFrame:
        """One row per check: margin, active, sensitivity (d fun / d limit; at a corner where it
        is one-sided, the value as the limit rises, and both sides in their own columns)."""
        side = {k: self.sensitivity_sides.get(k, {}) for k in self.margins}
        return pd.DataFrame({
            "check": list(self.margins),
            "margin": list(self.margins.values()),
            "active": [k in self.active for k in self.margins],
            "sensitivity": [self.sensitivity.get(k, 0.0) for k in self.margins],
            "sensitivity_raised": [side[k].get("raised", self.sensitivity.get(k, 0.0)) for k in self.margins],
            "sensitivity_lowered": [side[k].get("lowered", self.sensitivity.get(k, 0.0)) for k in self.margins],
        })

    def _sensitivity_text(self, name, value) -> str:
        sides = self.sensitivity_sides.get(name)
        if sides:
            return f"{name} {sides['raised']:+.4g} if raised / {sides['lowered']:+.4g} if lowered (corner)"
        return f"{name} {value:+.4g}"

    def __repr__(self) -> str:
        lines = [
            f"     message: {self.message}",
            f"     success: {self.success}",
            f"       pairs: z1/z2 = {self.z1}/{self.z2}" + (f", x1 + x2 fixed at {self.x_sum_fixed:.10g}"
                                                          if self.x_sum_fixed is not None else ""),
            f"      x1, x2: {self.x1:.10g}, {self.x2:.10g}",
            f"         fun: {self.fun:.10g}  ({self.objective})",
            f"   eps_alpha: {self.eps_alpha:.6g}   a_w: {self.a_w:.6g} mm (m = {self.m:g})",
            f"      active: {', '.join(self.active) if self.active else '-'}",
            " sensitivity: " + (", ".join(self._sensitivity_text(k, v) for k, v in self.sensitivity.items()) or "-"),
            "     margins: " + ", ".join(f"{k} {v:+.4g}" for k, v in self.margins.items()),
            f"      method: {self.method}, tol {self.tol:g}, nit {self.nit}, {self.time_s * 1e3:.2f} ms",
            f"    accuracy: {self.accuracy}",
        ]
        if self.conflict:
            lines.insert(2, f"    conflict: {', '.join(self.conflict)}")
        return "\n".join(lines)


# --- inputs -------------------------------------------------------------------------------

GRID_N_MAX = 2001       # nodes per axis of the grid method: 4 M designs, ~4 s and ~3 GB at most
_CONSTANT_ON_LINE = ("max_x_sum", "min_specific_pressure")   # depend on x1 + x2 alone


def _default_objective(objective, a_w) -> str:
    """``max_x_sum`` on the plane; ``balanced_sliding`` on a fixed-a_w line, where objectives of
    the x-sum alone are constant and refused."""
    if objective is None:
        return "max_x_sum" if a_w is None else "balanced_sliding"
    objective = require_choice("objective", objective, OBJECTIVES)
    if a_w is not None and objective in _CONSTANT_ON_LINE:
        others = [o for o in OBJECTIVES if o not in _CONSTANT_ON_LINE]
        raise GearDesignError(
            f"objective {objective!r} depends on x1 + x2 alone, which a_w fixes: nothing to optimise; "
            f"with a fixed center distance choose one of {others}")
    return objective


def reachable_center_distance(prob: Problem, bounds=DEFAULT_BOUNDS) -> tuple[float, float]:
    """(a_w min, a_w max) in mm that x1 + x2 within ``bounds`` can give this pair: the x-sum
    runs over [2 lo, 2 hi], and above the x-sum where inv α_w = 0 (a_w = a cos α)."""
    lo, hi = bounds
    xs_zero = -(prob.z1 + prob.z2) * inv(prob.rack.alpha) / (2.0 * math.tan(prob.rack.alpha))
    a_cos = float(min_center_distance(prob.m, prob.z1, prob.z2, prob.rack))
    a_lo = a_cos if 2 * lo <= xs_zero else center_distance_from_x_sum(prob.m, prob.z1, prob.z2, 2 * lo, prob.rack)
    a_hi = center_distance_from_x_sum(prob.m, prob.z1, prob.z2, 2 * hi, prob.rack) if 2 * hi > xs_zero else a_cos
    return float(a_lo), float(a_hi)


def x_sum_for_housing(prob: Problem, a_w, bounds=DEFAULT_BOUNDS) -> float:
    """The x-sum of a housing centre distance ``a_w`` (mm), or one line naming the range of a_w
    this pair, module, rack and window can reach."""
    a_w = one_number("a_w (center distance)", require_positive("a_w (center distance)", a_w, unit="mm"))
    a_lo, a_hi = reachable_center_distance(prob, bounds)
    r = prob.rack
    where = (f"for m = {prob.m:g} mm, z1/z2 = {prob.z1}/{prob.z2}, rack {r.alpha_deg:g} deg, "
             f"x1, x2 in [{bounds[0]:g}, {bounds[1]:g}]")
    if not a_lo < a_w <= a_hi:
        raise GearDesignError(f"a_w (center distance) = {a_w:.10g} mm is out of reach: it must be in "
                              f"({a_lo:.8g}, {a_hi:.8g}] mm {where}")
    x_sum = float(x_sum_from_center_distance(prob.m, prob.z1, prob.z2, a_w, prob.rack))
    # the window holds x_sum/2 on both gears, so the fixed-sum line meets it
    return min(max(x_sum, 2 * bounds[0]), 2 * bounds[1])


# --- helpers ------------------------------------------------------------------------------

def _limit_factor(check) -> float:
    """d(margin)/d(limit) → converts a multiplier into d(fun)/d(limit)."""
    if isinstance(check, _checks.Jamming):
        return -1.0
    if isinstance(check, _checks.CustomCheck):
        return (1.0 if check.sense == ">=" else -1.0) / check.scale
    return 1.0


def grid_points(prob: Problem, n: int, bounds) -> np.ndarray:
    lo, hi = bounds
    if prob.nvar == 1:
        lo1 = max(lo, prob.x_sum - hi)
        hi1 = min(hi, prob.x_sum - lo)
        return np.linspace(lo1, hi1, n)[:, None]
    return _square_grid(n, float(lo), float(hi))


@functools.lru_cache(maxsize=16)
def _square_grid(n: int, lo: float, hi: float) -> np.ndarray:
    g = np.linspace(lo, hi, n)
    X1, X2 = np.meshgrid(g, g, indexing="ij")
    V = np.column_stack([X1.ravel(), X2.ravel()])
    V.flags.writeable = False
    return V


def _best_feasible(prob: Problem, V: np.ndarray):
    P, M = prob.evaluate(V, grads=False)
    feasible = (M >= 0).all(axis=0) if M.size else np.ones(V.shape[0], bool)
    score = np.where(feasible, P.min(axis=0), -np.inf)
    if not np.isfinite(score).any():
        return None, P, M
    return int(np.argmax(score)), P, M


def central_point(prob: Problem, V, M, bounds) -> np.ndarray:
    """(x, t): the point that maximises the smallest margin t near the least infeasible node of
    V (M its margins), by SLSQP; t >= 0 is a feasible point of a region thinner than the grid."""
    worst = M.min(axis=0) if M.size else np.zeros(V.shape[0])
    w, _, _ = _slsqp(_MinMargin(prob), V[int(np.argmax(worst))], bounds, ftol=1e-12, pieces_only=True)
    return w


class _Evaluator:
    """Caches Problem.evaluate_point at one point for the solvers (w = (v, t)).

    With ``window`` (lo, hi) the window's edges join the margins as linear checks
    v − lo >= 0 and hi − v >= 0 (after the problem's own), so that an optimum on the window
    is a KKT point like any other.
    """

    def __init__(self, prob: Problem, window=None):
        self.prob = prob
        self.key = None
        self.nfev = 0
        self.window = window
        if window is not None:
            eye = np.eye(prob.nvar)
            self._window_rows = np.concatenate((eye, -eye))

    def __call__(self, v):
        key = tuple(float(c) for c in v)
        if key != self.key:
            v = np.array(key)
            P, M, GP, GM = self.prob.evaluate_point(key)
            if self.window is not None:
                M = np.concatenate((M, v - self.window[0], self.window[1] - v))
                GM = np.concatenate((GM, self._window_rows))
            if not (np.isfinite(M).all() and np.isfinite(P).all()):
                P, M = np.nan_to_num(P, nan=-_BIG, neginf=-_BIG), np.nan_to_num(M, nan=-_BIG, neginf=-_BIG)
                GP, GM = np.nan_to_num(GP), np.nan_to_num(GM)
            self.val = (P, M, GP, GM)
            self.key = key
            self.nfev += 1
        return self.val


def _window(prob: Problem, bounds):
    """The box of the free variables: (lo, hi) arrays."""
    lo, hi = bounds
    if prob.nvar == 1:
        return np.array([max(lo, prob.x_sum - hi)]), np.array([min(hi, prob.x_sum - lo)])
    return np.array([lo, lo], dtype=float), np.array([hi, hi], dtype=float)


def _slsqp(prob: Problem, v0, bounds, ftol=1e-15, maxiter=200, pieces_only=False):
    """SLSQP on w = (v, t): maximise t s.t. pieces − t >= 0, margins >= 0."""
    ev = _Evaluator(prob)
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

    lo, hi = _window(prob, bounds)
    res = minimize(lambda w: -w[nv], w0, jac=lambda w: np.append(np.zeros(nv), -1.0),
                   constraints=[{"type": "ineq", "fun": cons, "jac": cons_jac}],
                   bounds=list(zip(lo, hi)) + [(None, None)], method="SLSQP",
                   options={"ftol": ftol, "maxiter": maxiter})
    return res.x, res.nit, ev


# --- the exact method: KKT systems of candidate active sets, solved by Newton ---------------

# These systems have at most three unknowns; they are solved in Python floats, where a
# numpy call (~10 µs for np.linalg.solve) would cost more than the arithmetic.

def _rows(GP, GM, act_p, act_m) -> list:
    """Gradients in w = (v, t) of the active constraints piece_k − t and margin_i, as rows."""
    return [GP[k].tolist() + [-1.0] for k in act_p] + [GM[i].tolist() + [0.0] for i in act_m]


def _solve_small(A: list, b: list) -> list:
    """x with A x = b for a square system of a few rows: Gaussian elimination with partial
    pivoting. Raises LinAlgError when A is singular to working precision."""
    n = len(b)
    A = [row[:] + [bi] for row, bi in zip(A, b)]
    scale = max((abs(a) for row in A for a in row[:n]), default=0.0)
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(A[r][c]))
        if abs(A[p][c]) <= 1e-14 * scale:
            raise np.linalg.LinAlgError("singular active-set system")
        A[c], A[p] = A[p], A[c]
        for r in range(c + 1, n):
            f = A[r][c] / A[c][c]
            if f:
                A[r] = [a - f * ac for a, ac in zip(A[r], A[c])]
    x = [0.0] * n
    for c in range(n - 1, -1, -1):
        x[c] = (A[c][n] - sum(A[c][k] * x[k] for k in range(c + 1, n))) / A[c][c]
    return x


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


def _kkt_newton(ev: _Evaluator, nv: int, act_p, act_m, w0, max_move: float, maxit: int = 30,
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
    w0 = [float(c) for c in w0]
    w = w0[:]

    def system(w):
        P, M, GP, GM = ev(w[:nv])
        rows = _rows(GP, GM, act_p, act_m)
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
            srow[j] = (_stationarity(_rows(GPj, GMj, act_p, act_m), nv) - F[-1]) / step
        if not all(map(math.isfinite, srow)):
            return None
    for it in range(1, maxit + 1):
        try:
            dw = _solve_small(rows + [srow] if edge else rows, [-f for f in F])
        except np.linalg.LinAlgError:
            return None
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
        if max(map(abs, dw[:nv])) <= step_tol * max(1.0, max(map(abs, w[:nv]))) or max(map(abs, F)) == 0.0:
            break
    ok = max(map(abs, F[:-1] if edge else F), default=0.0) <= 1e-10 and (not edge or abs(F[-1]) <= stat_tol)
    return (np.array(w), it) if ok else None


def _multipliers(prob: Problem, w, act_p, act_m, ev):
    """λ of the active constraints from e_t + Σ λ_j ∇c_j = 0 (least squares)."""
    nv = prob.nvar
    _, _, GP, GM = ev(w[:nv])
    rows = _rows(GP, GM, act_p, act_m)
    if not rows:
        return np.zeros(0), np.zeros(0)
    # least squares by the normal equations R Rᵀ λ = −R e_t: at most nv + 1 well-scaled rows
    A = [[sum(a * b for a, b in zip(r1, r2)) for r2 in rows] for r1 in rows]
    try:
        lam = np.array(_solve_small(A, [-r[-1] for r in rows]))
    except np.linalg.LinAlgError:
        lam, *_ = np.linalg.lstsq(np.array(rows).T, -np.append(np.zeros(nv), 1.0), rcond=None)
    return lam[:len(act_p)], lam[len(act_p):]


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


def _first_kkt_point(prob: Problem, ev: _Evaluator, w0, near_p, near_m, max_move: float, limit: int = 24):
    """The first candidate active set whose Newton solution is a KKT point: it holds every
    check, no piece is below t, the multipliers are >= 0, and t is no worse than at w0.

    Returns (w, act_p, act_m, newton iterations) or None.
    """
    nv = prob.nvar
    t0 = w0[nv]
    nit = 0
    cands = _active_sets(near_p, near_m, nv)
    if len(cands) > 1:   # try first the sets whose multipliers, linearised at w0, are >= 0
        cands.sort(key=lambda c: min(np.concatenate(_multipliers(prob, w0, *c, ev)), default=0.0) < 0)
    for act_p, act_m in cands[:limit]:
        out = _kkt_newton(ev, nv, act_p, act_m, w0, max_move, noisy=prob.fd_gradients)
        if out is None:
            continue
        w, it = out
        nit += it
        P, M, _, _ = ev(w[:nv])
        if (M.size and M.min() < -1e-12) or P.min() < w[nv] - 1e-10 or w[nv] < t0 - 1e-9:
            continue
        lp, lm = _multipliers(prob, w, act_p, act_m, ev)
        if (lp.size and lp.min() < -1e-7) or (lm.size and lm.min() < -1e-7):
            continue
        return w, act_p, act_m, nit
    return None


def _near(ev: _Evaluator, nv: int, w, reach: float, most: int = 4):
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


def _polish(prob: Problem, w, ev: _Evaluator, tol: float, act_tol=1e-5):
    """Newton on the active set of a converged SLSQP point: (w, act_p, act_m) or None."""
    nv = prob.nvar
    P, M, _, _ = ev(w[:nv])
    near_p = [k for k in range(P.size) if P[k] - w[nv] < act_tol]
    near_m = [i for i in range(M.size) if M[i] < act_tol]
    found = _first_kkt_point(prob, ev, w, near_p, near_m, max_move=1e-3)
    return None if found is None else found[:3]


def _sensitivities_at(prob: Problem, ev: _Evaluator, w, act_tol: float):
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
    lp, lm = _multipliers(prob, w, act_p, act_m, ev)
    sens, sides = {}, {}
    checks_of = {}
    for pos, j in enumerate(act_m):
        if j < len(prob.part_check):
            checks_of.setdefault(prob.part_check[j], []).append(pos)
    degenerate = len(act_p) + len(act_m) > nv + 1
    rows = np.array(_rows(GP, GM, act_p, act_m)) if degenerate else None
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


# --- the convex (SCP) method ----------------------------------------------------------------

_SCP_CACHE: dict = {}


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


def _curvature(ev: _Evaluator, v, lam_p, lam_m, h=1e-5):
    """L with LᵀL = PSD part of −∇²(Σ λ_p p + Σ λ_m m), second derivatives by central
    differences of the analytic gradients."""
    nv = v.size
    H = np.zeros((nv, nv))
    for j in range(nv):
        e = np.zeros(nv)
        e[j] = h
        _, _, GPu, GMu = ev(v + e)
        _, _, GPd, GMd = ev(v - e)
        H[:, j] = lam_p @ (GPu - GPd) / (2 * h) + (lam_m @ (GMu - GMd) / (2 * h) if lam_m.size else 0.0)
    B = -(H + H.T) / 2
    vals, vecs = np.linalg.eigh(B)
    vals = np.clip(vals, 1e-8, None)
    return (vecs * np.sqrt(vals)).T


def _solve_convex(prob: Problem, v0, bounds, tol, maxit=100):
    import cvxpy as cp

    nv = prob.nvar
    ev = _Evaluator(prob)
    P, M, GP, GM = ev(v0)
    problem, d, t, Pp, GPp, Mp, GMp, lo, hi, Lp, cons = _scp_problem(P.size, M.size, nv)
    blo, bhi = bounds
    if nv == 1:
        box_lo, box_hi = np.array([max(blo, prob.x_sum - bhi)]), np.array([min(bhi, prob.x_sum - blo)])
    else:
        box_lo, box_hi = np.array([blo, blo]), np.array([bhi, bhi])
    v = np.asarray(v0, dtype=float)
    radius = 0.25
    penalty = 10.0

    def merit(P, M):
        return P.min() - penalty * np.clip(-M, 0, None).sum()

    lam_p = np.full(P.size, 1.0 / P.size)
    lam_m = np.zeros(M.size)
    L = np.eye(nv) * 1e-4
    nit = 0
    for nit in range(1, maxit + 1):
        Pp.value, GPp.value, Lp.value = P, GP, L
        if M.size:
            Mp.value, GMp.value = M, GM
        lo.value = np.maximum(-radius, box_lo - v)
        hi.value = np.minimum(radius, box_hi - v)
        problem.solve(solver=cp.CLARABEL, tol_gap_abs=1e-12, tol_gap_rel=1e-12, tol_feas=1e-12)
        if d.value is None:
            radius /= 4
            if radius < tol:
                break
            continue
        step = np.asarray(d.value, dtype=float)
        predicted = float(problem.value) - merit(P, M)
        P1, M1, GP1, GM1 = ev(v + step)
        actual = merit(P1, M1) - merit(P, M)
        if actual < 0.1 * predicted and M.size and (M1 < 0).any():
            # second-order correction (Maratos effect): pull the violated checks back to zero
            bad = M1 < 0
            corr = -np.linalg.pinv(GM[bad]) @ M1[bad]
            P2, M2, GP2, GM2 = ev(v + step + corr)
            if merit(P2, M2) - merit(P, M) >= 0.1 * predicted:
                step = step + corr
                P1, M1, GP1, GM1 = P2, M2, GP2, GM2
                actual = merit(P1, M1) - merit(P, M)
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
    return v, nit, lam_m, ev


# --- conflicts ----------------------------------------------------------------------------

def smallest_conflict(prob: Problem, bounds=DEFAULT_BOUNDS, n: int = 161) -> list[str]:
    """A smallest set of checks that no (x1, x2) in the window satisfies together.

    Subsets are tried by size: the largest smallest-margin over a grid shows which subsets look
    empty, and a local maximisation of the smallest margin (SLSQP) confirms it.
    """
    V = grid_points(prob, n, bounds)
    _, M = prob.evaluate(V, grads=False)
    K = M.shape[0]
    for size in range(1, K + 1):
        for sub in itertools.combinations(range(K), size):
            worst = M[list(sub)].min(axis=0)
            i = int(np.argmax(worst))
            if worst[i] >= 0:
                continue
            sub_prob = Problem(prob.z1, prob.z2, prob.rack, [prob.checks[j] for j in sub], "max_x_sum",
                               prob.m, prob.tip_shortening, prob.x_sum)
            # maximise the smallest margin of the subset
            w, _, ev = _slsqp(_MinMargin(sub_prob), V[i], bounds, ftol=1e-12, pieces_only=True)
            if w[-1] < -1e-9:
                return [prob.names[j] for j in sub]
    return []


class _MinMargin(Problem):
    """Pieces = the margins themselves (to maximise the smallest), no hard constraints."""

    def __init__(self, base: Problem):
        self.__dict__.update(base.__dict__)

    def evaluate(self, V, grads=True):
        out = Problem.evaluate(self, V, grads)
        if not grads:
            return out[1], out[1][:0]
        P, M, GP, GM = out
        return M, M[:0], GM, GM[:0]

    def evaluate_point(self, v):
        P, M, GP, GM = Problem.evaluate_point(self, v)
        return M, M[:0], GM, GM[:0]


# --- the public function --------------------------------------------------------------------

def optimize_shifts(z1, z2, objective: str | None = None, checks=None, method: str = "exact",
                    tol: float | None = None, a_w: float | None = None, m: float | None = None, rack=None,
                    tip_shortening: bool = True, bounds=DEFAULT_BOUNDS, grid_n: int | None = None,
                    start=None) -> ShiftResult:
    """The best profile shifts x1, x2 for tooth counts z1, z2 under the chosen checks.

    Parameters
    ----------
    z1, z2 : tooth counts.
    objective : one of :data:`geardesign.shifts.problem.OBJECTIVES`; default ``max_x_sum``, or
        ``balanced_sliding`` when ``a_w`` fixes the x-sum (objectives that depend on the x-sum
        alone, ``max_x_sum`` and ``min_specific_pressure``, are refused then: they are constant).
    checks : None (no undercut, no interference, s_a >= 0.25 m, ε_α >= 1.2), a dict of
        :func:`geardesign.gears.checks.make_checks` options (``{"sa_min": 0.4, "undercut": False}``),
        or a list of :class:`geardesign.gears.checks.Check`.
    method : "grid" (fastest, x within half a node spacing), "convex" (SQP in cvxpy/Clarabel,
        ~1e-7 in x, dual sensitivities) or "exact" (active-set Newton, ~1e-12 in x; default).
    tol : tolerance in x (defaults: grid 0.01, convex 1e-7, exact 1e-9); every returned point
        satisfies the checks to within it.
    a_w : operating centre distance of the housing, mm; needs ``m``. It fixes x1 + x2 and the
        objective picks the split; an a_w the window cannot reach is refused with the reachable range.
    m : module, mm (scales a_w only; the shifts do not depend on it). Default 1 without ``a_w``.
    bounds : the window (lo, hi) searched for each of x1, x2.
    grid_n : nodes per axis of the grid method (default from ``tol``; at most GRID_N_MAX).
    start : a feasible (x1, x2) to start convex/exact from instead of their own coarse grid
        (the atlas passes the best node of its batched grid).

    >>> r = optimize_shifts(17, 26)          # seed 000's tooth counts: ε_α >= 1.2 caps x1 + x2
    >>> r.success, r.active, round(r.fun, 6)
    (True, ['contact_ratio'], 1.337093)
    """
    t0 = time.perf_counter()
    method = require_choice("method", method, METHODS)
    if a_w is not None and m is None:
        raise GearDesignError(f"a_w (center distance) = {a_w!r} mm needs the module m: give m (mm) too")
    objective = _default_objective(objective, a_w)
    tol = DEFAULT_TOL[method] if tol is None else one_number("tol", require_range("tol", tol, 1e-14, 1.0))
    lo, hi = validate_bounds(bounds)
    if grid_n is not None:
        grid_n = require_count("grid_n", grid_n, 2, GRID_N_MAX)
    prob = Problem(z1, z2, rack, checks, objective, 1.0 if m is None else m, tip_shortening)
    if prob.objective.kind == "margin" and not prob.checks:
        raise GearDesignError("objective 'max_margin' (the point farthest from every check's boundary) needs at "
                              "least one check, got checks=[]")
    x_sum = None
    if a_w is not None:
        x_sum = prob.x_sum = x_sum_for_housing(prob, a_w, (lo, hi))
    bounds = (lo, hi)

    def finish(v, nit, success, message, sensitivity=None, conflict=None, sides=None):
        x1, x2 = (float(c[0]) for c in prob.xy(np.asarray(v)[None, :]))
        geo, (P, M, _, _) = prob.evaluate_design(x1, x2)
        # a margin the solver cannot tell from zero is zero (no -2.8e-16 in reports)
        zero = tol if method != "grid" else 1e-12
        mg = {name: (0.0 if abs(v_) <= zero else float(v_)) for name, v_ in zip(prob.names, M)}
        fun = float(prob.objective.sense * P.min()) if prob.objective.kind != "margin" else float(P.min())
        values = [fun, float(geo["a_w"]), float(geo["eps_alpha"]), *mg.values()]
        if not all(map(math.isfinite, values)):
            raise GearDesignError(
                f"no finite result for z1/z2 = {prob.z1}/{prob.z2} ({prob.objective.name}, {method}): the pair's "
                f"geometry or a check is undefined at the point the solver reached ({x1:.6g}, {x2:.6g}); "
                f"check the rack and the window")
        if prob.x_sum is not None:
            message += (f"; x1 + x2 = {prob.x_sum:.10g} fixed by a_w = {a_w:.10g} mm, "
                        f"objective {prob.objective.name}")
        active = [k for k, v_ in mg.items() if abs(v_) <= max(tol, 1e-9) * 10]
        return ShiftResult(
            x1=x1, x2=x2, fun=fun, objective=prob.objective.name, success=success, message=message,
            method=method, tol=tol, nit=nit, time_s=time.perf_counter() - t0, margins=mg, active=active,
            sensitivity=sensitivity or {}, conflict=conflict or [], z1=prob.z1, z2=prob.z2, m=prob.m,
            x_sum_fixed=x_sum, a_w=float(geo["a_w"]), eps_alpha=float(geo["eps_alpha"]),
            sensitivity_sides=sides or {}, accuracy=_ACCURACY[method].format(tol=tol))

    if method == "grid":
        span = hi - lo
        n = grid_n or int(min(max(math.ceil(span / (2 * tol)) + 1, 11), 1001 if prob.nvar == 2 else 200001))
        if prob.nvar == 2:
            n = min(n, GRID_N_MAX)
        V = grid_points(prob, n, bounds)
        i, P, M = _best_feasible(prob, V)
        h = (V[-1, 0] - V[0, 0]) / (n - 1) if n > 1 else 0.0
        tol = max(h / 2, tol) if h > 0 else tol
        if i is None:
            w = central_point(prob, V, M, bounds)
            if w[-1] >= 0:
                return finish(w[:-1], 1, True, f"no feasible node among {V.shape[0]} (spacing {h:.3g}): the "
                              "region is thinner than the grid; returned its most central point nearby")
            conflict = smallest_conflict(prob, bounds)
            return finish(w[:-1], 1, False, _conflict_message(conflict), conflict=conflict)
        return finish(V[i], 1, True, f"best of {V.shape[0]} grid nodes (spacing {h:.3g})")

    # feasible starts for convex and exact
    n_start = _START_N if prob.nvar == 2 else 401
    if start is not None and prob.nvar == 2:
        V = np.asarray(start, dtype=float).reshape(1, 2)
        starts, M = _starts(prob, V, 1)
        if not starts:
            V = grid_points(prob, _START_N, bounds)
            starts, M = _starts(prob, V, _START_N)
    else:
        V = grid_points(prob, n_start, bounds)
        starts, M = _starts(prob, V, n_start)
    if not starts or not _feasible_at(prob, starts[0]):
        # no feasible node: the region, if any, is thinner than the grid; the most central
        # point near the least infeasible node starts the solve
        w = central_point(prob, V, M, bounds)
        if w[-1] < 0:
            conflict = smallest_conflict(prob, bounds)
            return finish(w[:-1], 1, False, _conflict_message(conflict), conflict=conflict)
        starts = [w[:-1]] + starts[:_MAX_STARTS - 1]

    if method == "convex":
        v, nit, lam, ev = _solve_convex(prob, starts[0], bounds, tol)
        Pv, Mv, _, _ = ev(v)
        ok = not (Mv.size and Mv.min() < -tol)
        msg = "converged: trust region below tol" if ok else "stopped with a check violated beyond tol"
        w = np.append(v, Pv.min())
        sens, sides = _sensitivities_at(prob, _Evaluator(prob, window=_window(prob, bounds)), w, act_tol=10 * tol)
        return finish(v, nit, ok, msg, sens, sides=sides)

    # exact: from each start (the best node of each separate feasible piece and the grid's local
    # maxima, best first), Newton on the KKT systems of the checks that pass near it (the
    # window's edges count as checks); SLSQP, then that polish, only when none gives a KKT point.
    # The best of these local optima is returned: a region may have several pieces and corners.
    ev = _Evaluator(prob, window=_window(prob, bounds))
    h = (hi - lo) / (n_start - 1)
    best = None
    nit = 0
    nv = prob.nvar
    for v0 in starts:
        w, it, msg = _exact_from(prob, ev, v0, bounds, tol, h)
        nit += it
        Mw = ev(w[:nv])[1]
        score = w[-1] if not (Mw.size and Mw.min() < -tol) else -math.inf
        if best is None or score > best[0] + 1e-12:
            best = (score, w, msg)
    score, w, msg = best
    if score == -math.inf and not _exists(prob, w[:nv]):
        return finish(starts[0], nit, False, _NO_OPTIMUM.format(objective=prob.objective.name))
    Mv = ev(w[:nv])[1][:len(prob.part_check)]
    ok = not (Mv.size and Mv.min() < -tol)
    if len(starts) > 1:
        msg += f" (best of {len(starts)} starts)"
    sens, sides = _sensitivities_at(prob, ev, w, act_tol=1e-9)
    return finish(w[:nv], nit, ok, msg if ok else "a check is violated beyond tol", sens, sides=sides)


_MAX_STARTS = 4
_NO_OPTIMUM = ("no optimum: {objective} keeps improving toward the edge where the pair stops existing "
               "(inv alpha_w -> 0 or a tip circle at its base circle); the checks asked for do not bound it "
               "(keep the interference checks, or narrow the window); returned the best start node")


def _feasible_at(prob: Problem, v) -> bool:
    """True when every check holds at v."""
    M = prob.evaluate_point(v)[1]
    return not (M.size and M.min() < 0)


def _exists(prob: Problem, v) -> bool:
    """True when the pair's geometry exists (every margin and piece finite) at v."""
    P, M, _, _ = prob.evaluate_point(v)
    return bool(np.isfinite(P).all() and np.isfinite(M).all())


def _starts(prob: Problem, V: np.ndarray, n: int):
    """Start points for the local solvers on the grid V (n nodes per axis), best first, at most
    _MAX_STARTS: the best node of every separate feasible piece of the grid, and the local
    maxima of the objective over the nodes that miss feasibility by less than one node
    spacing (first-order distance to every violated boundary), away from the feasible nodes,
    where they beat every feasible node: a piece thinner than the grid holds no node, but its
    neighbours come that close. Returns (starts, margins at V)."""
    from scipy import ndimage

    P, M = prob.evaluate(V, grads=False)
    feasible = (M >= 0).all(axis=0) if M.size else np.ones(V.shape[0], bool)
    fun = P.min(axis=0)
    fun = np.where(np.isnan(fun), -np.inf, fun)
    score = np.where(feasible, fun, -np.inf)
    if n < 2 or V.shape[0] < n ** prob.nvar:              # a given start, no grid
        return ([V[int(np.argmax(score))]] if np.isfinite(score).any() else []), M
    shape = (n, n) if prob.nvar == 2 else (n,)
    box = np.ones((3,) * prob.nvar, bool)
    labels, count = ndimage.label(feasible.reshape(shape), structure=box)
    if count <= 1:
        idx = [int(np.argmax(score))] if count else []
    else:
        best_of = ndimage.maximum_position(score.reshape(shape), labels, range(1, count + 1))
        idx = [int(np.ravel_multi_index(p, shape)) for p in best_of]
    best = score.max()
    # beyond two nodes of every feasible node, better than all of them
    far = ~ndimage.binary_dilation(feasible.reshape(shape), structure=box, iterations=2).ravel()
    cand = far & (fun > best)
    if M.size and cand.any():
        h = (V[-1, 0] - V[0, 0]) / (n - 1)
        Mg = np.where(np.isfinite(M), M, np.nan).reshape((-1,) + shape)
        slope = np.zeros_like(Mg)
        for ax in range(1, prob.nvar + 1):    # largest one-node change along either axis, per unit x
            d = np.abs(np.diff(Mg, axis=ax)) / h
            lo = [(0, 0)] * Mg.ndim
            hi = [(0, 0)] * Mg.ndim
            lo[ax], hi[ax] = (1, 0), (0, 1)
            slope = np.fmax(slope, np.fmax(np.pad(d, lo, constant_values=np.nan), np.pad(d, hi, constant_values=np.nan)))
        with np.errstate(invalid="ignore"):
            near = ((M >= 0) | (-M <= h * slope.reshape(M.shape))).all(axis=0)
        near_score = np.where(cand & near, fun, -np.inf).reshape(shape)
        if np.isfinite(near_score).any():
            peak = np.isfinite(near_score) & (near_score >= ndimage.maximum_filter(near_score, footprint=box,
                                                                                    mode="constant", cval=-np.inf))
            idx += [int(i) for i in np.flatnonzero(peak.ravel())]
    chosen = []
    for i in sorted(idx, key=lambda k: (not feasible[k], -fun[k])):
        at = np.array(np.unravel_index(i, shape))
        if all(np.abs(at - np.array(np.unravel_index(c, shape))).max() > 2 for c in chosen):
            chosen.append(i)
        if len(chosen) == _MAX_STARTS:
            break
    return [V[i] for i in chosen], M


def _exact_from(prob: Problem, ev: _Evaluator, v0, bounds, tol, h):
    """One local exact solve from the feasible point v0: (w, iterations, message)."""
    nv = prob.nvar
    w0 = np.append(v0, ev(v0)[0].min())
    found = _first_kkt_point(prob, ev, w0, *_near(ev, nv, w0, reach=2.2 * h), max_move=3 * h)
    if found is not None:
        return found[0], found[3], "converged: KKT system of the active set solved by Newton from a grid node"
    w, nit, ev_s = _slsqp(prob, v0, bounds)
    polished = _polish(prob, w, ev_s, tol)
    if polished is not None:
        return polished[0], nit, "converged: SLSQP, then Newton on the KKT system of its active set"
    return w, nit, "converged (SLSQP; active-set polish not applicable)"


def _conflict_message(conflict) -> str:
    if conflict:
        return f"no feasible point: checks {', '.join(conflict)} conflict"
    return "no feasible point in the window: every check passes somewhere, but not all together"
