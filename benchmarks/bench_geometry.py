"""Geometry speed, as ratios against plain references written here (this machine drifts ±50 %):

* vectorised geometry + the seven default check margins against a plain straight-line numpy
  version of the same seven margins (textbook formulas, arccos and all), and that plain version
  evaluated in the library's cache-sized blocks (what blocking alone gives a numpy kernel doing its work);
* one pair's GearPair(...).geometry() against a plain-Python evaluation of a few fields, and
  ``gd.pair_geometry`` on single numbers against GearPair(...).geometry();
* ``import geardesign`` (and the first GearPair) against ``import numpy``;
* helical (β = 15°) and internal pairs against spur pairs with the same tooth counts and shifts
  (vectorised and one design), the ratios issue 12 asks to keep within 1.3x;
* a region's grid (41 × 41 nodes of one pair, what feasible_region and the atlas evaluate) against the
  plain version on the same nodes.

The plain margins agree with the library's (tests/test_benchmarks.py holds them to 1e-9 on scattered
designs): the interference margin is ρ_p − max(ρ_l, 0), as the check defines it.

Run: python benchmarks/bench_geometry.py [N]
Prints figures; asserts nothing (speed is measured, not tested).
"""
import math
import subprocess
import sys
import time

import numpy as np

import geardesign as gd
from geardesign import checks
from geardesign.gears.geometry import BLOCK, exact_sum_nodes, mesh_geometry
from geardesign.gears.mesh import Mesh


def designs(n, seed=0):
    rng = np.random.default_rng(seed)
    z1 = rng.integers(12, 60, n)
    z2 = rng.integers(20, 150, n)
    x1 = rng.uniform(-0.3, 0.9, n)
    x2 = rng.uniform(-0.3, 0.9, n)
    return z1, z2, x1, x2


def one_pass(z1, z2, x1, x2, rack, cs, full=True):
    """Every design's geometry (all fields, or with ``full=False`` those the checks read) and its
    margins, block by block: only the margins are kept at full size."""
    return mesh_geometry(Mesh(z1, z2, rack, True), 1.0, x1, x2, full, then=lambda geo: checks.margins(geo, cs))


def kind_designs(n, seed=1):
    """Designs every kind admits (z2 > z1 for a ring), shared by the spur, helical and internal runs."""
    rng = np.random.default_rng(seed)
    z1 = rng.integers(12, 60, n)
    z2 = z1 + rng.integers(15, 90, n)
    return z1, z2, rng.uniform(0.0, 0.6, n), rng.uniform(0.0, 0.6, n)


KINDS = (("spur", {}), ("helical 15°", dict(beta_deg=15.0)), ("internal", dict(internal=True)))


def plain_margins(z1, z2, x1, x2, alpha=math.radians(20.0), ha=1.0, c=0.25, rho_f=0.38, sa_min=0.25, eps_min=1.2):
    """The seven default margins, straight-line numpy, m = 1 (textbook forms, no care for digits)."""
    inv = lambda a: np.tan(a) - a
    inv_w = inv(alpha) + 2 * (x1 + x2) * np.tan(alpha) / (z1 + z2)
    t = np.cbrt(3 * inv_w)                             # tan α_w by Newton from the series start
    for _ in range(6):
        t = t - (t - np.arctan(t) - inv_w) * (1 + t * t) / (t * t)
    aw_ = np.arctan(t)
    a = (z1 + z2) / 2
    a_w = a * np.cos(alpha) / np.cos(aw_)
    y = a_w - a
    dy = x1 + x2 - y
    ra1, ra2 = z1 / 2 + ha + x1 - dy, z2 / 2 + ha + x2 - dy
    rb1, rb2 = z1 / 2 * np.cos(alpha), z2 / 2 * np.cos(alpha)
    g = a_w * np.sin(aw_)
    rho_a1, rho_a2 = np.sqrt(ra1 ** 2 - rb1 ** 2), np.sqrt(ra2 ** 2 - rb2 ** 2)
    eps = (rho_a1 + rho_a2 - g) / (np.pi * np.cos(alpha))
    aa1, aa2 = np.arccos(rb1 / ra1), np.arccos(rb2 / ra2)
    sa1 = 2 * ra1 * (np.pi / (2 * z1) + 2 * x1 * np.tan(alpha) / z1 + inv(alpha) - inv(aa1))
    sa2 = 2 * ra2 * (np.pi / (2 * z2) + 2 * x2 * np.tan(alpha) / z2 + inv(alpha) - inv(aa2))
    hl = ha + c - rho_f * (1 - np.sin(alpha))
    xmin1, xmin2 = hl - z1 * np.sin(alpha) ** 2 / 2, hl - z2 * np.sin(alpha) ** 2 / 2
    rho_l1, rho_l2 = (x1 - xmin1) / np.sin(alpha), (x2 - xmin2) / np.sin(alpha)
    rho_p1, rho_p2 = g - rho_a2, g - rho_a1
    return (x1 - xmin1, x2 - xmin2, rho_p1 - np.maximum(rho_l1, 0), rho_p2 - np.maximum(rho_l2, 0),
            sa1 - sa_min, sa2 - sa_min, eps - eps_min)


