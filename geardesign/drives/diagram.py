"""The diagram of a drive: the input, each stage as its kinematic symbol, the shafts between
them with their speed and torque, and the keys on them (a schematic, not to scale)."""
from __future__ import annotations

__all__ = ["plot_drive"]

_STAGE_W = 2.2      # width of one stage's cell in the schematic's units
_COLORS = {"given": "#d9d9d9", "gear": "#9ecae1", "chain": "#fdd0a2", "input": "#c7e9c0"}


def plot_drive(analysis, ax=None):
    """Draw ``analysis`` (a :class:`~geardesign.drives.drive.DriveAnalysis`); returns the Axes.

    Power flows left to right: the input (motor) block, then per stage its symbol — a box for a
    bought unit, two meshing circles for a gear pair (radii in the ratio of the teeth), two
    sprockets and the chain strands for a chain drive — and after each a vertical shaft labelled
    with its n [rpm] and T [N·m]; a keyed hub shows as a black bar with its key.
    """
    import matplotlib.pyplot as plt
    from matplotlib.patches import Circle, FancyBboxPatch

    flow = analysis.flow
    stages = analysis.stages
    if ax is None:
        _, ax = plt.subplots(figsize=(2.2 + 2.4 * len(stages), 4.0))
    y0 = 0.0

    def box(x, w, h, color, text):
        ax.add_patch(FancyBboxPatch((x, y0 - h / 2), w, h, boxstyle="round,pad=0.02", fc=color, ec="k", lw=1))
        ax.text(x + w / 2, y0, text, ha="center", va="center", fontsize=8)

    drive = analysis.drive
    label = (f"motor\n{drive.motor['designation']}" if drive is not None and drive.motor is not None else "input")
    box(0.0, 1.2, 0.9, _COLORS["input"], f"{label}\n{flow['power_kw'].iloc[0]:.3g} kW")
    first = stages[0]["summary"] if stages else {"kind": "given"}
    r_first = {"gear": 0.9 / max(1.0, first.get("ratio", 1.0)), "chain": 0.35}.get(first["kind"], 0.0)
    xs = [1.35 + r_first]            # shaft k at xs[k], seen end-on: the wheels turn about them
    for k_st, st in enumerate(stages):
        s = st["summary"]
        x = xs[-1]
        if s["kind"] == "gear":
            r1 = 0.9 / max(1.0, s["ratio"])
            r2 = r1 * s["ratio"]
            r1, r2 = (0.9 * r1 / max(r1, r2), 0.9 * r2 / max(r1, r2))
            for xc, r in ((x, r1), (x + r1 + r2, r2)):
                ax.add_patch(Circle((xc, y0), r, fc=_COLORS["gear"], ec="k", lw=1, alpha=0.9))
            xs.append(x + r1 + r2)
            text = (f"{s['name']}: z {s['z1']}/{s['z2']}, m {s['m']:g}\n"
                    f"x {s['x1']:.3f}/{s['x2']:.3f}, a_w {s['a_w_mm']:.1f} mm")
        elif s["kind"] == "chain":
            r1 = 0.35
            r2 = min(r1 * s["ratio"], 0.9)
            x2 = x + r1 + r2 + 0.8
            for xc, r in ((x, r1), (x2, r2)):
                ax.add_patch(Circle((xc, y0), r, fc=_COLORS["chain"], ec="k", lw=1))
            ax.plot([x, x2], [y0 + r1, y0 + r2], color="k", lw=1.2)
            ax.plot([x, x2], [y0 - r1, y0 - r2], color="k", lw=1.2)
            xs.append(x2)
            text = f"{s['name']}: {s['designation']}\nz {s['z1']}/{s['z2']}, {s['links']} links"
        else:
            box(x + 0.15, 1.3, 0.9, _COLORS["given"], f"{s['name']}\nu = {s['ratio']:g}")
            xs.append(x + 1.6)
            text = ""
        mid = 0.5 * (x + xs[-1])
        if text:
            # every other stage's label higher: neighbours' labels met over a shared shaft
            ax.text(mid, y0 + 1.0 + 0.5 * (k_st % 2), text, ha="center", va="bottom", fontsize=7.5)
        ax.text(mid, y0 - 1.0, f"u {s['ratio']:.4g}, η {s['efficiency']:g}", ha="center", va="top", fontsize=7)
    for k, x in enumerate(xs):
        ax.plot([x], [y0], "o", color="k", ms=4, zorder=5)
        ax.text(x, y0 - 1.35, f"shaft {k}\n{flow['n_rpm'].iloc[k]:.4g} rpm\n{flow['torque_nm'].iloc[k]:.4g} N·m",
                ha="center", va="top", fontsize=7.5)
    for i, row in analysis.keys.reset_index(drop=True).iterrows():
        x = xs[int(row["at"])]
        size = f"{row['b_mm']:g}x{row['h_mm']:g}x{row['length_mm']:g}" if row["length_mm"] == row["length_mm"] else "none"
        ax.plot([x], [y0], "s", color="red" if not row["feasible"] else "k", ms=7, zorder=6)
        # under the shaft's own label, not on the wheels (where it crossed their rims)
        ax.text(x, y0 - 2.2 - 0.25 * (i % 2), f"key {size}" + (" (2)" if row["n_keys"] == 2 else ""), ha="center",
                va="top", fontsize=7, color="k" if row["feasible"] else "red", zorder=7)
    ax.set_xlim(-0.2, xs[-1] + 1.1)
    ax.set_ylim(y0 - 2.9, y0 + 2.1)
    ax.set_aspect("equal")
    ax.axis("off")
    verdict = "every check holds" if analysis.success else "FAILS"
    ax.set_title(f"u = {analysis.total_ratio:.4g}: {verdict}; smallest margin {analysis.min_margin:+.3f} "
                 f"({analysis.limiting})", fontsize=9)
    return ax
