"""A worm + chain drive search (issue 39's goal: <= 2 s): seed 002's brake stand, 4 kW at 1500 rpm, a worm stage
sized by its load (WormStage(None, None, z1=2, casting="centrifugal"): for each design the smallest GOST 2144-76 /
GOST 19672-74 worm that holds every worm check, the ANSI/AGMA 6034-B92 load at that design's own torque included)
and a roller chain (GOST 13568, chain.design's checks), total ratio 25 ± 3 % (1500 -> 60 rpm), min_size. Timed on
its first call in a fresh process (CPU time of that process: imports excluded, catalogs and caches cold).

References, timed in the same run:

* the plain loop: the same worm sizing one design at a time (``size_worm`` on Python floats for each design's wheel
  teeth, worm speed and torque), timed on a sample of the search's designs and scaled to their number;
* the same search with the worm given (m_x = 5 mm, q = 10: no sizing, the geometric checks only), in a fresh
  process too.

One core; the machine is shared, so read the ratios.

    python benchmarks/bench_worm_drive.py
"""
import json
import math
import subprocess
import sys
import time

import numpy as np

JOB = """
import geardesign as gd
worm = gd.WormStage({worm}, z1=2, ratio_range=(8, 40), efficiency=0.87, name="worm", {extra})
d = gd.Drive(power_kw=4, n_in_rpm=1500, stages=[worm, gd.ChainStage(name="chain", k_e=2.148)])
U = 25.0
"""
SIZED = JOB.format(worm="None, None", extra='casting="centrifugal"')
GIVEN = JOB.format(worm="5.0, 10.0", extra="")
RUN = """
import json, time
{job}
t0, c0 = time.perf_counter(), time.process_time()
r = d.optimize(total_ratio=U, ratio_tol=0.03, objective="min_size", progress=False)
wall, cpu = time.perf_counter() - t0, time.process_time() - c0
w = r.best.drive.stages[0]
print(json.dumps(dict(wall=wall, cpu=cpu, designs=r.n_candidates, ok=bool(r.success),
                      worm=dict(z2=w.z2, m_x=w.m_x, q=w.q, a=w.a),
                      chain=r.best.stages[1]["summary"].get("designation"))))
"""


def fresh(job: str) -> dict:
    out = subprocess.run([sys.executable, "-c", RUN.format(job=job)], capture_output=True, text=True, check=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def plain_loop(sample: int = 300, seed: int = 39):
    """CPU seconds per design of the worm's sizing one design at a time (size_worm on floats), over a sample of
    the designs the search meets: wheel teeth 16 … 80 (ratios 8 … 40), the worm at 1500 rpm, the torque of 4 kW
    through the worm (T_out = T_in·u·η)."""
    import geardesign as gd
    from geardesign.drives.stage_kinds.worm import size_worm

    stage = gd.WormStage(None, None, z1=2, ratio_range=(8, 40), efficiency=0.87, casting="centrifugal")
    rng = np.random.default_rng(seed)
    z2 = rng.integers(16, 81, sample)
    t_in = 4000.0 / (1500.0 * math.pi / 30.0)
    size_worm(stage, 25, 1500.0, t_in * 12.5 * 0.87)          # warm: catalogs loaded
    c0 = time.process_time()
    for zz in z2:
        try:
            size_worm(stage, int(zz), 1500.0, t_in * zz / 2 * 0.87)
        except gd.GearDesignError:
            pass
    return (time.process_time() - c0) / sample


def main() -> None:
    sized = fresh(SIZED)
    given = fresh(GIVEN)
    per_design = plain_loop()
    loop = per_design * sized["designs"]
    print("worm (sized by its AGMA load) + chain, 4 kW at 1500 rpm, u = 25 ± 3 %, min_size; first call in a fresh "
          "process (CPU s)")
    print(f"  search, worm sized          {sized['cpu']:7.3f} s  (wall {sized['wall']:.3f} s; goal <= 2 s)  "
          f"{sized['designs']} designs, best worm {sized['worm']}, chain {sized['chain']}")
    print(f"  search, worm given (m_x 5)  {given['cpu']:7.3f} s  {given['cpu'] / sized['cpu']:6.2f}x of the sized "
          f"search's time")
    print(f"  plain loop, size_worm one design at a time: {per_design * 1e3:.3f} ms/design x {sized['designs']} = "
          f"{loop:.2f} s  ({loop / sized['cpu']:.1f}x the sized search)")


if __name__ == "__main__":
    main()
