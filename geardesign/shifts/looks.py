"""How each check looks in every picture: its colour, its line style, and what a legend says it
asks with its limit. One table per fact, so a check registry can carry them; the contour PNG
(:meth:`Region.plot <geardesign.shifts.region.Region.plot>`), the interactive page
(:mod:`geardesign.shifts.contour_html`) and the optimum's margins all read them here."""
from __future__ import annotations

from ..gears.checks import check_colour

__all__ = ["PLANET_RING_COLOURS", "CHECK_LEGENDS", "check_style", "check_legend", "margin_bars"]

# A check's own colour is the check registry's (geardesign.gears.checks.check_colour, declared on its
# class); what a legend says it asks, with its limit ({g}: the gear's mark in a symbol, "1" or ",sun";
# {gear}: the gear in words; {limit}: the check's limit), is the table below.
# a planetary set's planet-ring mesh: colours of their own, apart from each other and from the
# sun-planet mesh's (darkening the sun-planet colours made three of them one dark red)
PLANET_RING_COLOURS = {
    "interference": "#e377c2", "tip_thickness": "chocolate", "contact_ratio": "navy",
    "ring_tip": "darkgreen", "tip_interference": "darkgoldenrod", "cutter_trimming": "#8c564b",
    "cutter_interference": "#bcbd22",
}
CHECK_LEGENDS = {
    "undercut": "no undercut, {gear}", "interference": "no root interference, {gear}",
    "tip_thickness": "s_a{g}/m ≥ {limit:g}", "contact_ratio": "ε_α ≥ {limit:g}",
    "total_contact_ratio": "ε_γ ≥ {limit:g}", "jamming": "the mating tip short of N{g}",
    "center_distance": "a_w = housing's {limit:g} mm", "ring_tip": "ring tip circle outside its base circle",
    "tip_interference": "tips clear each other (trochoid)", "cutter_trimming": "no trimming of the ring by its cutter",
    "cutter_interference": "no interference of the cutter with the ring",
    "radial_assembly": "planets assemble radially", "tooth_difference": "z_ring − z_planet large enough",
    "neighbours": "planet tips clear by ≥ {limit:g}·m", "contact_strength": "S_H ≥ {limit:g} (ISO 6336-2)",
    "root_strength": "S_F{g} ≥ {limit:g} (ISO 6336-3)",
}
_CUSTOM_COLOURS = ("tab:olive", "tab:pink", "tab:gray", "darkgoldenrod", "teal")
_GEARS = ("sun", "planet", "ring")


def _parts(name: str) -> tuple:
    """(mesh or None, kind, gear or None) of a check's name: "tip_thickness1" -> (None,
    "tip_thickness", "1"); "planet-ring:interference_ring" -> ("planet-ring", "interference", "ring")."""
    if ":" in name:
        mesh, kind = name.split(":", 1)
        gear = kind.rsplit("_", 1)[-1] if kind.rsplit("_", 1)[-1] in _GEARS else None
        return mesh, (kind.rsplit("_", 1)[0] if gear else kind), gear
    kind = name.rstrip("12")
    return None, kind, (name[len(kind):] or None) if check_colour(name) is not None else None


def check_style(name: str) -> tuple[str, str]:
    """(colour, line style) of a check, the same in every plot: the colour by its kind, solid
    for gear 1 and dashed for gear 2; a custom check gets a colour from its name. A planetary
    set's checks ("planet-ring:interference_planet") take their kind's colour (the planet-ring
    mesh's from :data:`PLANET_RING_COLOURS`) and their gear's style: solid sun, dashed planet,
    dash-dot ring; a check of the whole mesh solid in sun-planet, dashed in planet-ring; the set's
    own dotted."""
    mesh, kind, gear = _parts(name)
    custom = _CUSTOM_COLOURS[sum(map(ord, kind if mesh else name)) % len(_CUSTOM_COLOURS)]
    if mesh is not None:
        colour = (PLANET_RING_COLOURS.get(kind) if mesh == "planet-ring" else None) or check_colour(kind) or custom
        # the set's own checks dotted, whichever gear they name (the planet's damage over both meshes beside the
        # planet-ring mesh's dashed planet checks)
        style = ":" if mesh == "set" else ({"sun": "-", "planet": "--", "ring": "-."}.get(gear)
                                           or {"sun-planet": "-", "planet-ring": "--"}.get(mesh, ":"))
        return colour, style
    colour = check_colour(name)
    if colour is not None:
        return colour, "--" if gear == "2" else "-"
    return custom, "-."


def check_legend(check) -> str:
    """A legend's entry for a check: its name and what it asks, with its limit
    ("contact_ratio: ε_α ≥ 1.2"); a check of unknown kind by its name and label."""
    _, kind, gear = _parts(check.name)
    text = CHECK_LEGENDS.get(kind)
    if text is None:
        mesh = check.name.split(":", 1)[0] + ": " if ":" in check.name else None
        # a mesh's check says its mesh in its name already ("sun-planet:pitting_damage_sun"): not twice
        label = check.label[len(mesh):] if mesh and check.label.startswith(mesh) else check.label
        return f"{check.name}: {label}" if label else check.name
    g = "" if gear is None else (gear if gear.isdigit() else f",{gear}")
    words = "" if gear is None else (f"gear {gear}" if gear.isdigit() else f"the {gear}")
    return f"{check.name}: " + text.format(g=g, gear=words, limit=check.limit)


def margin_bars(ax, margins: dict, active, title: str):
    """Every check's margin as a bar in its colour (≥ 0 holds), the active ones outlined and
    marked "(active)": the picture of an optimum. Returns the Axes."""
    from matplotlib.colors import to_rgba

    names = list(margins)
    # the transparency in the fill colours: an ``alpha=`` would also make the absent edges black
    ax.barh(range(len(names)), [margins[k] for k in names], color=[to_rgba(check_style(k)[0], 0.75) for k in names],
            edgecolor=[(0, 0, 0, 1.0 if k in active else 0.0) for k in names], linewidth=1.6)
    ax.set_yticks(range(len(names)), [f"{k} (active)" if k in active else k for k in names])
    span = max([abs(v) for v in margins.values() if v == v] + [1e-300])
    for i, k in enumerate(names):      # the value at each bar's end: a margin of 0.007 has no visible bar
        v = margins[k]
        ax.text(v + (0.01 if v >= 0 else -0.01) * span, i, f"{v:+.3g}", va="center", ha="left" if v >= 0 else "right",
                fontsize=8, color="black" if v >= 0 else "darkred")
    lo = min([v for v in margins.values() if v == v] + [0.0])
    ax.set_xlim(lo - (0.15 * span if lo < 0 else 0.0), 1.12 * span)
    ax.axvline(0.0, color="black", lw=0.8)
    ax.invert_yaxis()
    ax.set_xlabel("margin (≥ 0 holds; outlined: active at the optimum)")
    ax.set_title(title, fontsize=10)
    ax.grid(True, axis="x", lw=0.3)
    return ax
