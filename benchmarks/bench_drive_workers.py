"""Drive.optimize serially and on a local Dask cluster of 2 workers: the number of shift solves (goal of issue 35
§5: equal), whether the tables are identical, and the wall and CPU time of this process (the cluster's start
included: a first call as a user makes it).

Drives: a 4 kW gear (m = 3) + roller chain for min_size and max_margin, and the 75 kW gear sized by ISO 6336
(42CrMo4) + chain of bench_drive_optimize.py.

Run: python benchmarks/bench_drive_workers.py
Prints figures; asserts nothing (speed is measured, not tested).
"""
import os
import time

import geardesign as gd
from geardesign.drives.stage_kinds.gear import clear_shift_cache


def compare(label, drive, **kw):
    out = {}
    for workers in (None, 2):
        clear_shift_cache()
        t, c = time.perf_counter(), time.process_time()
        r = drive.optimize(workers=workers, **kw)
        out[workers] = (r, time.perf_counter() - t, time.process_time() - c)
    (s, ts, cs), (p, tp, cp) = out[None], out[2]
    print(f"{label}: shift solves serial {s.n_shift_solves}, workers=2 {p.n_shift_solves}; tables identical "
          f"{s.table.equals(p.table)}; wall {ts:.2f} s / {tp:.2f} s, CPU here {cs:.2f} s / {cp:.2f} s "
          f"(load {os.getloadavg()[0]:.1f})")


def main():
    small = gd.Drive(power_kw=4, n_in_rpm=1450, stages=[gd.GearStage(3), gd.ChainStage()])
    compare("4 kW, m = 3, min_size", small, total_ratio=10, top=3, objective="min_size")
    compare("4 kW, m = 3, max_margin", small, total_ratio=10, top=3, objective="max_margin")
    sized = gd.Drive(power_kw=75, n_in_rpm=1480, stages=[gd.GearStage(m=None, material="42CrMo4"),
                                                          gd.ChainStage(catalog="gost13568")])
    compare("75 kW sized gear + chain", sized, total_ratio=8)


if __name__ == "__main__":
    main()
