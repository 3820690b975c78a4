"""A planetary set seen along its axis: the three gears' circles and the planets around the sun."""
from __future__ import annotations

import math

import numpy as np

from ..errors import GearDesignError
from ..gears.planetary import PlanetarySet
from ..validate import _show, require_axes

__all__ = ["plot_planetary"]

_COLOURS = {"sun": "tab:blue", "planet": "tab:orange", "ring": "tab:green"}


def _circle(ax, cx, cy, d, **kw):
    t = np.linspace(0.0, 2.0 * math.pi, 361)
    ax.plot(cx + d / 2.0 * np.cos(t), cy + d / 2.0 * np.sin(t), **kw)


def plot_planetary(s: PlanetarySet, ax=None):
    """The set's circles: tip (solid), operating pitch (dash-dot), root (thin) of the sun, every
    planet at the carrier arm a_w (equally spaced, or at ``planet_angles_deg``) and the ring; the
    carrier circle dotted; the gap between neighbouring planets' tips marked. Title: teeth,
    shifts, a_w, ratio. Returns the matplotlib Axes.

    >>> ax = plot_planetary(PlanetarySet(1.75, 21, 43, 108, 3, 0.438, 0.0426, 0.0))
    >>> len(ax.lines) > 12
    True
    """
    import matplotlib.pyplot as plt

    if not isinstance(s, PlanetarySet):
        raise GearDesignError(f"plot_planetary needs a geardesign.PlanetarySet, got {_show(s)}")
    if ax is None:
        _, ax = plt.subplots(figsize=(7.4, 7.4))
    require_axes("ax", ax)
    geo = s.geometry()
    sp, pr = geo["sun-planet"], geo["planet-ring"]
    a_w = s.a_w
    n = s.n_planets
    angles = (np.arange(n) * 360.0 / n if s.planet_angles_deg is None else np.asarray(s.planet_angles_deg)) + 90.0
    gears = [("sun", 0.0, 0.0, sp.da1, sp.dw1, sp.df1)]
    gears += [("planet", a_w * math.cos(math.radians(t)), a_w * math.sin(math.radians(t)), sp.da2, sp.dw2, sp.df2)
              for t in angles]
    gears += [("ring", 0.0, 0.0, pr.da2, pr.dw2, pr.df2)]
    for name, cx, cy, da, dw, df in gears:
        c = _COLOURS[name]
        _circle(ax, cx, cy, da, color=c, lw=1.6)
        _circle(ax, cx, cy, dw, color=c, lw=0.8, ls="-.")
        _circle(ax, cx, cy, df, color=c, lw=0.6)
        ax.plot([cx], [cy], marker="+", color=c, ms=8)
    _circle(ax, 0.0, 0.0, 2.0 * a_w, color="0.4", lw=0.8, ls=":")
    if n > 1:   # the neighbour gap between planets 1 and 2, along the line of their centres
        (_, x1, y1, da, _, _), (_, x2, y2, _, _, _) = gears[1], gears[2]
        ux, uy = (x2 - x1), (y2 - y1)
        dist = math.hypot(ux, uy)
        ux, uy = ux / dist, uy / dist
        p, q = (x1 + ux * da / 2, y1 + uy * da / 2), (x2 - ux * da / 2, y2 - uy * da / 2)
        gap = dist - da
        ax.annotate("", xy=q, xytext=p, arrowprops=dict(arrowstyle="<->", color="k", lw=0.8))
        ax.text((p[0] + q[0]) / 2, (p[1] + q[1]) / 2, f"  {gap:.3g} mm", fontsize=8, va="bottom")
    handles = [plt.Line2D([], [], color=_COLOURS[k], lw=1.6, label=f"{k}: z = {z}, x = {x:+.4f}")
               for k, z, x in (("sun", s.z_sun, s.x_sun), ("planet", s.z_planet, s.x_planet),
                               ("ring", s.z_ring, s.x_ring))]
    handles += [plt.Line2D([], [], color="0.3", lw=1.6, label="tip circles"),
                plt.Line2D([], [], color="0.3", lw=0.8, ls="-.", label="operating pitch circles"),
                plt.Line2D([], [], color="0.3", lw=0.6, label="root circles"),
                plt.Line2D([], [], color="0.4", lw=0.8, ls=":", label=f"carrier arm a_w = {a_w:.5g} mm")]
    ax.legend(handles=handles, fontsize=8, loc="upper right", framealpha=0.9)
    r = pr.df2 / 2.0 * 1.04
    ax.set_xlim(-r, r)
    ax.set_ylim(-r, r)
    ax.set_aspect("equal")
    ax.set_xlabel("mm")
    ax.set_title(f"Planetary set {s.meshes.title}, m = {s.m:g} mm\n"
                 f"a_w = {a_w:.6g} mm (planet-ring {s.a_w_planet_ring:.6g}), ratio {s.ratio:.6g} "
                 f"({s.arrangement.replace('_', ' ')})", fontsize=10)
    ax.grid(True, lw=0.3, alpha=0.5)
    return ax
