"""The drive's shafts (issue 37 item 5), as ratios against references timed in the same run:

* forces and shaft analysis of a two-stage reducer: every element's load on its shaft (mesh forces on the
  operating circle, torques), the two bearings' reactions of each shaft and each shaft's deflection at its gears'
  face ends (the beam, :func:`geardesign.drives.shafting_analysis.beam_deflections`), three shafts; against a
  plain-Python statics of the same loads (sums of forces and moments, no beam) — the issue's goal: <= 1 ms; at
  1.5, 15 and 45 kW (the seats and bearings, so the shafts' sections, are sized for each load);
* the sized 75 kW drive of benchmarks/bench_reducer.py (job sized75) optimised with ``shafting=Shafting()``
  (the ranked designs re-analysed on their shafts: DIN 743 seat sizes, bearings for the life, K_Hβ from f_sh)
  against the same search without, each in a fresh process (CPU seconds) — the issue's goal: <= 2x.

Times are CPU times (time.process_time; the machine is shared). Prints figures; asserts nothing.

    python benchmarks/bench_drive_shafts.py [--no-search]
"""
from __future__ import annotations

import json
import subprocess
import sys
import time


from functools import partial

import timing

best = partial(timing.best, repeat=5, number=200)
POWERS_KW = (1.5, 15.0, 45.0)     # the reducer's loads: its seats, bearings and so its shafts' sections change with them    # CPU time per call, the best of several rounds (benchmarks/timing.py)


def shafts_of_a_reducer(power_kw=15.0):
    import geardesign as gd
    from geardesign.drives.shafting import Shafting
    from geardesign.drives.shafting_analysis import beam_deflections, element_loads, two_support_reactions

    drive = gd.Drive(power_kw=power_kw, n_in_rpm=1460, shafting=Shafting(), stages=[
        gd.GearStage(3, 20, 80, material="42CrMo4", face_width_mm=45, name="fast", beta_deg=12),
        gd.GearStage(4, 21, 84, material="42CrMo4", face_width_mm=65, name="slow")])
    an = drive.analyse()
    stages, T = list(an.stages), an.flow["torque_nm"].to_numpy()
    layout = {k: (m.sections, m.supports_mm, {ld.name: ld.x_mm for ld in m.loads})
              for k, m in ((k, a.model) for k, a in an.shafting["analyses"].items())}
    widths = {"fast": 45.0, "slow": 65.0}

    def ours():
        for k, els in element_loads(drive, stages, T).items():
            sections, supports, xs = layout[k]
            x = [xs[e.name] for e in els]
            fy, fz, fx, y = ([getattr(e, f) for e in els] for f in ("fy", "fz", "fx", "y_mm"))
            two_support_reactions(x, fy, fz, fx, y, *supports)
            ends = [x for e in els if e.width_mm for x in (xs[e.name] - widths[e.name] / 2, xs[e.name] + widths[e.name] / 2)]
            beam_deflections(sections, supports, x, fy, fz, [-a * b for a, b in zip(y, fx)], [0.0] * len(x), ends)

    loads = {k: [(layout[k][2][e.name], e.fy, e.fz, e.fx, e.y_mm) for e in els]
             for k, els in element_loads(drive, stages, T).items()}

    def reference():      # plain-Python statics of the same loads (what any shaft tool does first)
        for k, rows in loads.items():
            xa, xb = layout[k][1]
            fy = sum(r[1] for r in rows)
            fz = sum(r[2] for r in rows)
            by = -(sum(r[1] * (r[0] - xa) for r in rows) - sum(r[4] * r[3] for r in rows)) / (xb - xa)
            bz = -sum(r[2] * (r[0] - xa) for r in rows) / (xb - xa)
            _ = (-fy - by, by, -fz - bz, bz)

    t_ours, t_ref = best(ours), best(reference, number=2000)
    print(f"forces and shaft analysis, two-stage reducer (3 shafts), {power_kw:g} kW: {1e3 * t_ours:.3f} ms (goal <= 1 ms); "
          f"plain-Python statics {1e6 * t_ref:.1f} us; ratio {t_ours / t_ref:.0f}")


CHILD = r"""
import json, sys, time
import geardesign as gd
from geardesign.drives.shafting import Shafting
shafting = Shafting() if sys.argv[1] == "with" else None
drive = gd.Drive(power_kw=75, n_in_rpm=1480, shafting=shafting,
                 stages=[gd.GearStage(None, material='42CrMo4'), gd.ChainStage()])
c0 = time.process_time()
r = drive.optimize(total_ratio=8.0)
cpu = time.process_time() - c0
print(json.dumps(dict(cpu=cpu, success=r.success, message=r.message,
                      shafts=None if r.best is None or r.best.shafting is None else
                      r.best.shafting["shafts"][["shaft", "d_bearing_mm", "bearings", "least_safety"]].to_dict("records"))))
"""


def sized75():
    out = {}
    for mode in ("without", "with"):
        p = subprocess.run([sys.executable, "-c", CHILD, mode], capture_output=True, text=True, timeout=3600)
        out[mode] = json.loads(p.stdout.strip().splitlines()[-1]) if p.returncode == 0 else {"error": p.stderr[-400:]}
    for mode, r in out.items():
        print(f"sized75 {mode} shafting: " + (f"CPU {r['cpu']:.2f} s; {r['message']}" if "cpu" in r else r["error"]))
        if r.get("shafts"):
            print("  shafts: " + "; ".join(f"shaft {s['shaft']} d {s['d_bearing_mm']:g} mm {s['bearings']} "
                                           f"S {s['least_safety']:.3g}" for s in r["shafts"]))
    if all("cpu" in r for r in out.values()):
        print(f"  ratio with/without: {out['with']['cpu'] / out['without']['cpu']:.2f} (goal <= 2)")


if __name__ == "__main__":
    for power in POWERS_KW:
        shafts_of_a_reducer(power)
    if "--no-search" not in sys.argv:
        sized75()
