"""Shift optimisation: the speed-accuracy trade of each method, and the atlas time.

Run: python benchmarks/bench_shift.py [n_pairs]   (or --kinds: the kinds' ratios alone)
For each method and tolerance: median time per pair (one call per pair) and the error
against method="exact" (distance in x and objective gap) over a fixed set of pairs; exact also as a ratio
to a plain numpy evaluation of the seven margins on its 31x31 start grid, timed beside each solve (the
machine's load falls on both);
then ``exact`` for helical (β = 15°) and internal pairs as a ratio of the spur time on the same
tooth counts (issues 12 and 29 ask for 1.5x at most), on the first 60 pairs and on 30 pairs with z2 up to 150;
then the batched atlas for z1 in 8..40, z2 in z1..120.
Prints figures; asserts nothing.
"""
import sys
import time

import numpy as np

import geardesign as gd
from bench_geometry import plain_margins
from geardesign.gears.geometry import exact_sum_nodes
from geardesign.shifts.objectives import OBJECTIVES
from geardesign.shifts.problem import DEFAULT_BOUNDS


def pairs(n, seed=7, z2_max=120):
    rng = np.random.default_rng(seed)
    out = set()
    while len(out) < n:
        z1 = int(rng.integers(10, 41))
        z2 = int(rng.integers(z1, z2_max + 1))
        out.add((z1, z2))
    return sorted(out)


def ring_pairs(n, seed=1):
    """The sample of issue 36 §3: z1 14..40, z2 drawn from z1 + 12..150 (pairs() draws z2 from z1..z2_max and
    kinds() lifts it to z1 + 10: fewer large rings)."""
    rng = np.random.default_rng(seed)
    z1 = rng.integers(14, 41, n)
    return [(int(a), int(rng.integers(a + 12, 151))) for a in z1]


def main(n=200):
    ps = pairs(n)
    exact = {}
    t_exact, t_plain = [], []
    g = exact_sum_nodes(*DEFAULT_BOUNDS, 31)
    X1, X2 = (a.ravel() for a in np.meshgrid(g, g, indexing="ij"))
    for z1, z2 in ps:
        t0 = time.perf_counter()
        exact[(z1, z2)] = gd.optimize_shifts(z1, z2, method="exact")
        t_exact.append(time.perf_counter() - t0)
        with np.errstate(all="ignore"):   # the plain reference, timed beside each solve
            t0 = time.perf_counter()
            plain_margins(float(z1), float(z2), X1, X2)
            t_plain.append(time.perf_counter() - t0)
    feasible = [p for p in ps if exact[p].success]
    print(f"{len(ps)} pairs (z1 10..40, z2 z1..120), objective max_x_sum, default checks; "
          f"{len(feasible)} feasible")
    print(f"{'method':<8} {'tol':>8} {'median ms/pair':>15} {'max |dx|':>10} {'median |dx|':>12} {'max obj gap':>12}")
    print(f"{'exact':<8} {1e-9:>8.0e} {np.median(t_exact) * 1e3:>15.2f} {0:>10.1e} {0:>12.1e} {0:>12.1e}")
    print(f"  (a plain numpy evaluation of the seven margins on the 31x31 start grid, timed beside each solve: "
          f"{np.median(t_plain) * 1e3:.3f} ms median; exact takes {np.median(t_exact) / np.median(t_plain):.1f}x that)")
    gd.optimize_shifts(17, 26, method="convex")   # compile the cvxpy problem once
    for method, tols, subset in (("convex", (1e-4, 1e-7), feasible[:60]), ("grid", (0.05, 0.01, 0.002), feasible)):
        for tol in tols:
            times, dx, gap = [], [], []
            for p in subset:
                t0 = time.perf_counter()
                r = gd.optimize_shifts(*p, method=method, tol=tol)
                times.append(time.perf_counter() - t0)
                e = exact[p]
                dx.append(np.hypot(r.x1 - e.x1, r.x2 - e.x2))
                gap.append(abs(r.fun - e.fun))
            print(f"{method:<8} {tol:>8.0e} {np.median(times) * 1e3:>15.2f} {max(dx):>10.1e} "
                  f"{np.median(dx):>12.1e} {max(gap):>12.1e}" + (f"   ({len(subset)} pairs)" if len(subset) != len(feasible) else ""))
    print("exact, every objective (same pairs): median / 90th percentile ms per pair, share solved by "
          "Newton from the grid node (the rest fall back to SLSQP)")
    for objective in sorted(o for o in OBJECTIVES if not OBJECTIVES[o].needs_load):   # strength: bench_strength_checks.py
        times, fast = [], 0
        for p in ps:
            t0 = time.perf_counter()
            r = gd.optimize_shifts(*p, objective=objective)
            times.append(time.perf_counter() - t0)
            fast += "grid node" in r.message
        print(f"  {objective:<22} {np.median(times) * 1e3:6.2f} / {np.percentile(times, 90) * 1e3:6.2f} ms"
              f"   {fast}/{len(ps)} by Newton from the grid node")
    times = []
    for z1, z2 in ps[:100]:
        a_w = (z1 + z2) / 2 + 0.3          # m = 1: x1 + x2 fixed by the centre distance
        t0 = time.perf_counter()
        gd.optimize_shifts(z1, z2, objective="balanced_sliding", a_w=a_w, m=1.0)
        times.append(time.perf_counter() - t0)
    print(f"  balanced_sliding, a_w fixed (1 variable): {np.median(times) * 1e3:.2f} ms median (100 pairs)")
    kinds(ps[:60])
    kinds(pairs(30, seed=29, z2_max=150))   # larger rings, where the ring's own checks decide more often
    kinds(ring_pairs(30))                    # issue 36 §3's sample: every ring at least 12 teeth larger
    t0 = time.perf_counter()
    df = gd.shift_atlas(range(8, 41), range(8, 121))
    dt = time.perf_counter() - t0
    print(f"atlas z1 8..40 x z2 z1..120 (exact, batched): {len(df)} pairs in {dt:.2f} s "
          f"({dt / len(df) * 1e3:.2f} ms/pair), {int(df.feasible.sum())} feasible")


