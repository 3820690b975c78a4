"""The shifts that make a planetary set fit: (x_sun, x_planet) free, x_ring from coaxiality.

A set's problem is a :class:`~geardesign.shifts.problem.Problem` whose design is the sun–planet
mesh's (x1 = x_sun, x2 = x_planet, so a fixed a_w fixes x_sun + x_planet as for a pair) and whose
geometry is both meshes' (:func:`geardesign.gears.planetary.set_geometry`): the ring's shift
follows from the coaxiality condition as an equality, the checks of both meshes and the set's
``neighbours`` are constraints, and the three methods, the conflict search, sensitivities and the
region run on it unchanged.

Objectives over both meshes: ``max_eps_alpha`` maximises the smaller ε_α, ``balanced_sliding``
balances the largest root sliding of all four roots, ``min_specific_pressure`` the larger pitch
point coefficient, ``max_margin`` the distance to every check of both meshes; ``max_x_sum``
maximises x_sun + x_planet (x_r − x_p grows with it: the largest common a_w); with a load,
``balanced_root_strength`` and ``max_min_safety`` read the strength checks of both meshes, each
mesh with its own load case (the smallest S/S_min of the four roots, or of every flank and root).
"""
from __future__ import annotations

import copy
import math
import time
from dataclasses import dataclass, field

import numpy as np

from ..errors import GearDesignError
from ..gears.geometry import A_W_RANGE_MM, min_center_distance, require_module
from ..gears.planet_damage import PlanetDamage
from ..gears.planetary import (ARRANGEMENTS, MESH_NAMES, Assembly, MeshCheck, PlanetaryMeshes, planetary_ratio,
                               set_checks, set_geometry)
from ..inline import html_view
from ..results import Result
from ..validate import one_number, require_choice, require_count, require_range
from .center_distance import x_sum_for_housing
from .grid import GRID_N_MAX
from .objectives import (CustomObjective, Objective, default_objective, life_piece, life_piece_gradient,
                         unlimited_life_note)
from .optimize import DEFAULT_TOL, METHODS, solve_problem
from .problem import _FLOAT_FAULTS, DEFAULT_BOUNDS, Problem, _holds_meshing, validate_bounds, with_meshing
from .looks import margin_bars
from .region import REGION_N_MAX, Region, region_of
from .result import conflict_text
from .methods import ACCURACY

__all__ = ["optimize_planetary_shifts", "planetary_region", "PlanetaryShiftResult", "PlanetaryProblem"]


class _SetObjective(Objective):
    """An objective of a pair applied over both meshes of a set: the pieces of both (the smallest
    rules), their gradients carried to (x_s, x_p); ``max_x_sum`` reads the sun–planet mesh only;
    a :class:`CustomObjective` gets the set's geometry dict."""

    def __init__(self, inner: Objective):
        self.inner = inner
        for name in ("name", "sense", "kind", "description", "x_sum_only", "needs_report_fields", "needs_load"):
            setattr(self, name, getattr(inner, name))
        self.meshes = MESH_NAMES[:1] if inner.name == "max_x_sum" else MESH_NAMES
        self.of_mesh = {tag: inner for tag in self.meshes}
        self.planet = ()     # max_life under a reversing spectrum: the planet's damage, summed over both meshes
        if isinstance(inner, CustomObjective) or type(inner).piece_gradients is Objective.piece_gradients:
            self.piece_gradients = lambda geo: None   # central differences in the set's shifts

    def bound(self, checks):
        """An objective that reads a load case (the strength objectives) bound to each mesh's own strength
        checks: each mesh carries its own load (the torque shared over the planets, relative speeds)."""
        if not self.needs_load:
            return self
        out = copy.copy(self)
        out.of_mesh = {tag: self.inner.bound([c.inner for c in checks if isinstance(c, MeshCheck) and c.mesh == tag])
                       for tag in self.meshes}
        if self.inner.name == "max_life":
            out.planet = tuple(c for c in checks if isinstance(c, PlanetDamage))
        return out

    def pieces(self, geo):
        if isinstance(self.inner, CustomObjective):
            return self.inner.pieces(geo)
        # the planet's flanks as max_life reads a pair's damage: −ln D of each
        planet = tuple(life_piece(D) for c in self.planet for D in c.flank_damage(geo))
        return tuple(p for tag in self.meshes for p in self.of_mesh[tag].pieces(geo[tag])) + planet

    def piece_gradients(self, geo):
        out = []
        for tag in self.meshes:
            for g1, g2 in self.of_mesh[tag].piece_gradients(geo[tag]):
                out.append((g1, g2) if tag == "sun-planet" else (g2 * geo["_r"], g1 + g2 * (1.0 + geo["_r"])))
        for c in self.planet:
            out += [life_piece_gradient(D, grad) for D, grad in zip(c.flank_damage(geo), c.flank_damage_gradients(geo))]
        return out


