"""Many tooth pairs at once: the optimal shifts and the region size for a table of z1 × z2."""
from __future__ import annotations

import time

import numpy as np
import pandas as pd

from ..errors import GearDesignError
from ..validate import ndim, require_bool, require_int
from ..gears.geometry import mesh_geometry, mesh_geometry_float
from ..gears.mesh import Z_MAX, Z_MIN, Mesh
from .problem import DEFAULT_BOUNDS, Problem
from .optimize import optimize_shifts

__all__ = ["shift_atlas"]

_ATLAS_N = 41   # grid nodes per axis of the batched first pass (area estimate and start points)
# The atlas's areas come from this coarse grid (spacing 0.11): each row carries ``area_error``,
# the change when every other node is dropped, a bound on the interpolation error; use
# :func:`geardesign.feasible_region` for one pair's exact area.


ATLAS_PAIRS_MAX = 100_000   # ~3 min at ~2 ms a pair; more is a batch job, split it


def _values(name, values) -> np.ndarray:
    if ndim(values) == 0 and not isinstance(values, (list, tuple, range)):
        values = [values]          # one tooth count is a list of one
    try:
        n = len(values)
    except TypeError:
        raise GearDesignError(f"{name} must be tooth counts (a list, range or array), got {values!r}") from None
    if not 1 <= n <= ATLAS_PAIRS_MAX:
        raise GearDesignError(f"{name} must hold 1 to {ATLAS_PAIRS_MAX:,} tooth counts, got {n:,}")
    return np.atleast_1d(require_int(name, list(values), Z_MIN, Z_MAX)).ravel()


def atlas_size(z1_values, z2_values, upper_only: bool = True, internal: bool = False) -> int:
    """How many pairs an atlas of these tooth counts holds (checked before any work). An
    internal pair needs a ring larger than its pinion: z2 > z1 always."""
    z1, z2 = np.sort(_values("z1_values", z1_values)), _values("z2_values", z2_values)
    if internal:
        return int(np.searchsorted(z1, z2, side="left").sum())
    if not upper_only:
        return int(z1.size * z2.size)
    return int(np.searchsorted(z1, z2, side="right").sum())


def _pairs(z1_values, z2_values, upper_only, internal):
    n = atlas_size(z1_values, z2_values, upper_only, internal)
    if n > ATLAS_PAIRS_MAX:
        raise GearDesignError(f"an atlas takes at most {ATLAS_PAIRS_MAX:,} pairs, these tooth counts make {n:,}")
    z1, z2 = _values("z1_values", z1_values), _values("z2_values", z2_values)
    Z1, Z2 = np.meshgrid(z1, z2, indexing="ij")
    Z1, Z2 = Z1.ravel(), Z2.ravel()
    keep = Z2 > Z1 if internal else (Z2 >= Z1 if upper_only else np.ones(Z1.shape, bool))
    return Z1[keep], Z2[keep]


