"""The diagram of a drive: the input, each stage as its kinematic symbol, the shafts between
them with their speed and torque, and the keys on them (a schematic, not to scale).

Each stage is drawn by its kind (:meth:`~geardesign.drives.stage_kinds.StageKind.draw`) on a
:class:`Canvas`; this module draws the rest: the input block, the shafts, the keys and the title,
and lays the labels out so that none overlaps another: each band of labels (the stages' above the
wheels; their ratios, the shafts' speeds and torques and the keys below) is measured by the renderer
and a label that would touch its neighbour goes one level further out. At the default size the
figure is made to fit its content at :data:`SCALE_PT` points per unit of the diagram."""
from __future__ import annotations

from .stage_kinds import kind_named

__all__ = ["plot_drive", "plot_layout", "Canvas", "SCALE_PT"]

_INPUT_COLOR = "#c7e9c0"
SCALE_PT = 54.0      # points per diagram unit at the default size (a gear's large wheel has radius 0.9)
_PAD = 0.12          # diagram units kept free between a band of labels and the next (and between levels)
_GAP = 0.3           # ... and between two labels side by side (closer, "0.98 u 3.4" reads as one label)
_TITLE_PT = 9
_BOX_PT = 8          # the font size of the text in a box
_CHAR_EM = 0.62      # a character's mean width in DejaVu Sans, in ems (for wrapping a box's text)


class Canvas:
    """The few shapes a stage kind draws with, on the diagram's centre line ``y0``; it keeps the
    extent of what was drawn (``lo``, ``hi``: the lowest and highest y) so the labels stay clear of it."""

    def __init__(self, ax, y0: float = 0.0):
        self.ax, self.y0 = ax, y0
        self.lo = self.hi = y0
        self.x_lo = self.x_hi = 0.0

    def _span(self, x0, x1, y0, y1) -> None:
        self.lo, self.hi = min(self.lo, y0), max(self.hi, y1)
        self.x_lo, self.x_hi = min(self.x_lo, x0), max(self.x_hi, x1)

    def box(self, x, w, h, color, text):
        """A rounded box from x, w wide and h high about the centre line, with ``text`` inside (its lines
        wrapped at the words to the box's width at the default scale)."""
        import textwrap

        from matplotlib.patches import FancyBboxPatch

        self.ax.add_patch(FancyBboxPatch((x, self.y0 - h / 2), w, h, boxstyle="round,pad=0.02", fc=color, ec="k", lw=1))
        chars = max(6, int(w * SCALE_PT / (_CHAR_EM * _BOX_PT)))     # the characters one line of the box holds
        text = "\n".join(textwrap.fill(line, chars, break_on_hyphens=False) for line in text.split("\n"))
        self.ax.text(x + w / 2, self.y0, text, ha="center", va="center", fontsize=_BOX_PT)
        self._span(x - 0.02, x + w + 0.02, self.y0 - h / 2 - 0.02, self.y0 + h / 2 + 0.02)

    def circle(self, xc, r, color, **kw):
        """A wheel of radius r about (xc, centre line)."""
        from matplotlib.patches import Circle

        self.ax.add_patch(Circle((xc, self.y0), r, fc=color, ec="k", lw=1, **kw))
        self._span(xc - r, xc + r, self.y0 - r, self.y0 + r)

    def line(self, xs, dys):
        """A line through (xs, centre line + dys), as a chain's strand."""
        self.ax.plot(xs, [self.y0 + d for d in dys], color="k", lw=1.2)
        self._span(min(xs), max(xs), self.y0 + min(dys), self.y0 + max(dys))


def _stages(canvas, analysis, x0: float) -> tuple[list, list, list]:
    """Each stage by its kind; (the x of every shaft, the stage labels, the ratio labels) with the labels as
    (x, text, colour). A kind that draws no wheel on its shafts (a bought unit's box) is kept clear of the
    wheels its neighbours put there."""
    xs, above, below = [x0], [], []
    stages = analysis.stages
    last = 0.0            # the radius of what the stage before drew on the shaft the next one starts from
    for k, st in enumerate(stages):
        s = st["summary"]
        kind = kind_named(s["kind"])
        x = xs[-1]
        if kind.wheels:
            x_out, text = kind.draw(canvas, x, s)
        else:
            x_out, text = kind.draw(canvas, x + last, s)
            if k + 1 < len(stages):
                nxt = stages[k + 1]["summary"]
                x_out += kind_named(nxt["kind"]).first_offset(nxt)
        last = kind.last_offset(s)
        xs.append(x_out)
        mid = 0.5 * (x + x_out)
        if text:
            above.append((mid, text, "k"))
        below.append((mid, f"u {s['ratio']:.4g}, η {s['efficiency']:.4g}", "k"))
    return xs, above, below