class PlanetaryProblem(Problem):
    """The shift problem of a planetary set (see the module docstring)."""

    def __init__(self, meshes: PlanetaryMeshes, m, checks=None, objective="max_x_sum", x_sum=None,
                 check_list=None, cutter=None, arrangement="ring_fixed"):
        self.meshes = meshes
        self.mesh = meshes.sun_planet
        self.m = float(m)
        self.checks = (set_checks(meshes, checks, cutter, arrangement) if check_list is None
                       else tuple(check_list))
        self.asked = self.checks
        if check_list is None:   # both meshes must mesh, whatever checks are dropped (see with_meshing)
            for tag in MESH_NAMES:
                self.checks = with_meshing(
                    self.checks, wrap=lambda c, tag=tag: MeshCheck(inner=c, mesh=tag),
                    holds=lambda c, tag=tag: isinstance(c, MeshCheck) and c.mesh == tag and _holds_meshing(c.inner))
        self.sgn = 1
        objective = objective if isinstance(objective, _SetObjective) else _SetObjective(
            default_objective(objective, x_sum_fixed=False))
        self.objective = objective.bound(self.checks)
        self.full = objective.needs_report_fields or any(c.needs_report_fields for c in self.checks)
        self.x_sum = None if x_sum is None else float(x_sum)
        self.names = [c.name for c in self.checks]
        self.part_check = [i for i, c in enumerate(self.checks) for _ in range(c.n_parts)]
        inner = objective.inner
        self.fd_gradients = (objective.kind == "margin" or isinstance(inner, CustomObjective)
                             or type(inner).piece_gradients is Objective.piece_gradients
                             or any(getattr(getattr(c, "inner", c), "fd_gradient", False) for c in self.checks))

    axis_labels = ("x_sun (profile shift of the sun)", "x_planet (x_ring follows from coaxiality)")

    @property
    def title(self) -> str:
        return self.meshes.title

    def geo(self, x1, x2) -> dict:
        return set_geometry(self.meshes, self.m, x1, x2, full=self.full)

    def geo_then(self, x1, x2, then) -> dict:
        # both meshes' geometry at once: a set's grids are small enough (the start grid, a region)
        return then(self.geo(x1, x2))

    def _geo_like(self, geo):
        return lambda x1, x2: set_geometry(self.meshes, geo["_m"], x1, x2, full=self.full)

    def _point_geo(self, x1: float, x2: float) -> dict:
        try:
            return set_geometry(self.meshes, self.m, float(x1), float(x2), full=self.full)
        except _FLOAT_FAULTS:
            with np.errstate(all="ignore"):
                return self.geo(np.float64(x1), np.float64(x2))

    def evaluate_design(self, x1: float, x2: float, parts: bool = False, grads: bool = True):
        try:
            geo = set_geometry(self.meshes, self.m, float(x1), float(x2), full=self.full)
            return geo, self.evaluate_geo(geo, parts, grads)
        except _FLOAT_FAULTS:
            with np.errstate(all="ignore"):
                geo = self.geo(np.float64(x1), np.float64(x2))
            return geo, self.evaluate_geo(geo, parts, grads)

    def subproblem(self, indices) -> "PlanetaryProblem":
        # the conflict search maximises the subset's margins: its objective is immaterial, and one that reads a
        # load (the strength or damage checks) may find none of its checks in the subset (as Problem.subproblem)
        return PlanetaryProblem(self.meshes, self.m, objective="max_x_sum", x_sum=self.x_sum,
                                check_list=[self.checks[j] for j in indices])


def _smallest(margins: dict, shown: int = 6) -> str:
    """The ``shown`` smallest margins, smallest first (a set has two meshes' checks: ~20), and how many more."""
    items = sorted(margins.items(), key=lambda kv: kv[1])
    text = ", ".join(f"{k} {v:+.4g}" for k, v in items[:shown])
    return text + (f" (+{len(items) - shown} larger; .to_frame() has all)" if len(items) > shown else "")


