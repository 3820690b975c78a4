"""The shift solvers with the ISO 6336 strength checks against the same solves without them (issue 26 §6:
`exact` with the three strength checks <= 2x its time without), measured in one run over the same pairs,
interleaved, median per pair; and feasible_region with and without them.

Run: python benchmarks/bench_strength_checks.py [PAIRS]
Prints figures; asserts nothing (speed is measured, not tested).
"""
import statistics
import sys
import time

import geardesign as gd
from geardesign.gears.strength import Load

CASE = {"load": Load(torque_nm=400, n_rpm=1000, life_h=20000), "material": "18CrNiMo7-6", "face_width_mm": 40.0}


def timed(fn):
    t = time.perf_counter()
    fn()
    return time.perf_counter() - t


def main(n_pairs: int = 12):
    pairs = [(z1, round(z1 * 3)) for z1 in range(17, 17 + n_pairs)]
    gd.optimize_shifts(20, 60, m=4, checks=CASE)                          # imports and the materials catalog
    for method in ("exact", "convex", "grid"):
        plain, loaded = [], []
        for z1, z2 in pairs:
            plain.append(timed(lambda: gd.optimize_shifts(z1, z2, m=4, method=method)))
            loaded.append(timed(lambda: gd.optimize_shifts(z1, z2, m=4, method=method, checks=CASE)))
        mp, ml = statistics.median(plain), statistics.median(loaded)
        ratios = sorted(b / a for a, b in zip(plain, loaded))
        print(f"{method:6s}: {len(pairs)} pairs, median {mp * 1e3:7.2f} ms without, {ml * 1e3:8.2f} ms with the three "
              f"strength checks: {ml / mp:5.1f}x (per pair {ratios[0]:.1f}x .. {ratios[-1]:.1f}x; goal for exact <= 2x)")
    a = timed(lambda: gd.feasible_region(20, 60, m=4))
    b = timed(lambda: gd.feasible_region(20, 60, m=4, checks=CASE))
    print(f"feasible_region 20/60: {a:.2f} s without, {b:.2f} s with: {b / a:.1f}x")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 12)
