"""The meshing drawing of a spur pair: both gears' generated teeth in mesh, their circles, the line of
action N1N2 with its active part and contact zones, and the pitch point.

The gears are placed as :mod:`geardesign.profiles.mesh` puts them (gear 1 about the origin, gear 2
about (0, a_w), zero backlash; ``roll_deg`` turns them together).
"""
from __future__ import annotations

import math

import numpy as np

from .mesh import require_pair, pair_outlines

__all__ = ["plot_mesh", "plot_diagrams", "contact_points", "line_of_action_diagrams"]

TEETH_SHOWN = 3   # teeth of each gear drawn either side of the line of centres


def contact_points(geo: dict) -> dict:
    """Points of the line of action (mm, gear 1's centre at the origin, gear 2's at (0, a_w)):
    N1, N2 (tangency with the base circles), P (pitch point), A (start of contact, gear 2's tip
    circle) and E (end of contact, gear 1's tip circle); the contact runs from A to E."""
    a_w, sin_w, cos_w = float(geo["a_w"]), float(geo["_sin_w"]), float(geo["_cos_w"])
    u = np.array([cos_w, sin_w])          # along N1 → N2: the line of action leans at α_w
    rb1, rb2 = float(geo["db1"]) / 2, float(geo["db2"]) / 2
    n1 = rb1 * np.array([-sin_w, cos_w])  # the normal from O1 to the line, turned by α_w from the centre line
    n2 = np.array([0.0, a_w]) + rb2 * np.array([sin_w, -cos_w])
    p = np.array([0.0, float(geo["dw1"]) / 2])
    rho_a1, rho_a2 = float(geo["_rho_a1"]), float(geo["_rho_a2"])
    g = float(geo["a_w"]) * sin_w
    return {"N1": n1, "N2": n2, "P": p, "A": n2 - rho_a2 * u, "E": n1 + rho_a1 * u, "u": u,
            "g": g, "p_b": float(geo["p_b"]), "cos_w": cos_w}


def plot_mesh(pair, ax=None, roll_deg: float = 0.0, points: int = 60):
    """Draw the meshing picture of a :class:`~geardesign.gears.pair.GearPair` (returns the axes)."""
    import matplotlib.pyplot as plt

    geo = pair._geo
    m, z1, z2 = pair.m, pair.z1, pair.z2
    if ax is None:
        _, ax = plt.subplots(figsize=(8.6, 7.4))
    a_w = float(geo["a_w"])
    (_, x1, y1), (_, x2, y2) = pair_outlines(pair, roll_deg, points)
    view = (TEETH_SHOWN + 0.5) * math.pi * float(geo["d1"]) / z1   # (π m_t) half-width of the window around the pitch point
    ax.fill(x1, y1, color="#c9d9ee", ec="#1f4e89", lw=1.0, label=f"gear 1 (z = {z1}, x = {pair.x1:.4g})")
    ax.fill(x2, y2, color="#f3d9c4", ec="#8a3b12", lw=1.0, label=f"gear 2 (z = {z2}, x = {pair.x2:.4g})")

    circles = (("db", ":", "base"), ("d", "-.", "reference"), ("dw", "--", "operating pitch"))
    t = np.linspace(-math.pi, math.pi, 721)
    for key, ls, what in circles:
        for gear, centre, col in ((1, 0.0, "#1f4e89"), (2, a_w, "#8a3b12")):
            r = float(geo[f"{key}{gear}"]) / 2
            ax.plot(r * np.sin(t), centre + r * np.cos(t), ls, lw=0.7, color=col,
                    label=f"{what} circles" if gear == 1 else None)
    c = contact_points(geo)
    ax.plot(*np.array([c["N1"], c["N2"]]).T, "-", color="0.35", lw=0.9, label="line of action N1N2")
    ax.plot(*np.array([c["A"], c["E"]]).T, "-", color="k", lw=2.4, label="active part (A to E)")
    # double contact over p_b·(ε_α − 1) at each end of the active part, single contact in the middle
    g_alpha = float(np.linalg.norm(c["E"] - c["A"]))
    d = g_alpha - c["p_b"]
    if d > 0:
        for start in (c["A"], c["E"] - d * c["u"]):
            seg = np.array([start, start + d * c["u"]])
            ax.plot(*seg.T, "-", color="#d62728", lw=4.5, alpha=0.55,
                    label="double contact" if start is c["A"] else None)
    for name in ("N1", "N2", "A", "E", "P"):
        pt = c[name]
        ax.plot(*pt, "o", ms=4 if name != "P" else 6, color="k")
        ax.annotate(name, pt, textcoords="offset points", xytext=(5, 4), fontsize=9)
    ax.set_xlim(-view, view)
    centre_y = float(geo["dw1"]) / 2
    ax.set_ylim(centre_y - 0.8 * view, centre_y + 0.8 * view)
    ax.set_aspect("equal")
    ax.set_xlabel("mm")
    section = " (transverse section)" if pair.mesh.beta_deg else ""
    ax.set_title(f"m = {m:g} mm{pair.mesh.kind_text}{section}, z1/z2 = {z1}/{z2}, x1/x2 = {pair.x1:.4g}/{pair.x2:.4g}"
                 + ("\n" if section else ": ")
                 + f"α_w = {float(geo['alpha_w_deg']):.4g}°, a_w = {a_w:.6g} mm, ε_α = {float(geo['eps_alpha']):.4g}",
                 fontsize=10)
    ax.legend(loc="upper left", fontsize=7, framealpha=0.9)
    return ax


