"""Nodes of the shift plane: the N×N grid of (x1, x2) (or a line of x1 at a fixed x-sum), evaluated
in one vectorised call; its best feasible node, and the start points it gives the local methods."""
from __future__ import annotations

import functools
import math

import numpy as np

from ..gears.checks import FEASIBILITY_TOL
from ..gears.geometry import exact_sum_nodes
from .problem import Problem

__all__ = ["grid_points", "best_feasible", "grid_starts", "one_node_change", "START_N", "MAX_STARTS"]


START_N = 31          # grid nodes per axis for the start of convex and exact (spacing 0.15)

MAX_STARTS = 4


def grid_points(prob: Problem, n: int, bounds) -> np.ndarray:
    lo, hi = bounds
    if prob.nvar == 1:
        lo1, hi1 = prob.x1_on_line(lo, hi)
        return np.linspace(lo1, hi1, n)[:, None]
    return _square_grid(n, float(lo), float(hi))


@functools.lru_cache(maxsize=16)
def _square_grid(n: int, lo: float, hi: float) -> np.ndarray:
    g = exact_sum_nodes(lo, hi, n)     # one operating angle per x-sum diagonal
    X1, X2 = np.meshgrid(g, g, indexing="ij")
    V = np.column_stack([X1.ravel(), X2.ravel()])
    V.flags.writeable = False
    return V


def best_feasible(prob: Problem, V: np.ndarray):
    """(index of the best feasible node of V or None, pieces (P, n), margins (K, n)). Costly checks (the
    strength chain) are evaluated only at the nodes every other check passes: a node that fails one of
    those is infeasible whatever they say (all of them at every node where none is feasible)."""
    light = prob.light() if hasattr(prob, "light") else None
    if light is None:
        P, M = prob.evaluate(V, grads=False)
    else:
        P, M = light.evaluate(V, grads=False)
        costly = [i for i, c in enumerate(prob.checks) if c.costly]
        rest = [i for i, c in enumerate(prob.checks) if not c.costly]
        near = (M[rest] >= -FEASIBILITY_TOL).all(axis=0)
        if not near.any():
            return None, *prob.evaluate(V, grads=False)
        M[costly] = -np.inf
        M[:, near] = prob.evaluate(V[near], grads=False)[1]
    feasible = (M >= -FEASIBILITY_TOL).all(axis=0) if M.size else np.ones(V.shape[0], bool)
    score = np.where(feasible, P.min(axis=0), -np.inf)
    if not np.isfinite(score).any():
        return (None, P, M) if light is None else (None, *prob.evaluate(V, grads=False))
    return int(np.argmax(score)), P, M


def grid_starts(prob: Problem, V: np.ndarray, n: int):
    """Start points for the local solvers on the grid V (n nodes per axis), best first, at most
    MAX_STARTS: the best node of every separate feasible piece of the grid, and the local
    maxima of the objective over the nodes that miss feasibility by less than one node
    spacing (first-order distance to every violated boundary), away from the feasible nodes,
    where they beat every feasible node: a piece thinner than the grid holds no node, but its
    neighbours come that close. Returns (starts, margins at V, ceilings): a start's ceiling is the most
    its piece can reach to first order (its best node plus one node's change of the objective along each
    axis, :func:`one_node_change`), NaN for a near node (its piece is not on the grid), inf for a grid's
    only piece or a given start."""
    from scipy import ndimage

    P, M = prob.evaluate(V, grads=False)
    feasible = (M >= -FEASIBILITY_TOL).all(axis=0) if M.size else np.ones(V.shape[0], bool)
    fun = P.min(axis=0)
    fun = np.where(np.isnan(fun), -np.inf, fun)
    score = np.where(feasible, fun, -np.inf)
    if n < 2 or V.shape[0] < n ** prob.nvar:              # a given start, no grid
        found = np.isfinite(score).any()
        return ([V[int(np.argmax(score))]] if found else []), M, ([math.inf] if found else [])
    shape = (n, n) if prob.nvar == 2 else (n,)
    box = np.ones((3,) * prob.nvar, bool)
    labels, count = ndimage.label(feasible.reshape(shape), structure=box)
    if count <= 1:
        idx = [int(np.argmax(score))] if count else []
        ceiling = {i: math.inf for i in idx}
    else:
        # a piece's best node and its ceiling, piece by piece (few pieces: cheaper than ndimage's
        # per-label reductions, which sort every node)
        with np.errstate(invalid="ignore"):   # -inf + inf where a node's pair does not exist: not in a piece
            reach = np.where(feasible, fun + one_node_change(fun.reshape(shape)).ravel(), -np.inf)
        labels = labels.ravel()
        idx, ceiling = [], {}
        for k in range(1, count + 1):
            inside = labels == k
            i = int(np.argmax(np.where(inside, score, -np.inf)))
            idx.append(i)
            ceiling[i] = float(reach[inside].max())
    best = score.max()
    # beyond two nodes of every feasible node, better than all of them
    far = ~ndimage.maximum_filter(feasible.reshape(shape), size=5, mode="constant", cval=False).ravel()
    cand = far & (fun > best)
    if M.size and cand.any():
        # only the margins some candidate misses decide whether it is near
        missed = M[((M < 0) & cand).any(axis=1)]
        Mg = np.where(np.isfinite(missed), missed, np.nan).reshape((-1,) + shape)
        # the largest one-node change of each margin, along either axis (a missing neighbour ignored)
        step = functools.reduce(np.fmax, _axis_changes(Mg, range(1, prob.nvar + 1)))
        near = (missed + step.reshape(missed.shape) >= 0).all(axis=0)   # step >= 0, never NaN
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
        if len(chosen) == MAX_STARTS:
            break
    return [V[i] for i in chosen], M, [float(ceiling.get(i, math.nan)) for i in chosen]


def one_node_change(F: np.ndarray) -> np.ndarray:
    """At each node of the grid values F, the sum over the axes of the largest change of F to a neighbour
    along that axis: to first order, F anywhere within one node spacing of the node is at most F there plus
    this. Inf where a neighbour's value is not finite (the pair stops existing there: no bound).

    >>> one_node_change(np.array([[0.0, 1.0], [3.0, 3.5]]))
    array([[4. , 3.5],
           [3.5, 3. ]])
    """
    return sum(_axis_changes(F, range(F.ndim), missing=np.inf))


def _axis_changes(F: np.ndarray, axes, missing=None) -> list:
    """For each of ``axes``, the largest change of F from each node to a neighbour along that axis; a change to a
    neighbour whose value is not finite (NaN) is ignored, or is ``missing`` when given."""
    out = []
    for ax in axes:
        step = np.zeros(F.shape)
        before = (slice(None),) * ax + (slice(1, None),)
        after = (slice(None),) * ax + (slice(None, -1),)
        with np.errstate(invalid="ignore"):
            d = np.abs(F[before] - F[after])
        if missing is not None:
            d = np.where(np.isnan(d), missing, d)
        np.fmax(step[before], d, out=step[before])     # the change to the node before
        np.fmax(step[after], d, out=step[after])       # and to the node after
        out.append(step)
    return out