def _shaft_labels(ax, analysis, xs, y0: float) -> tuple[list, list]:
    """The shafts' dots and key marks; (shaft labels, key labels) as (x, text, colour)."""
    flow = analysis.flow
    shafts, keys = [], []
    carried = _shaft_texts(ax, analysis, xs, y0)
    for k, x in enumerate(xs):
        ax.plot([x], [y0], "o", color="k", ms=4, zorder=5)
        extra, colour = carried.get(k, ("", "k"))
        shafts.append((x, f"shaft {k}\n{flow['n_rpm'].iloc[k]:.4g} rpm\n{flow['torque_nm'].iloc[k]:.4g} N·m{extra}",
                       colour))
    for _, row in analysis.keys.reset_index(drop=True).iterrows():
        x = xs[int(row["at"])]
        size = f"{row['b_mm']:g}x{row['h_mm']:g}x{row['length_mm']:g}" if row["length_mm"] == row["length_mm"] else "none"
        colour = "red" if not row["feasible"] else "k"
        ax.plot([x], [y0], "s", color=colour, ms=7, zorder=6)
        keys.append((x, f"key {size}" + (" (2)" if row["n_keys"] == 2 else ""), colour))
    return shafts, keys


def _pair(row) -> str:
    """' (X)' / ' (O)' after a tapered roller pair's designation (its arrangement), else ''."""
    m = str(row.get("mounting", ""))
    return f" {m[m.index('('):]}" if m.startswith("tapered pair") else ""


def _shaft_texts(ax, analysis, xs, y0: float) -> dict:
    """A drive with shafting: each shaft on bearings drawn with a bearing ring about it (red when one of its
    bearings or sections fails) and {shaft k: (its label's lines: bearing-seat d, bearings and their L10h, least
    DIN 743 safety; colour)}."""
    from matplotlib.patches import Circle

    sh = getattr(analysis, "shafting", None)
    if sh is None:
        return {}
    checks = analysis.checks
    out = {}
    bearings = sh["bearings"]
    for _, r in sh["shafts"].iterrows():
        k = int(r["shaft"])
        mine = checks["item"].isin([f"shaft {k}", *bearings.loc[bearings["shaft"] == k, "name"]])
        bad = bool((~checks.loc[mine, "ok"]).any())
        colour = "red" if bad else "k"
        for radius, fc in ((0.16, "white"), (0.1, "white")):
            ax.add_patch(Circle((xs[k], y0), radius, fc=fc, ec=colour, lw=1.2, zorder=4))
        lives = bearings.loc[bearings["shaft"] == k, "L10h"].to_numpy()
        out[k] = (f"\nd {r['d_bearing_mm']:g} mm, {r['bearings'].split('/')[0]} x2{_pair(r)}\nL10h {lives.min():.3g} h, "
                  f"S {r['least_safety']:.3g}", colour)
    return out


def _lay_out(ax, bands, top: float, bottom: float, scale_pt: float) -> tuple[float, float, float, float]:
    """Place every band's labels (``bands``: (+1 above / -1 below, [Text])) from the drawing outward,
    each label on the first level of its band where it touches no other; ``scale_pt`` points per unit.
    Returns the extent (x_lo, x_hi, y_lo, y_hi) of the labels."""
    renderer = ax.figure.canvas.get_renderer()
    unit_px = scale_pt * ax.figure.dpi / 72.0
    x_lo, x_hi, ends = float("inf"), float("-inf"), {1: top, -1: bottom}
    for direction, texts in bands:
        levels, heights = [], []
        placed = []
        for t in sorted(texts, key=lambda t: t.get_position()[0]):
            bb = t.get_window_extent(renderer)
            w, h = bb.width / unit_px, bb.height / unit_px
            x = t.get_position()[0]
            lo, hi = x - w / 2, x + w / 2
            level = next((i for i, spans in enumerate(levels)
                          if all(hi + _GAP <= a or lo - _GAP >= b for a, b in spans)), len(levels))
            if level == len(levels):
                levels.append([])
                heights.append(0.0)
            levels[level].append((lo, hi))
            heights[level] = max(heights[level], h)
            placed.append((t, level))
            x_lo, x_hi = min(x_lo, lo), max(x_hi, hi)
        start = ends[direction] + direction * _PAD
        offsets = [start + direction * (sum(heights[:i]) + _PAD * i) for i in range(len(levels))]
        for t, level in placed:
            t.set_y(offsets[level])
            t.set_verticalalignment("bottom" if direction > 0 else "top")
        if levels:
            ends[direction] = start + direction * (sum(heights) + _PAD * (len(levels) - 1))
    return x_lo, x_hi, ends[-1], ends[1]


