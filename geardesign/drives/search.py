"""The search behind :meth:`~geardesign.drives.drive.Drive.optimize`, as named steps over index arrays.

1. **options**: each stage's alternatives inside the ratio window its neighbours leave it
   (:meth:`StageKind.options`);
2. **combinations**: one option per stage whose product meets the total ratio, built stage by
   stage with the remaining stages' range as a bound;
3. **rows**: the combinations times the alternatives of equal ratio (:meth:`StageKind.rows`, e.g.
   chain catalog rows); then the flow of every design (vectorised);
4. **batch checks**: every margin that a stage kind computes in a batch (:meth:`StageKind.batch`),
   the motor's and every key's by its capacity;
5. **branch and bound**: the designs grouped by the options of the kinds solved one at a time
   (``solved``: gear pairs and their shifts), solved best bound first while a bound
   (:meth:`StageKind.bound`) can still enter the ``top`` list;
6. **result**: the ranked table, the closest failing designs, the best design fixed and analysed.

Every stage is reached through its :class:`~geardesign.drives.stage_kinds.StageKind`; nothing here
knows a kind by name.
"""
from __future__ import annotations

import heapq
import math
import time
from dataclasses import replace
from functools import lru_cache

import numpy as np
import pandas as pd

from .. import parallel
from ..errors import GearDesignError
from . import key
from .drive_results import DriveOptimum
from .limits import (CANDIDATES_MAX, COMBINATION_BLOCK, COMBINATIONS_MAX, INFEASIBLE_SHOWN, LOAD_BOUNDS_MAX,
                     LOAD_CELL, MARGIN_TOL, PLAIN_DESIGNS_MAX, PRUNE_GROWTH)
from .pruning import StageBounds, pruned_combinations
from .stage_kinds import Designs, StageFlow, kind_of   # Designs: re-exported here, where it was defined before
from .spread import solve_spread
from .shafting import thicker_bores
from .stages import Shaft

__all__ = ["Search", "Designs", "min_margin", "WALK_LABEL"]

WALK_LABEL = "drive: designs"     # the branch and bound's step, the one a progress(done, total) callback follows
RESIZE_ROUNDS = 4     # a design's gear stages sized again for its shafts' K_Hβ at most this many times


class _Large(Exception):
    """The ratio split has more designs than the plain enumeration takes (PLAIN_DESIGNS_MAX)."""


def min_margin(margins: dict):
    """(smallest margin, its check) of a {check: margin} dict; margins within MARGIN_TOL of 0 are 0."""
    if not margins:
        return math.inf, ""
    name = min(margins, key=lambda k: (margins[k] if np.isfinite(margins[k]) else -math.inf))
    v = float(margins[name])
    return (0.0 if abs(v) <= MARGIN_TOL else v), name


