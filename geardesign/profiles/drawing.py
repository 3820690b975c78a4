"""The meshing drawing of a pair (external or internal, spur or helical in the transverse section):
both gears' generated teeth in mesh, their circles, the line of action N1N2 with its active part and
contact zones, and the pitch point.

The gears are placed as :mod:`geardesign.profiles.mesh` puts them (gear 1 about the origin, gear 2
about (0, a_w), a ring about (0, −a_w); zero backlash; ``roll_deg`` turns them together).
"""
from __future__ import annotations

import math

import numpy as np

from ..validate import one_number, require_axes, require_range
from .mesh import ROLL_RANGE_DEG, pair_profiles, placed, require_pair

__all__ = ["plot_mesh", "plot_diagrams", "contact_points", "line_of_action_diagrams"]

TEETH_SHOWN = 3   # teeth of each gear drawn either side of the line of centres


def contact_points(geo: dict) -> dict:
    """Points of the line of action (mm, gear 1's centre at the origin, gear 2's at (0, a_w), a ring's
    at (0, −a_w)): N1, N2 (tangency with the base circles), P (pitch point), A (start of contact,
    gear 2's tip circle) and E (end of contact, gear 1's tip circle); the contact runs from A to E
    along ``u``. External pairs: N1, P, N2 in this order, A and E between N1 and N2. Internal: N2,
    N1, P — both tangency points on one side of P — and the contact beyond N1, toward P and past it.
    ``s_*``: each point's signed position from N1 along ``u`` (ρ1, gear 1's radius of curvature)."""
    a_w, sin_w, cos_w = float(geo["a_w"]), float(geo["_sin_w"]), float(geo["_cos_w"])
    internal = float(geo["_sgn"]) < 0
    rb1, rb2 = float(geo["db1"]) / 2, float(geo["db2"]) / 2
    n1 = rb1 * np.array([-sin_w, cos_w])  # the normal from O1 to the line, turned by α_w from the centre line
    rho_a1, rho_a2 = float(geo["_rho_a1"]), float(geo["_rho_a2"])
    g = a_w * sin_w
    if internal:   # the ring's centre (0, −a_w) on the same side: its normal to the line is parallel to O1N1
        u = np.array([cos_w, sin_w])      # along N2 → N1 → P
        n2 = np.array([0.0, -a_w]) + rb2 * np.array([-sin_w, cos_w])
        a_pt = n2 + rho_a2 * u
    else:
        u = np.array([cos_w, sin_w])      # along N1 → N2: the line of action leans at α_w
        n2 = np.array([0.0, a_w]) + rb2 * np.array([sin_w, -cos_w])
        a_pt = n2 - rho_a2 * u
    p = np.array([0.0, float(geo["dw1"]) / 2])
    out = {"N1": n1, "N2": n2, "P": p, "A": a_pt, "E": n1 + rho_a1 * u, "u": u,
           "g": g, "p_b": float(geo["p_b"]), "cos_w": cos_w, "internal": internal}
    out.update({f"s_{k}": float(np.dot(out[k] - n1, u)) for k in ("N2", "P", "A", "E")})
    return out