def plain_blocked(z1, z2, x1, x2):
    """:func:`plain_margins` block by block (BLOCK designs): what cache-sized blocks alone give the
    plain formulas, i.e. the speed a numpy kernel doing the plain version's work would reach."""
    out = np.empty((7, np.size(x1)))
    for s in range(0, np.size(x1), BLOCK):
        out[:, s:s + BLOCK] = plain_margins(z1[s:s + BLOCK], z2[s:s + BLOCK], x1[s:s + BLOCK], x2[s:s + BLOCK])
    return out


def plain_scalar(z1, z2, x1, x2, m, alpha=math.radians(20.0), ha=1.0):
    """A plain-Python pair evaluation of α_w, a_w, d_a1, d_a2 and ε_α (what scalar peers compute)."""
    inv_w = math.tan(alpha) - alpha + 2 * (x1 + x2) * math.tan(alpha) / (z1 + z2)
    t = (3 * inv_w) ** (1 / 3)
    for _ in range(6):
        t = t - (t - math.atan(t) - inv_w) * (1 + t * t) / (t * t)
    aw_ = math.atan(t)
    a = m * (z1 + z2) / 2
    a_w = a * math.cos(alpha) / math.cos(aw_)
    dy = x1 + x2 - (a_w - a) / m
    da1, da2 = m * (z1 + 2 * (ha + x1 - dy)), m * (z2 + 2 * (ha + x2 - dy))
    rb1, rb2 = m * z1 / 2 * math.cos(alpha), m * z2 / 2 * math.cos(alpha)
    eps = (math.sqrt(da1 ** 2 / 4 - rb1 ** 2) + math.sqrt(da2 ** 2 / 4 - rb2 ** 2) - a_w * math.sin(aw_)) \
        / (math.pi * m * math.cos(alpha))
    return aw_, a_w, da1, da2, eps


def best_of(fn, repeat=5):
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return min(times)


def import_cpu_s(code: str) -> float:
    """CPU seconds of a fresh interpreter running ``code`` (the best of three)."""
    probe = f"import time; t = time.process_time(); {code}; print(time.process_time() - t)"
    return min(float(subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True,
                                    check=True).stdout) for _ in range(3))


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
    t0 = time.perf_counter()
    g = gd.pair_geometry(1.0, z1, z2, x1, x2, fields=["a_w", "eps_alpha", "sa1", "sa2"])
    public_some = time.perf_counter() - t0
    del g
    print(f"N = {n:,} designs, geometry (all {len(gd.GEOMETRY_FIELDS)} fields) + {len(cs)} check margins, one core")
    print(f"  first call (fresh memory)  {cold:8.3f} s   {n / cold / 1e6:6.2f} M designs/s")
    print(f"  warm, best of {repeat}           {warm:8.3f} s   {n / warm / 1e6:6.2f} M designs/s")
    print(f"  pair_geometry (validated)  {public:8.3f} s   {n / public / 1e6:6.2f} M designs/s")
    print(f"  pair_geometry(fields=[a_w, eps_alpha, sa1, sa2]) {public_some:8.3f} s   "
          f"{n / public_some / 1e6:6.2f} M designs/s")
    zf1, zf2 = z1.astype(float), z2.astype(float)
    plain = best_of(lambda: plain_margins(zf1, zf2, x1, x2), repeat)
    lean = best_of(lambda: one_pass(z1, z2, x1, x2, rack, cs, full=False), repeat)
    print(f"  plain straight-line numpy, the 7 margins only: {plain:8.3f} s; geardesign (all fields + margins) "
          f"is {plain / warm:5.2f}x its speed; with the fields the checks read (full=False, what "
          f"pair_geometry(fields=...) and the solvers use) {lean:6.3f} s, {plain / lean:5.2f}x")
    blocked = best_of(lambda: plain_blocked(zf1, zf2, x1, x2), repeat)
    print(f"  the plain formulas themselves in blocks of {BLOCK:,} designs (cache-sized, as the library "
          f"evaluates): {blocked:6.3f} s, {plain / blocked:5.2f}x the plain; the library's check fields take "
          f"{lean / blocked:4.2f}x their time")
    agree(z1, z2, x1, x2, rack, cs)
    k = 5000
    lat = best_of(lambda: [gd.GearPair(8, 17, 26, 0.898, 0.517).geometry() for _ in range(k)]) / k
    ref = best_of(lambda: [plain_scalar(17, 26, 0.898, 0.517, 8.0) for _ in range(k)]) / k
    print(f"  GearPair(...).geometry(), all {len(gd.GEOMETRY_FIELDS)} fields, validated: {lat * 1e6:7.1f} us; "
          f"plain Python, 5 fields: {ref * 1e6:5.1f} us (ratio {lat / ref:4.1f})")
    # CPU time, the two interleaved: on a shared machine the wall clock of a 20 µs call drifts 10x
    cpu = {"pair": [], "one": []}
    for _ in range(7):
        for name, fn in (("pair", lambda: gd.GearPair(8, 17, 26, 0.898, 0.517).geometry()),
                         ("one", lambda: gd.pair_geometry(8, 17, 26, 0.898, 0.517))):
            t0 = time.process_time()
            for _ in range(k):
                fn()
            cpu[name].append((time.process_time() - t0) / k)
    one, lat_cpu = min(cpu["one"]), min(cpu["pair"])
    print(f"  gd.pair_geometry on single numbers: {one * 1e6:7.1f} us CPU, {one / lat_cpu:4.2f}x "
          f"GearPair(...).geometry() ({lat_cpu * 1e6:.1f} us CPU; issue 36 goal <= 1.5x)")
    kinds(min(n, 200_000), repeat)
    region_grid(repeat)
    t_np = import_cpu_s("import numpy")
    t_gd = import_cpu_s("import geardesign")
    t_pair = import_cpu_s("import geardesign as gd; gd.GearPair(8, 17, 26, 0.898, 0.517).geometry()")
    print(f"  import numpy {t_np:5.3f} s CPU; import geardesign {t_gd:5.3f} s ({t_gd / t_np:4.2f}x); "
          f"import + first GearPair.geometry() {t_pair:5.3f} s ({t_pair / t_np:4.2f}x)")


