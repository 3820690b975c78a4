"""The ``max_margin`` optimum (the Chebyshev centre of the normalised margins) of many tooth pairs at once.

A drive ranked by its smallest margin needs this optimum for nearly every tooth pair it enumerates
(hundreds), where one ``optimize_shifts(objective="max_margin")`` costs milliseconds: its pieces are the
checks' margins over their gradients' lengths, whose own gradients are central differences, so each
Newton step evaluates the pair five times. Here every pair advances together, each step one vectorised
evaluation of all pairs at five stencil points:

1. a coarse grid of the window (:data:`START_N` nodes per axis; the exact method's 31 where no node of it
   is feasible) for each pair; its best feasible node starts the pair. A pair whose feasible nodes fall
   into several pieces is left to the exact method, which starts from each;
2. sequential linear programming in a trust region: at the iterate the pieces are linearised and the
   linear programme "maximise t, piece_k + ∇piece_k · d >= t, |d_i| <= r" is solved by its vertices
   (:func:`_lp_step`); a step whose real gain falls short of a tenth of the promised one is refused and
   the region shrinks, one that keeps its promise on the region's edge widens it; a programme that sees
   no gain at a vertex whose multipliers are not all >= 0 (the gain lies past the :data:`LOW_PIECES`
   pieces it enumerates) is solved again in a region an eighth the size. Where the optimum is a vertex
   (three pieces equal, the usual case) the steps become Newton's on those three equations and converge
   quadratically;
3. where the walk ends on an edge instead (two pieces equal, their gradients opposite: tip thickness
   against interference, common at ratios 2–10), Newton on that edge's KKT system (:func:`_edges`);
4. a certificate at the point reached: the KKT conditions the exact method's own Newton stops on
   (:mod:`geardesign.shifts.kkt`): the active pieces equal, none lower, their multipliers >= 0, every
   check holding, inside the window, no worse than the start.

A pair without a certificate (no design, several pieces, fewer than three smooth check parts) is left to the
caller: ``optimize_shifts`` then runs the exact method's active-set search. ``optimize_shifts`` runs this
solver on its one pair first, and each pair's arithmetic here is elementwise, so a batch gives every pair the
bits of its own call. Against the active-set search: vertices to ~1e-13 in x, edges to its stationarity
tolerance (~1e-8 in x, ~1e-14 in the objective); ``tests/shifts/test_centres.py``.
"""
from __future__ import annotations

import functools
import itertools

import numpy as np

from ..errors import GearDesignError
from ..gears.checks import FEASIBILITY_TOL
from ..gears.geometry import mesh_geometry, mesh_geometry_float
from ..gears.mesh import Z_MAX, Z_MIN, Mesh
from ..validate import require_int
from .problem import _FD_STEP, DEFAULT_BOUNDS, Problem, validate_bounds
from .result import Outcome

__all__ = ["margin_centres", "serves", "solve", "solve_pairs", "START_N", "FINE_START_N", "PAIRS_MAX", "CHUNK", "LOW_PIECES", "MAX_STEPS",
           "EDGE_STEPS", "EDGE_REACH"]

START_N = 7          # start-grid nodes per axis: a spacing of 0.75 on the default window
FINE_START_N = 31    # the grid of a pair with no feasible node on the coarse one (the exact method's START_N)
PAIRS_MAX = 100_000  # tooth pairs in one call (a drive hands it MARGIN_AHEAD = 256): ~0.07 ms each
CHUNK = 1024         # pairs walked together: the linear programmes' arrays stay ~10 MB
START_POINTS = 65_536    # grid nodes evaluated at once while the start grids are searched
LOW_PIECES = 5       # the lowest pieces whose triples are the linear programme's candidate vertices
MAX_STEPS = 40       # linear programmes per pair before its walk ends (an edge: then Newton on the edge)
EDGE_STEPS = 12      # Newton steps on an edge
EDGE_REACH = 0.1     # the longest Newton step on an edge (in x) before the pair is left uncertified
_STEP_TOL = 1e-12    # a step this small (in x) ends the walk: the vertex equations hold to rounding
_EDGE_STAT_TOL = 1e-8    # the stationarity of an edge holds to the noise of its central-difference gradients
                         # (~1e-9 here): the exact method's tolerance on it (kkt._kkt_newton, noisy)
