"""Drive.optimize on a two-stage drive (spur gear m = 3 + roller chain, GOST 13568, total ratio 10 ± 3 %,
motor AIR100L4 4 kW / 1410 rpm from the catalog, keyed hubs on both output shafts); then issue 26 §6's
drive with the module and face width free (75 kW at 1480 rpm, spur gear sized by ISO 6336 in 42CrMo4 +
roller chain, u = 8 ± 3 %; goal <= 2 s on its first call), in a fresh process.

Prints, per objective: the first call (shift solves included: the shift cache is cleared), a repeat
(solved tooth pairs cached), the work done, and as a plain reference the same designs checked one
by one with the standalone functions (optimize_shifts, chain.design, key.select per ratio combination;
timed on a sample and scaled), i.e. what a loop over the split would cost. One core; the machine is
noisy (±50 %), so read the ratio.

    python benchmarks/bench_drive_optimize.py
"""
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

import geardesign as gd
from geardesign import chain, key
from geardesign.drives.stage_kinds.gear import clear_shift_cache
from geardesign.shifts.optimize import optimize_shifts


def make_drive():
    motor = gd.motor.select(4.0, 1450)
    return gd.Drive(motor=motor, stages=[gd.GearStage(3), gd.ChainStage(catalog="gost13568")],
                    shafts=[gd.Shaft(40, 60, 1, "pinion shaft"), gd.Shaft(60, 80, 2, "output")])


def sampled_combinations(drive, total_ratio, samples, seed):
    """(z1, z2, u_gear, chain z1s, chain z2s) of ``samples`` random gear tooth pairs of the drive that a chain
    completes to ``total_ratio`` ± 3 %: the combinations a plain loop checks."""
    gear, ch = drive.stages
    z1, z2 = gear.pairs(1.0, 100.0)
    rng = np.random.default_rng(seed)
    for i in rng.choice(z1.size, samples, replace=False):
        ug = z2[i] / z1[i]
        zc1, zc2 = ch.pairs(total_ratio / ug * 0.97, total_ratio / ug * 1.03)
        if zc1.size:
            yield int(z1[i]), int(z2[i]), ug, zc1, zc2


def plain_loop_per_combination(drive, samples=40, seed=1):
    """Seconds per ratio combination when each is checked with the standalone functions."""
    t = 0.0
    done = 0
    for z1, z2, ug, zc1, zc2 in sampled_combinations(drive, 10, samples, seed):
        t0 = time.process_time()
        optimize_shifts(z1, z2, "max_x_sum", None, "exact", m=3)
        n1 = drive.n_in_rpm / ug
        t1 = 27.09 * ug * 0.98
        chain.design(torque_nm=t1, n1_rpm=n1, ratio=zc2[0] / zc1[0], z1=int(zc1[0]))
        key.select(40, t1, 60)
        key.select(60, t1 * zc2[0] / zc1[0] * 0.96, 80)
        t += time.process_time() - t0
        done += 1
    return t / done


SIZED = ("gd.Drive(power_kw=75, n_in_rpm=1480, stages=[gd.GearStage(m=None, material='42CrMo4'), "
         "gd.ChainStage()])")
FRESH = f"""
import json, time
import geardesign as gd
d = {SIZED}
t0, c0 = time.perf_counter(), time.process_time()
r = d.optimize(total_ratio=8)
wall, cpu = time.perf_counter() - t0, time.process_time() - c0
b = r.table.iloc[0]
print(json.dumps(dict(wall=wall, cpu=cpu, solves=r.n_shift_solves, combos=r.n_combinations,
                      designs=r.n_candidates, best=[int(b['gear.z1']), int(b['gear.z2']), float(b['gear.m']),
                      float(b['gear.face_width_mm']), b['chain.designation'], int(b['chain.z1']), int(b['chain.z2']),
                      float(b['size_mm2'])])))
"""


