"""The ordinary jobs of issue 35 at default ranges, each on its first call in a fresh process (CPU time):

- the conveyor: a 15 kW, 1460 rpm motor (gd.motor.select) to ~60 rpm through two gear stages sized in 42CrMo4
  (module free) and a roller chain (GOST 13568); goal: finishes (no refusal);
- a three-stage reducer: 15 kW at 1460 rpm, u = 70 ± 3 %, three gear stages sized in 42CrMo4; goal <= 10 s.

Reference, timed in the same run: the plain loop, i.e. every ratio combination checked one by one with the
standalone functions (per gear stage: optimize_shifts at m = 1 and pair_strength over every ISO 54 module x face
width, as benchmarks/bench_drive_optimize.py times it), timed on a sample of tooth pairs and scaled to the
number of combinations in the ratio window (counted here). One core; the machine is shared, so read the ratio.

    python benchmarks/bench_drive_search.py
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
from geardesign.catalogs.tables import module_series
from geardesign.gears.strength import Load, pair_strength
from geardesign.shifts.optimize import optimize_shifts

JOBS = {
    "conveyor (2 sized gears + chain)": """
motor = gd.motor.select(15.0, 1460)
d = gd.Drive(motor=motor, stages=[gd.GearStage(None, material="42CrMo4", name="fast"),
                                  gd.GearStage(None, material="42CrMo4", name="slow"), gd.ChainStage()])
U = motor.motor["rated_speed_rpm"] / 60
""",
    "three sized gear stages, u = 70": """
d = gd.Drive(power_kw=15, n_in_rpm=1460, stages=[gd.GearStage(None, material="42CrMo4", name=f"g{i}")
                                                 for i in (1, 2, 3)])
U = 70.0
""",
}
RUN = """
import json, time
import geardesign as gd
{job}
t0, c0 = time.perf_counter(), time.process_time()
r = d.optimize(total_ratio=U, progress=False)
wall, cpu = time.perf_counter() - t0, time.process_time() - c0
stages = [{{k: v for k, v in s["summary"].items() if k in ("name", "z1", "z2", "m", "face_width_mm", "designation")}}
          for s in r.best.stages]
print(json.dumps(dict(wall=wall, cpu=cpu, solves=r.n_shift_solves, combos=r.n_combinations, designs=r.n_candidates,
                      U=U, ok=bool(r.success), size=float(r.table.iloc[0]["size_mm2"]), stages=stages), default=str))
"""


def window_count(drive, U, tol=0.03):
    """Ratio combinations (one option per stage) with the product in U ± tol, counted (not built)."""
    ratios = [st.pairs(1.0, 100.0) for st in drive.stages]
    ratios = [z2 / z1 for z1, z2 in ratios]
    rest = np.sort(np.multiply.outer(ratios[1], ratios[2]).ravel()) if len(ratios) == 3 else np.sort(ratios[1])
    lo, hi = U * (1 - tol), U * (1 + tol)
    return int(sum(np.searchsorted(rest, hi / r, "right") - np.searchsorted(rest, lo / r, "left") for r in ratios[0]))


def plain_per_stage(samples=20, seed=3):
    """CPU seconds of one sized gear stage checked alone: optimize_shifts at m = 1, then pair_strength over every
    ISO 54 module x face width b = ceil(psi_d·d1), psi_d = 0.2 ... 1.0 by 0.05."""
    st = gd.GearStage(None, material="42CrMo4")
    z1, z2 = st.pairs(1.0, 6.3)
    series = np.asarray(module_series(), dtype=float)
    psi = np.arange(0.2, 1.0 + 1e-9, 0.05)
    t = 0.0
    for i in np.random.default_rng(seed).choice(z1.size, samples, replace=False):
        c0 = time.process_time()
        o = optimize_shifts(int(z1[i]), int(z2[i]), "max_x_sum", None, "exact", m=1.0)
        M = np.repeat(series, psi.size)
        B = np.ceil(np.tile(psi, series.size) * M * z1[i] - 1e-9)
        pair_strength(M, int(z1[i]), int(z2[i]), o.x1, o.x2, load=Load(torque_nm=500.0, n_rpm=500.0),
                      material1="42CrMo4", face_width_mm=B)
        t += time.process_time() - c0
    return t / samples


def main():
    root = str(Path(gd.__file__).resolve().parents[1])
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([root, os.environ.get("PYTHONPATH", "")])}
    per_stage = plain_per_stage()
    print(f"plain loop: {1e3 * per_stage:.1f} ms CPU per sized gear stage checked alone")
    for name, job in JOBS.items():
        out = json.loads(subprocess.run([sys.executable, "-c", RUN.format(job=job)], capture_output=True, text=True,
                                        check=True, env=env, cwd=tempfile.gettempdir()).stdout)
        ns = {"gd": gd}
        exec(job, ns)
        combos = window_count(ns["d"], ns["U"])
        plain = combos * 2 * per_stage        # two sized gear stages checked per combination (the chain not counted)
        print(f"{name}: first call {out['wall']:.1f} s wall ({out['cpu']:.1f} s CPU), {out['solves']} shift solves; "
              f"{combos} combinations in the window, {out['combos']} kept under the cost limit, {out['designs']} "
              f"designs; plain loop ~{plain / 3600:.0f} h, {plain / out['cpu']:.0f}x")
        print(f"  best: size {out['size']:.6g} mm²; " + "; ".join(
            ", ".join(f"{k} {v}" for k, v in s.items()) for s in out["stages"]))


if __name__ == "__main__":
    main()
