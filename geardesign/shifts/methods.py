"""The shift solvers as a table: each method's name, default tolerance, what its accuracy means, and the
function that solves a built :class:`~geardesign.shifts.problem.Problem` with it. The dispatcher
(:func:`geardesign.shifts.optimize.solve_problem`), the CLI's and the scenes' choices read this table;
a new method is one module with its solver and one :func:`register_method` call (docs/extending.md)."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

from ..errors import GearDesignError
from . import balance, centres, grid, kkt, scp
from .starts import feasible_starts, start_nodes

__all__ = ["Method", "register_method", "METHOD_TABLE", "METHODS", "DEFAULT_TOL", "ACCURACY"]


@dataclass(frozen=True)
class Method:
    """A shift solver: ``solve(prob, bounds, tol, grid_n, start) -> Outcome``; ``accuracy`` says what
    ``tol`` means for it (formatted with ``tol``)."""

    name: str
    default_tol: float
    accuracy: str
    solve: Callable


METHOD_TABLE: dict[str, Method] = {}
METHODS: list[str] = []              # the names, in the order the CLI lists them
DEFAULT_TOL: dict[str, float] = {}
ACCURACY: dict[str, str] = {}


def register_method(method: Method) -> Method:
    """Add ``method`` to the table (and to the names, tolerances and accuracy texts read from it)."""
    if not isinstance(method, Method):
        raise GearDesignError(f"register_method takes a geardesign.shifts.methods.Method, got {type(method).__name__}")
    if method.name in METHOD_TABLE:
        raise GearDesignError(f"a method called {method.name!r} exists already")
    METHOD_TABLE[method.name] = method
    METHODS.append(method.name)
    DEFAULT_TOL[method.name] = method.default_tol
    ACCURACY[method.name] = method.accuracy
    return method


def _solve_grid(prob, bounds, tol, grid_n=None, start=None):
    return grid.solve(prob, bounds, tol, grid_n)


def _solve_convex(prob, bounds, tol, grid_n=None, start=None):
    starts, infeasible, _ = feasible_starts(prob, bounds, start)
    return infeasible if infeasible is not None else scp.solve(prob, starts, bounds, tol)


def _solve_exact(prob, bounds, tol, grid_n=None, start=None):
    if start is None and centres.serves(prob):     # one pair's Chebyshev centre, as a drive solves many
        out = centres.solve(prob, bounds)
        if out is not None:
            return out
    if start is None and balance.serves(prob):     # equal root sliding on a fixed-a_w line, a housing's pair
        out = balance.solve(prob, bounds)
        if out is not None:
            return out
    starts, infeasible, ceilings = feasible_starts(prob, bounds, start)
    if infeasible is not None:
        return infeasible
    h = (bounds[1] - bounds[0]) / (start_nodes(prob) - 1)
    return kkt.solve(prob, starts, bounds, tol, h, ceilings)


register_method(Method("grid", 1e-2, "best grid node: fun within one node spacing's change of the optimum; x within "
                                     "{tol:g} of it unless the optimum slides along a boundary nearly level with fun",
                       _solve_grid))
register_method(Method("convex", 1e-7, "SQP stopped when its step fell below tol: x within ~{tol:g} of the optimum",
                       _solve_convex))
register_method(Method("exact", 1e-9, "KKT point solved by Newton: x to ~1e-12, checks hold to {tol:g}", _solve_exact))