@dataclass
class PlanetaryShiftResult(Result):
    """The optimum of :func:`optimize_planetary_shifts`: the three shifts, the common centre
    distance, both meshes' margins (check names say the mesh), active checks, sensitivities
    d fun/d limit, and, when infeasible, the conflicting checks with their meshes."""

    x_sun: float
    x_planet: float
    x_ring: float
    fun: float
    objective: str
    success: bool
    message: str
    method: str
    tol: float
    nit: int
    time_s: float
    a_w: float
    a_w_planet_ring: float
    eps_alpha_sun_planet: float
    eps_alpha_planet_ring: float
    ratio: float
    arrangement: str
    z_sun: int
    z_planet: int
    z_ring: int
    n_planets: int
    m: float
    beta_deg: float = 0.0
    margins: dict = field(default_factory=dict)
    active: list = field(default_factory=list)
    sensitivity: dict = field(default_factory=dict)
    sensitivity_sides: dict = field(default_factory=dict)
    conflict: list = field(default_factory=list)
    a_w_fixed: float | None = None
    accuracy: str = ""

    def to_frame(self):
        """One row per check: mesh, margin, active, sensitivity."""
        import pandas as pd

        names = list(self.margins)
        return pd.DataFrame({"check": names, "mesh": [n.split(":", 1)[0] for n in names],
                             "margin": list(self.margins.values()), "active": [n in self.active for n in names],
                             "sensitivity": [self.sensitivity.get(n, 0.0) for n in names]})

    def _repr_html_(self) -> str:
        """Jupyter's view: the text, and both meshes' margins at the optimum as bars."""
        return html_view(repr(self), self.plot_margins, tables=(("margins", self.to_frame()),), dpi=60,
                         figsize=(7.0, 1.3 + 0.3 * len(self.margins)),
                         alt="margins at the optimum")

    def plot_margins(self, ax=None):
        """Bars of every check's margin at the optimum, both meshes and the set (active outlined)."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(7.0, 1.3 + 0.3 * len(self.margins)))
        return margin_bars(ax, self.margins, self.active,
                           f"z_s/z_p/z_r = {self.z_sun}/{self.z_planet}/{self.z_ring}, m = {self.m:g} mm: x_s/x_p/x_r "
                           f"= {self.x_sun:.3f}/{self.x_planet:.3f}/{self.x_ring:.3f} ({self.objective}"
                           f"{'' if self.success else ', FAILED'})")

    def __repr__(self) -> str:
        lines = [
            f"     message: {self.message}",
            f"     success: {self.success}",
            f"         set: z_s/z_p/z_r = {self.z_sun}/{self.z_planet}/{self.z_ring}, {self.n_planets} planets, "
            f"m = {self.m:g} mm" + (f", beta {self.beta_deg:g} deg" if self.beta_deg else "")
            + f", ratio {self.ratio:.6g} ({self.arrangement})",
            f"  x_s/x_p/x_r: {self.x_sun:.10g}, {self.x_planet:.10g}, {self.x_ring:.10g}",
            f"         fun: {self.fun:.10g}  ({self.objective})",
            f"         a_w: {self.a_w:.10g} mm (planet-ring {self.a_w_planet_ring:.10g} mm)"
            + (f", fixed at {self.a_w_fixed:.10g} mm" if self.a_w_fixed is not None else ""),
            f"   eps_alpha: sun-planet {self.eps_alpha_sun_planet:.6g}, planet-ring {self.eps_alpha_planet_ring:.6g}",
            f"      active: {', '.join(self.active) if self.active else '-'}",
            " sensitivity: " + (", ".join(f"{k} {v:+.4g}" for k, v in self.sensitivity.items()) or "-"),
            "     margins: " + _smallest(self.margins),
            f"      method: {self.method}, tol {self.tol:g}, nit {self.nit}, {self.time_s * 1e3:.2f} ms",
        ]
        if self.conflict:
            lines.insert(2, "    conflict: " + conflict_text(self.conflict, self.margins))
        return "\n".join(lines)


def _problem(z_sun, z_planet, z_ring, n_planets, m, objective, checks, rack, beta_deg, planet_angles_deg, a_w,
             bounds, cutter=None, arrangement="ring_fixed") -> PlanetaryProblem:
    """Validated inputs as a problem; a fixed ``a_w`` fixes x_s + x_p (one free shift)."""
    m = one_number("m (module)", require_module(m))
    meshes = PlanetaryMeshes(z_sun, z_planet, z_ring, n_planets, rack, beta_deg,
                             planet_angles_deg)
    prob = PlanetaryProblem(meshes, m, checks, default_objective(objective, x_sum_fixed=a_w is not None),
                            cutter=cutter, arrangement=arrangement)
    if a_w is not None:
        prob.x_sum = x_sum_for_housing(prob, a_w, bounds)
        a_min = float(min_center_distance(m, meshes.z_planet, meshes.z_ring, meshes.rack, meshes.beta_deg,
                                          internal=True))
        if not a_w > a_min:
            raise GearDesignError(f"a_w (center distance) = {a_w:.10g} mm is out of reach of the planet-ring mesh: "
                                  f"it must be > {a_min:.8g} mm (z_r - z_p = {meshes.z_ring - meshes.z_planet}, "
                                  f"m = {m:g} mm)")
    return prob


def optimize_planetary_shifts(z_sun, z_planet, z_ring, n_planets, m, a_w=None, objective=None, checks=None,
                              method: str = "exact", tol: float | None = None, rack=None, beta_deg: float = 0.0,
                              bounds=DEFAULT_BOUNDS, grid_n: int | None = None, arrangement: str = "ring_fixed",
                              planet_angles_deg=None, cutter=None) -> PlanetaryShiftResult:
    """The best shifts of a planetary set's three gears, both meshes coaxial.

    Parameters
    ----------
    z_sun, z_planet, z_ring : tooth counts (the ring's positive).  n_planets : 1..64.
    m : module, mm (the ring's checks depend on it through the default shaper cutter).
    a_w : a fixed carrier arm (common centre distance), mm: x_s + x_p is then fixed and the
        objective picks the split (default ``balanced_sliding``).
    objective : as :func:`~geardesign.shifts.optimize.optimize_shifts`, over both meshes (see
        the module docstring); default ``max_x_sum`` (``balanced_sliding`` with ``a_w``).
    checks : None or a dict of :func:`~geardesign.gears.checks.make_checks` options for both
        meshes plus ``neighbour_clearance`` (modules; default 0.5).
    method, tol, bounds, grid_n : as :func:`~geardesign.shifts.optimize.optimize_shifts`; the
        window bounds x_sun and x_planet.
    arrangement : which member is fixed, for the ratio (see
        :data:`~geardesign.gears.planetary.ARRANGEMENTS`).  planet_angles_deg : unequal spacing.
    cutter : the ring's :class:`~geardesign.gears.ring.ShaperCutter` (None: the standard one).

    >>> r = optimize_planetary_shifts(21, 43, 108, 3, 1.75, objective="max_eps_alpha")   # LECAD's teeth
    >>> round(r.x_sun, 4), round(r.x_planet, 4), round(r.x_ring, 4), abs(r.a_w - r.a_w_planet_ring) < 1e-9
    (-0.2283, 0.8262, 0.8894, True)
    >>> optimize_planetary_shifts(21, 43, 108, 3, 1.75, a_w=56.8).conflict     # at LECAD's printed a = 56.8 mm
    ['sun-planet:undercut_sun', 'planet-ring:interference_planet']
    """
    t0 = time.perf_counter()
    method = require_choice("method", method, METHODS)
    require_choice("arrangement", arrangement, tuple(ARRANGEMENTS))
    if a_w is not None:
        a_w = one_number("a_w (center distance)", require_range("a_w (center distance)", a_w, *A_W_RANGE_MM,
                                                                lo_open=True, unit="mm"))
    tol = DEFAULT_TOL[method] if tol is None else one_number("tol", require_range("tol", tol, 1e-14, 1.0))
    bounds = validate_bounds(bounds)
    if grid_n is not None:
        grid_n = require_count("grid_n", grid_n, 2, GRID_N_MAX)
    prob = _problem(z_sun, z_planet, z_ring, n_planets, m, objective, checks, rack, beta_deg, planet_angles_deg,
                    a_w, bounds, cutter, arrangement)
    if prob.objective.kind == "margin" and not prob.asked:
        raise GearDesignError("objective 'max_margin' needs at least one check, got none")
    out = solve_problem(prob, method, bounds, tol, grid_n)
    return _result(prob, out, method, out.tol or tol, a_w, arrangement, t0)


def _result(prob: PlanetaryProblem, out, method, tol, a_w, arrangement, t0) -> PlanetaryShiftResult:
    ms = prob.meshes
    x_s, x_p = (float(c[0]) for c in prob.xy(np.asarray(out.v)[None, :]))
    geo, (P, M, _, _) = prob.evaluate_design(x_s, x_p, grads=False)
    zero = tol if method != "grid" else 1e-12
    margins = {name: (0.0 if abs(v) <= zero else float(v)) for name, v in zip(prob.names, M)}
    fun = float(prob.objective.sense * P.min()) if prob.objective.kind != "margin" else float(P.min())
    x_r = float(geo["x_ring"])
    if not all(map(math.isfinite, [fun, x_r, float(geo["a_w"]), float(geo["a_w_pr"]), *margins.values()])):
        raise GearDesignError(f"no finite result for {ms.title} ({prob.objective.name}, {method}): a mesh's geometry "
                              f"is undefined at the point the solver reached ({x_s:.6g}, {x_p:.6g}); check the window")
    success, message, conflict = out.success, out.message, list(out.conflict)
    assembly = Assembly(meshes=ms)
    if assembly.margin(geo) < 0:   # no shift changes the tooth counts: the set fails whatever they are
        q = assembly.value(geo)
        success = False
        conflict = ["set:assembly"] + conflict
        message = (f"the planets cannot be assembled: {assembly.label.split(': ', 1)[1]} fails "
                   f"({q:.6g}); the shifts below are the best for the meshes alone")
    if prob.x_sum is not None:
        message += f"; x_sun + x_planet = {prob.x_sum:.10g} fixed by a_w = {a_w:.10g} mm, objective {prob.objective.name}"
    message += unlimited_life_note(prob.objective.name, fun)
    active = [k for k, v in margins.items() if abs(v) <= max(tol, 1e-9) * 10]
    return PlanetaryShiftResult(
        x_sun=x_s, x_planet=x_p, x_ring=x_r, fun=fun, objective=prob.objective.name, success=success,
        message=message, method=method, tol=tol, nit=out.nit, time_s=time.perf_counter() - t0,
        a_w=float(geo["a_w"]), a_w_planet_ring=float(geo["a_w_pr"]),
        eps_alpha_sun_planet=float(geo["sun-planet"]["eps_alpha"]),
        eps_alpha_planet_ring=float(geo["planet-ring"]["eps_alpha"]),
        ratio=planetary_ratio(ms.z_sun, ms.z_ring, arrangement), arrangement=arrangement, z_sun=ms.z_sun,
        z_planet=ms.z_planet, z_ring=ms.z_ring, n_planets=ms.n_planets, m=prob.m, beta_deg=ms.beta_deg,
        margins=margins, active=active, sensitivity=out.sensitivity, sensitivity_sides=out.sides,
        conflict=conflict, a_w_fixed=a_w, accuracy=out.accuracy or ACCURACY[method].format(tol=tol))


def planetary_region(z_sun, z_planet, z_ring, n_planets, m, checks=None, method: str = "exact",
                     tol: float | None = None, rack=None, beta_deg: float = 0.0, bounds=DEFAULT_BOUNDS,
                     n: int | None = None, cutter=None, arrangement: str = "ring_fixed") -> Region:
    """The region of (x_sun, x_planet) where every check of both meshes and ``neighbours`` holds,
    x_ring following from coaxiality; its boundary labelled with each check and its mesh. Like
    :func:`~geardesign.shifts.region.feasible_region` (``.plot()`` draws it, sun–planet checks
    solid, planet–ring dashed, the set's dotted).

    >>> reg = planetary_region(21, 43, 108, 3, 1.75)
    >>> reg.feasible
    True
    """
    if method not in ("grid", "exact"):
        raise GearDesignError(f"method must be 'grid' or 'exact' for a region, got {method!r}")
    tol = (0.01 if method == "grid" else 1e-9) if tol is None else one_number("tol", require_range("tol", tol, 1e-14, 1.0))
    lo, hi = validate_bounds(bounds)
    n = 321 if n is None else require_count("n", n, 11, REGION_N_MAX)
    require_choice("arrangement", arrangement, tuple(ARRANGEMENTS))
    prob = _problem(z_sun, z_planet, z_ring, n_planets, m, "max_x_sum", checks, rack, beta_deg, None, None,
                    (lo, hi), cutter, arrangement)
    return region_of(prob, method, tol, (lo, hi), n)
