"""A scene with a [teeth] section: u = 1.5 at m = 8 (seed 000's ratio), run end to end."""
import math

import pandas as pd

import geardesign as gd
from geardesign.cli import main

SCENE = """
title = "u = 1.5 tooth counts (seed 000)"
[teeth]
ratio = 1.5
ratio_tol = 0.02
module = 8
z1_range = [14, 20]
z_sum_max = 45
"""


def test_teeth_scene(tmp_path, capsys):
    path = tmp_path / "teeth.toml"
    path.write_text(SCENE, encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(path), "--out", str(out)]) == 0
    table = pd.read_csv(out / "teeth.csv")
    # every listed pair has its ratio within 2 % of 1.5 and respects the size bound (hand arithmetic)
    assert ((table.z2 / table.z1 - 1.5).abs() / 1.5 <= 0.02 + 1e-12).all()
    assert ((table.z1 + table.z2) <= 45).all() and table.z1.between(14, 20).all()
    # the enumeration is complete: every such pair by brute force is in the table
    brute = {(z1, z2) for z1 in range(14, 21) for z2 in range(z1, 46)
             if abs(z2 / z1 - 1.5) / 1.5 <= 0.02 and z1 + z2 <= 45}
    assert brute == set(zip(table.z1, table.z2))
    best = table.iloc[0]
    assert bool(best.feasible)
    # the chosen pair's shifts hold every check when recomputed with GearPair
    checks = gd.GearPair(8, int(best.z1), int(best.z2), best.x1, best.x2).checks(jamming=False)
    assert (checks["margin"] >= -1e-9).all()
    # and a_w agrees with the textbook formula a cos α / cos α_w
    inv = lambda a: math.tan(a) - a
    al = math.radians(20)
    target = inv(al) + 2 * (best.x1 + best.x2) * math.tan(al) / (best.z1 + best.z2)
    lo, hi = al, 1.2
    for _ in range(200):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if inv(mid) < target else (lo, mid)
    a_w = 8 * (best.z1 + best.z2) / 2 * math.cos(al) / math.cos(lo)
    assert abs(best.a_w_mm - a_w) < 1e-9
    report = (out / "report.md").read_text(encoding="utf-8")
    assert "Tooth counts for u = 1.5" in report
    assert f"{int(best.z1)}/{int(best.z2)}" in capsys.readouterr().out