_ZERO_MARGIN = 1e-9  # the exact method's tolerance: a margin it cannot tell from zero is reported as zero


def margin_centres(z1, z2, m: float = 1.0, checks=None, beta_deg: float = 0.0, face_width_mm=None,
                   bounds=DEFAULT_BOUNDS) -> dict:
    """The ``max_margin`` shifts of the external tooth pairs (z1[i], z2[i]) under one set of checks.

    Returns a dict of arrays over the pairs: ``ok`` (certified; the other entries are NaN where not),
    ``x1``, ``x2``, ``fun`` (the smallest normalised margin: the distance in x to the nearest boundary, to
    first order), ``a_w``, ``da1``, ``da2`` (mm) and ``margins`` ({check name: array}, margins within 1e-9
    of zero reported as 0, as optimize_shifts reports them).

    >>> r = margin_centres([17, 20], [26, 40])      # optimize_shifts(17, 26, "max_margin") gives the same
    >>> r["ok"].tolist(), round(float(r["x1"][0]), 4), round(float(r["x2"][0]), 4), round(float(r["fun"][0]), 4)
    ([True, True], 0.4918, -0.0329, 0.4862)
    """
    z1, z2 = (require_int(name, z, Z_MIN, Z_MAX).astype(float).ravel() for name, z in (("z1", z1), ("z2", z2)))
    if z1.size != z2.size or z1.size == 0:
        raise GearDesignError(f"z1 and z2 must hold the same number (>= 1) of tooth counts, got {z1.size} and {z2.size}")
    if z1.size > PAIRS_MAX:
        raise GearDesignError(f"margin_centres takes at most {PAIRS_MAX} tooth pairs at once, got {z1.size}")
    lo, hi = validate_bounds(bounds)
    prob = Problem(Mesh(int(z1[0]), int(z2[0]), beta_deg=beta_deg, face_width_mm=face_width_mm), checks,
                   "max_margin", m)
    parts = [solve_pairs(prob, z1[c], z2[c], lo, hi) for c in
             (slice(s, s + CHUNK) for s in range(0, z1.size, CHUNK))]     # each pair's arithmetic is its own
    x, ok, _, fun = (np.concatenate([p[k] for p in parts], axis=-1) for k in range(4))
    return _results(prob, z1, z2, x, ok, fun)


def serves(prob: Problem) -> bool:
    """True for the problems this solver takes: one external or internal pair's (not a planetary set's two
    meshes), objective ``max_margin``, both shifts free, no costly checks (the strength chain)."""
    return (type(prob) is Problem and prob.objective.kind == "margin" and prob.nvar == 2
            and not prob.costly_parts)


def solve(prob: Problem, bounds):
    """The exact method's ``max_margin`` optimum of the problem's own pair (both shifts free), as an
    :class:`~geardesign.shifts.result.Outcome`; None where this method gives no certificate (the exact
    method's active-set search then solves it)."""
    lo, hi = bounds
    x, ok, nit, _ = solve_pairs(prob, np.array([float(prob.z1)]), np.array([float(prob.z2)]), lo, hi)
    if not ok[0]:
        return None
    return Outcome(x[:, 0], int(nit[0]), True, "converged: KKT system of the active set (the vertex or edge of "
                                               "the smallest normalised margins) by sequential linear programming "
                                               "and Newton")