def plot_mesh(pair, ax=None, roll_deg: float = 0.0, points: int = 60, cutter=None, checks=None):
    """Draw the meshing picture of a :class:`~geardesign.gears.pair.GearPair` (returns the axes); a
    ring (internal pair) as the shaper ``cutter`` generates it (default: the checks' cutter). The title's
    last line is the verdict of ``checks`` (a table of :meth:`GearPair.checks`: the caller's limits and
    load case), by default of the checks under the default limits."""
    import matplotlib.pyplot as plt

    pair = require_pair(pair)
    geo = pair._geo
    m, z1, z2 = pair.m, pair.z1, pair.z2
    internal = bool(pair.mesh.internal)
    roll = math.radians(one_number("roll_deg", require_range("roll_deg", roll_deg, *ROLL_RANGE_DEG, unit="°")))
    p1, p2 = pair_profiles(pair, points, cutter)
    if ax is None:
        _, ax = plt.subplots(figsize=(8.6, 7.4))
    require_axes("ax", ax)
    a_w = float(geo["a_w"])
    centre2 = -a_w if internal else a_w
    shapes = {name: (x, y) for name, x, y in placed(pair, p1, p2, roll)}
    view = (TEETH_SHOWN + 0.5) * math.pi * float(geo["d1"]) / z1   # (π m_t) half-width of the window around the pitch point
    _draw_gears(ax, pair, shapes, p2, internal)
    _draw_circles(ax, geo, p2, internal, centre2)
    _draw_line_of_action(ax, contact_points(geo), internal)
    ax.set_xlim(-view, view)
    centre_y = float(geo["dw1"]) / 2
    ax.set_ylim(centre_y - 0.8 * view, centre_y + 0.8 * view)
    ax.set_aspect("equal")
    ax.set_xlabel("mm")
    section = " (transverse section)" if pair.mesh.beta_deg else ""
    long = bool(section) or internal
    ax.set_title(f"m = {m:g} mm{pair.mesh.kind_text}{section}, z1/z2 = {z1}/{z2}, x1/x2 = {pair.x1:.4g}/{pair.x2:.4g}"
                 + ("\n" if long else ": ")
                 + f"α_w = {float(geo['alpha_w_deg']):.4g}°, a_w = {a_w:.6g} mm, ε_α = {float(geo['eps_alpha']):.4g}"
                 + (f", ring cut by a z0 = {p2.z0} shaper at a_w0 = {p2.a_w0_mm:.5g} mm" if internal else "")
                 + "\n" + verdict_text(pair, checks),
                 fontsize=10)
    ax.legend(loc="upper left", fontsize=7, framealpha=0.9)
    return ax


def _draw_gears(ax, pair, shapes, p2, internal: bool) -> None:
    """Both gears filled: the pinion, and the wheel or (internal) the ring as an annulus."""
    from matplotlib.patches import PathPatch
    from matplotlib.path import Path

    ax.fill(*shapes["gear1"], color="#c9d9ee", ec="#1f4e89", lw=1.0, label=f"gear 1 (z = {pair.z1}, x = {pair.x1:.4g})")
    if not internal:
        ax.fill(*shapes["gear2"], color="#f3d9c4", ec="#8a3b12", lw=1.0,
                label=f"gear 2 (z = {pair.z2}, x = {pair.x2:.4g})")
        return
    # the annulus: rim and toothed bore as one path, wound oppositely (a hole)
    rim, bore = np.column_stack(shapes["gear2_rim"]), np.column_stack(shapes["gear2"])
    codes = lambda k: [Path.MOVETO] + [Path.LINETO] * (k - 2) + [Path.CLOSEPOLY]   # noqa: E731
    ax.add_patch(PathPatch(Path(np.vstack([rim, bore]), codes(len(rim)) + codes(len(bore))),
                           facecolor="#f3d9c4", edgecolor="#8a3b12", lw=1.0,
                           label=f"gear 2, ring (z = {pair.z2}, x = {pair.x2:.4g}; shaper z0 = {p2.z0})"))


def _draw_circles(ax, geo, p2, internal: bool, centre2: float) -> None:
    """Base, reference, operating pitch, tip and root circles of both gears."""
    # the root circle as generated: a ring's is the shaper's, 2(a_w0 + r_a0), not the rack-equivalent d_f2
    radii = {1: {"db": geo["db1"] / 2, "d": geo["d1"] / 2, "dw": geo["dw1"] / 2, "da": geo["da1"] / 2,
                 "df": geo["df1"] / 2},
             2: {"db": geo["db2"] / 2, "d": geo["d2"] / 2, "dw": geo["dw2"] / 2, "da": geo["da2"] / 2,
                 "df": p2.r_root_mm if internal else geo["df2"] / 2}}
    circles = (("db", ":", 0.7, "base"), ("d", "-.", 0.7, "reference"), ("dw", "--", 0.7, "operating pitch"),
               ("da", "-", 0.4, "tip and root"), ("df", "-", 0.4, None))
    t = np.linspace(-math.pi, math.pi, 1441)
    for key, ls, lw, what in circles:
        for gear, centre, col in ((1, 0.0, "#1f4e89"), (2, centre2, "#8a3b12")):
            r = float(radii[gear][key])
            ax.plot(r * np.sin(t), centre + r * np.cos(t), ls, lw=lw, color=col,
                    label=f"{what} circles" if gear == 1 and what else None)