@np.errstate(all="ignore")   # diverging candidates give NaN and inf: they are discarded at the end
def _batched_kkt(proto: Problem, Z1, Z2, start, iters: int = 10):
    """Every KKT candidate of every pair at once, for one-piece (smooth) objectives.

    Candidates: each pair of checks active (a vertex: m_a = m_b = 0) and each single check
    active with the objective's gradient normal to it (m_a = 0, ∇f × ∇m_a = 0). Newton runs on
    all (pair, candidate) systems in lockstep from the pair's best grid node; a candidate counts
    when it converged, holds every check, and has multipliers >= 0. The best valid candidate
    per pair is returned (NaN where none is valid; those pairs go to the one-by-one solver).
    """
    K = len(proto.checks)
    combos = [(a, b) for a in range(K) for b in range(a + 1, K)] + [(a, -1) for a in range(K)]
    B, C = len(Z1), len(combos)
    A = np.array([c[0] for c in combos])
    Bb = np.array([c[1] for c in combos])
    vertex = Bb >= 0
    z1 = np.repeat(Z1, C).astype(float)
    z2 = np.repeat(Z2, C).astype(float)
    a_idx = np.tile(A, B)
    b_idx = np.tile(np.where(vertex, Bb, 0), B)
    is_v = np.tile(vertex, B)
    mesh = proto.mesh.unchecked(z1, z2)
    X = np.repeat(start, C, axis=0)
    rows = np.arange(B * C)
    edge = np.flatnonzero(~is_v)
    edge_mesh, edge_rows = proto.mesh.unchecked(z1[edge], z2[edge]), np.arange(edge.size)
    h = 1e-6

    def grads_at(x1, x2):
        geo = mesh_geometry(mesh, 1.0, x1, x2, proto.full)
        return geo, proto.margins(geo), proto.margin_gradients(geo)

    def pgrad(geo):
        return proto.piece_gradients(geo)[0]

    for _ in range(iters):
        x1, x2 = X[:, 0], X[:, 1]
        geo, M, G = grads_at(x1, x2)
        ma, ga = M[a_idx, rows], G[a_idx, :, rows]
        mb, gb = M[b_idx, rows], G[b_idx, :, rows]
        gp = pgrad(geo).T                               # (n, 2)
        # the stationarity residual of edge candidates and its derivative by differences
        cross = gp[:, 0] * ga[:, 1] - gp[:, 1] * ga[:, 0]
        # its derivative only where it is used: the edge candidates (a quarter of the rows)
        dcross = np.zeros((len(rows), 2))
        for j, (dx1, dx2) in enumerate(((h, 0.0), (0.0, h))):
            gp_, gp__ = [], []
            for sgn in (1.0, -1.0):
                geo_s = mesh_geometry(edge_mesh, 1.0, x1[edge] + sgn * dx1, x2[edge] + sgn * dx2, proto.full)
                G_s = proto.margin_gradients(geo_s)[a_idx[edge], :, edge_rows]
                P_s = pgrad(geo_s).T
                (gp_ if sgn > 0 else gp__).append(P_s[:, 0] * G_s[:, 1] - P_s[:, 1] * G_s[:, 0])
            dcross[edge, j] = (gp_[0] - gp__[0]) / (2 * h)
        r2 = np.where(is_v, mb, cross)
        j2 = np.where(is_v[:, None], gb, dcross)
        det = ga[:, 0] * j2[:, 1] - ga[:, 1] * j2[:, 0]
        ok = np.isfinite(det) & (np.abs(det) > 1e-14) & np.isfinite(ma) & np.isfinite(r2)
        sdet = np.where(ok, det, 1.0)
        with np.errstate(all="ignore"):
            d1 = np.where(ok, (ma * j2[:, 1] - r2 * ga[:, 1]) / sdet, 0.0)
            d2 = np.where(ok, (r2 * ga[:, 0] - ma * j2[:, 0]) / sdet, 0.0)
        X = X - np.clip(np.column_stack([d1, d2]), -0.2, 0.2)
    geo, M, G = grads_at(X[:, 0], X[:, 1])
    return _best_candidate(proto, geo, M, G, pgrad(geo).T, X, a_idx, b_idx, is_v, rows, B, C)


def _best_candidate(proto, geo, M, G, gp, X, a_idx, b_idx, is_v, rows, B, C):
    """Each pair's best converged, feasible KKT candidate (NaN where none)."""
    x1, x2 = X[:, 0], X[:, 1]
    ma, mb = M[a_idx, rows], M[b_idx, rows]
    ga, gb = G[a_idx, :, rows], G[b_idx, :, rows]
    cross = gp[:, 0] * ga[:, 1] - gp[:, 1] * ga[:, 0]
    conv = (np.abs(ma) < 1e-11) & np.where(is_v, np.abs(mb) < 1e-11, np.abs(cross) < 1e-9)
    feas = (M >= -1e-12).all(axis=0)
    # multipliers: ∇f = −Σ λ ∇m  (λ >= 0 for a maximum)
    det = ga[:, 0] * gb[:, 1] - ga[:, 1] * gb[:, 0]
    sdet = np.where(np.abs(det) > 1e-14, det, 1.0)
    lam_a_v = (-gp[:, 0] * gb[:, 1] + gp[:, 1] * gb[:, 0]) / sdet
    lam_b_v = (-ga[:, 0] * gp[:, 1] + ga[:, 1] * gp[:, 0]) / sdet
    lam_a_e = -(gp * ga).sum(axis=1) / np.maximum((ga * ga).sum(axis=1), 1e-300)
    kkt = np.where(is_v, (lam_a_v >= -1e-9) & (lam_b_v >= -1e-9), lam_a_e >= -1e-9)
    valid = conv & feas & kkt & np.isfinite(x1) & np.isfinite(x2)
    f = np.where(valid, proto.pieces(geo)[0], -np.inf).reshape(B, C)
    best = np.argmax(f, axis=1)
    got = np.isfinite(f[np.arange(B), best])
    out = np.full((B, 2), np.nan)
    pick = np.arange(B) * C + best
    out[got] = X[pick[got]]
    return out


