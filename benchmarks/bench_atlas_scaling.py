"""The atlas's cost per pair as the atlas grows: 10³, 10⁴, 3·10⁴ and 10⁵ pairs with a large wheel (the ranges of
issue 36 §3, where the optimum of most pairs lies on the window's edge x2 = 3), as CPU time per pair against the
10³-pair atlas's, measured in the same run; and how many pairs went to the one-by-one solver (with the feasible
ones among them: the docstring promises only infeasible pairs go there).

Before the window's edges were candidates of the batched Newton, 36 % of the feasible pairs went one by one and the
cost per pair rose from 0.77 ms at 10³ pairs to 1.42 ms at 10⁵ (1.8×); the goal is ≤ 1.1×.

Run: python benchmarks/bench_atlas_scaling.py [--largest 100000]
Prints figures; asserts nothing (speed is measured, not tested).
"""
import argparse
import os
import time

from geardesign.shifts import atlas

# (z1 range, z2 range): every z1 with every z2 (z2 > z1 throughout)
SIZES = {
    1_024: (range(12, 44), range(185, 217)),
    10_000: (range(12, 112), range(185, 285)),
    29_929: (range(12, 185), range(185, 358)),
    100_000: (range(12, 212), range(212, 712)),
}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--largest", type=int, default=100_000, help="leave out the atlases larger than this")
    args = ap.parse_args()
    alone = []
    solve = atlas._row_solved

    def counted(z1, z2, *rest):
        row = solve(z1, z2, *rest)
        alone.append(row["feasible"])
        return row

    atlas._row_solved = counted
    atlas.shift_atlas([17], [200])      # warm: imports and caches
    ref = None
    for n, (z1, z2) in SIZES.items():
        if n > args.largest:
            continue
        assert atlas.atlas_size(z1, z2) == n
        alone.clear()
        t = time.process_time()
        df = atlas.shift_atlas(z1, z2)
        per = (time.process_time() - t) / n
        ref = ref or per
        print(f"{n:>7,} pairs (z1 {z1.start}..{z1.stop - 1} x z2 {z2.start}..{z2.stop - 1}): "
              f"{per * 1e3:6.3f} ms CPU a pair,"
              f" {per / ref:4.2f}x the 10^3 atlas's; feasible {int(df.feasible.sum()):,}; one by one {len(alone):,}"
              f" ({sum(alone):,} of them feasible); load average {os.getloadavg()[0]:.1f}")


if __name__ == "__main__":
    main()