def _draw_line_of_action(ax, c: dict, internal: bool) -> None:
    """The line of action through N1, N2, its active part A–E, the double-contact stretches, the points."""
    # for an internal pair the line goes on beyond N1 to where the contact ends
    ends = [c["s_N2"], 0.0] + ([c["s_A"], c["s_E"], c["s_P"]] if internal else [])
    line = np.array([c["N1"] + min(ends) * c["u"], c["N1"] + max(ends) * c["u"]])
    ax.plot(*line.T, "-", color="0.35", lw=0.9, label="line of action (through N1, N2)")
    ax.plot(*np.array([c["A"], c["E"]]).T, "-", color="k", lw=2.4, label="active part (A to E)")
    # double contact over p_b·(ε_α − 1) at each end of the active part, single contact in the middle
    d = (c["s_E"] - c["s_A"]) - c["p_b"]
    if d > 0:
        for start in (c["A"], c["E"] - d * c["u"]):
            seg = np.array([start, start + d * c["u"]])
            ax.plot(*seg.T, "-", color="#d62728", lw=4.5, alpha=0.55,
                    label="double contact" if start is c["A"] else None)
    for name, offset in (("N1", (-16, -12)), ("N2", (-16, -12)), ("A", (5, 4)), ("E", (5, 4)), ("P", (-13, 5))):
        pt = c[name]
        ax.plot(*pt, "o", ms=4 if name != "P" else 6, color="k")
        ax.annotate(name, pt, textcoords="offset points", xytext=offset, fontsize=9)


def verdict_text(pair, table=None) -> str:
    """"every check holds" or "FAILS contact_ratio (1.153 vs limit 1.2), ..." of ``table`` (a checks table of
    the pair), by default under the default limits."""
    given = table is not None
    table = pair.checks() if table is None else table
    bad = table.loc[~table["ok"].astype(bool)]
    if bad.empty:
        return f"every check holds ({len(table)} checks)" if given else "every check holds (default limits)"
    return "FAILS " + ", ".join(f"{r['check']} ({float(r['value']):.4g} vs limit {float(r['limit']):.4g})"
                                for _, r in bad.iterrows())


def line_of_action_diagrams(geo: dict, n: int = 400, s_mm=None) -> dict:
    """Specific sliding of both gears and the specific pressure coefficient along the line of action,
    by the signed position s from N1 (mm, along :func:`contact_points`' ``u``): ρ1 = s, and
    ρ2 = g − s (external) or g + s (internal: the ring's concave flank, N2 behind N1) the radii of
    curvature at the contact point; ϑ1 = 1 − ρ2/(u ρ1), ϑ2 = 1 − u ρ1/ρ2, γ = m cos β_b (1/ρ1 ± 1/ρ2)
    (+ external, − internal: the normal-section m/ρ_red; Kudryavtsev's diagrams, the same definitions
    as the geometry's end values and pitch-point coefficient). Over N1N2 for an external pair; for an
    internal one from N1 (or A, if the contact starts behind it) to past E. ``s_mm`` evaluates at
    given positions instead of n."""
    c = contact_points(geo)
    g, u, m = c["g"], float(geo["_z2"]) / float(geo["_z1"]), float(geo["_m"])
    cbb = math.cos(math.radians(float(geo["beta_b_deg"])))
    if s_mm is not None:
        s = np.asarray(s_mm, dtype=float)
    elif c["internal"]:
        span = c["s_E"] - c["s_A"]
        s = np.linspace(min(c["s_A"], 0.0) - 0.2 * span, max(c["s_E"], c["s_P"]) + 0.25 * span, n)
    else:
        s = np.linspace(g * 1e-3, g * (1 - 1e-3), n)
    rho1 = s
    rho2 = g + s if c["internal"] else g - s
    with np.errstate(divide="ignore", invalid="ignore"):
        pressure = m * cbb * ((rho2 - rho1) if c["internal"] else (rho1 + rho2)) / (rho1 * rho2)
        sliding1, sliding2 = 1.0 - rho2 / (u * rho1), 1.0 - u * rho1 / rho2
    return {"s_mm": s, "sliding1": sliding1, "sliding2": sliding2, "pressure": pressure,
            "s_A": c["s_A"], "s_E": c["s_E"], "s_P": c["s_P"], "g": g, "p_b": c["p_b"], "internal": c["internal"]}


