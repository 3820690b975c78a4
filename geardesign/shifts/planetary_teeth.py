"""Tooth counts of a planetary set for a ratio: standard and non-standard sets, solved and ranked.

Enumeration (vectorised, bounded before any solve): every z_sun in ``z_sun_range``, every z_ring
whose ratio (:func:`~geardesign.gears.planetary.planetary_ratio` of the arrangement) is within
``ratio_tol`` of the asked one, and every z_planet with |z_ring − z_sun − 2 z_planet| <=
``nonstandard_max`` (0 is the standard set z_r = z_s + 2 z_p, coaxial without shifts; a
difference of a tooth or two is what shifts can absorb). Candidates whose planets cannot be
assembled ((z_s + z_r)/N not whole) or whose planets overlap even at zero shifts are listed
with that reason and not solved; every other one gets :func:`optimize_planetary_shifts`.

Ranking (best first): feasible before infeasible; the smaller |ratio error|; the better
objective (default ``max_eps_alpha``: the smaller of the two meshes' ε_α, largest first); the
smaller ring (a smaller set).
"""
from __future__ import annotations

import functools
import math
import time
from dataclasses import dataclass

import numpy as np
import pandas as pd

from .. import parallel
from ..errors import GearDesignError
from ..gears.planetary import ARRANGEMENTS, N_PLANETS_RANGE, PlanetaryMeshes, planetary_ratio
from ..results import RankedTable
from ..validate import one_number, require_choice, require_count, require_positive, require_range
from .objectives import resolve_objective
from .optimize import METHODS
from .planetary import PlanetaryProblem, optimize_planetary_shifts

__all__ = ["select_planetary_teeth", "PlanetaryTeethSelection", "PLANETARY_SOLVES_MAX", "NONSTANDARD_MAX_RANGE"]

PLANETARY_SOLVES_MAX = 2000        # candidates solved at most in one search (~50 ms each), per worker
# candidates per chunk sent to a worker: at ~50 ms a solve, 4 outweigh a task's ~2 ms of scheduling 100 times
PLANETARY_CHUNK_MIN, PLANETARY_CHUNK_MAX = 4, 100
NONSTANDARD_MAX_RANGE = (0, 6)     # teeth: beyond a few, no shift within the window makes a set coaxial
Z_SUN_RANGE_LIMIT = (3, 1000)
DEFAULT_OBJECTIVE = "max_eps_alpha"


@dataclass
class PlanetaryTeethSelection(RankedTable):
    """The ranked result of :func:`select_planetary_teeth`: ``table`` one row per candidate (solved
    or not, ``reason`` says why a row fails), best first; ``best`` the first row if feasible."""

    table: pd.DataFrame
    ratio: float
    ratio_tol: float
    n_planets: int
    m: float
    arrangement: str
    objective: str
    method: str
    n_solved: int = 0
    time_s: float = 0.0

    @property
    def message(self) -> str:
        b = self.best
        if b is None:
            return (f"no feasible set among {len(self.table)} candidates for ratio {self.ratio:g} ± "
                    f"{self.ratio_tol:.3g} with {self.n_planets} planets; see the reasons in the table")
        kind = "standard" if b["standard"] else "non-standard"
        return (f"z_s/z_p/z_r = {b['z_sun']}/{b['z_planet']}/{b['z_ring']} ({kind}), ratio {b['ratio']:.6g}, "
                f"x = {b['x_sun']:.4f}/{b['x_planet']:.4f}/{b['x_ring']:.4f}, a_w {b['a_w']:.6g} mm")

    def __repr__(self) -> str:
        return (f"PlanetaryTeethSelection({self.status}: {self.message}; {len(self.table)} candidates, "
                f"{self.n_solved} solved, {self.time_s:.2f} s)")


