"""ISO 6336 strength speed, as ratios against plain references written here (this machine drifts ±50 %):

* one pair's full strength (``strength(pair, load, material=...)``: every factor of parts 1, 2, 3, the result
  object with its factor table) and the bare dict of ``pair_strength`` on numbers, against a plain-Python float
  evaluation of the contact side (geometry, Z_H, Z_E, Z_ε, σ_H0, σ_H with fixed K factors);
* the vectorised chain over N, 5N and 10N designs (every factor, both gears, both methods' work for method B; the
  first call at each size), in designs/s, against a straight-line numpy evaluation of the same contact side over the
  same designs;
* the peak memory of one large call in a fresh process, every field against ``fields=`` the four safety factors;
* the shift solvers' call: ``pair_strength`` on the 5 designs of a finite-difference stencil with their geometry
  given (``geometry=``, as geardesign.gears.checks.strength does once per solver iteration).

The issue's goals: ≤ 100 µs for one pair, ≥ 1 M designs/s vectorised.

Times are CPU times of this process (time.process_time): on a machine shared with other jobs the wall clock of a
call drifts by 2-4x from one repeat to the next, its CPU time much less (the code is single-threaded).

Run: python benchmarks/bench_strength.py [N]
Prints figures; asserts nothing (speed is measured, not tested).
"""
import math
import sys
import time

import numpy as np

from geardesign import GearPair
from geardesign.gears.geometry import mesh_geometry
from geardesign.gears.strength import Load, material, pair_strength, strength
from geardesign.gears.strength.chain import CHAIN_GEOMETRY_FIELDS


from timing import best    # CPU time per call, the best of several rounds (benchmarks/timing.py)


def once(fn):
    """The CPU time of one call (s)."""
    t = time.process_time()
    fn()
    return time.process_time() - t


def plain_contact(m, z1, z2, x1, x2, T1, b, sigma_Hlim=767.0, K=1.3):
    """σ_H and S_H of a spur pair, straight from the formulas (plain floats, 20° rack, fixed K and Z_NT = 1)."""
    a = math.radians(20.0)
    inv_w = math.tan(a) - a + 2 * (x1 + x2) * math.tan(a) / (z1 + z2)
    w = math.atan(math.cbrt(3 * inv_w))
    for _ in range(6):
        w -= (math.tan(w) - w - inv_w) / math.tan(w) ** 2
    d1 = m * z1
    ZH = math.sqrt(2 * math.cos(w) / (math.cos(a) ** 2 * math.sin(w)))
    ea = 1.6
    Ze = math.sqrt((4 - ea) / 3)
    u = z2 / z1
    sH = ZH * 189.8 * Ze * math.sqrt(2000 * T1 / (d1 * b) * (u + 1) / u) * math.sqrt(K)
    return sH, sigma_Hlim / sH


def plain_contact_numpy(m, z1, z2, x1, x2, T1, b, sigma_Hlim=767.0, K=1.3):
    a = math.radians(20.0)
    inv_w = math.tan(a) - a + 2 * (x1 + x2) * math.tan(a) / (z1 + z2)
    w = np.arctan(np.cbrt(3 * inv_w))
    for _ in range(6):
        w -= (np.tan(w) - w - inv_w) / np.tan(w) ** 2
    d1 = m * z1
    ZH = np.sqrt(2 * np.cos(w) / (math.cos(a) ** 2 * np.sin(w)))
    Ze = math.sqrt((4 - 1.6) / 3)
    u = z2 / z1
    sH = ZH * 189.8 * Ze * np.sqrt(2000 * T1 / (d1 * b) * (u + 1) / u) * math.sqrt(K)
    return sH, sigma_Hlim / sH


def stencil_call(pair, load, mat, h=1e-6):
    """pair_strength as the shift solvers' strength checks call it: the design and its four neighbours in (x1, x2),
    their geometry from mesh_geometry given."""
    x1 = pair.x1 + np.array([0.0, h, -h, 0.0, 0.0])
    x2 = pair.x2 + np.array([0.0, 0.0, 0.0, h, -h])
    z1, z2, m = np.full(5, float(pair.z1)), np.full(5, float(pair.z2)), np.full(5, float(pair.m))
    geo = mesh_geometry(pair.mesh.unchecked(z1[None], z2[None]), m[None], x1[None], x2[None], full=False)
    sub = {k: np.broadcast_to(geo[k], (1, 5))[0] for k in CHAIN_GEOMETRY_FIELDS + ("_z1", "_z2")}
    return lambda: pair_strength(m, z1, z2, x1, x2, load=load, material1=mat, face_width_mm=pair.face_width_mm,
                                 geometry=sub)