def agree(z1, z2, x1, x2, rack, cs):
    """How far the plain margins are from the library's: on the benchmark's designs and at z2 = 5000."""
    big = np.random.default_rng(2).uniform(0.0, 0.5, (2, 2000))
    for name, (a, b, c, d) in (("these designs", (z1, z2, x1, x2)), ("z1 20, z2 5000", (20, 5000, *big))):
        ours = one_pass(a, b, c, d, rack, cs, full=False)
        with np.errstate(all="ignore"):
            plain = plain_margins(np.asarray(a, float), np.asarray(b, float), c, d)
        worst = max(float(np.nanmax(np.abs(ours[ck.name] - p))) for ck, p in zip(cs, plain))
        print(f"  plain against geardesign margins, {name}: max |difference| {worst:.1e}")


def kinds(n, repeat):
    """Each kind's geometry (all fields) against spur's, vectorised and for one design."""
    z1, z2, x1, x2 = kind_designs(n)
    rack = gd.BasicRack()
    vec, one = {}, {}
    for name, kind in KINDS:
        mesh = Mesh(z1, z2, rack, True, **kind)
        vec[name] = best_of(lambda: mesh_geometry(mesh, 1.0, x1, x2), repeat)
        k = 3000
        one[name] = best_of(lambda: [gd.GearPair(8, 17, 40, 0.4, 0.3, **kind).geometry() for _ in range(k)]) / k
    print(f"  kinds, {n:,} designs vectorised (all fields) and GearPair(8, 17, 40, 0.4, 0.3).geometry():")
    for name, _ in KINDS:
        print(f"    {name:<12} {n / vec[name] / 1e6:6.2f} M designs/s ({vec[name] / vec['spur']:4.2f}x spur's time); "
              f"one design {one[name] * 1e6:6.1f} us ({one[name] / one['spur']:4.2f}x spur's time)")


def region_grid(repeat, z1=17, z2=26, n=41):
    """One pair's region grid (n × n nodes of x1, x2 in [-1, 2], on exact_sum_nodes as the start grid
    and the atlas lay them): geometry + margins, against plain."""
    g = exact_sum_nodes(-1.0, 2.0, n)
    X1, X2 = (a.ravel() for a in np.meshgrid(g, g, indexing="ij"))
    rack, cs = gd.BasicRack(), gd.make_checks()
    reps = 50
    ours = best_of(lambda: [one_pass(z1, z2, X1, X2, rack, cs, full=False) for _ in range(reps)], repeat) / reps
    with np.errstate(all="ignore"):
        plain = best_of(lambda: [plain_margins(float(z1), float(z2), X1, X2) for _ in range(reps)], repeat) / reps
    print(f"  region grid {n}x{n} of {z1}/{z2}, geometry (check fields) + margins: {ours * 1e3:6.3f} ms; "
          f"plain {plain * 1e3:6.3f} ms; geardesign is {plain / ours:4.2f}x its speed")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 1_000_000)
