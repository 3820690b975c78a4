"""The atlas on a local Dask cluster of 1 and 2 worker processes against the serial run.

Run from the repository root:  python benchmarks/bench_parallel.py [--repeats 3]
Needs the Dask extra (pip install "geardesign[dask]"). Each round runs the same atlas serially,
on 1 worker and on 2 workers (the clusters started once, before the rounds; their start is
reported on its own), and on a user's own cluster made as Dask's docs make one
(``LocalCluster(n_workers=2, threads_per_worker=1)`` and ``Client``, default settings: issue 36 §3),
checks that every table is the serial one bit for bit, and prints each time, the best and the spread. Then the per-pair cost, the scheduling cost of one task (a round
trip of a task that does nothing) and, from them, an estimate for a 10^7-pair atlas on 64 workers.
The machine's load average is printed beside the figures: on a shared machine they move with it.
"""
from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from geardesign import parallel  # noqa: E402
from geardesign.shifts import atlas  # noqa: E402

Z1, Z2 = range(12, 61), range(12, 161)     # 6,076 pairs (z2 >= z1), all feasible but the thinnest
BIG_PAIRS, BIG_WORKERS = 10**7, 64


def nothing(chunk):
    return chunk


def same_bits(a, b) -> bool:
    if list(a.columns) != list(b.columns) or a.dtypes.tolist() != b.dtypes.tolist():
        return False
    for col in a.columns:
        x, y = a[col].to_numpy(), b[col].to_numpy()
        if x.dtype.kind == "f" and not np.array_equal(x.view(np.int64), y.view(np.int64)):
            return False
        if x.dtype.kind != "f" and not (x == y).all():
            return False
    return True


def timed(fn):
    t0 = time.perf_counter()
    out = fn()
    return time.perf_counter() - t0, out


def _cpu_s() -> float:
    import psutil
    t = psutil.Process().cpu_times()
    return t.user + t.system


def cpu_timed(fn, client=None):
    """(wall s, this process's CPU s, each worker's CPU s, result): on a machine shared with other
    work the wall time measures the share of the cores a run got; the CPU seconds measure the work."""
    workers = (lambda: client.run(_cpu_s)) if client is not None else (lambda: {})
    w0, c0 = workers(), _cpu_s()
    t, out = timed(fn)
    c1, w1 = _cpu_s(), workers()
    return t, c1 - c0, [w1[k] - w0[k] for k in w0], out


