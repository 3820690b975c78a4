"""The grid method: every piece and margin on an N×N grid in one vectorised call; the best
feasible node. Coarse and fast; the achieved tolerance is half the grid spacing."""
from __future__ import annotations

import math

from .conflict import INFEASIBLE_ACCURACY, conflict_message, smallest_conflict
from .local import central_point
from .nodes import best_feasible, grid_points
from .problem import Problem
from .result import Outcome

__all__ = ["solve", "GRID_N_MAX"]

GRID_N_MAX = 2001       # nodes per axis of the grid method: 4 M designs, ~4 s and ~3 GB at most
_LINE_N_MAX = 200_001   # nodes of a fixed-a_w line


def nodes_for(tol: float, span: float, nvar: int, grid_n: int | None) -> int:
    """Nodes per axis: ``grid_n``, or enough for a spacing of 2·tol (at least 11)."""
    if grid_n:
        return grid_n
    n = int(min(max(math.ceil(span / (2 * tol)) + 1, 11), 1001 if nvar == 2 else _LINE_N_MAX))
    return min(n, GRID_N_MAX) if nvar == 2 else n


def solve(prob: Problem, bounds, tol: float, grid_n: int | None = None) -> Outcome:
    n = nodes_for(tol, bounds[1] - bounds[0], prob.nvar, grid_n)
    V = grid_points(prob, n, bounds)
    i, P, M = best_feasible(prob, V)
    h = (V[-1, 0] - V[0, 0]) / (n - 1) if n > 1 else 0.0
    asked = tol
    tol = max(h / 2, tol) if h > 0 else tol
    capped = (f"; tol {asked:g} asked, but the grid is capped at {n} nodes per axis: the spacing achieved is "
              f"{h:.3g} (x within {tol:.3g}); method='exact' gives x to ~1e-12" if tol > asked * (1 + 1e-9) else "")
    if i is not None:
        return Outcome(V[i], 1, True, f"best of {V.shape[0]} grid nodes (spacing {h:.3g}){capped}", tol=tol)
    w = central_point(prob, V, M, bounds)
    if w[-1] >= 0:
        return Outcome(w[:-1], 1, True, f"no feasible node among {V.shape[0]} (spacing {h:.3g}): the region is "
                       "thinner than the grid; returned its most central point nearby", tol=tol)
    conflict = smallest_conflict(prob, bounds)
    return Outcome(w[:-1], 1, False, conflict_message(conflict), conflict=conflict, tol=tol,
                   accuracy=INFEASIBLE_ACCURACY)
