"""Time to evaluate every candidate of the full GOST and ISO chain catalogs for one drive.

Run from the repository root:  python benchmarks/bench_chain_design.py
Goal: under 50 ms per design call (all rows x strands x z1 candidates, all checks, ranking).
"""
from __future__ import annotations

import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from geardesign import chain, key  # noqa: E402

CASES = [
    ("gost13568, z1 = 13, strands 1-4", dict(catalog="gost13568", z1=13, strands=(1, 2, 3, 4))),
    ("gost13568, free z1 (13..27), strands 1-4", dict(catalog="gost13568", strands=(1, 2, 3, 4))),
    ("iso606 A+B, free z1, strands 1-3", dict(catalog="iso606", strands=(1, 2, 3))),
    ("iso606 A+B, free z1, power rating", dict(catalog="iso606", strands=(1, 2, 3), method="power_rating")),
]


def best_of(fn, repeat=7):
    fn()  # warm-up: loads and caches the CSV tables
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return min(times), sorted(times)[len(times) // 2], out


def main():
    print(f"{'case':48s} {'candidates':>10s} {'best ms':>9s} {'median ms':>10s}")
    for label, extra in CASES:
        args = dict(torque_nm=380, n1_rpm=120, ratio=1, k_e=2.148)
        args.update(extra)
        t_best, t_med, res = best_of(lambda: chain.design(**args))
        print(f"{label:48s} {len(res.candidates):10d} {t_best * 1e3:9.2f} {t_med * 1e3:10.2f}")
    t_best, t_med, sel = best_of(lambda: key.select(60, 503, 50))
    print(f"{'key.select(60 mm, 503 N·m, hub 50 mm)':48s} {len(sel.candidates):10d} {t_best * 1e3:9.2f} {t_med * 1e3:10.2f}")


if __name__ == "__main__":
    main()
