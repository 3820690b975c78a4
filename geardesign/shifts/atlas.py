"""Many tooth pairs at once: the optimal shifts and the region size for a table of z1 × z2."""
from __future__ import annotations

import functools
import time

import numpy as np
import pandas as pd

from .. import parallel
from ..errors import GearDesignError
from ..validate import ndim, require_bool, require_callable, require_int
from ..gears.checks import FEASIBILITY_TOL
from ..gears.geometry import exact_sum_nodes, mesh_geometry, mesh_geometry_float
from ..gears.mesh import Z_MAX, Z_MIN, Mesh
from .problem import DEFAULT_BOUNDS, Problem, validate_bounds
from . import centres
from .optimize import optimize_shifts

__all__ = ["shift_atlas"]

_ATLAS_N = 41   # grid nodes per axis of the batched first pass (area estimate and start points)
# The atlas's areas come from this coarse grid (spacing 0.11): each row carries ``area_error``,
# the change when every other node is dropped, a bound on the interpolation error; use
# :func:`geardesign.feasible_region` for one pair's exact area.


ATLAS_PAIRS_MAX = 100_000   # ~3 min at ~2 ms a pair on one machine; times the workers on a cluster
# pairs per chunk sent to a worker: at ~0.5-2 ms a pair, 200 pairs outweigh a task's ~2 ms of
# scheduling and transfer 50 times over (benchmarks/bench_parallel.py); 5000 keep progress moving
ATLAS_CHUNK_MIN, ATLAS_CHUNK_MAX = 200, 5000


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


def _pairs(z1_values, z2_values, upper_only, internal, limit=ATLAS_PAIRS_MAX):
    n = atlas_size(z1_values, z2_values, upper_only, internal)
    if n > limit:
        per = "" if limit == ATLAS_PAIRS_MAX else f" ({ATLAS_PAIRS_MAX:,} per worker)"
        raise GearDesignError(f"an atlas takes at most {limit:,} pairs{per}, these tooth counts make {n:,}")
    z1, z2 = _values("z1_values", z1_values), _values("z2_values", z2_values)
    Z1, Z2 = np.meshgrid(z1, z2, indexing="ij")
    Z1, Z2 = Z1.ravel(), Z2.ravel()
    keep = Z2 > Z1 if internal else (Z2 >= Z1 if upper_only else np.ones(Z1.shape, bool))
    return Z1[keep], Z2[keep]


_REACH = 6.0   # node spacings: checks whose boundary lies farther from a pair's start node are not candidates


@np.errstate(all="ignore")   # diverging candidates give NaN and inf: they are discarded at the end
def _batched_kkt(proto: Problem, Z1, Z2, start, h_node: float, iters: int = 10, bounds=None):
    """Every KKT candidate of every pair at once, for one-piece (smooth) objectives.

    Candidates: each pair of checks active (a vertex: m_a = m_b = 0) and each single check
    active with the objective's gradient normal to it (m_a = 0, ∇f × ∇m_a = 0), among the checks
    whose boundary lies (to first order) within ``_REACH`` node spacings ``h_node`` of the pair's
    start node. Newton runs on all (pair, candidate) systems in lockstep from the start node; a
    system leaves the loop once its step is below 1e-13 or it breaks down. A candidate counts
    when it converged, holds every check, lies in the window ``bounds``, and has multipliers >= 0.
    The window's four edges count as checks among the candidates (linear margins x − lo, hi − x): a pair
    whose region reaches past the window, as most with a large wheel (z2 > 180) do, has its optimum on an
    edge, and without them 36 % of the feasible pairs of z1 12..184 × z2 185..357 went one by one. The best
    valid candidate per pair is returned (NaN where none is valid; those pairs go to the one-by-one solver).
    """
    a_idx, b_idx, is_v, pair = _kkt_candidates(proto, Z1, Z2, start, h_node, bounds)
    z1, z2 = Z1[pair].astype(float), Z2[pair].astype(float)
    X = start[pair].copy()
    live = np.arange(pair.size)
    for _ in range(iters):
        if not live.size:
            break
        x1, x2, r = X[live, 0], X[live, 1], np.arange(live.size)
        geo = mesh_geometry(proto.mesh.unchecked(z1[live], z2[live]), 1.0, x1, x2, proto.full)
        M, G = _with_window(*proto.margins_and_gradients(geo), x1, x2, bounds)
        ma, ga = M[a_idx[live], r], G[a_idx[live], :, r]
        mb, gb = M[b_idx[live], r], G[b_idx[live], :, r]
        # the second equation: m_b = 0 at a vertex, the stationarity residual ∇f × ∇m_a = 0 on an edge
        cross = _cross(_piece_gradient(proto, geo).T, ga)
        dcross = np.zeros((live.size, 2))
        edge = np.flatnonzero(~is_v[live])
        if edge.size:
            dcross[edge] = _cross_slope(proto, z1[live[edge]], z2[live[edge]], x1[edge], x2[edge], a_idx[live[edge]],
                                        bounds)
        v = is_v[live]
        ok, step = _newton_step(ma, ga, np.where(v, mb, cross), np.where(v[:, None], gb, dcross))
        X[live] -= step
        # converged (a step below 1e-13) or broken down (no finite Newton step): leave the loop
        live = live[ok & (np.abs(step).max(axis=1) > 1e-13)]
    geo = mesh_geometry(proto.mesh.unchecked(z1, z2), 1.0, X[:, 0], X[:, 1], proto.full)
    M, G = _with_window(*proto.margins_and_gradients(geo), X[:, 0], X[:, 1], bounds)
    return _best_candidate(proto, geo, M, G, _piece_gradient(proto, geo).T, X, a_idx, b_idx, is_v, pair, Z1.size,
                           bounds)