def solve_pairs(prob: Problem, z1, z2, lo: float, hi: float):
    """(points (2, n), certified (n,), steps (n,), smallest piece there (n,), NaN where not certified) of the
    pairs (z1[i], z2[i]) of the problem's kind.
    Each pair's arithmetic is its own (elementwise): a pair gives the same bits alone or in a batch. A problem
    of fewer than three smooth parts (checks dropped) has no vertex to walk to: none is certified."""
    fun = np.full(z1.size, np.nan)
    if len(prob.part_check) < 3:
        return np.full((2, z1.size), np.nan), np.zeros(z1.size, dtype=bool), np.zeros(z1.size, dtype=np.int64), fun
    x, t_start, single = _starts(prob, z1, z2, lo, hi, START_N)
    i = np.flatnonzero(~(t_start >= 0.0))
    if i.size:    # no feasible node on the coarse grid: the region is small; the exact method's own grid
        x[:, i], t_start[i], single[i] = _starts(prob, z1[i], z2[i], lo, hi, FINE_START_N)
    started = (t_start >= 0.0) & single
    x, P, GP, done, nit = _walk(prob, z1, z2, x, started, (hi - lo) / (START_N - 1), hi - lo)
    i = np.flatnonzero(done)
    ok = np.zeros(z1.size, dtype=bool)
    ok[i] = _vertex_holds(P[:, i], GP[:, :, i]) & _holds(P[:, i], x[:, i], t_start[i], lo, hi)
    fun[ok] = P[:, ok].min(axis=0)
    i = np.flatnonzero(started & ~ok)
    if i.size:
        x[:, i], ok[i], steps, fun[i] = _edges(prob, z1[i], z2[i], x[:, i], t_start[i], lo, hi)
        nit[i] += steps
    return x, ok, nit, fun


def _walk(prob: Problem, z1, z2, x, started, radius0: float, radius_max: float):
    """Sequential linear programming in a trust region from the points x (2, n) of the ``started`` pairs:
    (x, pieces, their gradients, converged, steps) per pair."""
    n = z1.size
    done = np.zeros(n, dtype=bool)
    alive = started.copy()
    radius = np.full(n, radius0)     # the trust region's half-width in x
    P, GP = np.full((len(prob.part_check), n), np.nan), np.full((len(prob.part_check), 2, n), np.nan)
    nit = np.zeros(n, dtype=np.int64)
    i = np.flatnonzero(alive)
    P[:, i], GP[:, :, i] = _stencil(prob, z1[i], z2[i], x[:, i])
    for _ in range(MAX_STEPS):
        i = np.flatnonzero(alive & ~done)
        if i.size == 0:
            break
        nit[i] += 1
        t0 = P[:, i].min(axis=0)
        d, t_lp = _lp_step(P[:, i], GP[:, :, i], radius[i])
        # no gain in the linear model: a KKT vertex has converged; anywhere else the gain lies past pieces
        # the programme leaves out (beyond the LOW_PIECES lowest), so it looks again in a smaller region
        flat = ~(t_lp - t0 > 1e-15 * (1.0 + np.abs(t0)))
        if flat.any():
            f = i[flat]
            kkt = _vertex_holds(P[:, f], GP[:, :, f])
            done[f[kkt]] = True
            radius[f[~kkt]] /= 8.0
            alive[f[~kkt & (radius[f] < 1e-13)]] = False
            i, d, t_lp, t0 = i[~flat], d[:, ~flat], t_lp[~flat], t0[~flat]
        step = np.abs(d).max(axis=0)
        x_try = x[:, i] + d
        P_try, GP_try = _stencil(prob, z1[i], z2[i], x_try)
        with np.errstate(invalid="ignore"):
            gain, promised = P_try.min(axis=0) - t0, t_lp - t0
            take = (gain >= 0.1 * promised) & (promised > 0) | (step <= 1e-9) & (gain >= -1e-13)
        j = i[take]
        x[:, j], P[:, j], GP[:, :, j] = x_try[:, take], P_try[:, take], GP_try[:, :, take]
        # a step below the tolerance ends the walk at a KKT vertex; elsewhere the region shrinks, as above
        f = j[step[take] <= _STEP_TOL]
        kkt = _vertex_holds(P[:, f], GP[:, :, f])
        done[f[kkt]] = True
        radius[f[~kkt]] /= 8.0
        # the model held: a step on the region's edge may grow it; else the region shrinks below the step
        grow = take & (gain >= 0.75 * promised) & (step >= 0.99 * radius[i])
        radius[i[grow]] = np.minimum(2.0 * radius[i[grow]], radius_max)
        radius[i[~take]] = step[~take] / 4.0
        alive[i[~take & (radius[i] < 1e-13)]] = False
    return x, P, GP, done, nit


