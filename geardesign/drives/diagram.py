"""The diagram of a drive: the input, each stage as its kinematic symbol, the shafts between
them with their speed and torque, and the keys on them (a schematic, not to scale).

Each stage is drawn by its kind (:meth:`~geardesign.drives.stage_kinds.StageKind.draw`) on a
:class:`Canvas`; this module draws the rest: the input block, the shafts, the keys and the title."""
from __future__ import annotations

from .stage_kinds import kind_named

__all__ = ["plot_drive", "Canvas"]

_INPUT_COLOR = "#c7e9c0"


class Canvas:
    """The few shapes a stage kind draws with, on the diagram's centre line ``y0``."""

    def __init__(self, ax, y0: float = 0.0):
        self.ax, self.y0 = ax, y0

    def box(self, x, w, h, color, text):
        """A rounded box from x, w wide and h high about the centre line, with ``text`` inside."""
        from matplotlib.patches import FancyBboxPatch

        self.ax.add_patch(FancyBboxPatch((x, self.y0 - h / 2), w, h, boxstyle="round,pad=0.02", fc=color, ec="k", lw=1))
        self.ax.text(x + w / 2, self.y0, text, ha="center", va="center", fontsize=8)

    def circle(self, xc, r, color, **kw):
        """A wheel of radius r about (xc, centre line)."""
        from matplotlib.patches import Circle

        self.ax.add_patch(Circle((xc, self.y0), r, fc=color, ec="k", lw=1, **kw))

    def line(self, xs, dys):
        """A line through (xs, centre line + dys), as a chain's strand."""
        self.ax.plot(xs, [self.y0 + d for d in dys], color="k", lw=1.2)


def _stages(canvas, analysis, x0: float) -> list:
    """Each stage by its kind, its label above and its ratio below; the x of every shaft."""
    ax, y0 = canvas.ax, canvas.y0
    xs = [x0]
    for k_st, st in enumerate(analysis.stages):
        s = st["summary"]
        x = xs[-1]
        x_out, text = kind_named(s["kind"]).draw(canvas, x, s)
        xs.append(x_out)
        mid = 0.5 * (x + xs[-1])
        if text:
            # every other stage's label higher: neighbours' labels met over a shared shaft
            ax.text(mid, y0 + 1.0 + 0.5 * (k_st % 2), text, ha="center", va="bottom", fontsize=7.5)
        ax.text(mid, y0 - 1.0, f"u {s['ratio']:.4g}, η {s['efficiency']:g}", ha="center", va="top", fontsize=7)
    return xs


def _shafts_and_keys(ax, analysis, xs, y0: float) -> None:
    flow = analysis.flow
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


def plot_drive(analysis, ax=None):
    """Draw ``analysis`` (a :class:`~geardesign.drives.drive.DriveAnalysis`); returns the Axes.

    Power flows left to right: the input (motor) block, then per stage its symbol — a box for a
    bought unit, two meshing circles for a gear pair (radii in the ratio of the teeth), two
    sprockets and the chain strands for a chain drive, each kind's own drawing — and after each a
    vertical shaft labelled with its n [rpm] and T [N·m]; a keyed hub shows as a black bar with its key.
    """
    import matplotlib.pyplot as plt

    stages = analysis.stages
    if ax is None:
        _, ax = plt.subplots(figsize=(2.2 + 2.4 * len(stages), 4.0))
    canvas = Canvas(ax)
    y0 = canvas.y0
    drive = analysis.drive
    label = (f"motor\n{drive.motor['designation']}" if drive is not None and drive.motor is not None else "input")
    canvas.box(0.0, 1.2, 0.9, _INPUT_COLOR, f"{label}\n{analysis.flow['power_kw'].iloc[0]:.3g} kW")
    first = stages[0]["summary"] if stages else None
    r_first = kind_named(first["kind"]).first_offset(first) if first else 0.0
    xs = _stages(canvas, analysis, 1.35 + r_first)   # shaft k at xs[k], seen end-on: the wheels turn about them
    _shafts_and_keys(ax, analysis, xs, y0)
    ax.set_xlim(-0.2, xs[-1] + 1.1)
    ax.set_ylim(y0 - 2.9, y0 + 2.1)
    ax.set_aspect("equal")
    ax.axis("off")
    verdict = "every check holds" if analysis.success else "FAILS"
    ax.set_title(f"u = {analysis.total_ratio:.4g}: {verdict}; smallest margin {analysis.min_margin:+.3f} "
                 f"({analysis.limiting})", fontsize=9)
    return ax
