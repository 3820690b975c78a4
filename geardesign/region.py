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

from .errors import GearDesignError, require_int, require_range
from .problem import DEFAULT_BOUNDS, Problem
from .shift import smallest_conflict

__all__ = ["feasible_region", "Region"]

WINDOW = "window"


@dataclass
class Region:
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

    @property
    def checks(self) -> list[str]:
        return list(self.problem.names)

    def contains(self, x1, x2):
        """True where every check holds (exact margins, vectorised)."""
        x1, x2 = np.broadcast_arrays(np.asarray(x1, dtype=float), np.asarray(x2, dtype=float))
        M = self.problem.margins(self.problem.geo(x1, x2))
        out = (M >= 0).all(axis=0) if M.size else np.ones(x1.shape, bool)
        return bool(out) if out.ndim == 0 else out

    def to_frame(self) -> pd.DataFrame:
        return self.boundary.copy()

    def limiting_checks(self) -> list[str]:
        """The checks that form part of the boundary, in order of appearance."""
        seen = []
        for c in self.boundary["check"]:
            if c not in seen:
                seen.append(c)
        return seen

    def __repr__(self) -> str:
        if not self.feasible:
            return (f"Region(z1/z2 = {self.z1}/{self.z2}: empty; conflicting checks: "
                    f"{', '.join(self.conflict) or 'none found'})")
        return (f"Region(z1/z2 = {self.z1}/{self.z2}, area {self.area:.6g}, {len(self.boundary)} vertices, "
                f"limited by {', '.join(self.limiting_checks())}; method {self.method}, tol {self.tol:g})")

    def plot(self, ax=None, isolines=("eps_alpha", "sa"), optimum=None, n: int = 241):
        """Draw the region and every check's curve, like a handbook blocking contour.

        ``isolines``: any of "eps_alpha" (ε_α) and "sa" (s_a/m of both gears) drawn as thin
        labelled contours; ``optimum``: a :class:`~geardesign.shift.ShiftResult` or (x1, x2) to mark.
        Returns the matplotlib Axes.
        """
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(7, 6))
        lo, hi = self.bounds
        g = np.linspace(lo, hi, n)
        X1, X2 = np.meshgrid(g, g, indexing="ij")
        geo = self.problem.geo(X1, X2)
        M = self.problem.margins(geo)
        colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
        handles = []
        for k, c in enumerate(self.problem.checks):
            mk = np.where(np.isfinite(M[k]), M[k], -10.0)
            if mk.min() < 0 < mk.max():
                cs = ax.contour(X1, X2, mk, levels=[0.0], colors=[colors[k % len(colors)]], linewidths=1.4)
                handles.append(plt.Line2D([], [], color=colors[k % len(colors)], label=c.name))
                del cs
        if isolines:
            with np.errstate(invalid="ignore"):
                if "eps_alpha" in isolines:
                    cs = ax.contour(X1, X2, geo["eps_alpha"], levels=[1.0, 1.1, 1.2, 1.3, 1.4, 1.5, 1.6],
                                    colors="0.6", linewidths=0.6, linestyles=":")
                    ax.clabel(cs, fmt="ε=%.1f", fontsize=7)
                if "sa" in isolines:
                    for j in (1, 2):
                        cs = ax.contour(X1, X2, geo[f"sa{j}"] / geo["_m"], levels=[0.0, 0.25, 0.4],
                                        colors="0.75", linewidths=0.6, linestyles="--")
                        ax.clabel(cs, fmt=f"s_a{j}/m=%.2f", fontsize=6)
        if self.feasible:
            for _, comp in self.boundary.groupby("component"):
                ax.fill(comp["x1"], comp["x2"], color="tab:green", alpha=0.25, lw=0)
            handles.append(plt.Rectangle((0, 0), 1, 1, color="tab:green", alpha=0.25, label="feasible"))
        if optimum is not None:
            ox, oy = (optimum.x1, optimum.x2) if hasattr(optimum, "x1") else optimum
            ax.plot([ox], [oy], "k*", ms=12)
            handles.append(plt.Line2D([], [], color="k", marker="*", ls="", ms=10, label="optimum"))
        ax.set_xlabel("x1 (profile shift, gear 1)")
        ax.set_ylabel("x2 (profile shift, gear 2)")
        ax.set_title(f"Blocking contour z1/z2 = {self.z1}/{self.z2}")
        ax.grid(True, lw=0.3)
        ax.legend(handles=handles, fontsize=8, loc="upper right")
        return ax


def _project(prob: Problem, P: np.ndarray, idx: np.ndarray, iters: int = 6) -> np.ndarray:
    """Newton steps x ← x − m_k ∇m_k/‖∇m_k‖² onto check idx[i]'s curve, all points at once."""
    P = P.copy()
    rows = np.arange(len(P))
    for _ in range(iters):
        x1, x2 = P[:, 0], P[:, 1]
        geo = prob.geo(x1, x2)
        M = prob.margins(geo)[idx, rows]
        G = prob.margin_gradients(geo)[idx, :, rows]
        nrm2 = (G ** 2).sum(axis=1)
        step = np.where(np.isfinite(M) & (nrm2 > 0), M / np.where(nrm2 > 0, nrm2, 1.0), 0.0)
        step = np.clip(step, -0.05, 0.05)
        P -= step[:, None] * G
    return P


