"""Issue 35's proof: ordinary reducer jobs, each searched in a fresh process (first call), with the design
the search returns re-checked stage by stage: a_w, shifts, the smallest margin at the nominal and at the
manufactured state, and S_H, S_F1, S_F2 recomputed by ``GearPair.strength`` at the stage's own torque.

    python benchmarks/bench_reducer.py [job ...]   # jobs: sized75, conveyor, conveyor_narrowed, three_stage

Times are CPU seconds of the search call (the machine is shared: compare runs of one session only). The
script reads only the public API, so it runs against an earlier checkout too (``PYTHONPATH=<checkout>``) for
the before/after figures of docs/drive_train.md.
"""
from __future__ import annotations

import json
import os
import subprocess
import sys

JOBS = {
    # the 75 kW two-stage sized drive of bench_drive_optimize.py
    "sized75": ("gd.Drive(power_kw=75, n_in_rpm=1480, stages=[gd.GearStage(None, material='42CrMo4'), "
                "gd.ChainStage()])", 8.0),
    # issue 35's conveyor: 15 kW, 1460 rpm to ~60 rpm through two sized gear stages and a roller chain
    "conveyor": ("gd.Drive(motor=gd.motor.select(15, 1460), stages=[gd.GearStage(None, material='42CrMo4', "
                 "name='fast'), gd.GearStage(None, material='42CrMo4', name='slow'), gd.ChainStage()])",
                 1460 / 60),
    # the same with the ranges a user had to narrow before the search took it (issue 35's 21 s run)
    "conveyor_narrowed": ("gd.Drive(motor=gd.motor.select(15, 1460), stages=[gd.GearStage(None, material='42CrMo4', "
                          "name='fast', z1_range=(17, 21), ratio_range=(3.5, 5)), gd.GearStage(None, "
                          "material='42CrMo4', name='slow', z1_range=(17, 21), ratio_range=(3.5, 5)), "
                          "gd.ChainStage(z1=17, ratio_range=(1.2, 1.6))])", 1460 / 60),
    # a three-stage gear reducer, 15 kW, 1460 rpm to ~20 rpm
    "three_stage": ("gd.Drive(motor=gd.motor.select(15, 1460), stages=[gd.GearStage(None, material='42CrMo4', "
                    "name='g1'), gd.GearStage(None, material='42CrMo4', name='g2'), "
                    "gd.GearStage(None, material='42CrMo4', name='g3')])", 1460 / 20),
}

CHILD = r"""
import json, sys, time
import geardesign as gd
drive = eval(sys.argv[1])
c0 = time.process_time()
try:
    r = drive.optimize(total_ratio=float(sys.argv[2]))
except gd.GearDesignError as exc:
    print(json.dumps(dict(refused=str(exc), cpu=time.process_time() - c0)))
    raise SystemExit
cpu = time.process_time() - c0
best = r.best
stages = []
for st, res in zip(best.drive.stages, best.stages):
    if getattr(st, "kind", "") != "gear":
        stages.append(dict(name=st.name, kind=getattr(st, "kind", "?")))
        continue
    rows = best.checks[best.checks["item"] == st.name]
    margins = dict(zip(rows["check"], rows["margin"].astype(float)))
    shop = [v for k, v in margins.items() if k.endswith("_manufactured")]
    flow = res.get("flow") or res.get("stage_flow")
    row = dict(name=st.name, m=st.m, z=[st.z1, st.z2], b=st.face_width_mm, x=[st.x1, st.x2],
               a_w=res["pair"].geometry().a_w, nominal_min=min(v for k, v in margins.items()
                                                               if not k.endswith("_manufactured")),
               manufactured_min=min(shop) if shop else None)
    if flow is not None:
        pair = gd.GearPair(st.m, st.z1, st.z2, st.x1, st.x2, beta_deg=st.beta_deg, face_width_mm=st.face_width_mm)
        s = pair.strength(gd.Load(torque_nm=flow.torque_in_nm, n_rpm=flow.n_in_rpm), material="42CrMo4")
        row.update(S_H=min(s.S_H1, s.S_H2), S_F1=s.S_F1, S_F2=s.S_F2, torque_nm=flow.torque_in_nm)
    stages.append(row)
print(json.dumps(dict(cpu=cpu, solves=r.n_shift_solves, combos=r.n_combinations, designs=r.n_candidates,
                      ratio=best.total_ratio, min_margin=best.min_margin, stages=stages), default=float))
"""


def run(job: str) -> dict:
    expr, ratio = JOBS[job]
    out = subprocess.run([sys.executable, "-c", CHILD, expr, repr(ratio)], capture_output=True, text=True,
                         env=dict(os.environ), timeout=3600)
    if out.returncode:
        return dict(error=out.stderr.strip().splitlines()[-1] if out.stderr.strip() else f"exit {out.returncode}")
    return json.loads(out.stdout.strip().splitlines()[-1])


def show(job: str, res: dict) -> None:
    print(f"{job}: {JOBS[job][0]}.optimize({JOBS[job][1]:.4g})")
    if "error" in res or "refused" in res:
        print(f"  {res.get('refused') or res.get('error')}")
        return
    print(f"  CPU {res['cpu']:.2f} s, {res['solves']} shift solves, {res['combos']} combinations, "
          f"{res['designs']} designs; u = {res['ratio']:.4f}, smallest margin {res['min_margin']:+.4f}")
    for s in res["stages"]:
        if "m" not in s:
            print(f"  {s['name']}: {s['kind']}")
            continue
        shop = "n/a" if s["manufactured_min"] is None else f"{s['manufactured_min']:+.4f}"
        text = (f"  {s['name']}: m {s['m']:g}, z {s['z'][0]}/{s['z'][1]}, b {s['b']:g} mm, x {s['x'][0]:.3f}/"
                f"{s['x'][1]:.3f}, a_w {s['a_w']:.3f} mm; smallest margin nominal {s['nominal_min']:+.4f}, "
                f"manufactured {shop}")
        if "S_H" in s:
            text += f"; GearPair.strength at {s['torque_nm']:.1f} N·m: S_H {s['S_H']:.3f}, S_F {s['S_F1']:.3f}/{s['S_F2']:.3f}"
        print(text)


if __name__ == "__main__":
    for job in sys.argv[1:] or list(JOBS):
        show(job, run(job))
