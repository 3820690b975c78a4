"""The feasible region of profile shifts (the blocking contour, блокирующий контур).

For tooth counts z1, z2 the region is every (x1, x2) where all chosen checks hold. Its
boundary is traced as the zero contour of the smallest margin on a grid (contourpy), each
vertex is labelled with the check that is smallest there, and with ``method="exact"`` every
vertex is moved onto its check's curve by Newton steps and the corners where the limiting
check changes are solved as the intersection of the two curves.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from ..errors import GearDesignError
from ..results import Result, plain
from ..gears.mesh import Mesh, mesh_of
from ..validate import one_number, require_axes, require_count, require_range
from ..gears.geometry import center_distance_from_x_sum
from ..inline import html_view
from .problem import DEFAULT_BOUNDS, Problem, validate_bounds
from .conflict import smallest_conflict
from .contour_html import write_contour_html
from .local import central_point
from .nodes import grid_points
from .looks import CHECK_LEGENDS, _parts, check_legend, check_style  # noqa: F401  (re-exported)

__all__ = ["feasible_region", "Region", "CHECK_LEGENDS", "check_style", "check_legend"]   # the looks re-exported

WINDOW = "window"


@dataclass
class Region(Result):
    """Feasible (x1, x2) region of one tooth pair.

    ``boundary`` is a DataFrame ``component, x1, x2, check``: ordered polygon vertices
    (counter-clockwise), ``check`` naming the check that limits the edge from that vertex to
    the next (``"window"`` where the region is cut by the search window). ``conflict`` names a
    smallest set of checks that cannot hold together when the region is empty.
    """

    z1: int
    z2: int
    boundary: pd.DataFrame
    area: float
    feasible: bool
    conflict: list
    method: str
    tol: float
    bounds: tuple
    problem: Problem = field(repr=False)
    area_error: float = 0.0

    _success_field = "feasible"
    _table_fields = ("boundary",)

    def to_dict(self) -> dict:
        out = {k: plain(getattr(self, k)) for k in ("z1", "z2", "feasible", "area", "area_error", "conflict",
                                                     "method", "tol", "bounds", "boundary")}
        out.update(checks=self.checks, limiting_checks=self.limiting_checks(), status=self.status)
        return out

    @property
    def checks(self) -> list[str]:
        return list(self.problem.names)

    def contains(self, x1, x2):
        """True where every check holds (exact margins, vectorised)."""
        x1, x2 = np.broadcast_arrays(np.asarray(x1, dtype=float), np.asarray(x2, dtype=float))
        M = self.problem.margins(self.problem.geo(x1, x2))
        out = (M >= 0).all(axis=0) if M.size else np.ones(x1.shape, bool)
        return bool(out) if out.ndim == 0 else out

    def limiting_checks(self) -> list[str]:
        """The checks that form part of the boundary, in order of appearance."""
        seen = []
        for c in self.boundary["check"]:
            if c not in seen:
                seen.append(c)
        return seen

    def __repr__(self) -> str:
        if not self.feasible:
            why = (f"checks {', '.join(self.conflict)} conflict" if self.conflict
                   else "every check holds somewhere in the window, but not all together")
            return f"Region({self.problem.title}: empty; {why})"
        return (f"Region({self.problem.title}, area {self.area:.6g} ± {self.area_error:.1g}, "
                f"{len(self.boundary)} vertices, "
                f"limited by {', '.join(self.limiting_checks())}; method {self.method}, tol {self.tol:g})")

    def plot(self, ax=None, isolines=("eps_alpha", "sa"), optimum=None, proposed=None, x_sum=None,
             n: int = 241):
        """Draw the blocking contour as a handbook does: every check's curve in its own fixed
        colour (the check registry's, :func:`geardesign.gears.checks.check_colour`; solid for gear 1, dashed for gear 2) with ticks on its
        forbidden side, the feasible region shaded, thin grey isolines of ε_α and s_a/m (levels
        that coincide with a check's limit are left to the check's curve).

        ``optimum``: a :class:`~geardesign.shifts.optimize.ShiftResult` or (x1, x2), marked with a star;
        ``proposed``: (x1, x2) of a proposed pair, marked with a cross; ``x_sum``: the line
        x1 + x2 = x_sum of a fixed centre distance, its feasible part drawn thick. An empty
        region says so in the axes, with the checks that conflict. Returns the matplotlib Axes.
        """
        import matplotlib.pyplot as plt

        n = require_count("n", n, 11, PLOT_N_MAX)
        if ax is None:
            _, ax = plt.subplots(figsize=(8.6, 6.2))
        require_axes("ax", ax)
        lo, hi = self.bounds
        g = np.linspace(lo, hi, n)
        X1, X2 = np.meshgrid(g, g, indexing="ij")
        with np.errstate(all="ignore"):
            geo = self.problem.geo(X1, X2)
            M = self.problem.margins(geo)
        handles = self._plot_checks(ax, X1, X2, M)
        if isolines:
            _isolines(ax, X1, X2, geo, isolines, self.problem.checks)
        handles += self._plot_region(ax)
        if x_sum is not None:
            handles += self._plot_x_sum(ax, float(x_sum))
        handles += self._plot_marks(ax, optimum, proposed)
        self._frame(ax, handles)
        return ax

    def _plot_checks(self, ax, X1, X2, M) -> list:
        """Every check's zero curve in its colour and style, ticked on its forbidden side; legend handles."""
        import matplotlib.pyplot as plt
        from matplotlib import patheffects

        handles = []
        for k, c in enumerate(self.problem.checks):
            # no geometry is no curve: masked, so a curve ends where the pair stops existing
            # instead of a staircase along the edge of existence
            mk = np.ma.masked_invalid(np.where(np.isfinite(M[k]), M[k], np.nan))
            if mk.count() == 0 or not (mk.min() < 0 < mk.max()):
                continue
            colour, style = check_style(c.name)
            cs = ax.contour(X1, X2, mk, levels=[0.0], colors=[colour], linewidths=1.6, linestyles=style)
            # ticks on the side where the margin is negative (contour lines keep higher values
            # on their left, the ticks go right)
            cs.set(path_effects=[patheffects.withTickedStroke(angle=-60, spacing=7, length=0.6)])
            handles.append(plt.Line2D([], [], color=colour, ls=style, lw=1.6, label=check_legend(c)))
        return handles

    def _plot_region(self, ax) -> list:
        """The feasible region shaded, or the conflict said in the axes; legend handles."""
        import matplotlib.pyplot as plt

        if not self.feasible:
            why = (f"checks {', '.join(self.conflict)} conflict" if self.conflict
                   else "no point holds every check")
            ax.text(0.5, 0.5, f"no feasible x1, x2:\n{why}", transform=ax.transAxes, ha="center", va="center",
                    fontsize=12, color="darkred", bbox=dict(boxstyle="round", fc="white", ec="darkred", alpha=0.9))
            return []
        for _, comp in self.boundary.groupby("component"):
            ax.fill(comp["x1"], comp["x2"], color="tab:green", alpha=0.22, lw=0)
        return [plt.Rectangle((0, 0), 1, 1, color="tab:green", alpha=0.22, label="feasible")]

    def _plot_marks(self, ax, optimum, proposed) -> list:
        """The optimum (a star) and a proposed pair (a cross, red where it fails); legend handles."""
        import matplotlib.pyplot as plt

        handles = []
        if optimum is not None:
            ox, oy = (optimum.x1, optimum.x2) if hasattr(optimum, "x1") else optimum
            ax.plot([ox], [oy], marker="*", color="k", ms=15, ls="", zorder=5)
            handles.append(plt.Line2D([], [], color="k", marker="*", ls="", ms=11,
                                      label=f"optimum ({ox:.3f}, {oy:.3f})"))
        if proposed is not None:
            px, py = proposed
            ok = bool(self.contains(px, py))
            ax.plot([px], [py], marker="X", color="tab:red" if not ok else "tab:blue", ms=11, ls="",
                    mec="white", zorder=5)
            handles.append(plt.Line2D([], [], color="tab:red" if not ok else "tab:blue", marker="X", ls="", ms=9,
                                      label=f"proposed ({px:.3f}, {py:.3f}){'' if ok else ': fails'}"))
        return handles

    def _frame(self, ax, handles) -> None:
        """The window, axis labels, title (the pair and its module), grid and the legend beside the axes."""
        import matplotlib.pyplot as plt

        lo, hi = self.bounds
        handles.append(plt.Line2D([], [], color="0.25", lw=0.7, ls=(0, (3, 2)), label="isolines ε_α, s_a/m"))
        ax.set_xlim(lo, hi)
        ax.set_ylim(lo, hi)
        ax.set_xlabel(self.problem.axis_labels[0], fontsize=10)
        ax.set_ylabel(self.problem.axis_labels[1], fontsize=10)
        ax.set_title(f"Blocking contour {self.problem.title}, m = {self.problem.m:g} mm "
                     "(ticks: forbidden side)", fontsize=11)
        ax.grid(True, lw=0.3, alpha=0.6)
        ax.set_aspect("equal")
        ax.legend(handles=handles, fontsize=8.5, loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0)

    def _repr_html_(self) -> str:
        """Jupyter's view: the text, and the blocking contour inline."""
        return html_view(repr(self), lambda ax: self.plot(ax=ax, n=161), figsize=(7.0, 5.2), alt="blocking contour")

    def to_html(self, path, optimum=None, proposed=None, x_sum=None, n: int = 121, overwrite: bool = False):
        """Write the blocking contour as an interactive page (plotly, works offline): hover shows
        every check's margin and ε_α, s_a/m, a_w at the nearest of n × n nodes, a legend click
        hides or shows a check; marks as in :meth:`plot`. Returns the path. See
        :mod:`geardesign.shifts.contour_html`."""
        return write_contour_html(self, path, optimum, proposed, x_sum, n, overwrite)

    def x_sum_line(self, x_sum: float, points: int = 2001):
        """The line x_Σ = x_sum (x1 + x2, or x2 − x1 for a ring pair) across the window: (x1, x2,
        inside, a_w in mm, legend text), or None where it misses the window. What both the PNG
        and the HTML contour draw."""
        prob = self.problem
        prob_line = prob.subproblem(range(len(prob.checks)))
        prob_line.x_sum = x_sum
        t = np.linspace(*prob_line.x1_on_line(*self.bounds), points)
        if t.size == 0 or t[0] > t[-1]:
            return None
        x2 = x_sum - prob.sgn * t
        a_w = float(center_distance_from_x_sum(prob.m, prob.z1, prob.z2, x_sum, prob.rack,
                                               beta_deg=prob.mesh.beta_deg, internal=prob.mesh.internal))
        xs_name = "x2 − x1" if prob.mesh.internal else "x1 + x2"
        return t, x2, np.asarray(self.contains(t, x2)), a_w, f"a_w = {a_w:.6g} mm ({xs_name} = {x_sum:.4g})"

    def _plot_x_sum(self, ax, x_sum: float) -> list:
        """The line x_Σ = x_sum across the window, its feasible part thick."""
        import matplotlib.pyplot as plt

        line = self.x_sum_line(x_sum)
        if line is None:
            return []
        t, x2, inside, _, label = line
        ax.plot(t, x2, color="k", lw=0.9, ls="--", zorder=3)
        seg = np.where(inside, x2, np.nan)
        ax.plot(t, seg, color="k", lw=3.2, solid_capstyle="butt", zorder=4)
        return [plt.Line2D([], [], color="k", lw=0.9, ls="--", label=label),
                plt.Line2D([], [], color="k", lw=3.2, label="its feasible part")]


PLOT_N_MAX = 1201      # nodes per axis of a plot's curves: 1.4 M designs, ~1 s


def _isolines(ax, X1, X2, geo, isolines, checks) -> None:
    """Thin grey labelled isolines; a level equal to a check's limit is that check's curve."""
    parts = [(_parts(c.name), c.limit) for c in checks]
    eps_limit = next((lim for (_, kind, _), lim in parts if kind == "contact_ratio"), None)
    # geo's sa1, sa2: gear 1 and 2 of a pair, the sun and the planet of a planetary set
    marks = ("1", "2") if "sun-planet" not in geo else (",sun", ",planet")
    sa_limit = {j: next((lim for (_, kind, gear), lim in parts if kind == "tip_thickness"
                         and gear in (str(j), ("sun", "planet")[j - 1])), None) for j in (1, 2)}
    style = dict(colors="0.35", linewidths=0.6, linestyles=[(0, (3, 2))])
    with np.errstate(invalid="ignore"):
        if "eps_alpha" in isolines:
            levels = [v for v in (1.0, 1.1, 1.2, 1.3, 1.4, 1.5, 1.6, 1.8) if eps_limit is None
                      or abs(v - eps_limit) > 1e-9]
            cs = ax.contour(X1, X2, np.ma.masked_invalid(geo["eps_alpha"]), levels=levels, **style)
            ax.clabel(cs, fmt="ε=%.1f", fontsize=8, inline_spacing=2)
        if "sa" in isolines:
            for j in (1, 2):
                levels = [v for v in (0.0, 0.25, 0.4) if sa_limit[j] is None or abs(v - sa_limit[j]) > 1e-9]
                if not levels:
                    continue
                cs = ax.contour(X1, X2, np.ma.masked_invalid(geo[f"sa{j}"] / geo["_m"]), levels=levels, **style)
                ax.clabel(cs, fmt=f"s_a{marks[j - 1]}/m=%.2f", fontsize=7.5, inline_spacing=2)


def _project(prob: Problem, P: np.ndarray, idx: np.ndarray, iters: int = 10) -> np.ndarray:
    """Newton steps x ← x − m_k ∇m_k/‖∇m_k‖² onto check idx[i]'s curve, all points at once."""
    P = P.copy()
    rows = np.arange(len(P))
    prob = prob.reading(idx)
    for _ in range(iters):
        x1, x2 = P[:, 0], P[:, 1]
        geo = prob.geo(x1, x2)
        M, G = prob.margins_and_gradients(geo)
        M, G = M[idx, rows], G[idx, :, rows]
        nrm2 = (G ** 2).sum(axis=1)
        step = np.where(np.isfinite(M) & (nrm2 > 0), M / np.where(nrm2 > 0, nrm2, 1.0), 0.0)
        step = np.clip(step, -0.05, 0.05)
        P -= step[:, None] * G
    return P


def _corners(prob: Problem, P: np.ndarray, a: np.ndarray, b: np.ndarray, iters: int = 12) -> np.ndarray:
    """Intersections of check a's and check b's curves by 2-D Newton, from the points P."""
    P = P.copy()
    rows = np.arange(len(P))
    prob = prob.reading(np.concatenate([a, b]))
    for _ in range(iters):
        x1, x2 = P[:, 0], P[:, 1]
        geo = prob.geo(x1, x2)
        M, G = prob.margins_and_gradients(geo)
        ma, mb = M[a, rows], M[b, rows]
        ga, gb = G[a, :, rows], G[b, :, rows]
        det = ga[:, 0] * gb[:, 1] - ga[:, 1] * gb[:, 0]
        ok = np.abs(det) > 1e-12
        with np.errstate(invalid="ignore"):   # a point past the pair's edge (margin −inf) becomes NaN, dropped later
            d1 = np.where(ok, (ma * gb[:, 1] - mb * ga[:, 1]) / np.where(ok, det, 1.0), 0.0)
            d2 = np.where(ok, (mb * ga[:, 0] - ma * gb[:, 0]) / np.where(ok, det, 1.0), 0.0)
        P[:, 0] -= np.clip(d1, -0.05, 0.05)
        P[:, 1] -= np.clip(d2, -0.05, 0.05)
    return P


REGION_N_MAX = 2001     # nodes per axis of a region's grid: 4 M designs, ~3 GB of geometry at most
NO_GEOMETRY = "no_geometry"   # edge where the pair stops existing (α_w -> 0, a tip at its base circle)


def feasible_region(z1=None, z2=None, rack=None, checks=None, method: str = "exact", tol: float | None = None,
                    m: float = 1.0, tip_shortening: bool = True, bounds=DEFAULT_BOUNDS,
                    n: int | None = None, beta_deg: float = 0.0, internal: bool = False,
                    face_width_mm: float | None = None, *, mesh: Mesh | None = None) -> Region:
    """The region of (x1, x2) where every chosen check holds, with its labelled boundary.

    Parameters as :func:`geardesign.shifts.optimize.optimize_shifts` (``mesh=`` a :class:`~geardesign.gears.mesh.Mesh`
    instead of the tooth counts and the mesh's keywords); ``method`` "grid" keeps the
    grid-interpolated contour (vertex error ~ grid step²), "exact" (default) puts every vertex
    on its check's curve (or the window's edge) and solves the corners to ~1e-12. ``n`` nodes
    per axis (default 321, or from ``tol`` for "grid"; at most REGION_N_MAX). A region thinner
    than the grid is found by a local search and traced on a finer grid around it. The area
    comes with ``area_error``, an estimate of its error (the change when every edge is halved
    onto its curve, over 3: chords lose area as the square of their length). An empty region is
    a result: ``feasible`` False and ``conflict`` naming a smallest set of conflicting checks.

    >>> reg = feasible_region(17, 26)
    >>> reg.feasible, bool(reg.contains(0.5, 0.5)), bool(reg.contains(0.898, 0.517))
    (True, True, False)
    """
    if method not in ("grid", "exact"):
        raise GearDesignError(f"method must be 'grid' or 'exact' for a region, got {method!r}")
    tol = (0.01 if method == "grid" else 1e-9) if tol is None else one_number("tol", require_range("tol", tol, 1e-14, 1.0))
    lo, hi = validate_bounds(bounds)
    if n is None:
        n = int(min(max(math.ceil((hi - lo) / tol) + 1, 41), 801)) if method == "grid" else 321
    n = require_count("n", n, 11, REGION_N_MAX)
    prob = Problem(mesh_of(mesh, z1, z2, rack, tip_shortening, beta_deg, internal, face_width_mm), checks, "max_x_sum",
                   m)
    return region_of(prob, method, tol, (lo, hi), n)


def region_of(prob: Problem, method: str, tol: float, window: tuple, n: int) -> Region:
    """The feasible region of a built problem (a pair's, or a planetary set's in its free shifts)
    in the validated ``window`` on an n×n grid: see :func:`feasible_region`."""
    lo, hi = window
    box_used = (lo, hi, lo, hi)
    loops = _trace(prob, box_used, n, window, method)
    h = (hi - lo) / (n - 1)
    if not loops or sum(abs(_shoelace(L)) for L, _ in loops) < h * h:
        # thinner than the grid? the most central point nearby says; then trace around it
        point = _central_point(prob, window)
        if point is not None:
            for w in (0.02, 0.06, 0.2, 0.6):
                box = (max(lo, point[0] - w), min(hi, point[0] + w), max(lo, point[1] - w), min(hi, point[1] + w))
                loops = _trace(prob, box, n, window, method)
                box_used = box
                if loops and not _touches_box(loops, box, window):
                    break
    if not loops:
        conflict = smallest_conflict(prob, window)
        return Region(prob.z1, prob.z2, pd.DataFrame(columns=["component", "x1", "x2", "check"]), 0.0,
                      False, conflict, method, tol, window, prob, area_error=0.0)
    frames, area, area_fine, off = [], 0.0, 0.0, 0.0
    for comp, (L, names) in enumerate(loops):
        off += _off_curve_area(prob, L, names)
        a = _shoelace(L)
        if a < 0:   # counter-clockwise, edge labels follow the start vertex
            L, names = L[::-1], np.roll(names[::-1], -1)
            a = -a
        area += a
        area_fine += abs(_shoelace(_halved(prob, L, names))) if method == "exact" else a
        frames.append(pd.DataFrame({"component": comp, "x1": L[:, 0], "x2": L[:, 1], "check": names}))
    err = abs(area_fine - area) / 3.0 + off
    if method == "exact" and len(loops) and n >= 41:
        # and what the same trace gives at half the resolution: a loop that pinches off or a
        # vertex that misses its curve shows there, where the chord estimate cannot see it
        coarse = sum(abs(_shoelace(L)) for L, _ in _trace(prob, box_used, (n + 1) // 2, window, method))
        err = max(err, abs(coarse - (area_fine + (area_fine - area) / 3.0)))
    return Region(prob.z1, prob.z2, pd.concat(frames, ignore_index=True), area_fine + (area_fine - area) / 3.0,
                  True, [], method, tol, window, prob, area_error=err)


def _shoelace(L: np.ndarray) -> float:
    x, y = L[:, 0], L[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


def _off_curve_area(prob: Problem, L: np.ndarray, names: np.ndarray) -> float:
    """Area a vertex left off its curve can misplace: its first-order distance to the curve
    times half its two edges, summed (0 where every vertex sits on its curve)."""
    index = {name: k for k, name in enumerate(prob.names)}
    k = np.array([index.get(nm, -1) for nm in names])
    on = k >= 0
    if not on.any():
        return 0.0
    prob = prob.reading(k[on])
    with np.errstate(all="ignore"):
        geo = prob.geo(L[on, 0], L[on, 1])
        rows = np.arange(on.sum())
        mk, G = prob.margins_and_gradients(geo)
        mk, G = mk[k[on], rows], G[k[on], :, rows]
        dist = np.abs(mk) / np.hypot(G[:, 0], G[:, 1])
    edge = np.hypot(*(np.roll(L, -1, axis=0) - L).T)
    half = (edge + np.roll(edge, 1)) / 2
    return float(np.nansum(np.where(np.isfinite(dist), dist, 0.0) * half[on]))


_ON_CURVE = 1e-6    # a projected point's margin this close to zero is on its curve


def _halved(prob: Problem, L: np.ndarray, names: np.ndarray) -> np.ndarray:
    """The polygon with the midpoint of every check edge moved onto that check's curve."""
    nxt = np.roll(np.arange(len(L)), -1)
    index = {name: k for k, name in enumerate(prob.names)}
    on_check = np.array([nm in index for nm in names])
    mids = (L + L[nxt]) / 2
    if on_check.any():
        k = np.flatnonzero(on_check)
        moved = _project(prob, mids[k], np.array([index[nm] for nm in names[k]]))
        # a point of the boundary holds every other check: a midpoint that lands where one fails has
        # left the arc between the edge's ends (across a thin sliver): the chord's midpoint stays
        good = np.isfinite(moved).all(axis=1)
        if good.any():
            with np.errstate(all="ignore"):
                worst = prob.margins(prob.geo(moved[good, 0], moved[good, 1])).min(axis=0)
            good[good] = worst >= -_ON_CURVE
        mids[k[good]] = moved[good]
    out = np.empty((2 * len(L), 2))
    out[0::2], out[1::2] = L, mids
    return out


def _central_point(prob: Problem, window):
    """A point where every check holds near the least infeasible node of a coarse grid, or None."""
    V = grid_points(prob, 61, window)
    _, M = prob.evaluate(V, grads=False)
    if not M.size:
        return None
    w = central_point(prob, V, M, window)
    return w[:2] if w[-1] >= 0 and np.isfinite(w).all() else None


def _touches_box(loops, box, window) -> bool:
    """True when a traced loop runs along an edge of the zoom box that is not the window's."""
    for L, _ in loops:
        for coord, edge in ((0, box[0]), (0, box[1]), (1, box[2]), (1, box[3])):
            if edge not in window and (np.abs(L[:, coord] - edge) < 1e-12).any():
                return True
    return False


def _trace(prob: Problem, box, n: int, window, method: str) -> list:
    """The loops [(vertices, edge labels)] of the zero contour of the smallest margin over the
    box (x1 lo, x1 hi, x2 lo, x2 hi), labelled, and with ``exact`` moved onto their curves."""
    import contourpy

    g1, g2 = np.linspace(box[0], box[1], n), np.linspace(box[2], box[3], n)
    X1, X2 = np.meshgrid(g1, g2, indexing="ij")
    with np.errstate(all="ignore"):
        F = _smallest_margin(prob, X1, X2)
    F = np.where(np.isfinite(F), F, -1.0)
    # a frame of -1 outside the box closes the loops along its edges
    h1, h2 = g1[1] - g1[0], g2[1] - g2[0]
    gp1 = np.concatenate([[box[0] - h1], g1, [box[1] + h1]])
    gp2 = np.concatenate([[box[2] - h2], g2, [box[3] + h2]])
    Fp = np.full((n + 2, n + 2), -1.0)
    Fp[1:-1, 1:-1] = F
    gen = contourpy.contour_generator(x=gp1, y=gp2, z=Fp.T, line_type=contourpy.LineType.Separate)
    out = []
    for L in gen.lines(0.0):
        L = np.asarray(L, dtype=float)
        if len(L) < 4:
            continue
        if np.allclose(L[0], L[-1]):
            L = L[:-1]
        L[:, 0] = np.clip(L[:, 0], box[0], box[1])
        L[:, 1] = np.clip(L[:, 1], box[2], box[3])
        out.append(_label(prob, L, box, window, method))
    return out


def _smallest_margin(prob: Problem, X1, X2) -> np.ndarray:
    """The smallest margin at the nodes (X1, X2) (n×n). Costly checks (the strength chain) are evaluated only
    at the nodes where every other check holds and at their neighbours: elsewhere the smallest margin is
    negative whatever they say, and no zero contour crosses a cell all of whose corners are negative."""
    from scipy import ndimage

    light = prob.light() if hasattr(prob, "light") else None
    costly = [i for i, c in enumerate(prob.checks) if c.costly]
    if light is None or len(costly) == len(prob.checks):
        M = prob.margins(prob.geo(X1, X2))
        return M.min(axis=0) if M.size else np.ones_like(X1)
    F = np.delete(light.margins(light.geo(X1, X2)), costly, axis=0).min(axis=0)
    near = ndimage.maximum_filter(F >= 0, size=3, mode="constant", cval=False)
    if near.any():
        F[near] = np.minimum(F[near], prob.margins(prob.geo(X1[near], X2[near]))[costly].min(axis=0))
    return F


def _label(prob: Problem, L: np.ndarray, box, window, method: str):
    """Vertices and edge labels of one loop: the smallest check at each vertex, the window, or
    the edge of existence; with ``exact`` each vertex moved onto its curve, each corner solved."""
    lo, hi = window
    on_box = ((np.abs(L[:, 0] - box[0]) < 1e-12) | (np.abs(L[:, 0] - box[1]) < 1e-12)
              | (np.abs(L[:, 1] - box[2]) < 1e-12) | (np.abs(L[:, 1] - box[3]) < 1e-12))
    with np.errstate(all="ignore"):
        Mv = prob.margins(prob.geo(L[:, 0], L[:, 1]))
    finite = np.isfinite(Mv).all(axis=0) if Mv.size else np.ones(len(L), bool)
    idx = np.argmin(np.where(np.isfinite(Mv), np.abs(Mv), np.inf), axis=0) if Mv.size else np.zeros(len(L), int)
    if method == "exact" and Mv.size:
        inner = ~on_box & finite
        if inner.any():
            moved = _project(prob, L[inner], idx[inner])
            ok = np.isfinite(moved).all(axis=1)
            L[np.flatnonzero(inner)[ok]] = moved[ok]
        L, idx, on_box, finite = _solve_corners(prob, L, idx, on_box, finite)
    names = np.array(prob.names, dtype=object)[idx] if Mv.size else np.full(len(L), WINDOW, dtype=object)
    names = np.where(~finite, NO_GEOMETRY, names)
    names = np.where(on_box & np.roll(on_box, -1), WINDOW, names)
    return L, names


def _solve_corners(prob: Problem, L, idx, on_box, finite):
    """Insert the exact corner between consecutive vertices limited by different checks, and move
    each box vertex next to a check vertex onto that check's curve along the box's edge."""
    nxt = np.roll(np.arange(len(L)), -1)
    inner = ~on_box & finite
    change = inner & inner[nxt] & (idx != idx[nxt])
    ins = {}
    if change.any():
        i = np.flatnonzero(change)
        C = _corners(prob, (L[i] + L[nxt[i]]) / 2, idx[i], idx[nxt[i]])
        ins = {int(k): C[j] for j, k in enumerate(i) if np.isfinite(C[j]).all()}
    # a box vertex whose neighbour lies on a check: where that check's curve crosses the edge
    prv = np.roll(np.arange(len(L)), 1)
    for k in np.flatnonzero(on_box & finite):
        for nb in (prv[k], nxt[k]):
            if inner[nb]:
                moved = _slide(prob, L[k], int(idx[nb]))
                if moved is not None:
                    L[k] = moved
                    idx[k] = idx[nb]
                break
    pts, labs, box, fin = [], [], [], []
    for k in range(len(L)):
        pts.append(L[k])
        labs.append(idx[k])
        box.append(on_box[k])
        fin.append(finite[k])
        if k in ins:            # the point where a check's curve crosses the edge after vertex k
            pts.append(ins[k])
            labs.append(idx[nxt[k]])
            box.append(False)
            fin.append(True)
    return np.array(pts), np.array(labs), np.array(box), np.array(fin)


def _slide(prob: Problem, p: np.ndarray, k: int, iters: int = 8):
    """Newton along the box edge through p (the coordinate that is not on the edge moves) onto
    check k's curve; None when it does not converge within a small step."""
    p = p.copy()
    start = p.copy()
    prob = prob.reading([k])
    for _ in range(iters):
        with np.errstate(all="ignore"):
            geo = prob.geo(np.array([p[0]]), np.array([p[1]]))
            mk, G = prob.margins_and_gradients(geo)
            mk, G = mk[k, 0], G[k, :, 0]
        # the free coordinate is the one along which the box edge runs: pick the larger slope
        j = int(np.argmax(np.abs(G)))
        if not (np.isfinite(mk) and np.isfinite(G[j]) and G[j] != 0):
            return None
        p[j] -= mk / G[j]
        if abs(mk) < 1e-14:
            break
    return p if np.abs(p - start).max() < 0.1 and np.isfinite(p).all() else None


