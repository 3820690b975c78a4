"""Forces and shaft analysis of a two-stage reducer (issue 37: <= 1 ms): the mesh forces of both stages
(gears/forces.py), then for each of the three shafts the reactions, moment and torque diagrams, deflection
and slope at the gears (drives/shaft_beam.py) and the DIN 743 safety at the seats (drives/din743.py: key
seats under the gears and the couplings, shoulders beside the bearings). Printed as the median time of one
whole reducer and as a ratio to a reference timed in the same run, interleaved: one
``GearPair(...).geometry()`` (a cost the other benchmarks also quote). CPU times (time.process_time).

Run: python benchmarks/bench_shaft.py [REPEATS]
Prints figures; asserts nothing (speed is measured, not tested).
"""
import statistics
import sys
import time

import geardesign as gd
from geardesign.drives.din743 import Notch, ShaftNotch, shaft_material, shaft_safety
from geardesign.drives.shaft_beam import ShaftLoad, ShaftModel, analyse_shaft

POWER_KW, SPEED_RPM = 15.0, 1450.0
STAGE1 = gd.GearPair(2.5, 21, 80, 0.3, 0.2, beta_deg=12, face_width_mm=40)
STAGE2 = gd.GearPair(4, 19, 66, 0.3, 0.1, beta_deg=10, face_width_mm=60)
# a stepped shaft: bearing seat d1, body d2, bearing seat d1, and (input, output) a coupling end d3;
# bearings at the middle of the seats
SEATS = {"input": (35.0, 45.0, 30.0), "intermediate": (40.0, 50.0, None), "output": (55.0, 65.0, 50.0)}
MATERIAL = shaft_material("42CrMo4")


def sections(d1, d2, d3):
    s = [(25.0, d1), (110.0, d2), (25.0, d1)]
    return s + [(40.0, d3)] if d3 else s


def reducer():
    """Forces of both meshes, then the three shafts: a list of (ShaftAnalysis, ShaftSafety)."""
    T1 = 9549.296585513721 * POWER_KW / SPEED_RPM
    f1 = STAGE1.forces(T1)
    f2 = STAGE2.forces(f1.torque2_nm)
    T2, T3 = f1.torque2_nm, f2.torque2_nm
    out = []
    # gear forces in the y (tangential) and z (radial, toward each gear's own axis) planes; the axial force
    # at the pitch radius
    shafts = {
        "input": [ShaftLoad(60.0, fy_n=-f1.F_t_n, fz_n=-f1.F_r_n, fx_n=f1.F_a_n, z_mm=f1.r1_mm, torque_nm=-T1),
                  ShaftLoad(180.0, torque_nm=T1)],
        "intermediate": [ShaftLoad(45.0, fy_n=f1.F_t_n, fz_n=f1.F_r_n, fx_n=-f1.F_a_n, z_mm=-f1.r2_mm,
                                   torque_nm=T2),
                         ShaftLoad(115.0, fy_n=-f2.F_t_n, fz_n=-f2.F_r_n, fx_n=f2.F_a_n, z_mm=f2.r1_mm,
                                   torque_nm=-T2)],
        "output": [ShaftLoad(115.0, fy_n=f2.F_t_n, fz_n=f2.F_r_n, fx_n=-f2.F_a_n, z_mm=-f2.r2_mm, torque_nm=T3),
                   ShaftLoad(180.0, torque_nm=-T3)],
    }
    for name, loads in shafts.items():
        d1, d2, d3 = SEATS[name]
        model = ShaftModel(sections(d1, d2, d3), [12.5, 147.5], loads)
        notches = [ShaftNotch(25.0, Notch("shoulder", r_mm=1.5)), ShaftNotch(135.0, Notch("shoulder", r_mm=1.5))]
        notches += [ShaftNotch(ld.x_mm, Notch("key")) for ld in loads]
        analysis = analyse_shaft(model, points=40)
        out.append((analysis, shaft_safety(analysis, notches, MATERIAL)))
    return out


def reducer_with_tables():
    """The same, and every table and the critical speeds asked for (what a report shows)."""
    return [(analysis.reactions, analysis.diagrams, analysis.elements, analysis.critical_speed_rpm, safety.table)
            for analysis, safety in reducer()]


def reference():
    gd.GearPair(3, 21, 64, 0.3, 0.2).geometry()


def timed(fn):
    """CPU time of one call (the machine is shared: wall time measures the neighbours too)."""
    t = time.process_time()
    fn()
    return time.process_time() - t


def main(repeats: int = 200):
    result = reducer()                  # imports, catalogs
    reference()
    tr, tf, tt = [], [], []
    for _ in range(repeats):
        tr.append(timed(reference))
        tf.append(timed(reducer))
        tt.append(timed(reducer_with_tables))
    mr, mf, mt = statistics.median(tr), statistics.median(tf), statistics.median(tt)
    print(f"two-stage reducer, forces + 3 shafts (reactions, moments, deflection and slope at the gears, DIN 743 at "
          f"{sum(len(s.table) for _, s in result)} sections): median {mf * 1e3:.3f} ms (min {min(tf) * 1e3:.3f}) over "
          f"{repeats} runs (goal <= 1 ms); reference GearPair(...).geometry() median {mr * 1e3:.3f} ms (min "
          f"{min(tr) * 1e3:.3f}): ratio {mf / mr:.1f}x (of the minima {min(tf) / min(tr):.1f}x)")
    print(f"  with every table and the critical speeds asked for: median {mt * 1e3:.3f} ms, {mt / mr:.1f}x")
    for analysis, safety in result:
        r = analysis.reactions
        print(f"  R = {', '.join(f'{v:.1f}' for v in r['R_n'])} N, max deflection "
              f"{analysis.max_deflection_mm * 1000:.2f} µm, {safety.message}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 200)