def _with_window(M, G, x1, x2, bounds):
    """The checks' margins (K, n) and gradients (K, 2, n) with the window's four edges after them as linear
    checks x1 − lo, hi − x1, x2 − lo, hi − x2 (gradients ±1); unchanged without ``bounds``."""
    if bounds is None:
        return M, G
    lo, hi = bounds
    W = np.stack([x1 - lo, hi - x1, x2 - lo, hi - x2])
    GW = np.zeros((4, 2, W.shape[1]))
    GW[0, 0], GW[1, 0], GW[2, 1], GW[3, 1] = 1.0, -1.0, 1.0, -1.0
    return np.concatenate([M, W]), np.concatenate([G, GW])


def _kkt_candidates(proto: Problem, Z1, Z2, start, h_node: float, bounds=None):
    """The (candidate, pair) systems: every pair of checks a < b (a vertex) and every single check a (an
    edge) among those whose boundary lies within _REACH node spacings of the pair's start node, the window's
    edges (``bounds``) among the checks; returns a, b (0 for an edge), whether each is a vertex, and its pair."""
    K = len(proto.checks) + (0 if bounds is None else 4)
    geo0 = mesh_geometry(proto.mesh.unchecked(Z1.astype(float), Z2.astype(float)), 1.0, start[:, 0], start[:, 1],
                         proto.full)
    M0, G0 = _with_window(*proto.margins_and_gradients(geo0), start[:, 0], start[:, 1], bounds)
    near = (M0 <= _REACH * h_node * np.sqrt((G0 ** 2).sum(axis=1))) | ~np.isfinite(M0)    # (K, B)
    combos = np.array([(a, b) for a in range(K) for b in range(a + 1, K)] + [(a, -1) for a in range(K)])
    take = near[combos[:, 0]] & np.where(combos[:, 1:2] >= 0, near[np.maximum(combos[:, 1], 0)], True)
    cand, pair = np.nonzero(take)                   # rows: (candidate, pair)
    a_idx, b_idx = combos[cand, 0], combos[cand, 1]
    return a_idx, np.maximum(b_idx, 0), b_idx >= 0, pair


def _piece_gradient(proto: Problem, geo):
    """∇f of the (one-piece) objective, shape (2, n)."""
    return proto.piece_gradients(geo)[0]


def _cross(gp, ga):
    """∇f × ∇m_a, rows of (n, 2) gradients: zero where ∇f is normal to the check's boundary."""
    return gp[:, 0] * ga[:, 1] - gp[:, 1] * ga[:, 0]


def _cross_slope(proto: Problem, z1, z2, x1, x2, a_rows, bounds=None, h: float = 1e-6):
    """∂(∇f × ∇m_a)/∂(x1, x2) of edge candidates, (n, 2), by central differences of the analytic gradients
    (a window edge's among them when ``bounds`` are given: see :func:`_with_window`)."""
    e_mesh, e_rows = proto.mesh.unchecked(z1, z2), np.arange(z1.size)
    out = np.empty((z1.size, 2))
    for j, (dx1, dx2) in enumerate(((h, 0.0), (0.0, h))):
        side = []
        for sgn in (1.0, -1.0):
            geo_s = mesh_geometry(e_mesh, 1.0, x1 + sgn * dx1, x2 + sgn * dx2, proto.full)
            G_s = proto.margin_gradients(geo_s)
            if bounds is not None:
                G_s = _with_window(np.zeros((0, z1.size)), G_s, x1, x2, bounds)[1]
            G_s = G_s[a_rows, :, e_rows]
            side.append(_cross(_piece_gradient(proto, geo_s).T, G_s))
        out[:, j] = (side[0] - side[1]) / (2 * h)
    return out


