"""Feasible start points for the local methods (convex, exact): the best node of each separate
feasible piece of a coarse grid, or of a given start; the most central point when no node is feasible."""
from __future__ import annotations

import math

import numpy as np

from .conflict import INFEASIBLE_ACCURACY, conflict_message, smallest_conflict
from .local import central_point
from .nodes import MAX_STARTS, START_N, grid_starts, grid_points
from .problem import Problem
from .result import Outcome

__all__ = ["feasible_starts", "feasible_at", "start_nodes"]

_LINE_START_N = 401   # nodes of a fixed-a_w line


def start_nodes(prob: Problem) -> int:
    """Nodes per axis of the start grid."""
    return START_N if prob.nvar == 2 else _LINE_START_N


def feasible_at(prob: Problem, v) -> bool:
    """True when every check holds at v."""
    M = prob.evaluate_point(v)[1]
    return not (M.size and M.min() < 0)


def feasible_starts(prob: Problem, bounds, start=None):
    """(starts, None, ceilings) best first, or ([], Outcome, []) naming the conflicting checks; each start's
    ceiling bounds what its piece can reach (:func:`~geardesign.shifts.nodes.grid_starts`)."""
    n = start_nodes(prob)
    if start is not None and prob.nvar == 2:
        V = np.asarray(start, dtype=float).reshape(1, 2)
        starts, M, ceilings = grid_starts(prob, V, 1)
        if not starts:
            V = grid_points(prob, START_N, bounds)
            starts, M, ceilings = grid_starts(prob, V, START_N)
    else:
        V = grid_points(prob, n, bounds)
        starts, M, ceilings = grid_starts(prob, V, n)
    if starts and feasible_at(prob, starts[0]):
        return starts, None, ceilings
    # no feasible node: the region, if any, is thinner than the grid; the most central point near
    # the least infeasible node starts the solve
    w = central_point(prob, V, M, bounds)
    if w[-1] < 0:
        conflict = smallest_conflict(prob, bounds)
        return [], Outcome(w[:-1], 1, False, conflict_message(conflict), conflict=conflict,
                           accuracy=INFEASIBLE_ACCURACY), []
    return [w[:-1]] + starts[:MAX_STARTS - 1], None, [math.inf] + ceilings[:MAX_STARTS - 1]
