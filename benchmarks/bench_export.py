"""DXF, SVG and CSV export of whole gears (issue 29 item 3.7: the DXF took 12-15 s for z = 25, 154 s for z = 100).

Prints, for gears of 25, 50, 100 and 200 teeth: the points written, the seconds per format, microseconds per point,
and as a plain reference the same points written as text lines "x y" with Python's file writes (what any writer
must at least do). Linear export: the µs per point stay flat as z grows. The first DXF call also imports ezdxf
(~0.5-1 s), so a warm-up runs first. One core; the machine is noisy, so read the ratios.

    python benchmarks/bench_export.py
"""
import tempfile
import time
from pathlib import Path

import geardesign as gd
from geardesign.profiles.export import gear_outline


def seconds(fn):
    t = time.perf_counter()
    fn()
    return time.perf_counter() - t


def plain_text(path, x, y):
    with open(path, "w") as fh:
        fh.writelines(f"{a!r} {b!r}\n" for a, b in zip(x.tolist(), y.tolist()))


def main():
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        gd.tooth_profile(2, 10, 0.0).to_dxf(tmp / "warm.dxf")
        print(f"{'z':>5} {'points':>8} {'dxf s':>7} {'svg s':>7} {'csv s':>7} {'plain s':>8} "
              f"{'dxf µs/pt':>10} {'dxf/plain':>10}")
        for z in (25, 50, 100, 200):
            p = gd.tooth_profile(2, z, 0.3)
            x, y = gear_outline(p)
            t_dxf = seconds(lambda: p.to_dxf(tmp / f"g{z}.dxf"))
            t_svg = seconds(lambda: p.to_svg(tmp / f"g{z}.svg"))
            t_csv = seconds(lambda: p.to_csv(tmp / f"g{z}.csv"))
            t_plain = seconds(lambda: plain_text(tmp / f"g{z}.txt", x, y))
            print(f"{z:>5} {x.size:>8} {t_dxf:>7.3f} {t_svg:>7.3f} {t_csv:>7.3f} {t_plain:>8.3f} "
                  f"{1e6 * t_dxf / x.size:>10.2f} {t_dxf / t_plain:>10.1f}")
        pair = gd.GearPair(3, 120, 52, 0.0, 0.815402, beta_deg=10.0)
        print(f"export_profiles(GearPair(3, 120, 52, 0, 0.815402, beta 10), 'g.dxf'): "
              f"{seconds(lambda: gd.export_profiles(pair, tmp / 'pair.dxf')):.2f} s (issue 29: over 60 s)")


if __name__ == "__main__":
    main()