def _limits(ax, canvas, bands, scale_pt: float, title_w: float) -> tuple:
    x_lo, x_hi, y_lo, y_hi = _lay_out(ax, bands, canvas.hi, canvas.lo, scale_pt)
    x0, x1 = min(x_lo, canvas.x_lo) - 0.15, max(x_hi, canvas.x_hi) + 0.15
    if x1 - x0 < title_w:       # the title as wide as the diagram at most
        grow = 0.5 * (title_w - (x1 - x0))
        x0, x1 = x0 - grow, x1 + grow
    return x0, x1, y_lo - 0.1, y_hi + 0.1


def plot_drive(analysis, ax=None):
    """Draw ``analysis`` (a :class:`~geardesign.drives.drive.DriveAnalysis`); returns the Axes.

    Power flows left to right: the input (motor) block, then per stage its symbol — a box for a
    bought unit, two meshing circles for a gear pair (radii in the ratio of the teeth), two
    sprockets and the chain strands for a chain drive, each kind's own drawing — and after each a
    vertical shaft labelled with its n [rpm] and T [N·m]; a keyed hub shows as a black square with its key.
    Without ``ax`` the figure is sized to its content (no label overlaps another); on a given ``ax``
    the labels are laid out at that Axes' scale.
    """
    import matplotlib.pyplot as plt

    own = ax is None
    if own:
        _, ax = plt.subplots(figsize=(6.0, 4.0))
    stages = analysis.stages
    canvas = Canvas(ax)
    y0 = canvas.y0
    drive = analysis.drive
    label = (f"motor\n{drive.motor['designation']}" if drive is not None and drive.motor is not None else "input")
    canvas.box(0.0, 1.2, 0.9, _INPUT_COLOR, f"{label}\n{analysis.flow['power_kw'].iloc[0]:.3g} kW")
    first = stages[0]["summary"] if stages else None
    r_first = kind_named(first["kind"]).first_offset(first) if first else 0.0
    xs, above, ratios = _stages(canvas, analysis, 1.35 + r_first)   # shaft k at xs[k], seen end-on
    shafts, keys = _shaft_labels(ax, analysis, xs, y0)

    def texts(items, size):
        return [ax.text(x, y0, text, ha="center", va="top", fontsize=size, color=colour, zorder=7)
                for x, text, colour in items]

    bands = [(1, texts(above, 7.5)), (-1, texts(ratios, 7)), (-1, texts(shafts, 7.5)), (-1, texts(keys, 7))]
    verdict = "every check holds" if analysis.success else "FAILS"
    title = ax.set_title(f"u = {analysis.total_ratio:.4g}: {verdict}; smallest margin {analysis.min_margin:+.3f} "
                         f"({analysis.limiting})", fontsize=_TITLE_PT)
    ax.set_aspect("equal")
    ax.axis("off")
    renderer = ax.figure.canvas.get_renderer()
    title_pt = title.get_window_extent(renderer).width * 72.0 / ax.figure.dpi + 12
    if own:
        x0, x1, ya, yb = _limits(ax, canvas, bands, SCALE_PT, title_pt / SCALE_PT)
        w_in, h_in = (x1 - x0) * SCALE_PT / 72.0, (yb - ya) * SCALE_PT / 72.0
        head = 2.4 * _TITLE_PT / 72.0          # the title's line and its pad above the axes
        ax.figure.set_size_inches(w_in, h_in + head)
        ax.set_position([0.0, 0.0, 1.0, h_in / (h_in + head)])
        ax.set_xlim(x0, x1)
        ax.set_ylim(ya, yb)
        return ax
    ax.set_xlim(-0.2, xs[-1] + 1.1)
    ax.set_ylim(y0 - 2.9, y0 + 2.1)
    for _ in range(3):          # the Axes' scale depends on the limits the layout sets: settle it
        ax.apply_aspect()
        box = ax.get_window_extent(renderer)
        (xa, xb), (ya, yb) = ax.get_xlim(), ax.get_ylim()
        scale = min(box.width / (xb - xa), box.height / (yb - ya)) * 72.0 / ax.figure.dpi
        x0, x1, ya, yb = _limits(ax, canvas, bands, scale, title_pt / scale)
        ax.set_xlim(x0, x1)
        ax.set_ylim(ya, yb)
    return ax


