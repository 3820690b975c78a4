"""Planetary sets: one set's exact optimum, and the tooth-count search for a ratio of about 5 with
3 planets over z_sun 12..40. Each figure also as a ratio against the exact optimum of the set's
sun-planet pair alone (optimize_shifts), measured in the same run: the set solves two meshes'
checks through the coaxiality condition.

    python benchmarks/bench_planetary.py
"""
import statistics
import time

import geardesign as gd

SETS = [(21, 43, 108, 3), (18, 27, 72, 3), (24, 37, 96, 3), (30, 46, 120, 3), (11, 12, 37, 3), (20, 25, 72, 4)]


def median_ms(func, repeat=5):
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        func()
        times.append(time.perf_counter() - t)
    return 1e3 * statistics.median(times)


def main():
    gd.optimize_planetary_shifts(21, 43, 108, 3, 2.0)   # warm: imports, caches
    print("one set, exact, max_eps_alpha (median of 5), against its sun-planet pair alone:")
    ratios = []
    for zs, zp, zr, n in SETS:
        t_set = median_ms(lambda: gd.optimize_planetary_shifts(zs, zp, zr, n, 2.0, objective="max_eps_alpha"))
        t_pair = median_ms(lambda: gd.optimize_shifts(zs, zp, objective="max_eps_alpha", m=2.0))
        ratios.append(t_set / t_pair)
        print(f"  {zs}/{zp}/{zr}, {n} planets: {t_set:7.1f} ms   pair {t_pair:6.1f} ms   ratio {t_set / t_pair:4.1f}")
    print(f"  median ratio set/pair: {statistics.median(ratios):.1f}")
    t = time.perf_counter()
    sel = gd.select_planetary_teeth(5.0, 3, 2.0, ratio_tol=0.02, z_sun_range=(12, 40))
    dt = time.perf_counter() - t
    print(f"tooth counts for ratio 5 ± 2 %, 3 planets, z_sun 12..40: {len(sel.table)} candidates, "
          f"{sel.n_solved} solved, {dt:.2f} s ({1e3 * dt / max(sel.n_solved, 1):.0f} ms per solve)")
    print("  best:", sel.message)


if __name__ == "__main__":
    main()