def _contour_area(g, F) -> float:
    """Area inside the zero contour of F (linear interpolation between nodes, so the error is
    ~ perimeter × step², not perimeter × step as a node count would give)."""
    import contourpy

    h = g[1] - g[0]
    gp = np.concatenate([[g[0] - h], g, [g[-1] + h]])
    Fp = np.full((F.shape[0] + 2, F.shape[1] + 2), -1.0)
    Fp[1:-1, 1:-1] = F
    gen = contourpy.contour_generator(x=gp, y=gp, z=Fp.T, line_type=contourpy.LineType.Separate)
    total = 0.0
    for L in gen.lines(0.0):
        x, y = np.clip(L[:, 0], g[0], g[-1]), np.clip(L[:, 1], g[0], g[-1])
        total += abs(0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))))
    return total


def _row_at(proto: Problem, z1, z2, x, area) -> dict:
    geo = mesh_geometry_float(proto.mesh.unchecked(z1, z2), 1.0, x[0], x[1])
    M = proto.margins(geo)
    fun = proto.fun(geo)
    tol = 1e-8
    row = {"z1": z1, "z2": z2, "feasible": True, "x1": float(x[0]), "x2": float(x[1]),
           "objective": float(fun), "eps_alpha": float(geo["eps_alpha"]), "area": area,
           "active": ",".join(n for n, m in zip(proto.names, M) if abs(m) <= tol), "conflict": ""}
    # a margin the batched Newton cannot tell from zero is zero (no 1e-16 "dips" in sweeps)
    row.update({f"margin_{n}": (0.0 if abs(float(m)) <= tol else float(m)) for n, m in zip(proto.names, M)})
    return row


