"""Which checks conflict: a smallest set of checks that no (x1, x2) in the window satisfies together."""
from __future__ import annotations

import itertools

import numpy as np

from .nodes import grid_points
from .local import maximin
from .problem import DEFAULT_BOUNDS, Problem

__all__ = ["smallest_conflict", "conflict_message"]


# subsets tried by size before the search settles for an irreducible conflict: a planetary set's checks under
# several load cases are ~50, and where no few of them conflict every subset of four is 230 000 of them (fuzz
# planetary_spectrum: minutes)
SUBSETS_MAX = 20000


def smallest_conflict(prob: Problem, bounds=DEFAULT_BOUNDS, n: int = 161) -> list[str]:
    """A smallest set of checks that no (x1, x2) in the window satisfies together.

    Subsets are tried by size: the largest smallest-margin over a grid shows which subsets look
    empty, and a local maximisation of the smallest margin (SLSQP) confirms it. Past
    :data:`SUBSETS_MAX` subsets, an irreducible conflict instead (no check of it can be left out; not
    always a smallest one): see :func:`_irreducible`.
    """
    V = grid_points(prob, n, bounds)
    _, M = prob.evaluate(V, grads=False)
    K = M.shape[0]
    if K and not _conflicts(prob, V, M, list(range(K)), bounds, grid_only=True):
        # a node holds every check (a start grid coarser than this one missed it): no subset conflicts, and the
        # search by size would try them all (fuzz planetary_spectrum: 34 checks, minutes)
        return []
    tried = 0
    for size in range(1, K + 1):
        for sub in itertools.combinations(range(K), size):
            tried += 1
            if tried > SUBSETS_MAX:
                return [prob.names[j] for j in _irreducible(prob, V, M, bounds)]
            if _conflicts(prob, V, M, list(sub), bounds):
                return [prob.names[j] for j in sub]
    return []


def _conflicts(prob: Problem, V, M, sub: list, bounds, grid_only: bool = False) -> bool:
    """True when the checks ``sub`` hold together at no grid node and (unless ``grid_only``) a local maximisation
    of their smallest margin from the best node confirms it."""
    worst = M[sub].min(axis=0)
    i = int(np.argmax(worst))
    if worst[i] >= 0:
        return False
    if grid_only:
        return True
    w, _ = maximin(prob.subproblem(sub), V[i], bounds)   # maximise the smallest margin of the subset
    return bool(w[-1] < -1e-9)


def _irreducible(prob: Problem, V, M, bounds) -> list[int]:
    """An irreducible conflict by deletion: each check in turn, those held at the most grid nodes first, is left
    out where the others still conflict; on the grid alone first (cheap), the set it leaves then confirmed by the
    local maximisation, and where that finds a point after all, the deletion again with each step confirmed
    (none when all of them together do not conflict)."""
    order = np.argsort(-np.mean(np.nan_to_num(M, nan=-1.0) >= 0, axis=1), kind="stable")
    everything = list(range(M.shape[0]))
    for grid_only in (True, False):
        keep = list(everything)
        for j in order:
            trial = [k for k in keep if k != j]
            if trial and _conflicts(prob, V, M, trial, bounds, grid_only):
                keep = trial
        if not grid_only or _conflicts(prob, V, M, keep, bounds):
            return keep if keep != everything or _conflicts(prob, V, M, keep, bounds) else []
    return []


# what the point of a failed result is, in place of the method's accuracy text (it is no optimum of anything)
INFEASIBLE_ACCURACY = ("no feasible point, so no optimum: x is the point of largest smallest margin found near the "
                       "least infeasible grid node (SLSQP), not certified")


def conflict_message(conflict) -> str:
    if len(conflict) == 1:
        return f"no feasible point: check {conflict[0]} conflicts with the window (it holds nowhere in it)"
    if conflict:
        return (f"no feasible point: checks {', '.join(conflict)} conflict (no shifts hold them all at once; each "
                f"may hold alone)")
    # no conflict confirmed: the checks may fail together only between the nodes the solver started from
    return ("no feasible point found in the window: every check passes somewhere, and no set of them is shown to "
            "conflict (a finer grid, method='grid' with a larger grid_n, may find a point that holds them all)")