def plot_diagrams(pair, axes=None):
    """The diagrams of seed 000 §7.8 along the line of action: specific sliding ϑ1, ϑ2 and the specific
    pressure coefficient γ, with the active part A–E and its double-contact ends marked."""
    import matplotlib.pyplot as plt

    d = line_of_action_diagrams(require_pair(pair)._geo)
    if axes is None:
        _, axes = plt.subplots(2, 1, figsize=(8.6, 6.4), sharex=True)
    require_axes("axes", axes, 2)
    ax1, ax2 = axes
    s = d["s_mm"]
    # break the curves at N1 (ρ1 = 0), where ϑ1 and γ have their pole
    pole = np.abs(s) < 1e-9 + 0.6 * float(np.max(np.diff(s)))
    active = (s >= d["s_A"]) & (s <= d["s_E"])
    for ax, series in ((ax1, (("sliding1", "ϑ1 (gear 1)", "#1f4e89"), ("sliding2", "ϑ2 (gear 2)", "#8a3b12"))),
                       (ax2, (("pressure", "γ = m(1/ρ1 " + ("− 1/ρ2)" if d["internal"] else "+ 1/ρ2)"), "k"),))):
        for key, label, col in series:
            v = np.where(pole, np.nan, d[key])
            ax.plot(s, v, ":", color=col, lw=0.8)
            ax.plot(s[active], v[active], "-", color=col, lw=1.8, label=label)
        lo_dc, hi_dc = d["s_A"] + (d["s_E"] - d["s_A"] - d["p_b"]), d["s_E"] - (d["s_E"] - d["s_A"] - d["p_b"])
        for x0, x1 in ((d["s_A"], lo_dc), (hi_dc, d["s_E"])):
            if x1 > x0:
                ax.axvspan(x0, x1, color="#d62728", alpha=0.12, lw=0)
        marks = (("A", d["s_A"]), ("P", d["s_P"]), ("E", d["s_E"])) + ((("N1", 0.0),) if d["internal"] else ())
        for name, pos in marks:
            ax.axvline(pos, color="0.5", lw=0.6, ls="-" if name != "N1" else "--")
            # N1 at the foot of its line: on a ring pair A may sit next to it
            ax.annotate(name, (pos, 1.0 if name != "N1" else 0.0), xycoords=("data", "axes fraction"),
                        xytext=(2, -12 if name != "N1" else 4), textcoords="offset points", fontsize=9)
        ax.grid(alpha=0.3)
        ax.legend(loc="upper right", bbox_to_anchor=(1.0, 0.9), fontsize=8)   # below the A, P, E marks
    ax1.set_ylim(-3.0, 1.2)
    ax1.set_ylabel("specific sliding")
    ax2.set_ylim(0.0, 4.0 * float(pair._geo["spec_pressure_pitch"]))
    ax2.set_ylabel("specific pressure coefficient")
    ax2.set_xlabel("position on the line of action from N1, mm (shaded: double contact)")
    kind = " internal" if d["internal"] else ""
    ax1.set_title(f"{kind.strip() + ' pair ' if kind else ''}z1/z2 = {pair.z1}/{pair.z2}, x1/x2 = {pair.x1:.4g}/{pair.x2:.4g}: "
                  "sliding and pressure along the line of action", fontsize=10)
    return axes