def shift_atlas(z1_values, z2_values, objective: str = "max_x_sum", checks=None, method: str = "exact",
                tol: float | None = None, rack=None, tip_shortening: bool = True, bounds=DEFAULT_BOUNDS,
                upper_only: bool = True, progress=None, beta_deg: float = 0.0, internal: bool = False,
                face_width: float | None = None) -> pd.DataFrame:
    """One row per tooth pair: feasible, x1, x2, objective, all margins, active checks, region area.

    The first pass is batched: every pair's margins on a 41×41 grid of (x1, x2) in one
    vectorised call per chunk of pairs. It gives the region area (traced on that grid
    from the zero contour of the smallest margin) and each pair's best node, from which ``method`` then polishes
    the optimum (``grid`` keeps the node). A pair whose region holds no node (a sliver, as for 8 to 11
    pinion teeth) starts the batched Newton from its least infeasible node; only pairs the batched
    Newton cannot settle (no valid KKT point: infeasible pairs, whose conflict is then searched) are
    solved one by one. ``upper_only`` keeps z2 >= z1 (an internal pair
    always needs z2 > z1). ``progress`` is called with the number of pairs done.
    ``beta_deg``, ``internal``, ``face_width``: the kind of every pair, as for
    :class:`~geardesign.gears.mesh.Mesh`; lengths are per unit module (m = 1), so ``face_width``
    is b/m here.

    >>> df = shift_atlas([17], [26, 40])
    >>> list(df.columns[:6]), bool(df.feasible.all())
    (['z1', 'z2', 'feasible', 'x1', 'x2', 'objective'], True)
    """
    t0 = time.perf_counter()
    internal = require_bool("internal", internal)
    Z1, Z2 = _pairs(z1_values, z2_values, upper_only, internal)
    if Z1.size == 0:
        raise GearDesignError("shift_atlas: no (z1, z2) pair to solve (with upper_only, z2 must be >= z1; "
                              "internal pairs need z2 > z1)")
    proto = Problem(Mesh(int(Z1[0]), int(Z2[0]), rack, tip_shortening, beta_deg, internal, face_width), checks,
                    objective, 1.0)
    rack = proto.rack
    lo, hi = bounds
    g = np.linspace(lo, hi, _ATLAS_N)
    X1, X2 = (a.ravel() for a in np.meshgrid(g, g, indexing="ij"))
    chunk = max(1, 200_000 // X1.size)
    area = np.zeros(Z1.size)
    area_error = np.zeros(Z1.size)
    start = np.full((Z1.size, 2), np.nan)
    near = np.full((Z1.size, 2), np.nan)    # the least infeasible node of a pair with no feasible node
    def node_values(geo):
        """The smallest margin (-1 where a gear does not exist) and the objective where feasible."""
        with np.errstate(all="ignore"):   # nodes where a gear does not exist: margin NaN → −inf
            M = proto.margins(geo)
        if not M.size:
            return {"F": np.ones(geo["a"].shape), "score": proto.pieces(geo).min(axis=0)}
        m_min = M.min(axis=0)
        P = proto.pieces(geo).min(axis=0) if proto.objective.kind != "margin" else m_min
        return {"F": np.where(np.isfinite(m_min), m_min, -1.0), "score": np.where(m_min >= 0, P, -np.inf)}

    for s in range(0, Z1.size, chunk):
        z1c, z2c = Z1[s:s + chunk, None], Z2[s:s + chunk, None]
        # block by block: only the two node values are stored for the whole chunk
        nodes = mesh_geometry(proto.mesh.unchecked(z1c, z2c), 1.0, X1[None, :], X2[None, :], proto.full,
                              then=node_values)
        F, score = nodes["F"], nodes["score"]
        for k in range(F.shape[0]):
            Fk = F[k].reshape(_ATLAS_N, _ATLAS_N)
            area[s + k] = _contour_area(g, Fk)
            # the same contour on every other node: the change bounds the interpolation error
            area_error[s + k] = abs(area[s + k] - _contour_area(g[::2], Fk[::2, ::2]))
        best = np.argmax(score, axis=1)
        ok = np.isfinite(score[np.arange(len(best)), best])
        start[s:s + chunk][ok] = np.column_stack([X1[best], X2[best]])[ok]
        least = np.argmax(F, axis=1)
        near[s:s + chunk][~ok] = np.column_stack([X1[least], X2[least]])[~ok]
    fast = np.full((Z1.size, 2), np.nan)
    if method == "exact" and proto.objective.kind == "smooth":
        from_node = np.where(np.isnan(start), near, start)
        has = ~np.isnan(from_node[:, 0])
        for s in range(0, int(has.sum()), 400):
            sel = np.flatnonzero(has)[s:s + 400]
            fast[sel] = _batched_kkt(proto, Z1[sel], Z2[sel], from_node[sel])
    rows = []
    for k, (z1, z2) in enumerate(zip(Z1.tolist(), Z2.tolist())):
        st = None if np.isnan(start[k, 0]) else start[k]
        if not np.isnan(fast[k, 0]):
            rows.append(_row_at(proto, z1, z2, fast[k], area[k]))
            rows[-1]["area_error"] = area_error[k]
            if progress is not None:
                progress(k + 1)
            continue
        r = optimize_shifts(z1, z2, objective=objective, checks=checks, method=method, tol=tol, rack=rack,
                            tip_shortening=tip_shortening, bounds=bounds, start=st, beta_deg=beta_deg,
                            internal=internal, face_width=face_width,
                            grid_n=_ATLAS_N if method == "grid" else None)
        row = {"z1": z1, "z2": z2, "feasible": r.success, "x1": r.x1, "x2": r.x2, "objective": r.fun,
               "eps_alpha": r.eps_alpha, "area": area[k], "area_error": area_error[k],
               "active": ",".join(r.active), "conflict": ",".join(r.conflict)}
        row.update({f"margin_{name}": v for name, v in r.margins.items()})
        rows.append(row)
        if progress is not None:
            progress(k + 1)
    df = pd.DataFrame(rows)
    df.attrs.update(objective=proto.objective.name, method=method, time_s=time.perf_counter() - t0)
    return df
