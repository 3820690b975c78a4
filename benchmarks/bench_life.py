"""ISO 6336-6 service life speed (issue 38), as ratios against references timed in the same run:

* the life of one pair under a 48-bin spectrum (``pair_life``: the chain over the 48 bins in one call, Miner's
  sums per gear and mode, the four safety factors for the required life) against one pair's single-load
  ``pair_strength`` on numbers, against the bare chain over the same 48 bins as ``pair_life`` calls it (the design in
  Python floats, the bins' arrays: the floor of the life's work) and against that chain on a 0-d array design with
  every field (how ``pair_life`` called it up to commit 671d8f7); the issue's goal is <= 1 ms; and ``pair.life`` (the
  same with its LifeResult, whose per-bin table is built when first read);
* ``optimize_shifts`` (max_x_sum) with the damage checks of a 48-bin spectrum against the same optimisation with
  the single-load strength checks (its 80 % torque); the issue's goal is <= 3x.

Times are CPU times of this process (time.process_time), best of several repeats (the machine is shared).

Run: python benchmarks/bench_life.py
Prints figures; asserts nothing (speed is measured, not tested).
"""
import time

import numpy as np

import geardesign as gd
from geardesign.gears.strength import Load, pair_strength
from geardesign.gears.strength.service_life import _STRESS_FIELDS, _bins_load, pair_life


from timing import best    # CPU time per call, the best of several rounds (benchmarks/timing.py)


def main():
    pair = gd.GearPair(4, 20, 60, 0.3, 0.1, face_width_mm=40)
    T = np.linspace(2.5, 120.0, 48)
    spec = gd.LoadSpectrum.from_bins(T, 1000, share=np.full(48, 1 / 48), duration_h=20000)
    m = np.float64(pair.m)

    def life():
        return pair_life(m, pair.z1, pair.z2, pair.x1, pair.x2, spectrum=spec, material1="42CrMo4",
                         face_width_mm=40.0, geometry=pair._geo)

    bins_load = _bins_load(spec, np.arange(48))

    def chain_bins():
        return pair_strength(pair.m, pair.z1, pair.z2, pair.x1, pair.x2, load=bins_load, material1="42CrMo4",
                             face_width_mm=40.0, geometry=pair._geo, fields=_STRESS_FIELDS)

    def chain_arrays():
        return pair_strength(m, pair.z1, pair.z2, pair.x1, pair.x2, load=bins_load, material1="42CrMo4",
                             face_width_mm=40.0, geometry=pair._geo)

    one_load = Load(torque_nm=120.0, n_rpm=1000)

    def one():
        return pair_strength(pair.m, pair.z1, pair.z2, pair.x1, pair.x2, load=one_load, material1="42CrMo4",
                             face_width_mm=40.0, geometry=pair._geo)

    t_life, t_chain, t_arrays = best(life), best(chain_bins), best(chain_arrays)
    t_one = best(one, number=200)
    t_result = best(lambda: pair.life(spec, "42CrMo4"))
    print(f"life of one pair, 48 bins:          {t_life * 1e3:8.3f} ms  (goal <= 1 ms)")
    print(f"  the chain over the 48 bins:       {t_chain * 1e3:8.3f} ms  (life / chain = {t_life / t_chain:.2f})")
    print(f"  the same on a 0-d array design:   {t_arrays * 1e3:8.3f} ms  (life / it = {t_life / t_arrays:.2f})")
    print(f"  one pair, one load (pair_strength): {t_one * 1e3:6.3f} ms  (life / one load = {t_life / t_one:.1f})")
    print(f"  pair.life (a LifeResult):         {t_result * 1e3:8.3f} ms  (it / pair_life = {t_result / t_life:.2f})")

    damage = {"spectrum": spec, "material": "42CrMo4", "face_width_mm": 40.0}
    strength = {"load": Load(torque_nm=96.0, n_rpm=1000, life_h=20000), "material": "42CrMo4",
                "face_width_mm": 40.0}
    runs = {}
    for name, checks in (("strength", strength), ("damage", damage)):
        gd.optimize_shifts(20, 60, m=4, checks=checks, objective="max_x_sum")   # warm: imports, caches

        def solve(checks=checks):
            return gd.optimize_shifts(20, 60, m=4, checks=checks, objective="max_x_sum")

        r = solve()
        runs[name] = (best(solve, repeat=3, number=2), r)
        print(f"optimize_shifts with {name} checks: {runs[name][0] * 1e3:8.1f} ms  x = ({r.x1:.4f}, {r.x2:.4f}), "
              f"active {r.active}, success {r.success}")
    print(f"  damage / strength = {runs['damage'][0] / runs['strength'][0]:.2f}  (goal <= 3)")


if __name__ == "__main__":
    main()
