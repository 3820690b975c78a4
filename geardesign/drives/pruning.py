"""The ratio split of a large drive enumerated under a cost limit: whole sub-trees of the split are left out
when a lower bound of their cost exceeds the limit, so that the search holds only the designs that can
still rank (:meth:`~geardesign.drives.search.Search.run` raises the limit until the ``top`` list is
complete within it).

The split is built from the output backwards: once the last stages' options are chosen (their ratio
product q), the torque into each of them is known to within the ratio tolerance (T_k = T_0·η_{<k}·U/q,
U the total ratio), so each chosen stage is bounded by its cost at that torque. A stage whose cost only
grows with its load along the power flow (:meth:`StageKind.cost_grows_with_load`: gear stages sized by
their strength, chains whose smallest feasible row grows with the load) is bounded per option and torque
cell (cells :data:`LOAD_CELL` wide, by its cost at the cell's lower edge on the stage's power curve,
n = P/ω); other stages by their load-free bound (:meth:`StageKind.bound`). The stages not chosen yet
count with their cheapest option at the least torque they can carry.

An option the stage cannot carry at a cell's lower edge (no module holds its checks there, or its tooth pair
reaches no standard centre distance) is bounded by +inf in that cell and above: by the same premise, a larger
torque does not make it feasible. Without this, a standard housing's many such pairs kept their load-free bound,
the limit rose past them round after round, and the conveyor of issue 35 was refused with 4·10⁶ designs left.
Where no option of a stage is feasible at all (every design infeasible), the bounds fall back to the load-free
ones, so that the search still evaluates designs and names the checks that fail.
"""
from __future__ import annotations

import math

import numpy as np

from .limits import COMBINATION_BLOCK, LOAD_CELL, MARGIN_TOL
from .stage_kinds import Designs, StageFlow

__all__ = ["StageBounds", "pruned_combinations"]

_CELL_OFFSET = 1 << 12     # cells of torques from 1e-3 to 1e9 N·m at LOAD_CELL = 1.1: -73 ... 218


