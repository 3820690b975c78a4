"""The shift solvers with the ISO 6336 strength checks against the same solves without them (issue 26 §6:
`exact` with the three strength checks <= 2x its time without), measured in one run over the same pairs,
interleaved, median per pair; an infeasible load case (its conflict named) against a feasible one of the same
pair; and feasible_region with and without them.

Run: python benchmarks/bench_strength_checks.py [PAIRS]
Prints figures; asserts nothing (speed is measured, not tested).
"""
import statistics
import sys
import time

import geardesign as gd
from geardesign.gears.strength import Load

CASE = {"load": Load(torque_nm=400, n_rpm=1000, life_h=20000), "material": "18CrNiMo7-6", "face_width_mm": 40.0}
# contact_strength conflicts with the geometry (issue 26: it took 3.9 s against 1.1 ms without the load)
INFEASIBLE = {"load": Load(torque_nm=200, n_rpm=1000, life_h=20000), "material": "42CrMo4", "face_width_mm": 40.0}


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
    # an infeasible case (S_H < S_Hmin wherever the chain holds): the conflict search's answer, against a
    # feasible solve of the same pair with the same load case at a lighter torque
    light = {**INFEASIBLE, "load": Load(torque_nm=100, n_rpm=1000, life_h=20000)}
    for method in ("exact", "grid"):
        feasible = timed(lambda: gd.optimize_shifts(20, 60, m=4, method=method, checks=light))
        infeasible = timed(lambda: gd.optimize_shifts(20, 60, m=4, method=method, checks=INFEASIBLE))
        print(f"{method:6s}: infeasible 20/60 at 200 N·m (42CrMo4) {infeasible * 1e3:7.1f} ms, feasible at 100 N·m "
              f"{feasible * 1e3:6.1f} ms: {infeasible / feasible:5.1f}x")
    a = timed(lambda: gd.feasible_region(20, 60, m=4))
    b = timed(lambda: gd.feasible_region(20, 60, m=4, checks=CASE))
    print(f"feasible_region 20/60: {a:.2f} s without, {b:.2f} s with: {b / a:.1f}x")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 12)
