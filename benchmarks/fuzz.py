"""A long self-fuzz run: generated bad and extreme input at every public entry point.

    python benchmarks/fuzz.py --cases 10000 --seed 1

prints the count of each outcome (ok, clean_error, traceback, nan_result, hang, half_written)
per target and overall, and the first reproducers of every failure. The generator and the rule
are in tests/fuzzcases.py (the CI sample is tests/test_fuzz.py). Files go to temporary folders.
"""
from __future__ import annotations

import argparse
import collections
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests"))

from fuzzcases import OUTCOMES, TARGETS, run_case  # noqa: E402


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cases", type=int, default=10000)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--seconds", type=float, default=3600.0, help="stop after this long")
    ap.add_argument("--targets", default=",".join(TARGETS), help="comma list of " + ", ".join(TARGETS))
    ap.add_argument("--case-limit", type=float, default=30.0, help="seconds before a case counts as a hang")
    args = ap.parse_args()
    targets = [t for t in args.targets.split(",") if t]
    counts = collections.Counter()
    per = collections.defaultdict(collections.Counter)
    bad = collections.defaultdict(list)
    t0 = time.perf_counter()
    done = 0
    for i in range(args.cases):
        if time.perf_counter() - t0 > args.seconds:
            break
        target = targets[i % len(targets)]
        outcome, desc, detail = run_case(target, args.seed * 1_000_003 + i, args.case_limit)
        counts[outcome] += 1
        per[target][outcome] += 1
        if outcome not in ("ok", "clean_error") and len(bad[outcome]) < 12:
            bad[outcome].append((target, desc, detail))
        done += 1
        if done % 500 == 0:
            print(f"... {done} cases, {time.perf_counter() - t0:.0f} s", file=sys.stderr)
    wall = time.perf_counter() - t0
    print(f"{done} cases in {wall:.0f} s (seed {args.seed})")
    print("outcome counts: " + ", ".join(f"{o} {counts[o]}" for o in OUTCOMES))
    width = max(map(len, targets))
    for t in targets:
        print(f"  {t:<{width}}  " + "  ".join(f"{o} {per[t][o]}" for o in OUTCOMES if per[t][o]))
    for outcome, rows in bad.items():
        print(f"\n{outcome}:")
        for target, desc, detail in rows:
            print(f"  [{target}] {desc[:240]}\n      -> {detail}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