def _newton_step(ma, ga, r2, j2):
    """Whether each 2×2 Newton system (m_a, r2) with rows ∇m_a, j2 has a finite solution, and the step
    by Cramer's rule, each component clipped to ±0.2 (0 where it has none)."""
    det = ga[:, 0] * j2[:, 1] - ga[:, 1] * j2[:, 0]
    ok = np.isfinite(det) & (np.abs(det) > 1e-14) & np.isfinite(ma) & np.isfinite(r2)
    sdet = np.where(ok, det, 1.0)
    d1 = np.where(ok, (ma * j2[:, 1] - r2 * ga[:, 1]) / sdet, 0.0)
    d2 = np.where(ok, (r2 * ga[:, 0] - ma * j2[:, 0]) / sdet, 0.0)
    return ok, np.clip(np.column_stack([d1, d2]), -0.2, 0.2)


def _best_candidate(proto, geo, M, G, gp, X, a_idx, b_idx, is_v, pair, B, bounds=None):
    """Each pair's best converged, feasible KKT candidate (NaN where none)."""
    rows = np.arange(X.shape[0])
    x1, x2 = X[:, 0], X[:, 1]
    ma, mb = M[a_idx, rows], M[b_idx, rows]
    ga, gb = G[a_idx, :, rows], G[b_idx, :, rows]
    cross = gp[:, 0] * ga[:, 1] - gp[:, 1] * ga[:, 0]
    conv = (np.abs(ma) < 1e-11) & np.where(is_v, np.abs(mb) < 1e-11, np.abs(cross) < 1e-9)
    feas = (M >= -FEASIBILITY_TOL).all(axis=0)
    if bounds is not None:
        feas &= (X >= bounds[0] - 1e-12).all(axis=1) & (X <= bounds[1] + 1e-12).all(axis=1)
    # multipliers: ∇f = −Σ λ ∇m  (λ >= 0 for a maximum)
    det = ga[:, 0] * gb[:, 1] - ga[:, 1] * gb[:, 0]
    sdet = np.where(np.abs(det) > 1e-14, det, 1.0)
    lam_a_v = (-gp[:, 0] * gb[:, 1] + gp[:, 1] * gb[:, 0]) / sdet
    lam_b_v = (-ga[:, 0] * gp[:, 1] + ga[:, 1] * gp[:, 0]) / sdet
    lam_a_e = -(gp * ga).sum(axis=1) / np.maximum((ga * ga).sum(axis=1), 1e-300)
    kkt = np.where(is_v, (lam_a_v >= -1e-9) & (lam_b_v >= -1e-9), lam_a_e >= -1e-9)
    valid = conv & feas & kkt & np.isfinite(x1) & np.isfinite(x2)
    f = np.where(valid, proto.pieces(geo)[0], -np.inf)
    best = np.full(B, -np.inf)
    np.maximum.at(best, pair, f)
    out = np.full((B, 2), np.nan)
    win = valid & (f == best[pair])
    out[pair[win]] = X[win]
    return out


_CX = np.array([0.0, 1.0, 1.0, 0.0])     # a cell's corners, counter-clockwise, in node spacings
_CY = np.array([0.0, 0.0, 1.0, 1.0])
_DX, _DY = np.roll(_CX, -1) - _CX, np.roll(_CY, -1) - _CY


