"""A drive search whose gear stages are sized by their service life (issue 38 §4, ``GearStage(spectrum=...)``)
against the same search sized by the single load alone, timed in the same run (first calls, shift cache cleared).

Two gear stages without a module (42CrMo4, 20 000 h), 7.5 kW at 1450 rpm, u = 12 ± 3 %, min_mass; the spectrum a
duty cycle of twice the nominal torque 5 % of the time, the nominal 50 %, half of it 45 %. Prints each search's CPU
time, its shift solves and best design, and the ratio (the damage checks rate each tooth pair at its own flow with
one ISO 6336-6 call per pair and flow).

    python benchmarks/bench_drive_life.py
"""
import time

import geardesign as gd
from geardesign.drives.stage_kinds.gear import clear_shift_cache

DUTY = gd.DutyCycle([2.0, 1.0, 0.5], [0.05, 0.5, 0.45])


def search(spectrum):
    """(result, CPU seconds) of the first call of the search."""
    stages = [gd.GearStage(None, material="42CrMo4", life_h=20000, spectrum=spectrum, name=f"gear {i}",
                           z1_range=(18, 22), z2_max=100) for i in (1, 2)]
    clear_shift_cache()
    c0 = time.process_time()
    r = gd.Drive(stages=stages, n_in_rpm=1450, power_kw=7.5).optimize(12, 0.03, "min_mass", top=3, progress=False)
    return r, time.process_time() - c0


def main():
    times = {}
    for label, spectrum in (("single load", None), ("duty cycle", DUTY)):
        r, t = search(spectrum)
        times[label] = t
        best = ", ".join(f"m {s['summary']['m']:g} b {s['summary']['face_width_mm']:g} "
                         f"{s['summary']['z1']}/{s['summary']['z2']}" for s in r.best.stages)
        print(f"{label:12s} {t:7.2f} s CPU, {r.n_shift_solves} shift solves, best {r.best.mass_kg:.2f} kg: {best}")
    print(f"ratio duty cycle / single load: {times['duty cycle'] / times['single load']:.2f}")


if __name__ == "__main__":
    main()
