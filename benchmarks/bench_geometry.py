"""Geometry speed: designs per second for geometry + all checks, and one scalar pair's latency.

Run: python benchmarks/bench_geometry.py [N]
Prints figures; asserts nothing (speed is measured, not tested).
"""
import sys
import time

import numpy as np

import geardesign as gd
from geardesign import checks
from geardesign.gears.geometry import mesh_geometry
from geardesign.gears.mesh import Mesh


def designs(n, seed=0):
    rng = np.random.default_rng(seed)
    z1 = rng.integers(12, 60, n)
    z2 = rng.integers(20, 150, n)
    x1 = rng.uniform(-0.3, 0.9, n)
    x2 = rng.uniform(-0.3, 0.9, n)
    return z1, z2, x1, x2


def one_pass(z1, z2, x1, x2, rack, cs):
    geo = mesh_geometry(Mesh(z1, z2, rack, True), 1.0, x1, x2)
    return checks.margins(geo, cs)


def main(n=1_000_000, repeat=5):
    rack, cs = gd.BasicRack(), gd.make_checks()
    z1, z2, x1, x2 = designs(n)
    t0 = time.perf_counter()
    one_pass(z1, z2, x1, x2, rack, cs)
    cold = time.perf_counter() - t0
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        one_pass(z1, z2, x1, x2, rack, cs)
        times.append(time.perf_counter() - t0)
    warm = min(times)
    # the public, validated call (returns the Geometry object)
    t0 = time.perf_counter()
    g = gd.pair_geometry(1.0, z1, z2, x1, x2)
    public = time.perf_counter() - t0
    del g
    print(f"N = {n:,} designs, geometry (all {len(gd.GEOMETRY_FIELDS)} fields) + {len(cs)} check margins, one core")
    print(f"  first call (fresh memory)  {cold:8.3f} s   {n / cold / 1e6:6.2f} M designs/s")
    print(f"  warm, best of {repeat}           {warm:8.3f} s   {n / warm / 1e6:6.2f} M designs/s")
    print(f"  pair_geometry (validated)  {public:8.3f} s   {n / public / 1e6:6.2f} M designs/s")
    k = 2000
    t0 = time.perf_counter()
    for _ in range(k):
        gd.GearPair(8, 17, 26, 0.898, 0.517).geometry()
    lat = (time.perf_counter() - t0) / k
    print(f"  scalar GearPair(...).geometry() latency: {lat * 1e6:8.1f} us")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 1_000_000)