def grid_areas(F: np.ndarray, h: float) -> np.ndarray:
    """Area where F >= 0 for each grid ``F[..., i, j]`` of nodes ``h`` apart, F taken linear along
    each cell edge (the zero contour's linear interpolation, so the error is ~ perimeter × h², not
    perimeter × h as a node count would give). A cell with all four corners >= 0 counts whole; a
    cell the contour crosses counts the polygon of its corners >= 0 and its edges' zero crossings,
    walked round the cell, by the shoelace formula. Holes are subtracted, pieces added.

    >>> g = np.linspace(-1.0, 1.0, 41)
    >>> X1, X2 = np.meshgrid(g, g, indexing="ij")
    >>> round(float(grid_areas(0.5 - np.abs(X1) - np.abs(X2), g[1] - g[0])), 12)   # a square of diagonal 1
    0.5
    """
    P = (F >= 0).view(np.uint8)
    n_pos = P[..., :-1, :-1] + P[..., 1:, :-1] + P[..., 1:, 1:] + P[..., :-1, 1:]
    whole = np.count_nonzero(n_pos == 4, axis=(-1, -2))
    *lead, i, j = np.nonzero((n_pos > 0) & (n_pos < 4))
    a = np.stack([F[(*lead, i, j)], F[(*lead, i + 1, j)], F[(*lead, i + 1, j + 1)], F[(*lead, i, j + 1)]], axis=1)
    p = a >= 0
    cross = p != np.roll(p, -1, axis=1)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.where(cross, a / (a - np.roll(a, -1, axis=1)), 0.0)
    # eight slots per cell: corner k, then the zero crossing on edge k (k -> k + 1)
    X, Y, used = np.empty((a.shape[0], 8)), np.empty((a.shape[0], 8)), np.empty((a.shape[0], 8), bool)
    X[:, 0::2], Y[:, 0::2], used[:, 0::2] = _CX, _CY, p
    X[:, 1::2], Y[:, 1::2], used[:, 1::2] = _CX + t * _DX, _CY + t * _DY, cross
    # an unused slot repeats the used one before it (cyclically): an edge of zero length
    last = np.maximum.accumulate(np.where(np.tile(used, 2), np.arange(16), -1), axis=1)[:, 8:] % 8
    X, Y = np.take_along_axis(X, last, 1), np.take_along_axis(Y, last, 1)
    part = 0.5 * (X * np.roll(Y, -1, axis=1) - np.roll(X, -1, axis=1) * Y).sum(axis=1)
    shape = F.shape[:-2]
    owner = np.ravel_multi_index(lead, shape) if shape else np.zeros(part.size, dtype=np.intp)
    total = whole.ravel() + np.bincount(owner, weights=part, minlength=max(1, int(np.prod(shape, dtype=int))))
    return h * h * total.reshape(shape)


def _row_at(proto: Problem, z1, z2, x) -> dict:
    geo = mesh_geometry_float(proto.mesh.unchecked(z1, z2), 1.0, x[0], x[1])
    M = proto.margins(geo)
    fun = proto.fun(geo)
    tol = 1e-8
    row = {"z1": z1, "z2": z2, "feasible": True, "x1": float(x[0]), "x2": float(x[1]),
           "objective": float(fun), "eps_alpha": float(geo["eps_alpha"]), "area": np.nan, "area_error": np.nan,
           "active": ",".join(n for n, m in zip(proto.names, M) if abs(m) <= tol), "conflict": ""}
    # a margin the batched Newton cannot tell from zero is zero (no 1e-16 "dips" in sweeps)
    row.update({f"margin_{n}": (0.0 if abs(float(m)) <= tol else float(m)) for n, m in zip(proto.names, M)})
    return row