def task_overhead_s(client, n: int = 400) -> float:
    """Seconds per task of a batch of tasks that do nothing: scheduling, transfer, gathering."""
    parallel.map_chunks(nothing, [[i] for i in range(20)], client=client)      # warm
    t, _ = timed(lambda: parallel.map_chunks(nothing, [[i] for i in range(n)], client=client))
    return t / n


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeats", type=int, default=3)
    args = ap.parse_args()
    n = atlas.atlas_size(Z1, Z2)
    print(f"atlas z1 {Z1.start}..{Z1.stop - 1} x z2 {Z2.start}..{Z2.stop - 1} (z2 >= z1): {n} pairs, "
          f"{os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f} at the start")
    import logging

    from distributed import Client, LocalCluster

    with parallel.cluster(workers=1) as one, parallel.cluster(workers=2) as two, \
            LocalCluster(n_workers=2, threads_per_worker=1, silence_logs=logging.CRITICAL) as users, \
            Client(users) as user:
        ref = atlas.shift_atlas(Z1, Z2)                           # warm this process too
        for c in (one, two, user):                                 # and the workers (imports, caches)
            atlas.shift_atlas(range(12, 30), range(30, 60), client=c)    # 540 pairs: a chunk on each worker
        times = {"serial": [], "1 worker": [], "2 workers": [], "user's 2": []}
        critical = {k: [] for k in times}     # CPU s of the busiest process: the wall time on idle cores
        # CPU s of every process of the run: on a loaded machine a worker the OS starves takes fewer chunks, so the
        # busiest process's share moves with the load; the sum does not (serial CPU x workers / sum: the speed-up
        # with the work shared evenly)
        total = {k: [] for k in times}
        identical = True
        for r in range(args.repeats):
            for label, kw in (("serial", {}), ("1 worker", {"client": one}), ("2 workers", {"client": two}),
                              ("user's 2", {"client": user})):
                t, here, there, df = cpu_timed(lambda: atlas.shift_atlas(Z1, Z2, **kw), kw.get("client"))
                times[label].append(t)
                critical[label].append(max([here] + there))
                total[label].append(here + sum(there))
                identical &= same_bits(df, ref)
                print(f"round {r + 1}, {label:9s}: wall {t:6.2f} s; CPU s here {here:6.2f}, on the workers "
                      + ", ".join(f"{w:.2f}" for w in there) + f" (load {os.getloadavg()[0]:.1f})")
        overhead = task_overhead_s(two)
    start_1, _ = timed(lambda: _start_stop(1))
    start_2, _ = timed(lambda: _start_stop(2))
    best = {k: min(v) for k, v in times.items()}
    print()
    for k, v in times.items():
        print(f"{k:10s} best {best[k]:6.2f} s  spread {min(v):.2f}-{max(v):.2f} s  "
              f"speed-up vs serial (best/best) {best['serial'] / best[k]:.2f}x, "
              f"round by round {min(s / t for s, t in zip(times['serial'], v)):.2f}-"
              f"{max(s / t for s, t in zip(times['serial'], v)):.2f}x")
    cbest = {k: min(v) for k, v in critical.items()}
    for k in ("1 worker", "2 workers", "user's 2"):
        rounds = [s / c for s, c in zip(critical["serial"], critical[k])]
        print(f"{k:10s} CPU seconds of the busiest process, best {cbest[k]:.2f} s: speed-up on idle cores "
              f"{cbest['serial'] / cbest[k]:.2f}x best/best, {min(rounds):.2f}-{max(rounds):.2f}x round by round "
              f"(serial CPU {cbest['serial']:.2f} s)")
    for k, n_w in (("1 worker", 1), ("2 workers", 2), ("user's 2", 2)):
        rounds = [n_w * s / c for s, c in zip(total["serial"], total[k])]
        print(f"{k:10s} CPU seconds of all its processes, best {min(total[k]):.2f} s: speed-up with the work shared "
              f"evenly {n_w * min(total['serial']) / min(total[k]):.2f}x best/best, {min(rounds):.2f}-{max(rounds):.2f}x "
              f"round by round")
    print(f"tables identical to the serial one, bit for bit, in every round: {identical}")
    per_pair = cbest["serial"] / n
    chunk = min(max(atlas.ATLAS_CHUNK_MIN, -(-BIG_PAIRS // (parallel.CHUNKS_PER_WORKER * BIG_WORKERS))),
                atlas.ATLAS_CHUNK_MAX)
    tasks = -(-BIG_PAIRS // chunk)
    eff = cbest["serial"] / cbest["2 workers"] / 2
    compute = BIG_PAIRS * per_pair / BIG_WORKERS
    print(f"per pair (serial CPU, best): {1e3 * per_pair:.3f} ms; one task's scheduling and transfer: "
          f"{1e3 * overhead:.2f} ms; local cluster start and close: 1 worker {start_1:.1f} s, "
          f"2 workers {start_2:.1f} s")
    print(f"\nestimate, {BIG_PAIRS:.0e} pairs on {BIG_WORKERS} workers: chunks of {chunk} pairs, {tasks} tasks; "
          f"compute {compute:.0f} s ({compute / 60:.1f} min) at this per-pair cost and perfect scaling; "
          f"scheduling {tasks * overhead:.1f} s in all; at the 2-worker efficiency measured here ({eff:.2f}) "
          f"{compute / eff / 60:.1f} min; in {-(-BIG_PAIRS // (atlas.ATLAS_PAIRS_MAX * BIG_WORKERS))} calls of at "
          f"most {atlas.ATLAS_PAIRS_MAX * BIG_WORKERS:,} pairs (the limit of {atlas.ATLAS_PAIRS_MAX:,} x 64 workers)")


def _start_stop(n: int) -> None:
    with parallel.cluster(workers=n):
        pass


if __name__ == "__main__":
    main()