class StageBounds:
    """Lower bounds (size mm², mass kg) of each stage's options at a torque, kept per (option, cell) between
    the limits tried. Needs the drive's input power (its power flow fixes each stage's power curve)."""

    def __init__(self, search):
        self.s = search
        drive, N = search.drive, len(search.stages)
        eta = drive._efficiencies()
        self.power_kw = [drive.power_kw * float(np.prod(eta[:k])) for k in range(N)]
        self.t0 = drive.power_kw * 1000.0 / (2.0 * math.pi * drive.n_in_rpm / 60.0)
        self.eta_before = [float(np.prod(eta[:k])) for k in range(N)]
        self.cache = [{} for _ in range(N)]
        self.rows_cache = [{} for _ in range(N)]     # a batch kind's (size, mass, holds) per row and cell
        self.free = [self._free(k) for k in range(N)]
        self.col = 0 if search.objective == "min_size" else 1     # the objective's column: size, mass
        self._least_of = [None] * N
        self.prune_infeasible = True        # an option infeasible at a cell's edge: +inf (see the module's text)

    def keep_infeasible(self) -> None:
        """Bound infeasible options by their load-free bounds from now on (a job where none is feasible)."""
        self.prune_infeasible = False
        self.cache = [{} for _ in self.cache]
        self._least_of = [None] * len(self._least_of)

    def least_of(self, k: int) -> np.ndarray:
        """Stage k's options' bounds at the least torque the stage can carry (the smallest ratios before it):
        below their bound at any torque they carry."""
        if self._least_of[k] is None:
            r_min = [float(o["ratio"].min()) for o in self.s.options[:k]]
            j = np.arange(self.s.options[k]["ratio"].size)
            T = np.full(j.size, self.t0 * self.eta_before[k] * math.prod(r_min))
            self._least_of[k] = self.at(k, j, T)[:, self.col]
        return self._least_of[k]

    def least(self) -> list:
        """Each stage's cheapest option at the least torque it can carry."""
        return [float(self.least_of(k).min()) for k in range(len(self.s.stages))]

    def _free(self, k: int) -> np.ndarray:
        """(options, 2) load-free bounds of stage k (0 for a kind that computes its cost in a batch)."""
        kind, st, opts = self.s.kinds[k], self.s.stages[k], self.s.options[k]
        if not kind.solved:
            return np.zeros((opts["ratio"].size, 2))
        size, mass = kind.bound(st, opts)
        return np.column_stack([np.broadcast_to(size, opts["ratio"].shape), np.broadcast_to(mass, opts["ratio"].shape)])

    def at(self, k: int, j: np.ndarray, torque_nm: np.ndarray) -> np.ndarray:
        """(n, 2) bounds of stage k's options ``j`` at input torques of at least ``torque_nm``."""
        kind, st = self.s.kinds[k], self.s.stages[k]
        if not kind.cost_grows_with_load(st):
            return self.free[k][j]
        uniq, inv = np.unique(self._keys(k, j, torque_nm), return_inverse=True)
        cache = self.cache[k]
        todo = [int(u) for u in uniq if int(u) not in cache]
        todo.sort(key=lambda u: (u % (2 * _CELL_OFFSET), u))     # by cell: options of one flow solved together
        if todo:
            self._fill(k, todo)
        return np.array([cache[int(u)] for u in uniq]).reshape(-1, 2)[inv.ravel()]

    def _keys(self, k: int, j: np.ndarray, torque_nm: np.ndarray) -> np.ndarray:
        cell = np.floor(np.log(torque_nm) / math.log(LOAD_CELL) + 1e-9).astype(np.int64) + _CELL_OFFSET
        return j.astype(np.int64) * (2 * _CELL_OFFSET) + cell

    def rows_within(self, k: int, j: np.ndarray, torque_nm: np.ndarray, others: np.ndarray, limit: float) -> tuple:
        """(design index, row) of the combinations' rows of batch stage k (options ``j`` at input torques of at
        least ``torque_nm``) whose bound, ``others`` (the other stages' bounds) plus the row's cost, is at most
        ``limit``: the rows that hold every check at the cell's edge flow (every row when none does)."""
        self.at(k, j, torque_nm)                         # fills the rows' cache
        rows = self.s.kinds[k].rows(self.s.stages[k])
        key = self._keys(k, j, torque_nm)
        uniq, inv = np.unique(key, return_inverse=True)
        cost = np.array([self.rows_cache[k][int(u)][self.col] for u in uniq])
        ok = np.array([self.rows_cache[k][int(u)][2] for u in uniq])
        ok = np.where(ok.any(axis=1, keepdims=True), ok, True)
        inv = inv.ravel()
        c, r = np.nonzero(ok[inv] & (others[:, None] + cost[inv] <= limit * (1 + 1e-12)))
        return c, rows[r]

    def _edge_flow(self, k: int, cell: int, ratio: float) -> StageFlow:
        """The flow into stage k at the lower edge of torque cell ``cell``, on the stage's power curve."""
        T = LOAD_CELL ** (cell - _CELL_OFFSET)
        n = self.power_kw[k] * 60_000.0 / (2.0 * math.pi * T)
        eta = self.s.stages[k].efficiency
        return StageFlow(n, T, n / ratio, T * ratio * eta)

    def _fill(self, k: int, keys: list) -> None:
        s, kind, st = self.s, self.s.kinds[k], self.s.stages[k]
        opts = s.options[k]
        js = [key // (2 * _CELL_OFFSET) for key in keys]
        flows = [self._edge_flow(k, key % (2 * _CELL_OFFSET), float(opts["ratio"][j])) for key, j in zip(keys, js)]
        options = [{name: col[j] for name, col in opts.items()} for j in js]
        if kind.solved:
            step = max(kind.solve_ahead(st, s.objective), 1) * 16
            for a in range(0, len(keys), step):
                before = kind.solve_count()
                sols = kind.solve_many(st, options[a:a + step], s.objective, flows[a:a + step])
                s.n_solves += kind.solve_count() - before
                for key, j, sol in zip(keys[a:a + step], js[a:a + step], sols):
                    self.cache[k][key] = (kind.solved_cost(st, sol) if sol["feasible"] else
                                          (math.inf, math.inf) if self.prune_infeasible else tuple(self.free[k][j]))
                s.report(f"bounds of stage '{st.name}'", a + len(sols), len(keys))
            return
        self._fill_batch(k, keys, js, flows)

    def _fill_batch(self, k, keys, js, flows) -> None:
        """A batch kind's bound per (option, cell): its cheapest row that holds every check at the cell's edge
        flow (the cheapest row when none holds)."""
        s, kind, st = self.s, self.s.kinds[k], self.s.stages[k]
        rows = kind.rows(st)
        n_rows = 1 if rows is None else rows.size
        js_a = np.repeat(np.asarray(js, dtype=np.int64), n_rows)
        f = np.repeat(np.array([[fl.n_in_rpm, fl.torque_in_nm, fl.n_out_rpm, fl.torque_out_nm] for fl in flows]),
                      n_rows, axis=0)
        view = Designs({name: col[js_a] for name, col in s.options[k].items()},
                       None if rows is None else np.tile(rows, len(js)), *f.T)
        b = kind.batch(st, view)
        size = np.broadcast_to(np.asarray(b.size_mm2, dtype=float), js_a.shape).reshape(len(js), n_rows)
        mass = np.broadcast_to(np.asarray(b.mass_kg, dtype=float), js_a.shape).reshape(len(js), n_rows)
        ok = np.ones(js_a.shape, dtype=bool)
        for v in b.margins.values():
            ok &= np.asarray(v, dtype=float) >= -MARGIN_TOL
        ok = ok.reshape(len(js), n_rows)
        for key, a, m, o in zip(keys, size, mass, ok):
            self.rows_cache[k][key] = (a.copy(), m.copy(), o.copy())
        any_ok = ok.any(axis=1, keepdims=True)
        use = np.where(any_ok, ok, True)
        bs = np.where(use, size, np.inf).min(axis=1)
        bm = np.where(use, mass, np.inf).min(axis=1)
        for key, a, m in zip(keys, bs, bm):
            self.cache[k][key] = (float(a), float(m))


def pruned_combinations(search, bounds: StageBounds, limit: float) -> tuple:
    """(idx, pruned): the ratio split's combinations (one option per stage, columns in stage order) whose
    cost bound is at most ``limit``, and how many sub-trees (partial combinations) were left out by it."""
    options, N, U_lo, U_hi = search.options, len(search.options), search.u_lo, search.u_hi
    col = bounds.col
    r_min = [float(o["ratio"].min()) for o in options]
    r_max = [float(o["ratio"].max()) for o in options]
    least = bounds.least()
    rest = [sum(least[:k]) for k in range(N + 1)]       # the stages before k, not chosen yet
    idx = np.zeros((1, 0), dtype=np.int64)
    q, lb = np.ones(1), np.zeros(1)
    pruned = 0
    for k in reversed(range(N)):
        ratio = options[k]["ratio"]
        lo_rest, hi_rest = math.prod(r_min[:k]), math.prod(r_max[:k])
        step = max(1, COMBINATION_BLOCK // max(ratio.size, 1))
        parts = []
        for a in range(0, q.size, step):
            new = q[a:a + step, None] * ratio[None, :]
            i, j = np.nonzero((new * hi_rest >= U_lo * (1 - 1e-12)) & (new * lo_rest <= U_hi * (1 + 1e-12)))
            i = i + a
            qq = q[i] * ratio[j]
            cheap = lb[i] + bounds.least_of(k)[j] + rest[k] <= limit * (1 + 1e-12)
            pruned += int(np.count_nonzero(~cheap))
            i, j, qq = i[cheap], j[cheap], qq[cheap]
            T = bounds.t0 * bounds.eta_before[k] * np.maximum(U_lo / qq, lo_rest)
            b = lb[i] + bounds.at(k, j, T)[:, col]
            keep = b + rest[k] <= limit * (1 + 1e-12)
            pruned += int(np.count_nonzero(~keep))
            parts.append((i[keep], j[keep], qq[keep], b[keep]))
        i = np.concatenate([p[0] for p in parts])
        j = np.concatenate([p[1] for p in parts])
        idx = np.column_stack([j, idx[i]])
        q = np.concatenate([p[2] for p in parts])
        lb = np.concatenate([p[3] for p in parts])
        if not q.size:
            return np.zeros((0, N), dtype=np.int64), pruned, None
    return idx, pruned, _rows(search, bounds, idx, lb, limit)


def _rows(search, bounds: StageBounds, idx: np.ndarray, lb: np.ndarray, limit: float):
    """(idx, {stage: rows}) of the combinations times the rows of the one stage that has rows, each row kept
    while the design's bound holds within ``limit`` (:meth:`StageBounds.rows_within`); None when no stage or
    more than one has rows (the search then takes every row)."""
    with_rows = [k for k, (kind, st) in enumerate(zip(search.kinds, search.stages)) if kind.rows(st) is not None]
    if len(with_rows) != 1 or not search.kinds[with_rows[0]].cost_grows_with_load(search.stages[with_rows[0]]):
        return None
    k = with_rows[0]
    ratios = np.column_stack([search.options[i]["ratio"][idx[:, i]] for i in range(idx.shape[1])])
    q = np.prod(ratios[:, k:], axis=1)
    lo_rest = math.prod(float(o["ratio"].min()) for o in search.options[:k])
    T = bounds.t0 * bounds.eta_before[k] * np.maximum(search.u_lo / q, lo_rest)
    own = bounds.at(k, idx[:, k], T)[:, bounds.col]
    c, r = bounds.rows_within(k, idx[:, k], T, lb - own, limit)
    return idx[c], {k: r}
