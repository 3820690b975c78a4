"""A profile-shift problem: tooth counts, rack, the checks a case asks for, and an objective.

Shared by the region (:mod:`geardesign.shifts.region`) and the optimisers (:mod:`geardesign.shifts.optimize`).
Everything is evaluated in one vectorised geometry call over any array of (x1, x2).
Objectives (:mod:`geardesign.shifts.objectives`) are maximised internally as F = sense · fun.
"""
from __future__ import annotations

import contextlib
import copy
import math
from dataclasses import dataclass

import numpy as np

from ..gears import checks as _checks
from ..errors import GearDesignError
from ..validate import one_number, require_count, require_range
from .objectives import Objective, resolve_objective
from ..gears.geometry import X_ABS_MAX, mesh_geometry, mesh_geometry_float, require_module
from ..gears.mesh import Z_MAX, Z_MIN, Mesh

__all__ = ["Problem", "validate_bounds", "DEFAULT_BOUNDS", "Meshing", "with_meshing", "MESHING_EPS_ALPHA_MIN"]


_FD_STEP = 1e-6
_FLOAT_FAULTS = (ZeroDivisionError, OverflowError, ValueError)


# The gears mesh when their tips overlap along the line of action (g_α > 0, ε_α > 0): a condition
# of existence (GearPair refuses a pair that does not mesh), not an optional check. The solvers hold
# it as ε_α >= this small positive limit, so that a point within a solver's tolerance of the
# boundary still meshes; a thousandth of a base pitch of contact is far below any working gear.
MESHING_EPS_ALPHA_MIN = 1e-3


@dataclass(frozen=True)
class Meshing(_checks.ContactRatio):
    """The gears mesh: ε_α >= :data:`MESHING_EPS_ALPHA_MIN` (path of contact g_α > 0, ISO 21771:2007
    eq. (141)); the margin and gradient are the contact ratio's. Added by :func:`with_meshing`
    wherever the checks asked for do not already hold the contact ratio at least this high."""

    limit: float = MESHING_EPS_ALPHA_MIN
    name: str = "meshing"
    label: str = "the gears mesh: eps_alpha > 0 (a condition of existence, kept when checks are dropped)"


def _holds_meshing(c) -> bool:
    return isinstance(c, _checks.ContactRatio) and c.limit >= MESHING_EPS_ALPHA_MIN


def with_meshing(checks: tuple, wrap=None, holds=_holds_meshing) -> tuple:
    """``checks`` with :class:`Meshing` appended unless a contact-ratio check already implies it;
    ``wrap(check) -> check`` puts it into a set's mesh (the planetary problem calls this per mesh
    with ``holds`` reading its own mesh's checks)."""
    if any(holds(c) for c in checks):
        return tuple(checks)
    return tuple(checks) + ((Meshing() if wrap is None else wrap(Meshing())),)