def kinds(ps, rounds=5):
    """exact per pair for each kind on the same tooth counts (a ring keeps >= 10 more teeth than its
    pinion), the kinds interleaved pair by pair and timed in CPU seconds, ``rounds`` times: a pair's time is the
    least of its rounds (the load of other processes only ever adds), the figure the median over the pairs; the
    ratio of each round's medians shows the spread; then internal/spur over the pairs whose internal solve used one
    start point and over those that used several (separate feasible pieces of the start grid, each solved; the
    message says "best of N starts")."""
    ps = [(z1, max(z2, z1 + 10)) for z1, z2 in ps]
    kinds = (("spur", {}), ("helical 15°", dict(beta_deg=15.0)), ("internal", dict(internal=True)))
    times = {name: np.full((rounds, len(ps)), np.inf) for name, _ in kinds}
    for name, kind in kinds:
        gd.optimize_shifts(*ps[0], **kind)
    several = np.zeros(len(ps), bool)   # internal pairs solved from more than one start (separate feasible pieces)
    for r in range(rounds):
        for j, p in enumerate(ps):
            for name, kind in kinds:
                t0 = time.process_time()
                res = gd.optimize_shifts(*p, method="exact", **kind)
                times[name][r, j] = time.process_time() - t0
                if name == "internal":
                    several[j] = "best of" in res.message
    med = {k: np.median(v.min(axis=0)) for k, v in times.items()}
    spread = np.median(times["internal"], axis=1) / np.median(times["spur"], axis=1)
    print(f"exact per kind ({len(ps)} pairs, z2 {min(p[1] for p in ps)}..{max(p[1] for p in ps)}, z2 >= z1 + 10, "
          f"CPU time, least of {rounds} rounds): " + "; ".join(
        f"{k} {v * 1e3:.2f} ms median ({v / med['spur']:.2f}x spur)" for k, v in med.items())
          + f"; internal/spur round by round {spread.min():.2f}-{spread.max():.2f}x")
    least = {k: v.min(axis=0) for k, v in times.items()}
    for label, sel in (("one start", ~several), ("several starts", several)):
        if sel.any():
            print(f"  internal pairs solved from {label}: {sel.sum()}, internal/spur "
                  f"{np.median(least['internal'][sel]) / np.median(least['spur'][sel]):.2f}x")


if __name__ == "__main__":
    if sys.argv[1:] == ["--kinds"]:     # the kinds alone (issue 36 §3's internal/spur figure)
        kinds(pairs(200)[:60])
        kinds(ring_pairs(30))
    else:
        main(int(sys.argv[1]) if len(sys.argv) > 1 else 200)