def _first_pass(proto: Problem, Z1, Z2, bounds):
    """Every pair's margins on the _ATLAS_N² grid, chunk by chunk: (area, area_error, best feasible
    node, least infeasible node), the nodes NaN where they do not apply."""
    lo, hi = bounds
    g = exact_sum_nodes(lo, hi, _ATLAS_N)     # one operating angle per x-sum diagonal
    X1, X2 = (a.ravel() for a in np.meshgrid(g, g, indexing="ij"))
    chunk = max(1, 200_000 // X1.size)
    area, area_error = np.zeros(Z1.size), np.zeros(Z1.size)
    start, least = np.full((Z1.size, 2), np.nan), np.full((Z1.size, 2), np.nan)

    def node_values(geo):
        """The smallest margin (-1 where a gear does not exist) and the objective where feasible."""
        if not proto.checks:
            return {"F": np.ones(geo["a"].shape), "score": proto.pieces(geo).min(axis=0)}
        # the least margin check by check, as Problem.margins(geo).min(axis=0) (NaN → −inf first, then the same
        # minimum in the same order): the (checks × block) stack was an array above glibc's 128 kB mmap threshold,
        # mapped afresh at every block on a Dask worker (see geometry.BLOCK)
        m_min = None
        with np.errstate(all="ignore"):   # nodes where a gear does not exist: margin NaN → −inf
            for v in proto._margin_values(geo):
                v = np.fmax(v, -np.inf)
                m_min = v if m_min is None else np.minimum(m_min, v)
        m_min = np.broadcast_to(m_min, np.shape(geo["_x1"]))
        P = proto.pieces(geo).min(axis=0) if proto.objective.kind != "margin" else m_min
        return {"F": np.where(np.isfinite(m_min), m_min, -1.0), "score": np.where(m_min >= 0, P, -np.inf)}

    for s in range(0, Z1.size, chunk):
        z1c, z2c = Z1[s:s + chunk, None], Z2[s:s + chunk, None]
        # block by block: only the two node values are stored for the whole chunk
        nodes = mesh_geometry(proto.mesh.unchecked(z1c, z2c), 1.0, X1[None, :], X2[None, :], proto.full,
                              then=node_values)
        F, score = nodes["F"].reshape(-1, _ATLAS_N, _ATLAS_N), nodes["score"]
        area[s:s + chunk] = grid_areas(F, g[1] - g[0])
        # the same contour on every other node: the change bounds the interpolation error
        area_error[s:s + chunk] = np.abs(area[s:s + chunk] - grid_areas(F[:, ::2, ::2], g[2] - g[0]))
        best, worst = np.argmax(score, axis=1), np.argmax(nodes["F"], axis=1)
        ok = np.isfinite(score[np.arange(len(best)), best])
        start[s:s + chunk][ok] = np.column_stack([X1[best], X2[best]])[ok]
        least[s:s + chunk][~ok] = np.column_stack([X1[worst], X2[worst]])[~ok]
    return area, area_error, start, least


def _polish(proto: Problem, Z1, Z2, start, h_node: float, batch: int = 400, bounds=None):
    """The batched KKT Newton (:func:`_batched_kkt`) for every pair with a start node; NaN elsewhere."""
    fast = np.full((Z1.size, 2), np.nan)
    has = np.flatnonzero(~np.isnan(start[:, 0]))
    for s in range(0, has.size, batch):
        sel = has[s:s + batch]
        fast[sel] = _batched_kkt(proto, Z1[sel], Z2[sel], start[sel], h_node, bounds=bounds)
    return fast


def _row_solved(z1: int, z2: int, start, solve_kw: dict) -> dict:
    """A row from optimize_shifts on one pair (its own starts and, when infeasible, its conflict)."""
    r = optimize_shifts(z1, z2, start=start, **solve_kw)
    row = {"z1": z1, "z2": z2, "feasible": r.success, "x1": r.x1, "x2": r.x2, "objective": r.fun,
           "eps_alpha": r.eps_alpha, "area": np.nan, "area_error": np.nan, "active": ",".join(r.active),
           "conflict": ",".join(r.conflict)}
    row.update({f"margin_{name}": v for name, v in r.margins.items()})
    return row


def shift_atlas(z1_values, z2_values, objective: str = "max_x_sum", checks=None, method: str = "exact",
                tol: float | None = None, rack=None, tip_shortening: bool = True, bounds=DEFAULT_BOUNDS,
                upper_only: bool = True, progress=None, beta_deg: float = 0.0, internal: bool = False,
                face_width_mm: float | None = None, *, client=None, workers=None) -> pd.DataFrame:
    """One row per tooth pair: feasible, x1, x2, objective, all margins, active checks, region area.

    The first pass is batched: every pair's margins on a 41×41 grid of (x1, x2) in one
    vectorised call per chunk of pairs. It gives the region area (traced on that grid
    from the zero contour of the smallest margin) and each pair's best node, from which ``method`` then polishes
    the optimum (``grid`` keeps the node). A pair whose region holds no node (a sliver, as for 8 to 11
    pinion teeth) starts the batched Newton from its least infeasible node; only pairs the batched
    Newton cannot settle (no valid KKT point: infeasible pairs, whose conflict is then searched) are
    solved one by one. ``upper_only`` keeps z2 >= z1 (an internal pair
    always needs z2 > z1). ``progress`` is called with the number of pairs done.
    ``beta_deg``, ``internal``, ``face_width_mm``: the kind of every pair, as for
    :class:`~geardesign.gears.mesh.Mesh`; lengths are per unit module (m = 1), so ``face_width_mm``
    is b/m here.

    ``client`` (a ``dask.distributed.Client``) or ``workers`` (a local cluster of that many
    processes, made for the call): the pairs go out in chunks of at least ATLAS_CHUNK_MIN, the
    table is the serial one bit for bit, and the limit of ATLAS_PAIRS_MAX pairs is multiplied by
    the number of workers (see :mod:`geardesign.parallel`).

    >>> df = shift_atlas([17], [26, 40])
    >>> list(df.columns[:6]), bool(df.feasible.all())
    (['z1', 'z2', 'feasible', 'x1', 'x2', 'objective'], True)
    """
    t0 = time.perf_counter()
    internal = require_bool("internal", internal)
    bounds = validate_bounds(bounds)
    require_callable("progress", progress)
    n_workers = parallel.slots(client, workers)
    Z1, Z2 = _pairs(z1_values, z2_values, upper_only, internal, ATLAS_PAIRS_MAX * n_workers)
    if Z1.size == 0:
        raise GearDesignError("shift_atlas: no (z1, z2) pair to solve (with upper_only, z2 must be >= z1; "
                              "internal pairs need z2 > z1)")
    setup = dict(first=(int(Z1[0]), int(Z2[0])), objective=objective, checks=checks, method=method, tol=tol,
                 rack=rack, tip_shortening=tip_shortening, bounds=bounds, beta_deg=beta_deg, internal=internal,
                 face_width_mm=face_width_mm)
    proto = _proto(setup)          # validates the inputs here, before any chunk goes out
    if not parallel.requested(client, workers):
        df = _atlas_rows(proto, Z1, Z2, setup, progress)
    else:
        parts = parallel.map_chunks(
            functools.partial(_atlas_chunk, setup),
            [(Z1[s], Z2[s]) for s in parallel.chunk_slices(Z1.size, n_workers, ATLAS_CHUNK_MIN, ATLAS_CHUNK_MAX)],
            client=client, workers=workers, progress=None if progress is None else lambda done, total: progress(done))
        df = pd.concat(parts, ignore_index=True)
    df.attrs.update(objective=proto.objective.name, method=method, time_s=time.perf_counter() - t0)
    return df


def _proto(setup: dict) -> Problem:
    """The problem of the atlas's first pair: its checks, objective and kind serve every pair."""
    mesh = Mesh(*setup["first"], setup["rack"], setup["tip_shortening"], setup["beta_deg"], setup["internal"],
                setup["face_width_mm"])
    return Problem(mesh, setup["checks"], setup["objective"], 1.0)


def _atlas_chunk(setup: dict, pairs) -> pd.DataFrame:
    """The rows of one chunk of pairs, on a worker: the serial computation on these pairs."""
    return _atlas_rows(_proto(setup), *pairs, setup, None)


def _atlas_rows(proto: Problem, Z1, Z2, setup: dict, progress) -> pd.DataFrame:
    """The atlas's table for the pairs Z1, Z2 (each row depends on its own pair only)."""
    method, bounds = setup["method"], setup["bounds"]
    area, area_error, start, least = _first_pass(proto, Z1, Z2, bounds)
    fast = np.full((Z1.size, 2), np.nan)
    if method == "exact" and proto.objective.kind == "smooth":
        # pairs with no feasible node (a sliver thinner than the grid) start from their least infeasible node
        fast = _polish(proto, Z1, Z2, np.where(np.isnan(start), least, start),
                       (bounds[1] - bounds[0]) / (_ATLAS_N - 1), bounds=bounds)
    elif method == "exact" and centres.serves(proto):
        # max_margin: every pair's Chebyshev centre at once, as optimize_shifts finds each (the same bits)
        x, ok, _, _ = centres.solve_pairs(proto, Z1.astype(float), Z2.astype(float), *bounds)
        fast[ok] = x[:, ok].T
    solve_kw = dict(objective=setup["objective"], checks=setup["checks"], method=method, tol=setup["tol"],
                    rack=proto.rack, tip_shortening=setup["tip_shortening"], bounds=bounds,
                    beta_deg=setup["beta_deg"], internal=setup["internal"], face_width_mm=setup["face_width_mm"],
                    grid_n=_ATLAS_N if method == "grid" else None)
    rows = []
    for k, (z1, z2) in enumerate(zip(Z1.tolist(), Z2.tolist())):
        if np.isnan(fast[k, 0]):    # not settled in the batch: one by one, with the conflict search
            rows.append(_row_solved(z1, z2, None if np.isnan(start[k, 0]) else start[k], solve_kw))
        else:
            rows.append(_row_at(proto, z1, z2, fast[k]))
        rows[-1].update(area=area[k], area_error=area_error[k])
        if progress is not None:
            progress(k + 1)
    return pd.DataFrame(rows)
