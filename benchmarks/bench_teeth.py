"""Time of a tooth-count search over z1 in 8..60 with the standard modules (ISO 54 / GOST 9563).

Run from the repository root:  python benchmarks/bench_teeth.py
A fixed centre distance is the natural case for a module search: each module admits only the
few tooth sums whose x-sum fits a_w, so the vectorised screen drops most (pair, module)
candidates before the optimiser runs. Reported: candidates screened, shift solves, time.
"""
from __future__ import annotations

import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from geardesign.shifts.teeth import select_teeth  # noqa: E402

CASES = [
    ("u 1.5 ±2 %, a_w 180, m series 1..50, exact", dict(ratio=1.5, a_w=180.0, m="series")),
    ("u 3.15 ±2 %, a_w 250, m series 1..50, exact", dict(ratio=3.15, a_w=250.0, m="series")),
    ("u 1.5 ±2 %, a_w 180, m series 1..50, grid", dict(ratio=1.5, a_w=180.0, m="series", method="grid")),
    ("u 1.5 ±2 %, a_w free, m = 8, exact", dict(ratio=1.5, m=8)),
]


def main():
    print(f"{'case (z1 in 8..60)':46s} {'screened':>9s} {'solved':>7s} {'feasible':>9s} {'s':>7s} "
          f"{'ms/solve':>9s}  best")
    for label, kw in CASES:
        t0 = time.perf_counter()
        sel = select_teeth(z1_range=(8, 60), **kw)
        dt = time.perf_counter() - t0
        b = sel.best
        best = "-" if b is None else f"{b['z1']}/{b['z2']} m {b['module_mm']:g} x {b['x1']:.3f}/{b['x2']:.3f}"
        print(f"{label:46s} {len(sel.table) + len(sel.skipped):9d} {sel.n_solved:7d} "
              f"{int(sel.table['feasible'].sum()):9d} {dt:7.2f} {1e3 * dt / max(sel.n_solved, 1):9.1f}  {best}")


if __name__ == "__main__":
    main()
