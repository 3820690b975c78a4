"""Which checks conflict: a smallest set of checks that no (x1, x2) in the window satisfies together."""
from __future__ import annotations

import itertools

import numpy as np

from .nodes import grid_points
from .local import maximin
from .problem import DEFAULT_BOUNDS, Problem

__all__ = ["smallest_conflict", "conflict_message"]


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
            sub_prob = prob.subproblem(sub)
            # maximise the smallest margin of the subset
            w, _ = maximin(sub_prob, V[i], bounds)
            if w[-1] < -1e-9:
                return [prob.names[j] for j in sub]
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
    return "no feasible point in the window: every check passes somewhere, but not all together"