def plot_layout(analysis, ax=None):
    """The drive's shafts seen from above, to scale (mm): a :class:`~geardesign.drives.drive.DriveAnalysis` with
    shafting. Each shaft on its bearings at y = Σ a_w of the gear stages before it, its sections stepped, the
    bearings aligned in the two housing walls (crossed boxes, d × D × B, red when a check of theirs fails), each
    gear as its tip diameter over its face width, overhung sprockets and couplings as their hubs; returns the Axes.
    """
    import matplotlib.pyplot as plt
    from matplotlib.patches import Rectangle

    sh = getattr(analysis, "shafting", None)
    if sh is None:
        from ..errors import GearDesignError

        raise GearDesignError("plot_layout needs a drive analysed with shafting (Drive(shafting=Shafting()))")
    if ax is None:
        _, ax = plt.subplots(figsize=(7.0, 5.0))
    stages = analysis.stages
    y, ys = 0.0, {}
    for k, st in enumerate(stages, start=1):       # the shafts' places across the reducer
        s = st["summary"]
        ys.setdefault(k - 1, y)
        if s["kind"] == "gear":
            y += s["a_w_mm"]
        elif s["kind"] == "chain":
            y += s["center_distance_mm"]
        ys[k] = y
    tips = {}
    for st in stages:
        if st["summary"]["kind"] == "gear":
            geo = st["pair"].geometry()
            tips[st["summary"]["name"]] = (geo.da1, geo.da2, st["stage"].width_mm)
    bearings = sh["bearings"]
    failing = set(analysis.checks.loc[~analysis.checks["ok"], "item"])
    colours = {s["summary"]["name"]: kind_named(s["summary"]["kind"]).colour for s in stages}
    x_lo = x_hi = 0.0
    for k, a in sh["analyses"].items():
        m = a.model
        x0 = m.supports_mm[0]                      # bearing A in the wall at x = 0
        yk = ys[k]
        ends = m.section_ends_mm
        for (length, d, _), xa in zip(m.sections, ends[:-1]):
            ax.add_patch(Rectangle((xa - x0, yk - d / 2), length, d, fc="#bdbdbd", ec="k", lw=0.6, zorder=2))
        x_lo, x_hi = min(x_lo, -x0), max(x_hi, ends[-1] - x0)
        for ld in m.loads:
            e = next(e for e in sh["elements"][k] if e.name == ld.name)
            if e.kind in ("pinion", "wheel"):
                da1, da2, b = tips[e.name]
                dia = da1 if e.kind == "pinion" else da2
                ax.add_patch(Rectangle((ld.x_mm - x0 - b / 2, yk - dia / 2), b, dia, fc=colours[e.name], ec="k",
                                       lw=0.8, alpha=0.85, zorder=3))
            else:
                d = float(m.diameter_at(ld.x_mm)[0])
                hub, w = 2.0 * d, 1.5 * d
                x_lo, x_hi = min(x_lo, ld.x_mm - x0 - w / 2), max(x_hi, ld.x_mm - x0 + w / 2)
                ax.add_patch(Rectangle((ld.x_mm - x0 - w / 2, yk - hub / 2), w, hub,
                                       fc=colours.get(e.name, _INPUT_COLOR), ec="k", lw=0.8, zorder=3))
                ax.text(ld.x_mm - x0, yk + hub / 2 + 4, e.name, ha="center", va="bottom", fontsize=6.5)
        for _, b in bearings[bearings["shaft"] == k].iterrows():
            colour = "red" if b["name"] in failing else "k"
            h = (b["D_mm"] - b["bore_mm"]) / 2
            for sign in (1, -1):
                yb = yk + sign * (b["bore_mm"] / 2 + h / 2)
                xb = b["x_mm"] - x0
                ax.add_patch(Rectangle((xb - b["B_mm"] / 2, yb - h / 2), b["B_mm"], h, fc="white", ec=colour, lw=1.0,
                                       zorder=4))
                ax.plot([xb - b["B_mm"] / 2, xb + b["B_mm"] / 2], [yb - h / 2, yb + h / 2], color=colour, lw=0.7, zorder=5)
                ax.plot([xb - b["B_mm"] / 2, xb + b["B_mm"] / 2], [yb + h / 2, yb - h / 2], color=colour, lw=0.7, zorder=5)
    for k in sh["analyses"]:          # each shaft's name and bearings right of the drawing
        yk = ys[k]
        bb = bearings[bearings["shaft"] == k]
        ax.text(x_hi + 10, yk, f"shaft {k}\n{bb['designation'].iloc[0]} x2{_pair(bb.iloc[0])}", ha="left",
                va="center", fontsize=7,
                color="red" if f"shaft {k}" in failing or set(bb["name"]) & failing else "k")
    span = max(float(r["span_mm"]) for _, r in sh["shafts"].iterrows())
    y_all = [ys[k] for k in sh["analyses"]]
    for xw in (0.0, span):                          # the housing walls through the bearings
        ax.plot([xw, xw], [min(y_all) - 60, max(y_all) + 60], color="#636363", lw=1.0, ls="--", zorder=1)
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.set_xlim(x_lo - 20, x_hi + 100)
    ax.set_xlabel("x, mm (bearing A of each shaft at 0)")
    ax.set_ylabel("y, mm (the line of centres)")
    verdict = "every check holds" if analysis.success else "FAILS"
    ax.set_title(f"shafts and bearings seen from above: {verdict}", fontsize=_TITLE_PT)
    return ax
