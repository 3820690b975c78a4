"""A long self-fuzz run: generated bad and extreme input at every public entry point.

    python tools/fuzz.py --cases 10000 --seed 1

prints the count of each outcome (ok, clean_error, traceback, nan_result, hang, half_written,
fails_checks, feasibility_tol, warning, link_replaced; see tests/fuzzcases.py) per target and
overall, and the first reproducers of every failure. The generator and the rule are in
tests/fuzzcases.py, tests/fuzzsurfaces.py, tests/fuzzstrength.py and tests/fuzzmachines.py (the CI
sample is tests/test_fuzz.py); the load-capacity targets alone:

    python tools/fuzz.py --targets strength_pair,pair_strength,strength_solvers,strength_planetary,\
strength_cli,strength_drive,strength_report,planetary_spectrum

(planetary_spectrum: sets under load spectra on the sun, reversing ones among them, re-checked against
planetary_life);
the machine elements (engine, spectra and life, worms, bearings, shafts, efficiency, their commands):

    python tools/fuzz.py --targets engine,joint_forces,load_spectrum,pair_life,damage_optimize,worm,\
select_worm,bearing,shaft,stage_efficiency,cli_machines

Every file a case writes goes into a temporary folder: the run makes a private one, points the
temporary directory of this process and its children (TMPDIR) at it, and counts a case that
leaves anything in it as half_written. Not a benchmark: it times nothing but its own run.
"""
from __future__ import annotations

import argparse
import collections
import os
import shutil
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

from tests.fuzzcases import OUTCOMES, TARGETS, run_case  # noqa: E402


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cases", type=int, default=10000)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--seconds", type=float, default=3600.0, help="stop after this long")
    ap.add_argument("--targets", default=",".join(TARGETS), help="comma list of " + ", ".join(TARGETS))
    ap.add_argument("--case-limit", type=float, default=30.0, help="seconds before a case counts as a hang")
    args = ap.parse_args()
    targets = [t for t in args.targets.split(",") if t]
    unknown = [t for t in targets if t not in TARGETS]
    if unknown:
        ap.error(f"unknown targets {unknown}")
    private = tempfile.mkdtemp(prefix="geardesign-fuzz-")
    os.environ["TMPDIR"] = tempfile.tempdir = private
    try:
        return _run(args, targets, private)
    finally:
        shutil.rmtree(private, ignore_errors=True)


def _left_behind(private: str) -> list:
    """What a case left in the private temporary folder (then removed for the next case)."""
    left = os.listdir(private)
    for name in left:
        path = os.path.join(private, name)
        if os.path.isdir(path) and not os.path.islink(path):
            shutil.rmtree(path, ignore_errors=True)
        else:
            os.unlink(path)
    return left


def _run(args, targets, private) -> int:
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
        left = _left_behind(private)
        if left and outcome in ("ok", "clean_error"):
            outcome, detail = "half_written", f"left in the temporary folder: {[n[:40] for n in left[:5]]}"
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
