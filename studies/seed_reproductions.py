"""Seed 000 (engine gear pair) and seed 002 (brake-stand chain drive and keys) recomputed:
runs both example scenes into studies/out/seed000 and studies/out/seed002 and writes
studies/out/seed_reproductions.csv (each printed seed number next to the recomputed value) and
seed_reproductions.png (the seed 000 blocking contour with the seed's point).
"""
import math
import sys
from pathlib import Path

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import pandas as pd

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))            # run from a checkout
import geardesign as gd  # noqa: E402
from geardesign.scene import run_scene  # noqa: E402

OUT = HERE / "out"


def main():
    OUT.mkdir(exist_ok=True)
    rep0 = run_scene(HERE / "scenes" / "seed000_gear.toml", OUT / "seed000")
    rep2 = run_scene(HERE / "scenes" / "seed002_chain.toml", OUT / "seed002")
    g = gd.GearPair(8, 17, 26, 0.898, 0.517).geometry()
    opt = rep0.results["gear"]["optimum"]
    chain = rep2.results["chain"].best
    key = gd.key.capacity(60, 32, 300, 120)
    lp_needed = 2 * 503.129e3 / (60 * 4 * 300)       # l_p >= 2T/(d·k·[σ]) with the seed's k = 4 mm, [σ] = 300
    est = gd.chain.pitch_estimate_mm(380, 13, 29, 2.148, 1.0), gd.chain.pitch_estimate_mm(380, 13, 29, 2.148, 1.7)
    rows = [
        ("000", "inv alpha_w", 0.38868, g.inv_alpha_w, "decimal slip: 0.03886"),
        ("000", "alpha_w [deg]", 26 + 8 / 60, g.alpha_w_deg, "26°08' does not follow from inv α_w"),
        ("000", "a_w [mm]", math.nan, g.a_w, "drifts with α_w"),
        ("000", "eps_alpha", 0.133, g.eps_alpha, "printed 0.133; truth 1.153 < 1.2: the seed's shifts fail"),
        ("000", "x1 (optimum, max x-sum)", 0.898, opt.x1, "tables' x1; optimum sits on ε_α = 1.2"),
        ("000", "x2 (optimum, max x-sum)", 0.517, opt.x2, ""),
        ("002", "pitch estimate, 1 strand [mm]", 36.23, est[0], "agrees"),
        ("002", "pitch estimate, 2 strands [mm]", 30.35, est[1], "agrees"),
        ("002", "chain", math.nan, math.nan, f"seed 2PR-31.75; tool {chain['designation']}"),
        ("002", "hinge pressure [MPa]", math.nan, chain["pressure_mpa"], "seed never checks p against [p] = 29"),
        ("002", "links", 30, chain["links"], "seed uses its three-sided layout (3a + πd)/t"),
        ("002", "centre distance [mm]", 178.57, chain["center_distance_mm"], "for 24 links"),
        ("002", "key working length [mm]", 27.952, lp_needed, "seed's 27.952 is [σ] = 150 MPa"),
        ("002", "key 18x11x32 capacity [N·m]", math.nan, key["torque_nm"], "carries the seed's 503.129 N·m"),
    ]
    df = pd.DataFrame(rows, columns=["seed", "quantity", "seed_value", "recomputed", "note"])
    df.to_csv(OUT / "seed_reproductions.csv", index=False)
    fig, ax = plt.subplots(figsize=(7, 6))
    rep0.results["gear"]["region"].plot(ax=ax, optimum=opt)
    ax.plot([0.898], [0.517], "rx", ms=10, mew=2)
    ax.annotate("seed 000: 0.898/0.517\nε_α = %.3f" % g.eps_alpha, (0.898, 0.517), color="r",
                textcoords="offset points", xytext=(8, -20))
    ax.set_title("Seed 000, z = 17/26: the seed's shifts lie outside ε_α >= 1.2")
    fig.savefig(OUT / "seed_reproductions.png", dpi=110, bbox_inches="tight")
    with pd.option_context("display.width", 160, "display.max_colwidth", 60):
        print(df.to_string(index=False, float_format=lambda v: f"{v:.5g}"))
    for line in rep0.summary + rep2.summary:
        print(" ", line)


if __name__ == "__main__":
    main()