class Problem:
    """The checks and the objective of one tooth pair, as vectorised functions of (x1, x2).

    With ``x_sum`` given (a fixed centre distance) the design has one free variable, x1,
    and x2 = x_sum − x1 (x2 = x_sum + x1 for an internal pair, whose x_Σ is x2 − x1).
    """

    _recent = None   # key -> (evaluate_point's value, its geometry) of the last points evaluated
    _RECENT = 32     # points remembered: the best of several starts, evaluated again for the result
    _geos = None     # key -> geometry of the last points, shared with the views of :meth:`reading_only`

    def __init__(self, mesh: Mesh, checks=None, objective="max_x_sum", m=1.0, x_sum=None, meshing: bool = True):
        if not isinstance(mesh, Mesh):
            raise GearDesignError(f"mesh must be a geardesign.Mesh, got {type(mesh).__name__}")
        for name in ("z1", "z2"):
            require_count(name, getattr(mesh, name), Z_MIN, Z_MAX)   # one pair: no arrays here
        self.mesh = mesh
        self.m = one_number("m (module)", require_module(m))
        self.checks = _checks.resolve_checks(checks, internal=mesh.internal)
        # the checks the caller asked for; ``checks`` adds the condition of existence (meshing)
        self.asked = self.checks
        if meshing:
            self.checks = with_meshing(self.checks)
        self.sgn = mesh.sign
        self.objective = resolve_objective(objective).bound(self.checks)
        # the report-only geometry fields are computed only when a check or the objective reads them
        self.full = self.objective.needs_report_fields or any(c.needs_report_fields for c in self.checks)
        self.x_sum = None if x_sum is None else float(x_sum)
        self.names = [c.name for c in self.checks]
        # the smooth parts the solvers see (see Check.part_margins): part -> index of its check
        self.part_check = [i for i, c in enumerate(self.checks) for _ in range(c.n_parts)]
        # gradients that are central differences carry ~1e-10 noise, their derivatives more
        self.fd_gradients = _fd_gradients(self.objective, self.checks)

    # --- evaluation ---------------------------------------------------------------------
    # The checks and pieces are written once, as formulas on a geometry dict; the dict holds
    # arrays (the vectorised path: grids, regions, atlases) or Python floats (the
    # single-point path of the local solvers, ~20× cheaper than a one-element array call).

    z1 = property(lambda self: self.mesh.z1)
    z2 = property(lambda self: self.mesh.z2)
    rack = property(lambda self: self.mesh.rack)

    def geo(self, x1, x2) -> dict:
        return mesh_geometry(self.mesh, self.m, x1, x2, self.full)

    def geo_then(self, x1, x2, then) -> dict:
        """``then(geo)`` over the designs block by block, only its values kept (see mesh_geometry)."""
        return mesh_geometry(self.mesh, self.m, x1, x2, self.full, then=then)

    def _geo_like(self, geo):
        """geo(x1, x2) -> dict at the same m, z1, z2 as ``geo`` (arrays or floats alike; an atlas
        evaluates many tooth pairs through one problem)."""
        core = mesh_geometry_float if isinstance(geo["_x1"], float) else mesh_geometry
        mesh = self.mesh.unchecked(geo["_z1"], geo["_z2"])
        return lambda x1, x2: core(mesh, geo["_m"], x1, x2, self.full)

    def _central(self, func, geo):
        """(∂func/∂x1, ∂func/∂x2) by central differences around the design(s) of ``geo``."""
        h, at = _FD_STEP, self._geo_like(geo)
        x1, x2 = geo["_x1"], geo["_x2"]
        out = []
        with np.errstate(invalid="ignore"):
            for up, down in ((at(x1 + h, x2), at(x1 - h, x2)), (at(x1, x2 + h), at(x1, x2 - h))):
                f_up, f_down = func(up), func(down)
                g = (f_up - f_down) / (2 * h)
                if not np.all(np.isfinite(g)):
                    # a domain edge within h of the design (an arcsine's argument reaching 1): the
                    # one-sided difference on the side where the function exists
                    f0 = func(geo)
                    one = np.where(np.isfinite(f_up - f0), (f_up - f0) / h, (f0 - f_down) / h)
                    g = np.where(np.isfinite(g), g, one)
                    g = float(g) if np.ndim(g) == 0 else g
                out.append(g)
        return tuple(out)

    def _margin_values(self, geo, parts: bool = False) -> list:
        if parts:
            return [v for c in self.checks for v in c.part_margins(geo)]
        return [c.margin(geo) for c in self.checks]

    def _margin_gradient_values(self, geo, parts: bool = False) -> list:
        """[(∂m/∂x1, ∂m/∂x2)] per check (or per part): analytic, central differences for
        custom checks."""
        if parts:
            return [g or self._central(lambda gg, c=c, j=j: c.part_margins(gg)[j], geo)
                    for c in self.checks for j, g in enumerate(c.part_gradients(geo))]
        return [c.gradient(geo) or self._central(c.margin, geo) for c in self.checks]

    def _piece_values(self, geo) -> tuple:
        return self.objective.pieces(geo)

    def _piece_gradient_values(self, geo) -> list:
        grads = self.objective.piece_gradients(geo)
        if grads is None:
            n = len(self.objective.pieces(geo))
            grads = [self._central(lambda g, k=k: self.objective.pieces(g)[k], geo) for k in range(n)]
        return grads

    def margins(self, geo) -> np.ndarray:
        """(K, ...) margins; designs whose geometry does not exist get −inf."""
        return np.fmax(_stack(self._margin_values(geo), geo["_x1"]), -np.inf)   # fmax passes the number where one is NaN

    def margin_gradients(self, geo) -> np.ndarray:
        """(K, 2, ...) ∂margin/∂(x1, x2)."""
        return _stack_pairs(self._margin_gradient_values(geo), geo["_x1"])

    def margins_and_gradients(self, geo) -> tuple:
        """(:meth:`margins`, :meth:`margin_gradients`): the gradients asked first, so that a check whose values
        come with them (the strength chain's stencil) is evaluated once."""
        G = self.margin_gradients(geo)
        return self.margins(geo), G

    def pieces(self, geo) -> np.ndarray:
        """(P, ...) pieces whose minimum is the maximised function F = sense·fun."""
        return _stack(self._piece_values(geo), geo["_x1"])

    def piece_gradients(self, geo) -> np.ndarray:
        """(P, 2, ...) gradients of :meth:`pieces`."""
        return _stack_pairs(self._piece_gradient_values(geo), geo["_x1"])

    def part_distances(self, geo) -> np.ndarray:
        """(parts, ...) each smooth part's first-order distance in x to its boundary, part/‖∇part‖
        (−inf where undefined): the pieces ``max_margin`` maximises."""
        M = _stack(self._margin_values(geo, parts=True), geo["_x1"])
        G = _stack_pairs(self._margin_gradient_values(geo, parts=True), geo["_x1"])
        with np.errstate(invalid="ignore", divide="ignore"):
            P = M / np.sqrt(G[:, 0] ** 2 + G[:, 1] ** 2)
        return _defined(P, M)

    def _normalised(self, geo) -> np.ndarray:
        """(K, ...) each check's first-order distance in x to its boundary: the smallest over its
        smooth parts of :meth:`part_distances`, the pieces the single-design path maximises (a check of
        two parts, ρ_p >= ρ_l and ρ_p >= 0, has two boundaries; the margin's active part alone would
        miss the other's)."""
        P = self.part_distances(geo)
        if P.shape[0] == len(self.checks):
            return P
        owner = np.asarray(self.part_check)
        return np.stack([P[owner == i].min(axis=0) for i in range(len(self.checks))])

    def fun(self, geo) -> np.ndarray:
        """The objective in its natural sense (what the user asked to max- or minimise)."""
        if self.objective.kind == "margin":
            return self._normalised(geo).min(axis=0)
        return self.objective.sense * self.pieces(geo).min(axis=0)

    def with_checks(self, checks) -> "Problem":
        """This problem (mesh, objective, x-sum) with ``checks`` in place of its own, one for one: the cheaper
        stand-ins of its costly checks that the solvers walk on (:meth:`light`, :meth:`modelled_at`)."""
        out = copy.copy(self)
        out.checks, out._recent = tuple(checks), None
        out.objective = self.objective.bound(out.checks)
        out.fd_gradients = _fd_gradients(out.objective, out.checks)
        return out

    @property
    def costly_parts(self) -> set:
        """The indices of the margin parts that belong to costly checks (see Check.costly)."""
        return {k for k, i in enumerate(self.part_check) if self.checks[i].costly}

    def light(self) -> "Problem | None":
        """This problem with its costly checks left unevaluated (NaN margins), for the steps of a solver that read
        only the other checks; None when it has none, or when its objective reads them."""
        if not self.costly_parts or self.objective.needs_load or self.objective.kind == "margin":
            return None
        return self.with_checks(_Unevaluated(c.name, n_parts=c.n_parts) if c.costly else c for c in self.checks)

    def relaxed(self) -> "Problem | None":
        """This problem without its costly checks, for a first solve: where its optimum holds them too, it is the
        optimum of this problem (a relaxation's optimum that is feasible is optimal), found without the chain.
        None when there are none, or when the objective reads them."""
        if not self.costly_parts or self.objective.needs_load or self.objective.kind == "margin":
            return None
        out = self.with_checks(c for c in self.checks if not c.costly)
        out.names = [c.name for c in out.checks]
        out.part_check = [i for i, c in enumerate(out.checks) for _ in range(c.n_parts)]
        return out

    def holds_costly(self, v) -> bool:
        """True when every costly check holds (to the feasibility tolerance) at the free-variable point v."""
        x1, x2 = (float(c[0]) for c in self.xy(np.asarray(v, dtype=float)[None, :]))
        _, (_, M, _, _) = self.evaluate_design(x1, x2, grads=False)
        return all(M[i] >= -_checks.FEASIBILITY_TOL for i, c in enumerate(self.checks) if c.costly)

    def reading(self, checks) -> "Problem":
        """This problem, or its :meth:`light` view when none of the checks at the indices ``checks`` is costly:
        for a step that reads those checks alone (a boundary traced or a corner solved)."""
        light = self.light()
        if light is None or any(self.checks[i].costly for i in np.unique(checks)):
            return self
        return light

    def reading_only(self, parts) -> "Problem":
        """This problem with only the checks that own the margin ``parts`` evaluated (the others' margins NaN, as
        :meth:`light` leaves its costly ones): for Newton on one active set, which reads those rows alone (a ring
        pair's cutter checks cost more than the geometry). The view and this problem share the geometry of the
        points they evaluate, so a point reached by the view and checked in full is computed once. Itself when
        the objective reads the checks (``max_margin``, a load) or every check is among them."""
        if self.objective.needs_load or self.objective.kind == "margin":
            return self
        keep = {self.part_check[k] for k in parts if k < len(self.part_check)}
        if len(keep) == len(self.checks):
            return self
        if self._geos is None:
            self._geos = {}
        out = self.with_checks(c if i in keep else _Unread(c.name, n_parts=c.n_parts) for i, c in enumerate(self.checks))
        out._geos = self._geos
        return out

    def modelled_at(self, v) -> "Problem":
        """This problem with its costly checks replaced by their quadratic models around the point v (see
        Check.modelled_at): one evaluation of them, then a problem as cheap as one without them."""
        x1, x2 = float(v[0]), (float(v[1]) if self.x_sum is None else self.x_sum - self.sgn * float(v[0]))
        geo = self._point_geo(x1, x2)   # one geometry: the checks share the chain's evaluation kept in it
        out = self.with_checks(c.modelled_at(geo) for c in self.checks)
        out.anchor = np.array([float(c) for c in v])
        return out

    def subproblem(self, indices) -> "Problem":
        """The same design space with only the checks at ``indices`` (the conflict search)."""
        return Problem(self.mesh, [self.checks[j] for j in indices], "max_x_sum", self.m, self.x_sum, meshing=False)

    @property
    def title(self) -> str:
        """What the plots and reprs call this problem: "z1/z2 = 17/26 (internal)"."""
        return f"z1/z2 = {self.z1}/{self.z2}{self.mesh.kind_text}"

    axis_labels = ("x1 (profile shift, gear 1)", "x2 (profile shift, gear 2)")

    # --- the design variables -----------------------------------------------------------
    @property
    def nvar(self) -> int:
        """Free variables: (x1, x2), or x1 alone when the x-sum is fixed."""
        return 2 if self.x_sum is None else 1

    def xy(self, V):
        """(x1, x2) arrays from free-variable points V of shape (n, nvar)."""
        V = np.atleast_2d(np.asarray(V, dtype=float))
        if self.x_sum is None:
            return V[:, 0], V[:, 1]
        return V[:, 0], self.x_sum - self.sgn * V[:, 0]

    def x1_on_line(self, lo: float, hi: float) -> tuple[float, float]:
        """The x1 interval where the fixed-x_Σ line stays inside the window [lo, hi]²."""
        if self.sgn > 0:
            return max(lo, self.x_sum - hi), min(hi, self.x_sum - lo)
        return max(lo, lo - self.x_sum), min(hi, hi - self.x_sum)

    def evaluate(self, V, grads: bool = True):
        """Pieces (P, n) and margins (K, n) at points V (n, nvar), and with ``grads`` their
        gradients in the free variables, (P, nvar, n) and (K, nvar, n).

        Every objective is "maximise the smallest piece subject to margins >= 0": one piece for
        smooth objectives, two for balanced sliding, and the normalised margins for max_margin.
        """
        x1, x2 = self.xy(V)
        if not grads:   # block by block: only P and M are stored for all points (grids reach millions)
            out = self.geo_then(x1, x2, lambda geo: {
                "M": self.margins(geo),
                "P": self._normalised(geo) if self.objective.kind == "margin" else self.pieces(geo)})
            return out["P"], out["M"]
        geo = self.geo(x1, x2)
        M, GM = self.margins_and_gradients(geo)
        P = self._normalised(geo) if self.objective.kind == "margin" else self.pieces(geo)
        if self.objective.kind == "margin":
            GP = np.stack(self._central(self._normalised, geo), axis=1)
        else:
            GP = self.piece_gradients(geo)
        return P, M, self._free(GP), self._free(GM)

    def evaluate_point(self, v):
        """:meth:`evaluate` at one point v (nvar,) on the float path, for the local solvers:
        P (P,), M (parts,), GP (P, nvar), GM (parts, nvar). The margins come as the checks'
        smooth parts (:attr:`part_check` maps each to its check)."""
        x1, x2 = float(v[0]), (float(v[1]) if self.x_sum is None else self.x_sum - self.sgn * float(v[0]))
        key = (x1, x2, self.x_sum)   # the free variables' gradients depend on x_sum too
        if self._recent is None:
            self._recent = {}
        if key in self._recent:   # a start checked, then solved from
            return self._recent[key][0]
        geo, (P, M, GP, GM) = self.evaluate_design(x1, x2, parts=True)
        out = P, M, self._free(GP), self._free(GM)
        if len(self._recent) >= self._RECENT:
            self._recent.pop(next(iter(self._recent)))
        self._recent[key] = (out, geo)
        if self._geos is not None:
            if len(self._geos) >= self._RECENT:
                self._geos.pop(next(iter(self._geos)))
            self._geos[key] = geo
        return out

    def evaluate_design(self, x1: float, x2: float, parts: bool = False, grads: bool = True):
        """(geo, (P, M, GP, GM)) of one design on the float path; where Python floats fault (a
        division by zero exactly at a boundary, an overflow), the same formulas on 0-d numpy
        arrays, which give inf/NaN as the vectorised path does. The geometry of a point
        :meth:`evaluate_point` saw lately (a solver's final iterate, usually) is reused. Without
        ``grads`` GP and GM are None (unless the objective is made of normalised margins)."""
        key = (x1, x2, self.x_sum)
        seen = (self._recent or {}).get(key)
        geo = seen[1] if seen is not None else (self._geos or {}).get(key)
        try:
            geo = geo if geo is not None else mesh_geometry_float(self.mesh, self.m, x1, x2, self.full)
            return geo, self.evaluate_geo(geo, parts, grads)
        except _FLOAT_FAULTS:
            geo = self._array_geo(x1, x2)
            return geo, self.evaluate_geo(geo, parts, grads)

    def _point_geo(self, x1: float, x2: float) -> dict:
        """The geometry of one design: Python floats, or 0-d arrays where the floats fault."""
        try:
            return mesh_geometry_float(self.mesh, self.m, x1, x2, self.full)
        except _FLOAT_FAULTS:
            return self._array_geo(x1, x2)

    def _array_geo(self, x1: float, x2: float) -> dict:
        with np.errstate(all="ignore"):
            return self.geo(np.float64(x1), np.float64(x2))

    def evaluate_geo(self, geo, parts: bool = False, grads: bool = True):
        """P, M, GP, GM with gradients in (x1, x2) for one design given as a float geometry dict
        (margins per check, or per smooth part with ``parts``); a margin that does not exist is −inf."""
        # 0-d arrays (where floats faulted): boundaries of existence give inf/NaN quietly
        with contextlib.nullcontext() if type(geo["_x1"]) is float else np.errstate(all="ignore"):
            if not grads and self.objective.kind != "margin":
                return np.array(self._piece_values(geo), dtype=float), self._margins_only(geo, parts), None, None
            M, GM = self._margins_and_gradients(geo, parts)
            if self.objective.kind == "margin":
                P = _normalise(M, GM)
                GP = np.array(self._central(lambda g: _normalise(*self._margins_and_gradients(g, parts)), geo)).T
            else:
                P = np.array(self._piece_values(geo), dtype=float)
                GP = np.array(self._piece_gradient_values(geo), dtype=float).reshape(-1, 2)
        return P, M, GP, GM

    def _margins_only(self, g, parts: bool) -> np.ndarray:
        M = self._margin_values(g, parts)
        if any(v != v for v in M):   # NaN: the margin does not exist here
            M = [v if v == v else -np.inf for v in M]
        return np.array(M, dtype=float)

    def _margins_and_gradients(self, g, parts: bool):
        return self._margins_only(g, parts), \
            np.array(self._margin_gradient_values(g, parts), dtype=float).reshape(-1, 2)

    def _free(self, G):
        """Gradients in (x1, x2) → in the free variables (d/dx1 along x2 = x_sum − sgn·x1)."""
        return G if self.x_sum is None else (G[:, 0] - self.sgn * G[:, 1])[:, None]


