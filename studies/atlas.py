"""Feasible-region area and optimal shifts (max x-sum) for z1 in 8..40 and z2 in z1..120.

Writes studies/out/atlas.csv and atlas.png (heat maps of area, x1, x2, x1 + x2).
"""
import sys
import time
from pathlib import Path

import matplotlib
matplotlib.use("Agg")
import matplotlib.colors  # noqa: E402
import matplotlib.patches  # noqa: E402
import matplotlib.pyplot as plt

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # run from a checkout
import geardesign as gd  # noqa: E402

OUT = Path(__file__).resolve().parent / "out"


def main():
    OUT.mkdir(exist_ok=True)
    t0 = time.perf_counter()
    df = gd.shift_atlas(range(8, 41), range(8, 121), objective="max_x_sum")
    dt = time.perf_counter() - t0
    df.to_csv(OUT / "atlas.csv", index=False)
    fig, axes = plt.subplots(2, 2, figsize=(12, 8), sharex=True, sharey=True)
    df = df.assign(x_sum=df["x1"] + df["x2"])
    feasible = df.pivot(index="z2", columns="z1", values="feasible").astype(float)
    panels = (("area", "feasible-region area", "area in the (x1, x2) plane (shift coefficients²)"),
              ("x1", "x1 at the optimum", "x1 (profile shift of gear 1)"),
              ("x2", "x2 at the optimum", "x2 (profile shift of gear 2)"),
              ("x_sum", "x1 + x2 at the optimum (the largest)", "x1 + x2"))
    for ax, (col, title, unit) in zip(axes.ravel(), panels):
        piv = df.pivot(index="z2", columns="z1", values=col).where(feasible.astype(bool))
        # grey: computed, no shifts pass every check; white: z2 < z1, not computed (the same pairs swapped)
        ax.pcolormesh(feasible.columns, feasible.index, feasible.where(feasible == 0), shading="nearest",
                      cmap=matplotlib.colors.ListedColormap(["0.72"]))
        im = ax.pcolormesh(piv.columns, piv.index, piv.values, shading="nearest", cmap="viridis")
        fig.colorbar(im, ax=ax, label=unit)
        ax.set_title(title)
        ax.set_xlabel("z1"); ax.set_ylabel("z2")
        ax.text(0.97, 0.04, "z2 < z1: not computed\n(the same pairs, gears swapped)", transform=ax.transAxes,
                ha="right", va="bottom", fontsize=8, color="0.3")
    axes[0, 0].legend(handles=[matplotlib.patches.Patch(color="0.72", label="no shifts pass every check")],
                      loc="upper right", fontsize=8)
    fig.suptitle("Shift atlas: max x1 + x2 with ε_α >= 1.2, s_a >= 0.25 m, no undercut or interference "
                 "(standard rack, tips shortened)")
    fig.savefig(OUT / "atlas.png", dpi=110, bbox_inches="tight")
    act = df.loc[df["feasible"], "active"].value_counts()
    print(f"{len(df)} pairs in {dt:.1f} s; feasible {int(df['feasible'].sum())}")
    print(f"area: min {df['area'].min():.3f} at z1/z2 = {df.loc[df['area'].idxmin(), ['z1', 'z2']].tolist()}, "
          f"max {df['area'].max():.3f}")
    print(f"x_sum: {df['x_sum'].min():.3f} .. {df['x_sum'].max():.3f}")
    print("active sets at the optimum:")
    print(act.head(6).to_string())


if __name__ == "__main__":
    main()
