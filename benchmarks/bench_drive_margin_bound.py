"""How far a bound on the gear's margin can prune Drive.optimize(objective="max_margin") (issue 29 §4), on
the drive of bench_drive_optimize.py (spur gear m = 3 + roller chain GOST 13568, u = 10 ± 3 %).

The branch and bound may skip a group of designs (one gear tooth pair) only when a bound proves that none of
its designs can enter the top list, i.e. that min(batch margins, the gear's smallest raw check margin at the
shift solution of the max_margin objective) stays below the listed designs' margin τ. The shift solution is
the Chebyshev centre of the normalised margins (margin/‖∇margin‖), not the point of the largest smallest raw
margin. A bound that holds whatever point of the shift window [-1.5, 3]² the solver returns cannot lie below
R* = max over the window of min_k margin_k(x); every node of a grid is a witness: a group with a node whose
smallest raw margin (and whose batch margins) reach τ cannot be skipped by such a bound. This script counts
those groups and, from the measured cost of one max_margin shift solve, the first call's floor for a search
that solves every one of them (each at today's cost), against 2 × the first call of min_size (the goal).

    python benchmarks/bench_drive_margin_bound.py
"""
import time

import numpy as np

from bench_drive_optimize import make_drive
from geardesign.drives.search import Search
from geardesign.drives.stage_kinds.gear import clear_shift_cache
from geardesign.gears.mesh import Mesh
from geardesign.shifts.problem import DEFAULT_BOUNDS, Problem

GRID_N = 91     # nodes per axis of the witness grid (any grid gives witnesses; a finer one finds more)


def first_call(drive, objective):
    """(result, CPU seconds) of the first call (shift cache cleared)."""
    clear_shift_cache()
    c0 = time.process_time()
    r = drive.optimize(10, objective=objective)
    return r, time.process_time() - c0


def groups(drive):
    """Each group's (z1, z2) and its designs' largest batch margin, as the max_margin search forms them."""
    s = Search(drive, 10.0, 0.03, "max_margin", 10, time.perf_counter())
    s.enumerate()
    s.batch_checks()
    order, starts, _, glb = s._groups()
    k = s.solved_k[0]
    pairs = [(int(s.option_at(k, order[i])["z1"]), int(s.option_at(k, order[i])["z2"])) for i in starts]
    return pairs, -glb


def witness(z1, z2, m):
    """(the largest smallest raw check margin over the nodes of a GRID_N² grid of the window (≤ R*), its x1,
    its x2): the default checks, as the drive's gear stage has them."""
    g = np.linspace(*DEFAULT_BOUNDS, GRID_N)
    x1, x2 = (a.ravel() for a in np.meshgrid(g, g, indexing="ij"))
    p = Problem(Mesh(z1, z2), None, "max_margin", m=m)
    with np.errstate(all="ignore"):
        low = p.margins(p.geo(x1, x2)).min(axis=0)
    i = int(np.nanargmax(low))
    return float(low[i]), float(x1[i]), float(x2[i])


def main():
    drive = make_drive()
    drive.optimize(10)                       # imports, catalogs read once
    r_size, t_size = first_call(drive, "min_size")
    r_margin, t_margin = first_call(drive, "max_margin")
    c0 = time.process_time()
    drive.optimize(10, objective="max_margin")
    t_walk = time.process_time() - c0        # the same search with every tooth pair solved already
    tau = float(r_margin.table["min_margin"].iloc[min(9, len(r_margin.table) - 1)])
    pairs, batch = groups(drive)
    w = np.array([witness(z1, z2, drive.stages[0].m)[0] for z1, z2 in pairs])
    keep = np.minimum(w, batch) >= tau
    per_solve = (t_margin - t_walk) / r_margin.n_shift_solves
    floor = t_walk + keep.sum() * per_solve
    print("CPU seconds, one core; the machine is noisy, read the ratios")
    print(f"min_size first call {t_size:.3f} s ({r_size.n_shift_solves} shift solves); max_margin first call "
          f"{t_margin:.3f} s ({r_margin.n_shift_solves} solves), {t_margin / t_size:.1f}x; repeat (all solved) "
          f"{t_walk:.3f} s; {1e3 * per_solve:.2f} ms per max_margin solve")
    print(f"top list's margin tau = {tau:+.6f}; {len(pairs)} groups; largest batch margin in a group "
          f"{batch.min():+.3f} ... {batch.max():+.3f}")
    print(f"groups with a window node whose smallest raw gear margin reaches tau ({GRID_N}² grid): {keep.sum()} "
          f"of {len(pairs)}; no bound valid over the window can skip them")
    print(f"floor with every such group solved at today's cost: {floor:.3f} s = {floor / t_size:.1f}x min_size "
          f"(goal <= 2x); it needs <= {1e3 * max(2 * t_size - t_walk, 0) / max(keep.sum(), 1):.2f} ms per solve")


if __name__ == "__main__":
    main()