def _corners(prob: Problem, P: np.ndarray, a: np.ndarray, b: np.ndarray, iters: int = 12) -> np.ndarray:
    """Intersections of check a's and check b's curves by 2-D Newton, from the points P."""
    P = P.copy()
    rows = np.arange(len(P))
    for _ in range(iters):
        x1, x2 = P[:, 0], P[:, 1]
        geo = prob.geo(x1, x2)
        M = prob.margins(geo)
        G = prob.margin_gradients(geo)
        ma, mb = M[a, rows], M[b, rows]
        ga, gb = G[a, :, rows], G[b, :, rows]
        det = ga[:, 0] * gb[:, 1] - ga[:, 1] * gb[:, 0]
        ok = np.abs(det) > 1e-12
        d1 = np.where(ok, (ma * gb[:, 1] - mb * ga[:, 1]) / np.where(ok, det, 1.0), 0.0)
        d2 = np.where(ok, (mb * ga[:, 0] - ma * gb[:, 0]) / np.where(ok, det, 1.0), 0.0)
        P[:, 0] -= np.clip(d1, -0.05, 0.05)
        P[:, 1] -= np.clip(d2, -0.05, 0.05)
    return P


def feasible_region(z1, z2, rack=None, checks=None, method: str = "exact", tol: float | None = None,
                    m: float = 1.0, tip_shortening: bool = True, bounds=DEFAULT_BOUNDS,
                    n: int | None = None) -> Region:
    """The region of (x1, x2) where every chosen check holds, with its labelled boundary.

    Parameters as :func:`geardesign.shift.optimize_shifts`; ``method`` "grid" keeps the
    grid-interpolated contour (vertex error ~ grid step²), "exact" (default) puts every vertex
    on its check's curve and solves the corners to ~1e-12. ``n`` nodes per axis (default 161,
    or from ``tol`` for "grid"). An empty region is a result: ``feasible`` False and
    ``conflict`` naming a smallest set of conflicting checks.

    >>> reg = feasible_region(17, 26)
    >>> reg.feasible, bool(reg.contains(0.5, 0.5)), bool(reg.contains(0.898, 0.517))
    (True, True, False)
    """
    import contourpy

    if method not in ("grid", "exact"):
        raise GearDesignError(f"method must be 'grid' or 'exact' for a region, got {method!r}")
    tol = (0.01 if method == "grid" else 1e-9) if tol is None else float(require_range("tol", tol, 1e-14, 1.0))
    lo, hi = (float(b) for b in bounds)
    if not lo < hi:
        raise GearDesignError(f"bounds must be (lo, hi) with lo < hi, got {bounds!r}")
    if n is None:
        n = int(min(max(math.ceil((hi - lo) / tol) + 1, 41), 801)) if method == "grid" else 161
    n = int(require_int("n", n, 11))
    prob = Problem(z1, z2, rack, checks, "max_x_sum", m, tip_shortening)
    g = np.linspace(lo, hi, n)
    X1, X2 = np.meshgrid(g, g, indexing="ij")
    M = prob.margins(prob.geo(X1, X2))
    F = M.min(axis=0) if M.size else np.ones_like(X1)
    F = np.where(np.isfinite(F), F, -1.0)
    h = g[1] - g[0]
    gp = np.concatenate([[lo - h], g, [hi + h]])
    Fp = np.full((n + 2, n + 2), -1.0)
    Fp[1:-1, 1:-1] = F
    gen = contourpy.contour_generator(x=gp, y=gp, z=Fp.T, line_type=contourpy.LineType.Separate)
    loops = [np.asarray(l) for l in gen.lines(0.0) if len(l) >= 4]
    if not loops:
        conflict = smallest_conflict(prob, (lo, hi))
        return Region(prob.z1, prob.z2, pd.DataFrame(columns=["component", "x1", "x2", "check"]), 0.0,
                      False, conflict, method, tol, (lo, hi), prob)
    frames, area = [], 0.0
    for comp, L in enumerate(loops):
        if np.allclose(L[0], L[-1]):
            L = L[:-1]
        L = np.clip(L, lo, hi)
        on_window = (np.abs(L[:, 0] - lo) < 1e-12) | (np.abs(L[:, 0] - hi) < 1e-12) | \
                    (np.abs(L[:, 1] - lo) < 1e-12) | (np.abs(L[:, 1] - hi) < 1e-12)
        Mv = prob.margins(prob.geo(L[:, 0], L[:, 1]))
        idx = np.argmin(np.where(np.isfinite(Mv), np.abs(Mv), np.inf), axis=0)
        if method == "exact" and (~on_window).any():
            inner = ~on_window
            L[inner] = _project(prob, L[inner], idx[inner])
            # corners: consecutive vertices limited by different checks
            nxt = np.roll(np.arange(len(L)), -1)
            change = inner & inner[nxt] & (idx != idx[nxt])
            if change.any():
                i = np.flatnonzero(change)
                mids = (L[i] + L[nxt[i]]) / 2
                C = _corners(prob, mids, idx[i], idx[nxt[i]])
                pts, labs, win = [], [], []
                ins = dict(zip(i.tolist(), range(len(i))))
                for k in range(len(L)):
                    pts.append(L[k]); labs.append(idx[k]); win.append(on_window[k])
                    if k in ins:
                        pts.append(C[ins[k]]); labs.append(idx[nxt[k]]); win.append(False)
                L, idx, on_window = np.array(pts), np.array(labs), np.array(win)
        names = np.array(prob.names, dtype=object)[idx]
        names = np.where(on_window & np.roll(on_window, -1), WINDOW, names)
        x, y = L[:, 0], L[:, 1]
        signed = 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))
        if signed < 0:   # counter-clockwise, edge labels follow the start vertex
            L, names = L[::-1], np.roll(names[::-1], -1)
            signed = -signed
        area += signed
        frames.append(pd.DataFrame({"component": comp, "x1": L[:, 0], "x2": L[:, 1], "check": names}))
    return Region(prob.z1, prob.z2, pd.concat(frames, ignore_index=True), area, True, [], method, tol, (lo, hi), prob)