def _candidates(ratio, ratio_tol, n_planets, z_sun_range, nonstandard_max, arrangement):
    """(z_s, z_p, z_r) arrays of every candidate within the ratio tolerance."""
    zs = np.arange(z_sun_range[0], z_sun_range[1] + 1)
    lo, hi = ratio * (1 - ratio_tol), ratio * (1 + ratio_tol)
    # z_r interval per z_sun from the ratio's inverse (monotonic in z_r for each arrangement)
    if arrangement == "ring_fixed":
        r_lo, r_hi = (lo - 1) * zs, (hi - 1) * zs
    elif arrangement == "carrier_fixed":   # ratio = -z_r/z_s
        r_lo, r_hi = -ratio * (1 - ratio_tol) * zs, -ratio * (1 + ratio_tol) * zs
    else:   # sun_fixed: 1 + z_s/z_r
        with np.errstate(divide="ignore"):
            r_lo, r_hi = zs / max(hi - 1, 1e-300), zs / max(lo - 1, 1e-300)
    rows = []
    for s, a, b in zip(zs, np.ceil(r_lo - 1e-9).astype(np.int64), np.floor(r_hi + 1e-9).astype(np.int64)):
        for r in range(max(int(a), int(s) + 7), min(int(b), 100_000) + 1):
            for d in range(-nonstandard_max, nonstandard_max + 1):
                if (r - s - d) % 2 == 0 and (r - s - d) // 2 >= 3:
                    rows.append((int(s), (r - s - d) // 2, r))
            if len(rows) > 50 * PLANETARY_SOLVES_MAX:
                raise GearDesignError(f"more than {50 * PLANETARY_SOLVES_MAX} tooth-count candidates for ratio "
                                      f"{ratio:g} ± {ratio_tol:g}: narrow z_sun_range or ratio_tol")
    return np.array(rows, dtype=np.int64).reshape(-1, 3)


def select_planetary_teeth(ratio, n_planets, m, ratio_tol: float = 0.02, z_sun_range=(12, 40),
                           nonstandard_max: int = 2, arrangement: str = "ring_fixed", objective=DEFAULT_OBJECTIVE,
                           checks=None, method: str = "exact", rack=None, beta_deg: float = 0.0,
                           cutter=None, *, client=None, workers=None, progress=None) -> PlanetaryTeethSelection:
    """Every (z_sun, z_planet, z_ring) for ``ratio`` (the signed n_in/n_out of ``arrangement``, as
    :func:`~geardesign.gears.planetary.planetary_ratio` and the results give it: "carrier_fixed" turns
    the ring against the sun, so its ratios are < -1; a positive one is refused), standard and
    non-standard, with the shifts that make each fit, ranked (see the module docstring). The table's
    ``ratio`` is signed the same way, its ``ratio_error`` is (ratio - asked)/|asked|.

    ``client`` (a ``dask.distributed.Client``) or ``workers`` (a local cluster of that many
    processes, made for the call) solve the candidates in chunks of at least PLANETARY_CHUNK_MIN;
    the table is the serial one bit for bit and PLANETARY_SOLVES_MAX is multiplied by the number of
    workers (see :mod:`geardesign.parallel`). ``progress(done, total)`` counts solved candidates.

    >>> sel = select_planetary_teeth(5.0, 3, 2.0, ratio_tol=0.0, z_sun_range=(18, 18), nonstandard_max=0)
    >>> b = sel.best                       # 1 + 72/18 = 5, (18 + 72)/3 = 30: the standard set
    >>> int(b["z_sun"]), int(b["z_planet"]), int(b["z_ring"]), bool(b["standard"])
    (18, 27, 72, True)
    """
    t0 = time.perf_counter()
    ratio, ratio_tol, n_planets, nonstandard_max, z_range, arrangement = _validate(
        ratio, ratio_tol, n_planets, nonstandard_max, z_sun_range, arrangement)
    method = require_choice("method", method, METHODS)
    obj = resolve_objective(objective)
    m = float(one_number("m (module)", require_positive("m (module)", m, unit="mm")))
    table = _screen(_candidates(ratio, ratio_tol, n_planets, z_range, nonstandard_max, arrangement),
                    ratio, n_planets, arrangement)
    todo = table.index[table["reason"] == ""]
    n_workers = parallel.slots(client, workers)
    if todo.size > PLANETARY_SOLVES_MAX * n_workers:
        per = "" if n_workers == 1 else f" ({PLANETARY_SOLVES_MAX} per worker x {n_workers})"
        raise GearDesignError(f"{todo.size} tooth-count candidates to solve, more than "
                              f"{PLANETARY_SOLVES_MAX * n_workers}{per}: narrow z_sun_range, ratio_tol or "
                              f"nonstandard_max")
    kw = dict(objective=obj, checks=checks, method=method, rack=rack, beta_deg=beta_deg, arrangement=arrangement,
              cutter=cutter)
    _options_ok(table, todo, n_planets, m, kw)
    if not parallel.requested(client, workers):
        for k, i in enumerate(todo):
            _solve_row(table, i, n_planets, m, kw)
            if progress is not None:
                progress(k + 1, todo.size)
    else:
        teeth = table.loc[todo, ["z_sun", "z_planet", "z_ring"]].to_numpy(np.int64)
        parts = parallel.map_chunks(
            functools.partial(_solve_chunk, n_planets, m, kw),
            [teeth[s] for s in parallel.chunk_slices(todo.size, n_workers, PLANETARY_CHUNK_MIN, PLANETARY_CHUNK_MAX)],
            client=client, workers=workers, progress=progress)
        for i, outcome in zip(todo, [o for part in parts for o in part]):
            _put_row(table, i, outcome)
    return PlanetaryTeethSelection(_rank(table, obj.sense), ratio, ratio_tol, n_planets, m, arrangement, obj.name,
                                   method, n_solved=int(todo.size), time_s=time.perf_counter() - t0)


def _validate(ratio, ratio_tol, n_planets, nonstandard_max, z_sun_range, arrangement):
    ratio = one_number("ratio", require_range("ratio", ratio, -1e4, 1e4))
    arrangement = require_choice("arrangement", arrangement, tuple(ARRANGEMENTS))
    # the ratio is signed, n_in/n_out as planetary_ratio gives it: the carrier-fixed set turns its ring backwards
    if arrangement == "ring_fixed" and not ratio > 1 or arrangement == "sun_fixed" and not 1 < ratio < 2 \
            or arrangement == "carrier_fixed" and not ratio < -1:
        allowed = {"ring_fixed": "> 1", "sun_fixed": "in (1, 2)",
                   "carrier_fixed": f"< -1 (signed n_in/n_out: the ring turns against the sun; give {-abs(ratio):g})"
                   if ratio > 1 else "< -1 (signed n_in/n_out: the ring turns against the sun)"}[arrangement]
        raise GearDesignError(f"ratio = {ratio:g} cannot be made by a simple planetary set with the {arrangement} "
                              f"arrangement: it must be {allowed}")
    ratio_tol = one_number("ratio_tol", require_range("ratio_tol", ratio_tol, 0.0, 0.5))
    n_planets = require_count("n_planets", n_planets, *N_PLANETS_RANGE)
    nonstandard_max = require_count("nonstandard_max", nonstandard_max, *NONSTANDARD_MAX_RANGE)
    if isinstance(z_sun_range, (str, bytes, dict)) or not hasattr(z_sun_range, "__len__") or len(z_sun_range) != 2:
        raise GearDesignError(f"z_sun_range must be (lo, hi) whole numbers in [{Z_SUN_RANGE_LIMIT[0]}, "
                              f"{Z_SUN_RANGE_LIMIT[1]}], got {z_sun_range!r}")
    zlo, zhi = (require_count("z_sun_range", v, *Z_SUN_RANGE_LIMIT) for v in z_sun_range)
    if zlo > zhi:
        raise GearDesignError(f"z_sun_range must be (lo, hi) with lo <= hi, got {z_sun_range!r}")
    return ratio, ratio_tol, n_planets, nonstandard_max, (zlo, zhi), arrangement


_COLUMNS = ["z_sun", "z_planet", "z_ring", "standard", "ratio", "ratio_error", "feasible", "x_sun", "x_planet",
            "x_ring", "a_w", "eps_alpha_sun_planet", "eps_alpha_planet_ring", "fun", "reason"]


def _screen(cand, ratio, n_planets, arrangement) -> pd.DataFrame:
    """One row per candidate; the reason for those that no shift can save: planets that cannot be
    assembled, or that overlap with tips at zero shift (the planet's tip grows with its shift as
    fast as a_w does: 2 a sin(π/N) > d_p + 2m is needed)."""
    z_s, z_p, z_r = (cand[:, k] for k in range(3))
    ratios = planetary_ratio(z_s, z_r, arrangement) if len(cand) else np.zeros(0)
    table = pd.DataFrame({"z_sun": z_s, "z_planet": z_p, "z_ring": z_r, "standard": z_r == z_s + 2 * z_p,
                          "ratio": ratios, "ratio_error": (ratios - ratio) / abs(ratio),
                          "feasible": False}, columns=_COLUMNS)
    for c in _COLUMNS[7:-1]:
        table[c] = np.nan
    q = (z_s + z_r) / n_planets
    fits = (n_planets == 1) | ((z_s + z_p) * math.sin(math.pi / n_planets) > z_p + 2.0)
    table["reason"] = np.where(q != np.round(q), [f"set:assembly: (z_s + z_r)/N = {v:.4g} is not whole" for v in q],
                               np.where(fits, "", "set:neighbours: the planets overlap whatever the shifts"))
    return table


def _options_ok(table, todo, n_planets, m, kw) -> None:
    """Refuse a bad option (a NaN face width, a strength objective without a load, ...) by name, up front:
    the per-candidate solves below turn their errors into reasons, which would hide it as "no feasible
    set" (issue 36 §1.4). The options are validated on one candidate's problem, built as each solve
    builds it."""
    rows = todo if todo.size else table.index
    if not rows.size:
        return
    z_s, z_p, z_r = (int(table.loc[rows[0], c]) for c in ("z_sun", "z_planet", "z_ring"))
    meshes = PlanetaryMeshes(z_s, z_p, z_r, n_planets, kw["rack"], kw["beta_deg"])
    PlanetaryProblem(meshes, m, kw["checks"], kw["objective"], cutter=kw["cutter"], arrangement=kw["arrangement"])


def _solve_row(table, i, n_planets, m, kw) -> None:
    row = table.loc[i]
    _put_row(table, i, _solve_set(int(row["z_sun"]), int(row["z_planet"]), int(row["z_ring"]), n_planets, m, kw))


def _solve_set(z_s, z_p, z_r, n_planets, m, kw):
    """The optimum of one set, or the GearDesignError it raised."""
    try:
        return optimize_planetary_shifts(z_s, z_p, z_r, n_planets, m, **kw)
    except GearDesignError as exc:
        return exc


def _solve_chunk(n_planets, m, kw, teeth) -> list:
    """A chunk of (z_sun, z_planet, z_ring) rows solved on a worker."""
    return [_solve_set(int(a), int(b), int(c), n_planets, m, kw) for a, b, c in teeth]


def _put_row(table, i, r) -> None:
    """Row ``i`` of the table from its optimum (or the error it raised)."""
    if isinstance(r, GearDesignError):
        table.loc[i, "reason"] = str(r)
        return
    table.loc[i, ["feasible", "x_sun", "x_planet", "x_ring", "a_w", "eps_alpha_sun_planet", "eps_alpha_planet_ring",
                  "fun", "reason"]] = [bool(r.success), r.x_sun, r.x_planet, r.x_ring, r.a_w, r.eps_alpha_sun_planet,
                                       r.eps_alpha_planet_ring, r.fun,
                                       "" if r.success else f"checks {', '.join(r.conflict)} conflict"]


def _rank(table, sense) -> pd.DataFrame:
    """Feasible first, the smaller |ratio error|, the better objective, the smaller ring."""
    if table.empty:
        return table
    table["feasible"] = table["feasible"].astype(bool)
    key = pd.DataFrame({"inf": ~table["feasible"], "err": table["ratio_error"].abs().round(12),
                        "fun": (-sense * table["fun"]).fillna(np.inf), "zr": table["z_ring"]})
    return table.loc[key.sort_values(["inf", "err", "fun", "zr"], kind="stable").index].reset_index(drop=True)