def _edges(prob: Problem, z1, z2, x, t_start, lo: float, hi: float):
    """Newton on the KKT system of an edge, from the walk's points x (2, n): the two lowest pieces equal and
    their gradients opposite (the stationarity of :func:`geardesign.shifts.kkt._stationarity`, its
    derivative by forward differences of the central-difference gradients, as the exact method starts
    its own). Returns (x, certified, steps, smallest piece where certified)."""
    n = z1.size
    cols = np.arange(n)
    P, G = _stencil(prob, z1, z2, x)
    a, b = np.argsort(P, axis=0)[:2]
    done = np.zeros(n, dtype=bool)
    live = np.isfinite(P[a, cols]) & np.isfinite(P[b, cols])
    nit = np.zeros(n, dtype=np.int64)
    for _ in range(EDGE_STEPS):
        i = np.flatnonzero(live & ~done)
        if i.size == 0:
            break
        nit[i] += 1
        ai, bi, xi = a[i], b[i], x[:, i]
        h = 1e-5 * np.maximum(1.0, np.abs(xi))
        (P0, G0), (P1, G1), (P2, G2) = (_stencil(prob, z1[i], z2[i], xi + dx) for dx in
                                        (0.0, h * [[1.0], [0.0]], h * [[0.0], [1.0]]))
        c = np.arange(i.size)
        with np.errstate(all="ignore"):
            s0, s1, s2 = (_opposed(g[ai, :, c], g[bi, :, c]) for g in (G0, G1, G2))
            f1 = P0[ai, c] - P0[bi, c]
            # the two pieces equal to rounding, their gradients opposite to the differences' noise: the point
            # the exact method accepts (its stationarity tolerance); no further step is taken from it
            there = (np.abs(f1) <= 1e-12 * np.maximum(1.0, np.abs(P0[ai, c]))) & (np.abs(s0) <= _EDGE_STAT_TOL)
            j11, j12 = G0[ai, 0, c] - G0[bi, 0, c], G0[ai, 1, c] - G0[bi, 1, c]
            j21, j22 = (s1 - s0) / h[0], (s2 - s0) / h[1]
            det = j11 * j22 - j12 * j21
            d1, d2 = (-f1 * j22 + s0 * j12) / det, (-j11 * s0 + j21 * f1) / det
            step = np.maximum(np.abs(d1), np.abs(d2))
        done[i[there]] = True
        bad = ~there & (~np.isfinite(step) | (step > EDGE_REACH))
        live[i[bad]] = False
        move = ~there & ~bad
        x[:, i[move]] = xi[:, move] + np.stack((d1, d2))[:, move]
    ok = live & done
    fun = np.full(n, np.nan)
    i = np.flatnonzero(ok)
    if i.size:
        P, G = _stencil(prob, z1[i], z2[i], x[:, i])
        ok[i] = _edge_holds(P, G, a[i], b[i]) & _holds(P, x[:, i], t_start[i], lo, hi)
        fun[i] = np.where(ok[i], P.min(axis=0), np.nan)
    return x, ok, nit, fun


def _opposed(ga, gb):
    """(g_a × g_b)/(‖g_a‖‖g_b‖) of gradient rows (n, 2): zero when the two are parallel or opposite."""
    return (ga[:, 0] * gb[:, 1] - ga[:, 1] * gb[:, 0]) / (np.hypot(ga[:, 0], ga[:, 1]) * np.hypot(gb[:, 0], gb[:, 1]))


def _pieces(prob: Problem, z1, z2, x1, x2):
    """The normalised pieces (parts, n) of the designs (Problem.part_distances over many tooth pairs)."""
    with np.errstate(all="ignore"):
        return prob.part_distances(mesh_geometry(prob.mesh.unchecked(z1, z2), prob.m, x1, x2, prob.full))