class Search:
    """One :meth:`Drive.optimize` call: the designs (one option per stage × rows) as index arrays,
    their flow and batch margins, and what the branch and bound has evaluated (``ex``)."""

    def __init__(self, drive, U: float, tol: float, objective: str, top: int, t0: float):
        self.drive, self.stages, self.U, self.tol = drive, drive.stages, U, tol
        self.kinds = [kind_of(st) for st in self.stages]
        self.objective, self.top, self.t0 = objective, top, t0
        self.u_lo, self.u_hi = U * (1 - tol), U * (1 + tol)
        self.solved_k = [k for k, kind in enumerate(self.kinds) if kind.solved]
        self.n_solves = 0
        # groups of the walk looked at ahead: the most any solved stage takes at once (StageKind.solve_ahead)
        self.look_ahead = max([1] + [self.kinds[k].solve_ahead(self.stages[k], objective) for k in self.solved_k])

    def run(self, progress=None, where=None) -> DriveOptimum:
        """The search; ``progress(label, done, total)`` is told how far each long step is (None: nothing);
        ``where``: client= / workers= of :func:`geardesign.parallel.cluster` for the
        options the walk solves together (:func:`geardesign.drives.spread.solve_spread`; empty: here)."""
        self.report = progress or (lambda label, done, total: None)
        self.n_pruned, self._bounds = 0, None
        why = self._stage_options()          # 1: options per stage
        if not why:
            try:                             # 2: ratio combinations (all of them, when few enough)
                why = self._combinations(PLAIN_DESIGNS_MAX if self._prunable() else None)
            except _Large:
                return self._run_pruned()
        if why:
            return self.no_split(why)
        self._designs()                      # 3: the combinations times the rows, their flow
        self.batch_checks()                  # 4: every batch margin, key and motor check at once
        with parallel.cluster(**(where or {})) as self.client:
            self.branch_and_bound()      # 5: the solved stages, best bound first
        return self.result()                 # 6: ranked table, the closest failing designs, the best

    def _prunable(self) -> bool:
        """A split too large to hold whole may be enumerated under a cost limit (:mod:`.pruning`): the
        objectives of size and mass, with the input power given (it fixes each stage's power curve)."""
        return self.drive.power_kw is not None and self.objective in ("min_size", "min_mass")

    def _run_pruned(self) -> DriveOptimum:
        """Steps 2-6 under a cost limit raised by PRUNE_GROWTH from the cheapest bound until the ``top``
        list is complete within it (a design left out costs more than its bound, so more than the limit)
        or nothing is left out."""
        self._bounds = bounds = StageBounds(self)
        limit = sum(bounds.least())          # every stage's cheapest option at the least torque it can carry
        if not math.isfinite(limit):         # a stage none of whose options is feasible: the failing designs named
            bounds.keep_infeasible()
            limit = sum(bounds.least())
        while True:
            idx, pruned, with_rows = pruned_combinations(self, bounds, limit)
            n = with_rows[0].shape[0] if with_rows is not None else idx.shape[0] * self._rows_factor()
            if n > CANDIDATES_MAX:
                raise GearDesignError(
                    f"{n} designs (ratio combinations x chain rows) could still rank after "
                    f"{pruned} sub-trees of the ratio split were bounded out, more than {CANDIDATES_MAX}: narrow "
                    f"the stages' z1_range, z2_max, ratio_range, the chain's strands or catalog, or ratio_tol")
            self.report("drive: bounding the ratio split", 1, 1)
            if n:
                self.idx, self.n_comb, self.n_pruned = idx, idx.shape[0], pruned
                self._designs(with_rows)
                self.batch_checks()
                # here, not on the cluster: the bounds' solves are batched per torque cell already
                self.client = None
                self.branch_and_bound()
                cost = np.sort(self.ex["cost"][self.ex["feas"]])
                if pruned == 0 or (cost.size >= self.top and cost[self.top - 1] <= limit):
                    return self.result()
                if cost.size >= self.top:    # the list is complete within the cost of its last design
                    limit = max(limit, float(cost[self.top - 1]))
                    continue
            elif pruned == 0:
                return self.no_split(f"no combination of the stages' tooth pairs gives u = {self.U:g} ± "
                                     f"{100 * self.tol:g} %")
            limit *= PRUNE_GROWTH

    # -- 1-3: the designs
    def _designs(self, with_rows=None) -> None:
        """The combinations times the rows (``with_rows``: (idx, {stage: rows}) already chosen), their
        ratios, flow and ratio error."""
        if with_rows is None:
            self._expand_rows()
        else:
            self.idx, self.rows = with_rows
            self.n_cand = self.idx.shape[0]
        self.ratios = np.column_stack([self.options[k]["ratio"][self.idx[:, k]] for k in range(len(self.stages))])
        self.n, self.T, self.P = self.drive._flow(self.ratios)
        self.err = np.abs(np.prod(self.ratios, axis=1) - self.U) / self.U
        return ""

    def _stage_options(self) -> str:
        """Each stage's options inside the window its neighbours leave it."""
        stages, N = self.stages, len(self.stages)
        span = [kind.ratio_span(s) for kind, s in zip(self.kinds, stages)]
        self.options = []
        for k, st in enumerate(stages):
            lo_rest = math.prod(span[j][0] for j in range(N) if j != k)
            hi_rest = math.prod(span[j][1] for j in range(N) if j != k)
            w_lo, w_hi = self.u_lo / hi_rest, self.u_hi / lo_rest
            opts = self.kinds[k].options(st, w_lo, w_hi)
            if opts["ratio"].size == 0:
                reach = (math.prod(a for a, _ in span), math.prod(b for _, b in span))
                return (f"stage '{st.name}' has no option with a ratio in [{w_lo:.4g}, {w_hi:.4g}], the window "
                        f"the other stages leave it for u = {self.U:g} ± {100 * self.tol:g} % (the stages' ratio "
                        f"ranges reach u in [{reach[0]:.4g}, {reach[1]:.4g}])")
            self.options.append(opts)
        return ""

    def _combinations(self, most=None) -> str:
        """One option per stage, the product inside the ratio window (the remaining stages' range
        bounds each partial product). Each step is counted before it is built, in blocks of partial
        products (a step's pairs never all in memory at once), and refused by name beyond
        COMBINATIONS_MAX."""
        options, N = self.options, len(self.options)
        idx = np.zeros((1, 0), dtype=np.int64)
        prod = np.ones(1)
        for k, o in enumerate(options):
            rest_lo = math.prod(float(options[j]["ratio"].min()) for j in range(k + 1, N))
            rest_hi = math.prod(float(options[j]["ratio"].max()) for j in range(k + 1, N))
            ratio = o["ratio"]
            step = max(1, COMBINATION_BLOCK // max(ratio.size, 1))
            blocks = [slice(s, s + step) for s in range(0, prod.size, step)]
            keeps, total = [], 0
            for b in blocks:
                new = prod[b, None] * ratio[None, :]
                keeps.append(np.nonzero((new * rest_hi >= self.u_lo * (1 - 1e-12))
                                        & (new * rest_lo <= self.u_hi * (1 + 1e-12))))
                total += keeps[-1][0].size
                if most is not None and total * self._rows_factor() > most:
                    raise _Large(total)     # known before the rest of the step is built
            if total * (k + 1) > COMBINATIONS_MAX * N:
                raise GearDesignError(f"the ratio split has {total} combinations of the first {k + 1} stages' "
                                      f"options, more than the {COMBINATIONS_MAX} this search holds in memory: "
                                      f"narrow the stages' z1_range, z2_max or ratio_range, or ratio_tol")
            i = np.concatenate([ii + b.start for (ii, _), b in zip(keeps, blocks)]) if keeps else np.zeros(0, np.int64)
            j = np.concatenate([jj for _, jj in keeps]) if keeps else np.zeros(0, np.int64)
            idx = np.column_stack([idx[i], j])
            prod = prod[i] * ratio[j]
        if prod.size == 0:
            return f"no combination of the stages' tooth pairs gives u = {self.U:g} ± {100 * self.tol:g} %"
        self.idx, self.n_comb = idx, prod.size
        return ""

    def _rows_factor(self) -> int:
        """How many designs one ratio combination makes (the product of the stages' row counts)."""
        return math.prod(r.size for r in (k.rows(st) for k, st in zip(self.kinds, self.stages)) if r is not None)

    def _expand_rows(self) -> None:
        """The combinations times the rows of every stage that has rows (e.g. chain catalog rows)."""
        idx, rows = self.idx, {}
        for k, (kind, st) in enumerate(zip(self.kinds, self.stages)):
            r = kind.rows(st)
            if r is None:
                continue
            total = idx.shape[0] * r.size
            if total > CANDIDATES_MAX:
                raise GearDesignError(f"{total} designs (ratio combinations x chain rows) exceed {CANDIDATES_MAX}: "
                                      f"narrow the stages' ranges, strands or catalog")
            idx = np.repeat(idx, r.size, axis=0)
            for kk in rows:
                rows[kk] = np.repeat(rows[kk], r.size)
            rows[k] = np.tile(r, idx.shape[0] // r.size)
        self.idx, self.rows, self.n_cand = idx, rows, idx.shape[0]

    def option_at(self, k: int, c) -> dict:
        """Stage k's option columns at design(s) ``c``."""
        return {name: col[self.idx[c, k]] for name, col in self.options[k].items()}

    def flow_at(self, k: int, c: int) -> StageFlow:
        return StageFlow(float(self.n[c, k]), float(self.T[c, k]), float(self.n[c, k + 1]), float(self.T[c, k + 1]))

    # -- 4: every margin computed in a batch
    def batch_checks(self) -> None:
        n_cand, T = self.n_cand, self.T
        margins: dict = {("motor", name): v for name, v in self.drive._motor_margins(self.P[:, 0]).items()}
        self.batch_size, self.batch_mass, self.info = np.zeros(n_cand), np.zeros(n_cand), {}
        for k, (kind, st) in enumerate(zip(self.kinds, self.stages)):
            view = Designs(self.option_at(k, slice(None)), self.rows.get(k), self.n[:, k], T[:, k], self.n[:, k + 1],
                           T[:, k + 1])
            b = kind.batch(st, view)
            margins.update({(st.name, name): v for name, v in b.margins.items()})
            self.batch_size += b.size_mm2
            self.batch_mass += b.mass_kg
            self.info[k] = b.info
        margins.update(self._key_margins())
        self.names = list(margins)
        M = (np.column_stack([np.asarray(margins[k], dtype=float) for k in self.names]) if self.names
             else np.zeros((n_cand, 0)))
        self.M = np.where(np.abs(M) <= MARGIN_TOL, 0.0, M)
        Mf = np.where(np.isnan(self.M), -np.inf, self.M)
        self.batch_min = Mf.min(axis=1) if self.names else np.full(n_cand, np.inf)
        self.batch_arg = Mf.argmin(axis=1) if self.names else np.zeros(n_cand, dtype=np.int64)
        self.batch_ok = self.batch_min >= 0

    def _key_margins(self) -> dict:
        """Every hub's key by its capacity: one key where it holds, else two (as key.select picks)."""
        margins, self.key_n = {}, {}
        for sh in self.drive.shafts:
            _, caps = key_caps(sh)
            Ts = self.T[:, sh.at]
            one = (Ts <= min(caps[1])) | (sh.max_keys < 2)
            crush = np.where(one, caps[1][0], caps[2][0])
            shear = np.where(one, caps[1][1], caps[2][1])
            margins[(f"key '{sh.name}'", "crushing")] = 1.0 - Ts / crush
            margins[(f"key '{sh.name}'", "shear")] = 1.0 - Ts / shear
            self.key_n[sh.name] = np.where(one, 1, 2)
        return margins

    # -- 5: the solved stages, branch and bound
    def _flow_groups(self) -> dict:
        """For each load-dependent solved stage, each design's group of equal input flow."""
        groups = {}
        for k in self.solved_k:
            if self.kinds[k].load_dependent(self.stages[k]):
                groups[k] = _row_groups(self.n[:, k], self.T[:, k])
        return groups

    def _solution(self, k: int, c: int) -> dict:
        """Stage k's option at design c solved (kept per option, and per input flow when it depends on it)."""
        key = self._key(k, c)
        if key not in self._solved:
            kind = self.kinds[k]
            before = kind.solve_count()
            flow = self.flow_at(k, c) if k in self.flow_group else None
            self._solved[key] = kind.solve(self.stages[k], self.option_at(k, c), self.objective, flow)
            self.n_solves += kind.solve_count() - before
        return self._solved[key]

    def _key(self, k: int, c: int) -> tuple:
        j = int(self.idx[c, k])
        return (k, j, int(self.flow_group[k][c])) if k in self.flow_group else (k, j)

    def _solve_ahead(self, firsts) -> None:
        """The unsolved options of the groups whose first designs are ``firsts`` (the walk's next ones
        within the bound so far: one the walk then stops before costs a solve, never a result), each
        stage's solved together (:meth:`StageKind.solve_many`), so that their fixed costs are shared.
        A stage is solved ahead only when the walk's current group (``firsts[0]``) needs it: the window
        is then solved as one chunk, not topped up by one option per step (which would share nothing)."""
        for k in self.solved_k:
            ahead = self.kinds[k].solve_ahead(self.stages[k], self.objective)
            if not ahead or self._key(k, firsts[0]) in self._solved:
                continue
            todo: dict = {}
            for c in firsts[:ahead]:
                todo.setdefault(self._key(k, c), c)
            todo = {key: c for key, c in todo.items() if key not in self._solved}
            if len(todo) < 2:
                continue
            kind, load = self.kinds[k], k in self.flow_group
            before = kind.solve_count()
            sols = solve_spread(self.client, kind, self.stages[k], [self.option_at(k, c) for c in todo.values()],
                                self.objective, [self.flow_at(k, c) if load else None for c in todo.values()])
            self._solved.update(zip(todo, sols))
            self.n_solves += kind.solve_count() - before

    def _lower_bounds(self) -> np.ndarray:
        """Each design's cost whatever its solved stages give (their bounds; margins unknown)."""
        if self.objective == "max_margin":
            return -self.batch_min
        bound = (self.batch_size if self.objective == "min_size" else self.batch_mass).copy()
        for k in self.solved_k:
            s, m_ = self._stage_bounds(k)
            bound += s if self.objective == "min_size" else m_
        return bound

    def _stage_bounds(self, k: int) -> tuple:
        """Stage k's (size, mass) lower bound of every design: per option, or for a stage sized by
        its load per (option, input flow) while there are at most LOAD_BOUNDS_MAX of them."""
        kind, st = self.kinds[k], self.stages[k]
        if self._bounds is not None and kind.cost_grows_with_load(st):     # the pruned split's, per torque cell
            b = self._bounds.at(k, self.idx[:, k], self.T[:, k])
            return b[:, 0], b[:, 1]
        if k in self.flow_group and kind.cost_grows_with_load(st) and self._cells_pay():
            return self._cell_bounds(k)
        if k in self.flow_group:
            fg = self.flow_group[k]
            pairs, first, inv = np.unique(self.idx[:, k] * (int(fg.max()) + 1) + fg, return_index=True,
                                          return_inverse=True)
            if len(pairs) <= LOAD_BOUNDS_MAX:
                b = np.array([kind.bound_at(st, self.option_at(k, c), self.flow_at(k, c)) for c in first])
                return b[inv.ravel(), 0], b[inv.ravel(), 1]
        s, m_ = kind.bound(st, self.options[k])
        return s[self.idx[:, k]], m_[self.idx[:, k]]

    def _cells_pay(self) -> bool:
        """Cell bounds pay when two or more stages grow with their load: the walk, ordered by the others'
        bounds, would otherwise solve nearly every group; one such stage alone is solved as the walk goes."""
        return sum(1 for k in self.solved_k if self.kinds[k].cost_grows_with_load(self.stages[k])) >= 2

    def _cell_bounds(self, k: int) -> tuple:
        """Stage k's (size, mass) lower bound of every design, for a stage whose cost only grows with the load
        it carries along the power flow (:meth:`StageKind.cost_grows_with_load`: the torque into it up, its
        speed down): per option and cell of input torque (cells LOAD_CELL wide), the cost of the cell's design
        of least torque, solved (the walk finds it solved); where that design fails, the option's load-free
        bound (:meth:`StageKind.bound`)."""
        kind, st = self.kinds[k], self.stages[k]
        T = self.T[:, k]
        cell = np.floor(np.log(T / T.min()) / math.log(LOAD_CELL) + 1e-9).astype(np.int64)
        key = self.idx[:, k] * (int(cell.max()) + 1) + cell
        order = np.lexsort((T, key))
        ks = key[order]
        first = order[np.r_[True, ks[1:] != ks[:-1]]] if order.size else order
        _, inv = np.unique(key, return_inverse=True)     # the cells numbered in key order, as ``first``
        self._solve_designs(k, first, f"bounds of stage '{st.name}'")
        free_size, free_mass = kind.bound(st, self.options[k])
        b = np.empty((first.size, 2))
        for i, c in enumerate(first):
            sol = self._solved[self._key(k, c)]
            j = self.idx[c, k]
            b[i] = kind.solved_cost(st, sol) if sol["feasible"] else (free_size[j], free_mass[j])
        return b[inv.ravel(), 0], b[inv.ravel(), 1]

    def _solve_designs(self, k: int, designs, label: str) -> None:
        """Stage k solved at each of ``designs`` (its option at the design's flow) that is not solved yet,
        in chunks that its kind solves together (:meth:`StageKind.solve_many`)."""
        kind, st, load = self.kinds[k], self.stages[k], k in self.flow_group
        todo: dict = {}
        for c in designs:
            key = self._key(k, int(c))
            if key not in self._solved:
                todo.setdefault(key, int(c))
        keys, cs = list(todo), list(todo.values())
        step = max(kind.solve_ahead(st, self.objective), 1) * 4
        for s in range(0, len(cs), step):
            part = cs[s:s + step]
            before = kind.solve_count()
            sols = kind.solve_many(st, [self.option_at(k, c) for c in part], self.objective,
                                   [self.flow_at(k, c) if load else None for c in part])
            self._solved.update(zip(keys[s:s + step], sols))
            self.n_solves += kind.solve_count() - before
            self.report(label, s + len(part), len(cs))

    def _groups(self):
        """(order, starts, ends, bound per group) of the designs that pass every batch check,
        grouped by their solved stages' options (and input flows where the solve depends on it)."""
        self.flow_group = self._flow_groups()
        group_key = np.zeros(self.n_cand, dtype=np.int64)
        for k in self.solved_k:
            group_key = group_key * self.options[k]["ratio"].size + self.idx[:, k]
            if k in self.flow_group:
                group_key = group_key * (int(self.flow_group[k].max()) + 1) + self.flow_group[k]
        cand = np.flatnonzero(self.batch_ok)
        order = cand[np.argsort(group_key[cand], kind="stable")]
        gk = group_key[order]
        starts = np.flatnonzero(np.r_[True, gk[1:] != gk[:-1]]) if order.size else np.zeros(0, dtype=np.int64)
        glb = np.minimum.reduceat(self._lower_bounds()[order], starts) if order.size else np.zeros(0)
        return order, starts, np.r_[starts[1:], order.size], glb

    def branch_and_bound(self) -> None:
        """Groups of designs sharing their solved options, solved best bound first while a bound can
        still enter the ``top`` list; what each evaluated design costs is kept in ``self.ex``."""
        n_cand, top = self.n_cand, self.top
        self._solved = {}
        # limiting checks and reasons as codes into lists (object arrays of ~10⁶ strings are slow)
        labels = [f"{a}: {b}" for a, b in self.names] or [""]
        self.ex = ex = dict(cost=np.full(n_cand, np.nan), mm=np.full(n_cand, np.nan), size=np.full(n_cand, np.nan),
                            mass=np.full(n_cand, np.nan), feas=np.zeros(n_cand, dtype=bool),
                            done=np.zeros(n_cand, dtype=bool), lim=self.batch_arg.astype(np.int64),
                            why=np.full(n_cand, -1, dtype=np.int64), labels=labels, reasons=[])
        order, starts, ends, glb = self._groups()
        heap: list = []          # the `top` best costs so far, as a max-heap of −cost
        walk = np.argsort(glb, kind="stable")
        for i, g in enumerate(walk):
            limit = -heap[0] + 1e-12 * abs(heap[0]) if len(heap) >= top else math.inf
            if glb[g] > limit:
                break      # no design of this or any later group can enter the list
            members = order[starts[g]:ends[g]]
            ahead = walk[i:i + self.look_ahead]
            self._solve_ahead(order[starts[ahead[glb[ahead] <= limit]]])
            sols = [self._solution(k, members[0]) for k in self.solved_k]
            self.report(WALK_LABEL, int(np.count_nonzero(glb <= glb[g])), starts.size)
            self._exact(members, sols)
            for v in np.sort(ex["cost"][members][ex["feas"][members]])[:top]:
                if len(heap) < top:
                    heapq.heappush(heap, -float(v))
                elif -v > heap[0]:
                    heapq.heapreplace(heap, -float(v))

    def _exact(self, members, sols) -> None:
        """Cost, smallest margin, size, mass and feasibility of the designs ``members``, which share
        their solved options (solutions ``sols``), written into ``ex``."""
        ex = self.ex
        gsize = gmass = 0.0
        gfactor = 1.0       # the stages' preferences on the ranking (StageKind.rank_factor)
        gmm, glim, gfeas, why = math.inf, "", True, ""
        for k, sol in zip(self.solved_k, sols):
            st, kind = self.stages[k], self.kinds[k]
            m, name = min_margin(sol["margins"]) if sol["margins"] else (-math.inf, kind.unsolved_label)
            if m < gmm:
                gmm, glim = m, f"{st.name}: {name}"
            if not sol["feasible"]:
                gfeas, why = False, f"stage '{st.name}': {sol['reason']}"
                continue
            s, w = kind.solved_cost(st, sol)
            gsize += s
            gmass += w
            gfactor *= kind.rank_factor(st, sol)
        ng = self.batch_min[members]
        mm = np.minimum(ng, gmm)
        size, mass = self.batch_size[members] + gsize, self.batch_mass[members] + gmass
        ex["size"][members], ex["mass"][members], ex["mm"][members] = size, mass, mm
        if glim:
            ex["labels"].append(glim)
            ex["lim"][members] = np.where(gmm < ng, len(ex["labels"]) - 1, ex["lim"][members])
        ex["feas"][members] = gfeas & (mm >= 0)
        if why:
            ex["reasons"].append(why)
            ex["why"][members] = len(ex["reasons"]) - 1
        ex["done"][members] = True
        ex["cost"][members] = {"min_size": size * gfactor, "min_mass": mass * gfactor, "max_margin": -mm}[self.objective]

    # -- 6: the result
    def no_split(self, why: str) -> DriveOptimum:
        return DriveOptimum(success=False, message=f"no design: {why}", objective=self.objective, total_ratio=self.U,
                            ratio_tol=self.tol, table=pd.DataFrame(), best=None, conflict=(f"ratio: {why}",),
                            n_combinations=0, n_candidates=0, n_shift_solves=0, time_s=time.perf_counter() - self.t0)

    def _row(self, c) -> dict:
        row = {"total_ratio": float(np.prod(self.ratios[c])), "ratio_error": float(self.err[c])}
        for k, (kind, st) in enumerate(zip(self.kinds, self.stages)):
            row[f"{st.name}.ratio"] = float(self.ratios[c, k])
            row.update(kind.design_columns(st, self.option_at(k, c), self.info[k], c))
        for name, nk in self.key_n.items():
            row[f"key '{name}'.n_keys"] = int(nk[c])
        return row

    def _solved_cols(self, c, solve=True) -> dict:
        """The solved stages' columns of design c (``solve``: an evaluated design, whose solutions the walk
        kept; a stage sized by its load is not sized again per listed row)."""
        out = {}
        for k in self.solved_k:
            out.update(self.kinds[k].solved_columns(self.stages[k], self._solution(k, c) if solve else None))
        return out

    def _ranked_rows(self, feas) -> list:
        ex = self.ex
        what = {"min_size": "size", "min_mass": "mass", "max_margin": "smallest margin"}[self.objective]
        rows = []
        for rank, c in enumerate(feas[:self.top]):
            row = {"rank": rank + 1, "feasible": True, "size_mm2": ex["size"][c], "mass_kg": ex["mass"][c],
                   "min_margin": ex["mm"][c], "limiting": ex["labels"][ex["lim"][c]], **self._row(c),
                   **self._solved_cols(c)}
            if rank == 0:
                row["reason"] = "best"
            else:
                true = {"min_size": ex["size"], "min_mass": ex["mass"], "max_margin": -ex["mm"]}[self.objective]
                c0, d = true[feas[0]], true[c] - true[feas[0]]
                preferred = ex["cost"][c] > true[c] * (1.0 + 1e-12) and ex["cost"][feas[0]] <= true[feas[0]] * (
                    1.0 + 1e-12)     # a stage's preference (a series II module) ranks it behind
                row["reason"] = (f"{what} {100 * abs(d) / max(abs(c0), 1e-300):.3g} % worse than rank 1"
                                 if d > 1e-9 * max(abs(c0), 1e-300) else
                                 f"{what} {100 * abs(d) / max(abs(c0), 1e-300):.3g} % better than rank 1, ranked "
                                 f"behind it for a series II module" if preferred and d < 0 else
                                 "ties rank 1 on the objective; loses on ratio error or size")
            rows.append(row)
        return rows

    def _fails(self, c) -> list:
        """The checks design c fails (batch margins, then a solved stage's reason or margin)."""
        ex, names, M = self.ex, self.names, self.M
        fails = [f"{names[j][0]}: {names[j][1]} ({M[c, j]:+.3g})" for j in range(len(names)) if not M[c, j] >= 0]
        if ex["why"][c] >= 0:
            fails.append(ex["reasons"][ex["why"][c]])
        elif ex["done"][c] and ex["mm"][c] < 0 and not fails:
            fails.append(f"{ex['labels'][ex['lim'][c]]} ({ex['mm'][c]:+.3g})")
        return fails

    def _failing_rows(self) -> tuple[list, tuple]:
        """The closest failing designs (largest smallest margin), each with the stage checks that fail;
        and the first one's failing checks."""
        ex = self.ex
        bad = np.flatnonzero((ex["done"] & ~ex["feas"]) | ~self.batch_ok)
        mm = np.where(ex["done"], ex["mm"], self.batch_min)[bad]
        bad = bad[np.argsort(-np.where(np.isnan(mm), -np.inf, mm), kind="stable")][:INFEASIBLE_SHOWN]
        rows, first = [], ()
        for c in bad:
            fails = self._fails(c)
            known = bool(ex["done"][c]) or not self.solved_k
            rows.append({"rank": None, "feasible": False,
                         "size_mm2": ex["size"][c] if ex["done"][c] else (self.batch_size[c] if known else np.nan),
                         "mass_kg": ex["mass"][c] if ex["done"][c] else (self.batch_mass[c] if known else np.nan),
                         "min_margin": ex["mm"][c] if ex["done"][c] else self.batch_min[c],
                         "limiting": ex["labels"][ex["lim"][c]], **self._row(c),
                         **self._solved_cols(c, solve=bool(ex["done"][c])), "reason": "fails " + "; ".join(fails)})
            first = first or tuple(fails)
        return rows, first

    def result(self) -> DriveOptimum:
        ex, err = self.ex, self.err
        feas = np.flatnonzero(ex["feas"])
        feas = feas[np.lexsort((ex["size"][feas], np.round(err[feas], 12), np.round(ex["cost"][feas], 9)))]
        failing, conflict = self._failing_rows()
        table = pd.DataFrame(self._ranked_rows(feas) + failing)
        if len(table):
            table["rank"] = table["rank"].astype("Int64")     # failing designs have no rank
        shafts_note = ""
        if feas.size and self.drive.shafting is not None:      # the ranked designs on their shafts
            c, best, shafts_note = self._with_shafts(feas, table)
        elif feas.size:
            c = feas[0]
            best = self._fixed(c).analyse(self.objective)
        if feas.size and best is not None:
            # a design re-sized for its shafts is no longer the ranked one: its own figures, not the ranked ones
            size, mass, mm, lim = ((best.size_mm2, best.mass_kg, best.min_margin, best.limiting) if "re-sized" in
                                   shafts_note else (ex['size'][c], ex['mass'][c], ex['mm'][c],
                                                     ex['labels'][ex['lim'][c]]))
            msg = (f"u = {float(np.prod(self.ratios[c])):.6g} ({100 * float(err[c]):.3g} % off): size "
                   f"{size:.6g} mm², mass {mass:.4g} kg, smallest margin {mm:+.4f} "
                   f"({lim}); {int(ex['done'].sum())} of {self.n_cand} designs evaluated in full"
                   + shafts_note)
            conflict = ()
        elif feas.size:     # every ranked design fails on its shafts
            msg = "no ranked design holds on its shafts and bearings" + shafts_note
            conflict = tuple(f"{a}: {b}" for a, b in self._shaft_fails)
            feas = feas[:0]
        else:
            best = None
            msg = ("no design passes every check; the closest fails " + "; ".join(conflict)) if conflict else \
                "no design passes every check"
            msg += self._closest_solved()
        return DriveOptimum(success=bool(feas.size), message=msg, objective=self.objective, total_ratio=self.U,
                            ratio_tol=self.tol, table=table, best=best, conflict=conflict,
                            n_combinations=int(self.n_comb), n_candidates=int(self.n_cand),
                            n_shift_solves=int(self.n_solves), time_s=time.perf_counter() - self.t0)

    def _with_shafts(self, feas, table) -> tuple:
        """(design, its analysis or None, a note): the ranked designs analysed with their shafts, bearings and K_Hβ
        from the shafts (Drive(shafting=...)) in rank order, the first that holds every check taken; a design whose
        gear stage sized by its load fails with its shafts' K_Hβ is sized again first (:meth:`_resized`). A re-sized
        design grows, so for size and mass the ranks after it are analysed too while their ranked cost is below its
        new cost, and the cheapest that holds is taken (a rank 2 that holds as sized beats a rank 1 that had to double
        its module). The table's column ``shafts`` says for each one analysed whether it held (re-sized how) or which
        checks failed."""
        table["shafts"] = "not analysed"
        self._shaft_fails = ()
        held = None                    # (cost, rank, c, analysis, steps) of the cheapest re-sized design that holds
        for rank, c in enumerate(feas[:self.top]):
            if held is not None and not self.ex["cost"][c] < held[0]:
                break                  # re-sizing only grows a design: no later rank can be cheaper
            an, steps = self._resized(c, self._fixed(c).analyse(self.objective))
            bad = an.checks.loc[~an.checks["ok"], ["item", "check"]]
            done = "; ".join(steps)
            table.loc[table["rank"] == rank + 1, "shafts"] = (("holds" + (f" re-sized: {done}" if steps else ""))
                                                             if an.success else "fails " + "; ".join(
                f"{a}: {b}" for a, b in bad.itertuples(index=False)) + (f" (re-sized: {done})" if steps else ""))
            if rank == 0 and not an.success:
                self._shaft_fails = tuple(bad.itertuples(index=False))
            if not an.success:
                continue
            cost = {"min_size": an.size_mm2, "min_mass": an.mass_kg}.get(self.objective)
            if held is None or (cost is not None and cost < held[0]):
                held = (cost, rank, c, an, steps)
            if not steps or cost is None:
                break                  # held as ranked (nothing later is cheaper), or an objective without a bound
        if held is None:
            return feas[0], None, (f"; the {min(self.top, feas.size)} ranked designs each fail with their shafts, "
                                   f"bearings or K_Hβ from the shafts (column shafts)")
        _, rank, c, an, steps = held
        before = "rank 1 fails" if rank == 1 else f"ranks 1 to {rank} fail"
        note = "" if rank == 0 else (f"; rank {rank + 1} taken: {before} with their shafts, bearings or K_Hβ from "
                                     f"the shafts, or hold only re-sized to a larger design (column shafts)")
        if steps:
            note += (f"; rank {rank + 1} re-sized for the K_Hβ of its shafts: {'; '.join(steps)} (ranked at size "
                     f"{self.ex['size'][c]:.6g} mm², mass {self.ex['mass'][c]:.4g} kg)")
        return c, an, note

    def _resized(self, c, an) -> tuple:
        """(analysis, steps): design c's analysis on its shafts ``an``, and while a check of a gear stage sized by its
        load fails with K_Hβ from its shafts, that stage sized again for the f_sh its shafts gave
        (:meth:`StageKind.resize`: the first larger module and width of its sizing that holds with that f_sh scaled
        to its size; f_sh per b/m the largest seen, so the size only grows), and the drive analysed again, at most
        :data:`RESIZE_ROUNDS` times; ``steps`` says what was re-sized ("fast: m 3 → 3.5 mm, b 40 → 45 mm (f_sh
        21.9 µm from its shafts)")."""
        steps, per = [], {}        # per stage: the largest f_sh seen per b/m (GearKind.resize scales it so)
        drive = an.drive
        for _ in range(RESIZE_ROUNDS):
            if an.success:
                break
            failing = set(an.checks.loc[~an.checks["ok"], "item"])
            mm = an.shafting["mesh_misalignment"]
            from_shafts = dict(zip(mm["stage"], mm["f_sh_um"])) if len(mm) else {}
            src = dict(zip(mm["stage"], mm["source"])) if len(mm) else {}
            new, changed = list(drive.stages), False
            for k, (kind, st) in enumerate(zip(self.kinds, self.stages)):
                if st.name not in failing or src.get(st.name) != "shafts":
                    continue
                scale = float(new[k].width_mm) / float(new[k].m)
                per[k] = max(per.get(k, 0.0), float(from_shafts[st.name]) / scale)
                sized = kind.resize(st, new[k], self.option_at(k, c), self.objective, self.flow_at(k, c),
                                    per[k] * scale)
                if sized is None:
                    continue
                steps.append(f"{st.name}: m {new[k].m:g} → {sized.m:g} mm, b {new[k].width_mm:g} → "
                             f"{sized.width_mm:g} mm (f_sh {per[k] * scale:.3g} µm from its shafts)")
                new[k], changed = sized, True
            if not changed:
                break
            # the re-sized gears on shafts at least as thick as these: DIN 743 alone would thin them (a larger gear
            # has smaller forces), tilting the mesh more, and the re-sizing would run away (a conveyor reducer's fast
            # stage grew from m 4 to m 20 so)
            bores = {k: d for k, d in an.shafting["seat_bores"].items() if d is not None}
            fixed = replace(drive, stages=tuple(new), shafting=replace(
                drive.shafting, min_bore_mm=thicker_bores(drive.shafting.min_bore_mm, bores)))
            object.__setattr__(fixed, "_load_from_motor", self.drive._load_from_motor)
            try:
                drive, an = fixed, fixed.analyse(self.objective)
            except GearDesignError as exc:       # e.g. a re-sized stage its shafts cannot take: keep the last
                steps.append(f"stopped: {exc}")
                break
        return an, steps

    def _closest_solved(self) -> str:
        """When the closest failing design was stopped by its batch checks (its solved stages never
        solved) but others were solved and failed: what the closest of those fails, else ''."""
        ex = self.ex
        bad = np.flatnonzero(ex["done"] & ~ex["feas"])
        if not bad.size or not self.solved_k:
            return ""
        closest = np.flatnonzero(~self.batch_ok)
        if not closest.size or np.nanmax(self.batch_min[closest]) <= np.nanmax(np.where(np.isnan(ex["mm"][bad]), -np.inf,
                                                                                    ex["mm"][bad])):
            return ""
        c = bad[np.argmax(np.where(np.isnan(ex["mm"][bad]), -np.inf, ex["mm"][bad]))]
        return "; of the designs evaluated in full, the closest fails " + "; ".join(self._fails(c))

    def _fixed(self, c):
        """The drive with every free variable fixed at design c (shifts, teeth, chain row, ...)."""
        new = [kind.fix(st, self.option_at(k, c), self.info[k], c, self.objective, self.flow_at(k, c))
               for k, (kind, st) in enumerate(zip(self.kinds, self.stages))]
        fixed = replace(self.drive, stages=tuple(new))
        object.__setattr__(fixed, "_load_from_motor", self.drive._load_from_motor)
        return fixed


def _row_groups(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Each row's index among the distinct rows (a, b), numbered in their sorted order (as
    np.unique(..., axis=0) numbers them, without its row-wise sort of ~10⁶ rows)."""
    _, ia = np.unique(a, return_inverse=True)
    ub, ib = np.unique(b, return_inverse=True)
    _, inv = np.unique(ia.ravel() * ub.size + ib.ravel(), return_inverse=True)
    return inv.ravel()


@lru_cache(maxsize=256)
def _key_caps_cached(d, hub, crush, shear, end, max_keys):
    sh = Shaft(d, hub, 0, allowable_crush_mpa=crush, allowable_shear_mpa=shear, end=end, max_keys=max_keys)
    sel = sh.select(1e-6)
    caps = {}
    for n_keys in (1, 2):
        cap = key.capacity(d, sel.length_mm, crush, shear, end=end, n_keys=min(n_keys, max_keys))
        caps[n_keys] = (cap.torque_crush_nm, cap.torque_shear_nm)
    return sel.length_mm, caps


def key_caps(sh: Shaft):
    """(key length, {n_keys: (torque at the crushing limit, at the shear limit)}) of a hub [mm, N·m]."""
    return _key_caps_cached(sh.d_mm, sh.hub_length_mm, sh.allowable_crush_mpa, sh.allowable_shear_mpa, sh.end,
                            sh.max_keys)