def plain_sized_per_combination(samples=40, seed=2):
    """Seconds per ratio combination of the sized drive, each checked with the standalone functions: the
    pair's shifts (optimize_shifts at m = 1), its module and width by pair_strength over every ISO 54 module
    x face width b = ceil(psi_d·d1), psi_d = 0.2 ... 1.0 by 0.05, in one vectorised call, and chain.design at
    the chain's torque and speed."""
    from geardesign.catalogs.tables import module_series
    from geardesign.gears.strength import Load, pair_strength

    t_in = 75_000 / (2 * np.pi * 1480 / 60)
    series = np.asarray(module_series(), dtype=float)
    psi = np.arange(0.2, 1.0 + 1e-9, 0.05)
    t, done = 0.0, 0
    for z1, z2, ug, zc1, zc2 in sampled_combinations(eval(SIZED), 8, samples, seed):
        t0 = time.process_time()
        o = optimize_shifts(z1, z2, "max_x_sum", None, "exact", m=1.0)
        M = np.repeat(series, psi.size)
        B = np.ceil(np.tile(psi, series.size) * M * z1 - 1e-9)
        s = pair_strength(M, z1, z2, o.x1, o.x2, load=Load(torque_nm=t_in, n_rpm=1480),
                          material1="42CrMo4", face_width_mm=B)
        ok = (np.minimum(s["S_H1"], s["S_H2"]) >= s["S_Hmin"]) & (np.minimum(s["S_F1"], s["S_F2"]) >= s["S_Fmin"])
        assert ok.any()
        chain.design(torque_nm=t_in * ug * 0.98, n1_rpm=1480 / ug, ratio=zc2[0] / zc1[0], z1=int(zc1[0]))
        t += time.process_time() - t0
        done += 1
    return t / done


def sized_drive():
    """Issue 26 §6: the sized drive's first call in a fresh process, against the plain loop."""
    root = str(Path(gd.__file__).resolve().parents[1])      # the package this benchmark imported
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([root, os.environ.get("PYTHONPATH", "")])}
    out = json.loads(subprocess.run([sys.executable, "-c", FRESH], capture_output=True, text=True, check=True,
                                    env=env, cwd=tempfile.gettempdir()).stdout)
    plain = plain_sized_per_combination() * out["combos"]
    print()
    print(f"sized drive ({SIZED}).optimize(total_ratio=8), first call in a fresh process")
    print(f"  first call {out['wall']:.3f} s wall ({out['cpu']:.3f} s CPU), "
          f"{out['solves']} shift solves, {out['combos']} combinations, {out['designs']} designs; "
          f"plain loop {plain:.1f} s, {plain / out['cpu']:.0f}x; goal <= 2 s")
    z1, z2, m, b, des, c1, c2, size = out["best"]
    print(f"  best: gear {z1}/{z2} m = {m:g} b = {b:g} mm, chain {des} {c1}/{c2}, size {size:.6g} mm²")


def main():
    drive = make_drive()
    drive.optimize(10)           # imports, catalogs read once
    per_combo = plain_loop_per_combination(drive)
    print("times in s: wall (CPU of this process; on a shared machine the CPU time is the one-core figure)")
    print(f"{'objective':12} {'first call':>16} {'repeat':>16} {'combinations':>12} {'designs':>9} "
          f"{'shift solves':>12} {'plain loop':>10} {'speed-up':>9}")
    for objective in ("min_size", "min_mass", "max_margin"):
        clear_shift_cache()
        t0, c0 = time.perf_counter(), time.process_time()
        r = drive.optimize(10, objective=objective)
        first, first_cpu = time.perf_counter() - t0, time.process_time() - c0
        t0, c0 = time.perf_counter(), time.process_time()
        drive.optimize(10, objective=objective)
        repeat, repeat_cpu = time.perf_counter() - t0, time.process_time() - c0
        plain = per_combo * r.n_combinations
        print(f"{objective:12} {first:7.3f} ({first_cpu:6.3f}) {repeat:7.3f} ({repeat_cpu:6.3f}) "
              f"{r.n_combinations:12d} {r.n_candidates:9d} {r.n_shift_solves:12d} {plain:10.1f} "
              f"{plain / first_cpu:8.0f}x")
        b = r.table.iloc[0]
        print(f"{'':12} best: gear {b['gear.z1']}/{b['gear.z2']}, chain {b['chain.designation']} "
              f"{b['chain.z1']}/{b['chain.z2']}, u = {b['total_ratio']:.4f}, size {b['size_mm2']:.4g} mm², "
              f"mass {b['mass_kg']:.4g} kg, margin {b['min_margin']:+.3f}")
    sized_drive()


if __name__ == "__main__":
    main()
