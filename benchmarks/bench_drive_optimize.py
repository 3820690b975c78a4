"""Drive.optimize on a two-stage drive (spur gear m = 3 + roller chain, GOST 13568, total ratio 10 ± 3 %,
motor AIR100L4 4 kW / 1410 rpm from the catalog, keyed hubs on both output shafts).

Prints, per objective: the first call (shift solves included: the shift cache is cleared), a repeat
(solved tooth pairs cached), the work done, and as a plain reference the same designs checked one
by one with the standalone functions (optimize_shifts, chain.design, key.select per ratio combination;
timed on a sample and scaled), i.e. what a loop over the split would cost. One core; the machine is
noisy (±50 %), so read the ratio.

    python benchmarks/bench_drive_optimize.py
"""
import time

import numpy as np

import geardesign as gd
from geardesign import chain, key
from geardesign.drives.stage_kinds.gear import shift_solution
from geardesign.shifts.optimize import optimize_shifts


def make_drive():
    motor = gd.motor.select(4.0, 1450)
    return gd.Drive(motor=motor, stages=[gd.GearStage(3), gd.ChainStage(catalog="gost13568")],
                    shafts=[gd.Shaft(40, 60, 1, "pinion shaft"), gd.Shaft(60, 80, 2, "output")])


def plain_loop_per_combination(drive, samples=40, seed=1):
    """Seconds per ratio combination when each is checked with the standalone functions."""
    gear, ch = drive.stages
    z1, z2 = gear.pairs(1.0, 100.0)
    rng = np.random.default_rng(seed)
    t = 0.0
    done = 0
    for i in rng.choice(z1.size, samples, replace=False):
        ug = z2[i] / z1[i]
        zc1, zc2 = ch.pairs(10 / ug * 0.97, 10 / ug * 1.03)
        if zc1.size == 0:
            continue
        t0 = time.process_time()
        optimize_shifts(int(z1[i]), int(z2[i]), "max_x_sum", None, "exact", m=3)
        n1 = drive.n_in_rpm / ug
        t1 = 27.09 * ug * 0.98
        chain.design(torque_nm=t1, n1_rpm=n1, ratio=zc2[0] / zc1[0], z1=int(zc1[0]))
        key.select(40, t1, 60)
        key.select(60, t1 * zc2[0] / zc1[0] * 0.96, 80)
        t += time.process_time() - t0
        done += 1
    return t / done


def main():
    drive = make_drive()
    drive.optimize(10)           # imports, catalogs read once
    per_combo = plain_loop_per_combination(drive)
    print("times in s: wall (CPU of this process; on a shared machine the CPU time is the one-core figure)")
    print(f"{'objective':12} {'first call':>16} {'repeat':>16} {'combinations':>12} {'designs':>9} "
          f"{'shift solves':>12} {'plain loop':>10} {'speed-up':>9}")
    for objective in ("min_size", "min_mass", "max_margin"):
        shift_solution.cache_clear()
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


if __name__ == "__main__":
    main()