def _starts(prob: Problem, z1, z2, lo: float, hi: float, nodes: int):
    """Each pair's best node of the start grid ((2, n) points), its smallest piece (−inf: none exists) and
    whether the grid's feasible nodes are one piece (several pieces are left to the exact method's starts).
    Pairs go through in chunks of at most :data:`START_POINTS` grid nodes."""
    g = np.linspace(lo, hi, nodes)
    g1, g2 = (a.ravel() for a in np.meshgrid(g, g, indexing="ij"))
    k, n = g1.size, z1.size
    low = np.empty((n, k))
    step = max(1, START_POINTS // k)
    for s in range(0, n, step):
        c = slice(s, s + step)
        m = z1[c].size
        P = _pieces(prob, np.repeat(z1[c], k), np.repeat(z2[c], k), np.tile(g1, m), np.tile(g2, m))
        low[c] = P.min(axis=0).reshape(m, k)
    best = np.argmax(low, axis=1)
    return np.stack((g1[best], g2[best])), low[np.arange(n), best], _one_piece(low >= 0.0, best, nodes)


def _one_piece(feasible, best, nodes: int):
    """(n,) True where the feasible nodes (n, nodes²) are one piece with the best one: 8-connected, as the exact
    method tells the pieces of its grid apart (:func:`~geardesign.shifts.nodes.grid_starts`); every pair's grid
    labelled in one call, no piece reaching across pairs."""
    from scipy import ndimage

    feasible = feasible.reshape(-1, nodes, nodes)
    within = np.zeros((3, 3, 3), dtype=bool)
    within[1] = True
    labels = ndimage.label(feasible, structure=within)[0].reshape(len(best), -1)
    own = labels[np.arange(len(best)), best]
    return ((labels == own[:, None]) | (labels == 0)).all(axis=1) & (own > 0)


def _stencil(prob: Problem, z1, z2, x):
    """Pieces (parts, n) at the points x (2, n) and their gradients (parts, 2, n) by central differences
    (the exact method's step): one evaluation of the five stencil points of every pair."""
    h = _FD_STEP
    x1 = np.concatenate((x[0], x[0] + h, x[0] - h, x[0], x[0]))
    x2 = np.concatenate((x[1], x[1], x[1], x[1] + h, x[1] - h))
    P = _pieces(prob, np.tile(z1, 5), np.tile(z2, 5), x1, x2)
    P = P.reshape(P.shape[0], 5, -1)
    with np.errstate(invalid="ignore"):
        G = np.stack(((P[:, 1] - P[:, 2]) / (2 * h), (P[:, 3] - P[:, 4]) / (2 * h)), axis=1)
    return P[:, 0], G


@functools.lru_cache(maxsize=8)
def _combinations(n: int):
    """Index arrays of the triples and of the pairs among n pieces: ((3, T), (2, Q))."""
    return (np.array(list(itertools.combinations(range(n), 3))).T,
            np.array(list(itertools.combinations(range(n), 2))).T)


def _lp_step(P, G, radius):
    """The step d (2, n) to the best point of each pair's linearised programme in its trust region
    |d_i| <= radius, and the programme's value there: "maximise t, P_k + G_k · d >= t". Its optimum is a
    vertex, three of its planes meeting: three pieces, two pieces and a side of the region, or a corner;
    each is a candidate (moved into the region), and the one with the largest min_k (P_k + G_k · d)
    is taken. Only the :data:`LOW_PIECES` lowest pieces make candidates; all of them rate each."""
    n = P.shape[1]
    cols = np.arange(n)
    with np.errstate(all="ignore"):
        low = np.argsort(P, axis=0)[:LOW_PIECES]                    # (L, n)
        triples, pairs = _combinations(low.shape[0])
        p, g1, g2 = P[low, cols], G[low, 0, cols], G[low, 1, cols]  # (L, n)
        cands = [np.zeros((2, n))]
        # three pieces equal: p_a + g_a · d = p_b + g_b · d = p_c + g_c · d (Cramer on the differences)
        a, b, c = triples
        a11, a12, b1 = g1[b] - g1[a], g2[b] - g2[a], p[a] - p[b]
        a21, a22, b2 = g1[c] - g1[a], g2[c] - g2[a], p[a] - p[c]
        det = a11 * a22 - a12 * a21
        cands.append(np.stack(((b1 * a22 - b2 * a12) / det, (a11 * b2 - a21 * b1) / det), axis=1))
        # two pieces equal on a side d_1 = ±r or d_2 = ±r
        a, b = pairs
        for side in (radius, -radius):
            d2 = (p[b] - p[a] + (g1[b] - g1[a]) * side) / (g2[a] - g2[b])
            d1 = (p[b] - p[a] + (g2[b] - g2[a]) * side) / (g1[a] - g1[b])
            cands.append(np.stack((np.broadcast_to(side, d2.shape), d2), axis=1))
            cands.append(np.stack((d1, np.broadcast_to(side, d1.shape)), axis=1))
        corners = np.array([(1, 1), (1, -1), (-1, 1), (-1, -1)], dtype=float)[:, :, None] * radius
        cands.append(corners)
        D = np.concatenate([np.reshape(c, (-1, 2, n)) for c in cands])          # (C, 2, n)
        D = np.clip(np.nan_to_num(D, nan=0.0, posinf=0.0, neginf=0.0), -radius, radius)
        lin = P[:, None, :] + G[:, 0, None, :] * D[:, 0] + G[:, 1, None, :] * D[:, 1]   # (K, C, n)
        t = np.nan_to_num(lin.min(axis=0), nan=-np.inf)                         # (C, n)
    best = np.argmax(t, axis=0)
    return D[best, :, cols].T, t[best, cols]


def _vertex_holds(P, G):
    """At each pair's point, the KKT conditions of the vertex of its three lowest pieces: the three equal
    and the multipliers of e_t + Σ λ_j (∇piece_j, −1) = 0 non-negative."""
    cols = np.arange(P.shape[1])
    with np.errstate(all="ignore"):
        act = np.argsort(P, axis=0)[:3]
        equal = (np.abs(P[act, cols] - P.min(axis=0)) <= 1e-10).all(axis=0)
        g1, g2 = G[act, 0, cols], G[act, 1, cols]
        # Σ λ_j g_j = 0, Σ λ_j = 1: λ ∝ the 2×2 minors of the other two gradients
        lam = np.stack((g1[1] * g2[2] - g1[2] * g2[1], g1[2] * g2[0] - g1[0] * g2[2], g1[0] * g2[1] - g1[1] * g2[0]))
        lam = lam / lam.sum(axis=0)
    return equal & (lam >= -1e-7).all(axis=0) & np.isfinite(lam).all(axis=0)


def _edge_holds(P, G, a, b):
    """The KKT conditions of the edge of pieces a, b: the two equal and the smallest, their gradients
    opposite (within the exact method's tolerance on the stationarity, 1e-8), so that both multipliers
    are positive."""
    cols = np.arange(P.shape[1])
    with np.errstate(all="ignore"):
        ga, gb = G[a, :, cols], G[b, :, cols]
        equal = (np.abs(P[a, cols] - P.min(axis=0)) <= 1e-10) & (np.abs(P[b, cols] - P.min(axis=0)) <= 1e-10)
        return equal & (np.abs(_opposed(ga, gb)) <= _EDGE_STAT_TOL) & ((ga * gb).sum(axis=1) < 0)


def _holds(P, x, t_start, lo: float, hi: float):
    """Every check holding (each piece >= 0), the point inside the window, and no worse than the start."""
    t = P.min(axis=0)
    return (t >= -FEASIBILITY_TOL) & (t >= t_start - 1e-9) & ((x >= lo) & (x <= hi)).all(axis=0)


def _results(prob: Problem, z1, z2, x, ok, fun) -> dict:
    """The certified points' geometry and margins (per check), NaN elsewhere. They are read as one design
    is, on the float path (:func:`~geardesign.gears.geometry.mesh_geometry_float`, what ``optimize_shifts``
    reports and ``GearPair.geometry`` gives), so that a pair's figures do not depend on how it was solved."""
    i = np.flatnonzero(ok)
    out = {k: np.full(z1.size, np.nan) for k in ("x1", "x2", "a_w", "da1", "da2")}
    out["ok"], out["fun"] = ok, fun
    out["x1"][i], out["x2"][i] = x[0, i], x[1, i]
    margins = np.full((len(prob.checks), z1.size), np.nan)
    for j in i:
        geo = mesh_geometry_float(prob.mesh.unchecked(int(z1[j]), int(z2[j])), prob.m, x[0, j], x[1, j])
        mg = prob._margins_only(geo, parts=False)
        margins[:, j] = np.where(np.abs(mg) <= _ZERO_MARGIN, 0.0, mg)
        out["a_w"][j], out["da1"][j], out["da2"][j] = geo["a_w"], geo["da1"], geo["da2"]
    out["margins"] = dict(zip(prob.names, margins))
    return out