def _fd_gradients(objective, checks) -> bool:
    """True when a gradient the solvers read is a central difference (~1e-10 noise, its derivatives more)."""
    return (objective.kind == "margin" or type(objective).piece_gradients is Objective.piece_gradients
            or any(getattr(c, "fd_gradient", False) for c in checks))


@dataclass(frozen=True)
class _Unevaluated(_checks.Check):
    """A costly check not evaluated (NaN margins, a failing margin wherever read): :meth:`Problem.light`."""

    n_parts: int = 1

    def value(self, geo):
        return math.nan

    def gradient(self, geo):
        return math.nan, math.nan

    def part_margins(self, geo) -> list:
        return [math.nan] * self.n_parts

    def part_gradients(self, geo) -> list:
        return [(math.nan, math.nan)] * self.n_parts


@dataclass(frozen=True)
class _Unread(_Unevaluated):
    """A check a view of :meth:`Problem.reading_only` does not evaluate: margins 0 and gradients 0 (finite, so the
    evaluator keeps the rows it reads as they are; NaN would make it replace every non-finite value)."""

    def value(self, geo):
        return 0.0

    def gradient(self, geo):
        return 0.0, 0.0

    def part_margins(self, geo) -> list:
        return [0.0] * self.n_parts

    def part_gradients(self, geo) -> list:
        return [(0.0, 0.0)] * self.n_parts