def line_of_action_diagrams(geo: dict, n: int = 400, s_mm=None) -> dict:
    """Specific sliding of both gears and the specific pressure coefficient along N1N2, by the
    distance s from N1 (mm): ρ1 = s, ρ2 = g − s (the radii of curvature at the contact point),
    ϑ1 = 1 − ρ2/(u ρ1), ϑ2 = 1 − u ρ1/ρ2, γ = m (ρ1 + ρ2)/(ρ1 ρ2) (Kudryavtsev's diagrams; the same
    definitions as the geometry's end values). ``s_mm`` evaluates at given positions instead of n."""
    c = contact_points(geo)
    g, u, m = c["g"], float(geo["_z2"]) / float(geo["_z1"]), float(geo["_m"])
    s_a = float(np.linalg.norm(c["A"] - c["N1"]))
    s_e = float(np.linalg.norm(c["E"] - c["N1"]))
    s = np.linspace(g * 1e-3, g * (1 - 1e-3), n) if s_mm is None else np.asarray(s_mm, dtype=float)
    rho1, rho2 = s, g - s
    return {"s_mm": s, "sliding1": 1.0 - rho2 / (u * rho1), "sliding2": 1.0 - u * rho1 / rho2,
            "pressure": m * (rho1 + rho2) / (rho1 * rho2), "s_A": s_a, "s_E": s_e,
            "s_P": float(np.linalg.norm(c["P"] - c["N1"])), "g": g, "p_b": c["p_b"]}


def plot_diagrams(pair, axes=None):
    """The diagrams of seed 000 §7.8 along the line of action: specific sliding ϑ1, ϑ2 and the specific
    pressure coefficient γ, with the active part A–E and its double-contact ends marked."""
    import matplotlib.pyplot as plt

    d = line_of_action_diagrams(require_pair(pair)._geo)
    if axes is None:
        _, axes = plt.subplots(2, 1, figsize=(8.6, 6.4), sharex=True)
    ax1, ax2 = axes
    s = d["s_mm"]
    active = (s >= d["s_A"]) & (s <= d["s_E"])
    for ax, series in ((ax1, (("sliding1", "ϑ1 (gear 1)", "#1f4e89"), ("sliding2", "ϑ2 (gear 2)", "#8a3b12"))),
                       (ax2, (("pressure", "γ = m(ρ1 + ρ2)/(ρ1 ρ2)", "k"),))):
        for key, label, col in series:
            ax.plot(s, d[key], ":", color=col, lw=0.8)
            ax.plot(s[active], d[key][active], "-", color=col, lw=1.8, label=label)
        lo_dc, hi_dc = d["s_A"] + (d["s_E"] - d["s_A"] - d["p_b"]), d["s_E"] - (d["s_E"] - d["s_A"] - d["p_b"])
        for x0, x1 in ((d["s_A"], lo_dc), (hi_dc, d["s_E"])):
            if x1 > x0:
                ax.axvspan(x0, x1, color="#d62728", alpha=0.12, lw=0)
        for name in ("A", "P", "E"):
            ax.axvline(d[f"s_{name}"], color="0.5", lw=0.6)
            ax.annotate(name, (d[f"s_{name}"], 1.0), xycoords=("data", "axes fraction"), xytext=(2, -12),
                        textcoords="offset points", fontsize=9)
        ax.grid(alpha=0.3)
        ax.legend(loc="upper right", fontsize=8)
    ax1.set_ylim(-3.0, 1.2)
    ax1.set_ylabel("specific sliding")
    ax2.set_ylim(0.0, 4.0 * float(pair._geo["spec_pressure_pitch"]))
    ax2.set_ylabel("specific pressure coefficient")
    ax2.set_xlabel("position on the line of action from N1, mm (shaded: double contact)")
    ax1.set_title(f"z1/z2 = {pair.z1}/{pair.z2}, x1/x2 = {pair.x1:.4g}/{pair.x2:.4g}: sliding and pressure along N1N2",
                  fontsize=10)
    return axes