def main(n=200_000):
    mat = material("42CrMo4")
    load = Load(torque_nm=200, n_rpm=1000, life_h=20_000)
    pair = GearPair(m=4, z1=20, z2=60, x1=0.3, x2=0.1, face_width_mm=40)
    t_result = best(lambda: strength(pair, load, material=mat))
    t_dict = best(lambda: pair_strength(4, 20, 60, 0.3, 0.1, load=load, material1=mat, face_width_mm=40))
    t_plain = best(lambda: plain_contact(4, 20, 60, 0.3, 0.1, 200.0, 40.0), number=2000)
    print("one pair (42CrMo4, 20/60, m = 4, every factor of ISO 6336-1/-2/-3):")
    print(f"  strength(pair, ...) -> StrengthResult   {t_result * 1e6:9.0f} µs   ({t_result / t_plain:6.0f}x the plain "
          f"contact side, {t_plain * 1e6:.1f} µs)")
    print(f"  pair_strength(numbers) -> dict          {t_dict * 1e6:9.0f} µs   ({t_dict / t_plain:6.0f}x)")
    print(f"  goal: 100 µs -> {'met' if t_result <= 1e-4 else f'{t_result / 1e-4:.1f}x over'}")
    t_stencil = best(stencil_call(pair, load, mat))
    print(f"  pair_strength(5 designs, geometry=)     {t_stencil * 1e6:9.0f} µs   ({t_stencil / t_plain:6.0f}x; the "
          f"shift solvers' strength checks, once per iteration)")
    rng = np.random.default_rng(0)
    for size in (n, 5 * n, 10 * n):
        z1 = rng.integers(14, 40, size)
        z2 = z1 + rng.integers(5, 80, size)
        x1 = rng.uniform(0.0, 0.6, size)
        x2 = rng.uniform(0.0, 0.6, size)
        m = rng.choice([2.0, 3.0, 4.0, 5.0], size)
        t_vec = once(lambda: pair_strength(m, z1, z2, x1, x2, load=load, material1=mat, face_width_mm=10 * m))
        t_contact = once(lambda: pair_strength(m, z1, z2, x1, x2, load=load, material1=mat, face_width_mm=10 * m,
                                               root=False))
        t_np = once(lambda: plain_contact_numpy(m, z1, z2, x1, x2, 200.0, 10 * m))
        print(f"vectorised, {size:,} designs: {size / t_vec / 1e6:6.3f} M designs/s with every factor "
              f"({t_vec / t_np:5.1f}x the plain numpy contact side, {size / t_np / 1e6:.2f} M designs/s); "
              f"goal 1 M/s -> {'met' if size / t_vec >= 1e6 else 'not met'}; contact side only (root=False): "
              f"{size / t_contact / 1e6:.3f} M designs/s")
    for size in (10 * n, 50 * n):
        for fields in (None, ("S_H1", "S_H2", "S_F1", "S_F2")):
            rate, peak = fresh_peak(size, fields)
            print(f"vectorised, {size:,} designs in a fresh process, fields={fields}: {rate / 1e6:6.3f} M designs/s, "
                  f"peak resident memory {peak / 2 ** 30:5.2f} GiB")


PEAK = """
import resource, sys, time
import numpy as np
from geardesign.gears.strength import Load, material, pair_strength
size, fields = int(sys.argv[1]), eval(sys.argv[2])
rng = np.random.default_rng(0)
z1 = rng.integers(14, 40, size); z2 = z1 + rng.integers(5, 80, size)
x1 = rng.uniform(0.0, 0.6, size); x2 = rng.uniform(0.0, 0.6, size); m = rng.choice([2.0, 3.0, 4.0, 5.0], size)
mat, load = material("42CrMo4"), Load(torque_nm=200, n_rpm=1000, life_h=20_000)
base = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
t = time.process_time()
out = pair_strength(m, z1, z2, x1, x2, load=load, material1=mat, face_width_mm=10 * m, fields=fields)
t = time.process_time() - t
print(size / t, (resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - base) * 1024)
"""


def fresh_peak(size, fields):
    """(designs/s, peak resident bytes above the inputs) of one vectorised call in a fresh process (``fields``:
    pair_strength's option, None for every field)."""
    import subprocess
    out = subprocess.run([sys.executable, "-c", PEAK, str(size), repr(fields)], capture_output=True, text=True,
                         check=True).stdout.split()
    return float(out[0]), float(out[1])


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 200_000)
