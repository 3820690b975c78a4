"""The max_margin shifts of a drive's tooth pairs: all at once (shifts/centres.py) against one by one.

The pairs are those `Drive.optimize(objective="max_margin")` solves on the drive of bench_drive_optimize.py
(spur m = 3 + roller chain, u = 10 ± 3 %: 922 tooth pairs). Three ways to their optimum:

* batch: `margin_centres` on all of them (what the drive does, 256 at a time);
* one by one: `optimize_shifts(z1, z2, "max_margin", m=3)` per pair (the same solver on one pair);
* active-set search: the exact method's own KKT search per pair (the path before this solver; reference).

Printed: CPU time of each, per pair, their ratios, and how far the answers are apart; then the same drive at
other total ratios (u = 4, 6, 20: more of their pairs' optima are edges), max_margin's first call against
min_size's.

    python benchmarks/bench_margin_centres.py [n_sample]
"""
import sys
import time

import numpy as np

from bench_drive_margin_bound import groups
from bench_drive_optimize import make_drive
import geardesign as gd
from geardesign.drives.stage_kinds.gear import clear_shift_cache
from geardesign.shifts import centres


def cpu(fn):
    c0 = time.process_time()
    out = fn()
    return out, time.process_time() - c0


def main():
    sample = int(sys.argv[1]) if len(sys.argv) > 1 else 150
    drive = make_drive()
    pairs, _ = groups(drive)
    z1, z2 = np.array(pairs).T
    m = drive.stages[0].m
    centres.margin_centres(z1[:4], z2[:4], m)                      # imports and first-call costs
    rows = []
    for _ in range(2):
        r, t_batch = cpu(lambda: centres.margin_centres(z1, z2, m))
        rows.append(t_batch)
    t_batch = min(rows)
    pick = np.linspace(0, len(pairs) - 1, sample).astype(int)
    one, t_one = cpu(lambda: [gd.optimize_shifts(int(z1[i]), int(z2[i]), "max_margin", m=m) for i in pick])
    keep = centres.solve
    centres.solve = lambda prob, bounds: None
    try:
        old, t_old = cpu(lambda: [gd.optimize_shifts(int(z1[i]), int(z2[i]), "max_margin", m=m) for i in pick])
    finally:
        centres.solve = keep
    per_batch, per_one, per_old = t_batch / len(pairs), t_one / sample, t_old / sample
    dx_one = max(max(abs(r["x1"][i] - s.x1), abs(r["x2"][i] - s.x2)) for i, s in zip(pick, one))
    dx_old = max(max(abs(r["x1"][i] - s.x1), abs(r["x2"][i] - s.x2)) for i, s in zip(pick, old))
    print("CPU time, one core; the machine is noisy, read the ratios")
    print(f"{len(pairs)} tooth pairs, m = {m:g}: {int(r['ok'].sum())} certified by the batch")
    print(f"  batch        {t_batch:.3f} s, {1e3 * per_batch:.3f} ms a pair (best of 2)")
    print(f"  one by one   {1e3 * per_one:.3f} ms a pair ({sample} pairs): batch {per_one / per_batch:.0f}x faster")
    print(f"  active-set   {1e3 * per_old:.3f} ms a pair ({sample} pairs): batch {per_old / per_batch:.0f}x faster, "
          f"one by one {per_old / per_one:.1f}x")
    print(f"  largest |dx|: batch - one by one {dx_one:.1e}, batch - active-set search {dx_old:.1e}")
    print("the drive at other total ratios, first call (CPU s):")
    for u in (4.0, 6.0, 20.0):
        (size, t_size), (margin, t_margin) = (first_call(drive, u, objective) for objective in ("min_size", "max_margin"))
        print(f"  u = {u:g}: min_size {t_size:.3f} ({size.n_shift_solves} shift solves), max_margin {t_margin:.3f} "
              f"({margin.n_shift_solves}): {t_margin / t_size:.2f}x")


def first_call(drive, u, objective):
    clear_shift_cache()
    return cpu(lambda: drive.optimize(u, objective=objective))


if __name__ == "__main__":
    main()
