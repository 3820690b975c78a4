"""Worm pair geometry speed, as ratios against a plain reference written here and timed in the same run:

* one pair: ``worm_geometry_float`` (every field of WORM_FIELDS in Python floats), ``WormPair(...)`` (its inputs
  validated, the geometry, the existence checks), and the pair's check margins (the registry's checks on its geometry
  dict, no table), against ``plain_worm``: the lead angle, diameters, centre distance and mid-plane contact ratio
  from their formulas in plain Python;
* the vectorised ``worm_geometry`` over N designs, in designs/s, against the same few formulas in numpy.

The issue's goal: one worm pair's geometry, efficiency and rating <= 200 µs (the efficiency and rating come from
another branch; the geometry's share is what this measures).

Times are CPU times of this process (time.process_time): on a shared machine the wall clock drifts 2-4x.

Run: python benchmarks/bench_worm.py [N]
Prints figures; asserts nothing (speed is measured, not tested).
"""
import math
import sys
import time

import numpy as np

from geardesign.gears.checks import make_checks
from geardesign.gears.worm.geometry import worm_geometry, worm_geometry_float
from geardesign.gears.worm.pair import WormPair


from functools import partial

import timing

best = partial(timing.best, repeat=5, number=200)    # CPU time per call, the best of several rounds (benchmarks/timing.py)


def plain_worm(m_x, z1, z2, q, x2, alpha_deg=20.0, ha=1.0, c=0.25):
    """A few of the pair's quantities straight from the formulas (ZA, plain floats): the reference."""
    gamma = math.atan2(z1, q)
    a_x = math.radians(alpha_deg)
    d1, d2 = q * m_x, z2 * m_x
    da1, df1 = d1 + 2 * ha * m_x, d1 - 2 * (ha + c) * m_x
    da2, df2 = d2 + 2 * (ha + x2) * m_x, d2 - 2 * (ha + c - x2) * m_x
    a = (d1 + d2) / 2 + x2 * m_x
    rb2, ra2 = d2 / 2 * math.cos(a_x), da2 / 2
    eps = (math.sqrt(ra2 * ra2 - rb2 * rb2) - d2 / 2 * math.sin(a_x) + (ha - x2) * m_x / math.sin(a_x)) / (
        math.pi * m_x * math.cos(a_x))
    return gamma, da1, df1, da2, df2, a, eps


def plain_worm_arrays(m_x, z1, z2, q, x2, alpha_deg=20.0, ha=1.0, c=0.25):
    gamma = np.arctan2(z1, q)
    a_x = math.radians(alpha_deg)
    d1, d2 = q * m_x, z2 * m_x
    da2 = d2 + 2 * (ha + x2) * m_x
    a = (d1 + d2) / 2 + x2 * m_x
    rb2, ra2 = d2 / 2 * math.cos(a_x), da2 / 2
    eps = (np.sqrt(ra2 * ra2 - rb2 * rb2) - d2 / 2 * math.sin(a_x) + (ha - x2) * m_x / math.sin(a_x)) / (
        math.pi * m_x * math.cos(a_x))
    return gamma, d1 + 2 * ha * m_x, d1 - 2 * (ha + c) * m_x, da2, d2 - 2 * (ha + c - x2) * m_x, a, eps


def main(n: int = 1_000_000) -> None:
    args = (5.0, 2, 25, 10.0, 0.1)
    t_ref = best(lambda: plain_worm(*args))
    t_float = best(lambda: worm_geometry_float(*args))
    t_pair = best(lambda: WormPair(*args))
    pair = WormPair(*args)
    checks = make_checks(kind="worm")
    geo = pair._geo
    t_margins = best(lambda: [c.margin(geo) for c in checks])
    print("one worm pair (CPU time, best of 5 x 200)")
    print(f"  plain reference (7 quantities)    {t_ref * 1e6:8.2f} µs   1.0x")
    print(f"  worm_geometry_float (37 fields)   {t_float * 1e6:8.2f} µs   {t_float / t_ref:5.1f}x")
    print(f"  WormPair(...) validated           {t_pair * 1e6:8.2f} µs   {t_pair / t_ref:5.1f}x")
    print(f"  its 7 check margins               {t_margins * 1e6:8.2f} µs   {t_margins / t_ref:5.1f}x")
    print(f"  pair + margins                    {(t_pair + t_margins) * 1e6:8.2f} µs   (goal with efficiency and "
          "rating: <= 200 µs)")
    rng = np.random.default_rng(1)
    m = rng.choice([2.0, 2.5, 3.15, 4.0, 5.0, 6.3, 8.0], n)
    z1 = rng.integers(1, 5, n).astype(float)
    z2 = rng.integers(25, 80, n).astype(float)
    q = rng.choice([8.0, 10.0, 12.5, 16.0], n)
    x2 = rng.uniform(-0.8, 0.8, n)
    t_plain = best(lambda: plain_worm_arrays(m, z1, z2, q, x2), repeat=3, number=1)
    t_vec = best(lambda: worm_geometry(m, z1, z2, q, x2), repeat=3, number=1)
    print(f"\n{n} designs, vectorised (CPU time, best of 3)")
    print(f"  plain numpy reference (7 quantities)  {n / t_plain / 1e6:6.2f} M designs/s   1.0x time")
    print(f"  worm_geometry (37 fields)             {n / t_vec / 1e6:6.2f} M designs/s   {t_vec / t_plain:5.1f}x time")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 1_000_000)