def _stack(values, like) -> np.ndarray:
    """(len(values), *shape of like) floats; numbers and arrays alike broadcast into place."""
    out = np.empty((len(values),) + np.shape(like))
    for i, v in enumerate(values):
        out[i] = v
    return out


def _stack_pairs(pairs, like) -> np.ndarray:
    """(len(pairs), 2, *shape of like): each check's (∂/∂x1, ∂/∂x2)."""
    out = np.empty((len(pairs), 2) + np.shape(like))
    for i, (g1, g2) in enumerate(pairs):
        out[i, 0] = g1
        out[i, 1] = g2
    return out


def _normalise(M, G) -> np.ndarray:
    """margin/‖∇margin‖ for (K,) margins and (K, 2) gradients of one design; −inf where undefined."""
    with np.errstate(invalid="ignore", divide="ignore"):
        P = M / np.hypot(G[:, 0], G[:, 1])
    return _defined(P, M)


# the distance of a check that holds and does not move at all (a flat margin: a damage sum that is 0 wherever the
# stresses stay below the S-N curve's end): no boundary near, as far as any window reaches
FLAT_DISTANCE = 1e3


def _defined(P, M) -> np.ndarray:
    """The distances P = M/‖∇M‖ where finite; FLAT_DISTANCE where a holding margin has no gradient (M > 0 over 0);
    −inf where undefined (a failing or undefined margin)."""
    return np.where(np.isfinite(P), P, np.where(np.isinf(P) & (M > 0), FLAT_DISTANCE, -np.inf))


# The x window searched: [−1.5, 3] covers every shift used in practice (handbook blocking
# contours span about −1 … 2.5); with the default checks the tip thickness closes the region
# from above and undercut from below, well inside it.
DEFAULT_BOUNDS = (-1.5, 3.0)
# No window reaches past ±10: shifts beyond a few units make no gear (the tip or root circle
# crosses the base circle long before), and the geometry refuses them by name.
X_WINDOW_LIMIT = X_ABS_MAX


def validate_bounds(bounds) -> tuple[float, float]:
    """The search window (lo, hi) for each of x1, x2: two numbers within ±X_WINDOW_LIMIT, lo < hi."""
    try:
        lo, hi = bounds
    except (TypeError, ValueError):
        raise GearDesignError(f"bounds must be (lo, hi), got {bounds!r}") from None
    lo = one_number("bounds lo", require_range("bounds lo", lo, -X_WINDOW_LIMIT, X_WINDOW_LIMIT))
    hi = one_number("bounds hi", require_range("bounds hi", hi, -X_WINDOW_LIMIT, X_WINDOW_LIMIT))
    if not lo < hi:
        raise GearDesignError(f"bounds must be (lo, hi) with lo < hi, got {bounds!r}")
    return lo, hi

