"""The transverse tooth profile of an external spur gear as its rack cutter generates it.

The gear rolls its reference circle (radius r = m z / 2) on the rack's generating line, which lies
x·m below the rack's datum line (the profile shift). The straight rack flank envelops the involute,
the rack tip's rounding (radius ρ_f*·m) the trochoidal fillet, and the tip line the root circle.
Each contact point follows from the law of gearing: the common normal passes through the pitch
point I = (0, r), the instantaneous centre of the rolling (Litvin & Fuentes, *Gear Geometry and
Applied Theory*, 2nd ed., §10.5). Nothing here uses the involute formulas of
:mod:`geardesign.gears.geometry`, so the profile is an independent model to test them against.

Coordinates: mm, the gear centre at the origin, the tooth's centre line along +y, the right flank
at x > 0. The generation runs with a rack tooth centred on the y axis, i.e. a space of the gear
there; a generated point at polar angle η (from +y toward +x) belongs to the left flank of the tooth
centred at η = π/z, which mirrors onto the right flank of the tooth centred on +y at π/z − η.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import GearDesignError
from ..gears.rack import BasicRack, require_rack
from ..inline import html_view
from ..results import Result
from ..validate import one_number, require_count, require_range
from .export import gear_outline, write_outlines

__all__ = ["ToothProfile", "tooth_profile", "transverse_rack", "POINTS_MAX"]

POINTS_MAX = 20_000   # points per segment: a drawing needs a few hundred


@dataclass(frozen=True)
class _Cutter:
    """The rack at φ = 0: a tooth centred on x = 0, its datum line at y = r + x·m."""

    m: float
    z: int
    r: float           # reference (generating pitch) radius, mm
    alpha: float       # profile angle, rad
    xc: float          # centre of the tip rounding (right corner), mm
    yc: float
    rho: float         # tip rounding radius, mm
    flank_x0: float    # x of the right flank where it crosses the pitch line y = r, at φ = 0

    @classmethod
    def of(cls, m: float, z: int, x: float, rack: BasicRack) -> "_Cutter":
        r = m * z / 2.0
        a = rack.alpha
        datum = r + x * m
        rho = rack.rho_f * m
        yc = datum - (rack.ha + rack.c) * m + rho
        # right flank: x = πm/4 − (datum − y) tan α; the rounding touches it and the tip line
        xc = math.pi * m / 4.0 - (datum - yc) * math.tan(a) - rho / math.cos(a)
        return cls(m, z, r, a, xc, yc, rho, math.pi * m / 4.0 - x * m * math.tan(a))

    @property
    def r_base(self) -> float:
        return self.r * math.cos(self.alpha)

    def fillet(self, tau):
        """Points the rounding generates, by the direction τ of its outward normal, from the root
        (τ = −π/2) to the hand-over to the flank (τ = −α); the normal passes through I."""
        phi = (self.xc + (self.r - self.yc) * np.cos(tau) / np.sin(tau)) / self.r
        return _mirror(self, *_gear_frame(self.xc - self.r * phi + self.rho * np.cos(tau),
                                          self.yc + self.rho * np.sin(tau), phi))

    def tau_form(self) -> float:
        return -self.alpha

    def flank(self, s):
        """Points the straight flank generates, by the signed distance s along the line of action
        from I (s = r sin α at the base circle): the foot of the normal from I on the flank."""
        ca, sa = math.cos(self.alpha), math.sin(self.alpha)
        phi = (self.flank_x0 - s / ca) / self.r
        return _mirror(self, *_gear_frame(s * ca, self.r - s * sa, phi))

    def s_at_radius(self, radius):
        """s of the flank point at ``radius`` (>= r_b) on the real branch (from N toward the tip)."""
        return self.r * math.sin(self.alpha) - np.sqrt(np.maximum(np.asarray(radius) ** 2 - self.r_base ** 2, 0.0))

    def depth(self, X, Y):
        """Signed distance (mm) of rack-frame points into the rack tooth centred on X = 0 (> 0 inside)."""
        X = np.abs(X)
        a = self.alpha
        d_flank = (self.flank_x0 + (Y - self.r) * math.tan(a) - X) * math.cos(a)
        d_tip = Y - (self.yc - self.rho)
        corner = (Y < self.yc - self.rho * math.sin(a)) & (X > self.xc)
        return np.where(corner, self.rho - np.hypot(X - self.xc, Y - self.yc), np.minimum(d_flank, d_tip))

    def max_depth(self, r, eta):
        """How deep the gear point at radius r, polar angle η (generation frame) ever lies inside the
        cutter over the roll (> 0: the cutter removes it): a grid over φ, then two finer grids."""
        r, eta = np.broadcast_arrays(np.asarray(r, dtype=float), np.asarray(eta, dtype=float))
        r, eta = r.reshape(-1, 1), eta.reshape(-1, 1)
        phi = eta + np.linspace(-1.2, 1.2, 801)[None, :]
        step = 2.4 / 800
        for _ in range(3):
            d = self.depth(r * np.sin(eta - phi) + self.r * phi, r * np.cos(eta - phi))
            best = phi[np.arange(phi.shape[0]), np.argmax(d, axis=1)][:, None]
            phi = best + np.linspace(-2 * step, 2 * step, 41)[None, :]
            step = 4 * step / 40
        d = self.depth(r * np.sin(eta - phi) + self.r * phi, r * np.cos(eta - phi))
        return d.max(axis=1)

    def s_form(self) -> float:
        """s where the rounding hands over to the flank (its tangency point's contact)."""
        ca, sa = math.cos(self.alpha), math.sin(self.alpha)
        phi = (self.xc + (self.yc - self.r) * ca / sa) / self.r
        # the flank contact at this φ: s from the flank's x at the pitch line
        return (self.flank_x0 - self.r * phi) * ca


def _gear_frame(px, py, phi):
    """A fixed-frame point, the gear turned by φ (counter-clockwise), in the gear's frame."""
    c, s = np.cos(phi), np.sin(phi)
    return c * px + s * py, -s * px + c * py


def _mirror(cut: _Cutter, gx, gy):
    """Generated points (left flank of the tooth at η = π/z) onto the right flank of the tooth on +y."""
    radius = np.hypot(gx, gy)
    eta = math.pi / cut.z - np.arctan2(gx, gy)
    return radius * np.sin(eta), radius * np.cos(eta)


@dataclass(frozen=True, eq=False)
class ToothProfile(Result):
    """One tooth's right flank as generated, from the middle of the space to the tip, in mm.

    ``x_mm``, ``y_mm``: points (the tooth's centre line is the y axis); ``segment``: "root",
    "fillet", "involute" or "tip" per point. ``r_form_mm``: the radius where the fillet meets the
    involute (the form circle). ``undercut``: the cutter removed part of the involute above the base
    circle. ``tip_thickness_mm``: the arc thickness on the tip circle, measured on the profile.
    """

    m: float
    z: int
    x: float
    x_mm: np.ndarray
    y_mm: np.ndarray
    segment: np.ndarray
    r_form_mm: float
    undercut: bool
    tip_thickness_mm: float
    tip_diameter_mm: float = math.nan      # the circle the tooth is cut at
    tip_unshortened: bool = False          # cut at d + 2(h_a* + x)m, not at a pair's (shortened) tip circle

    _success_field = "exists"
    _kind = "gear"     # the files' title

    @property
    def exists(self) -> bool:
        return bool(self.x_mm.size)

    def to_frame(self):
        import pandas as pd

        return pd.DataFrame({"x_mm": self.x_mm, "y_mm": self.y_mm, "segment": self.segment})

    def __repr__(self) -> str:
        counts = ", ".join(f"{name} {int(np.sum(self.segment == name))}" for name in dict.fromkeys(self.segment.tolist()))
        lines = [f"{type(self).__name__}({self._kind} m = {self.m:g} mm, z = {self.z}, x = {self.x:.6g}): "
                 f"{self.x_mm.size} points ({counts})",
                 f"  tip d_a = {self.tip_diameter_mm:.6g} mm, s_a = {self.tip_thickness_mm:.6g} mm "
                 f"({self.tip_thickness_mm / self.m:.4g} m); form circle d_Ff = {2 * self.r_form_mm:.6g} mm; "
                 f"{'UNDERCUT' if self.undercut else 'no undercut'}"]
        lines += self._repr_extra()
        if self.tip_unshortened:
            lines.append("  NOTE: the tip is NOT shortened (d_a = d + 2(h_a* + x)m): in a pair the tip is cut at the "
                         "pair's tip circle; use gd.pair_profiles(pair) or tip_diameter_mm=pair.geometry().da1")
        lines.append("  .to_frame() points, .outline(), .to_dxf/.to_svg/.to_csv(path)")
        return "\n".join(lines)

    def _repr_extra(self) -> list:
        return []

    def outlines(self, name: str = "gear") -> list:
        """The whole gear as closed outlines ``[(name, x_mm, y_mm)]`` (a ring adds its rim)."""
        return [(name, *gear_outline(self))]

    def _write(self, path, overwrite: bool, suffix: str, data_block=None):
        return write_outlines(self.outlines(), path, overwrite,
                              f"{self._kind} m = {self.m:g} mm, z = {self.z}, x = {self.x:g}", self.m / 50,
                              suffixes=(suffix,), data_block=data_block)

    def to_csv(self, path, overwrite: bool = False):
        """The whole gear's closed outline as ``outline,x_mm,y_mm`` rows (:mod:`geardesign.profiles.export`)."""
        return self._write(path, overwrite, ".csv")

    def to_svg(self, path, overwrite: bool = False):
        """The whole gear's closed outline(s) as SVG paths in mm."""
        return self._write(path, overwrite, ".svg")

    def to_dxf(self, path, overwrite: bool = False, data_block=None):
        """The whole gear's closed outline(s) as DXF polylines in mm (ezdxf), one layer each; ``data_block`` (the
        table of :func:`geardesign.gears.data_block.data_block`, or text lines) as text beside them."""
        return self._write(path, overwrite, ".dxf", data_block)

    def _repr_html_(self) -> str:
        """Jupyter's view: the text, and the tooth drawn by segment inline."""
        return html_view(repr(self), self.plot, figsize=(4.6, 4.6), alt="tooth profile")

    def plot(self, ax=None):
        """The whole tooth, its segments (root, fillet, involute, tip) in their own colours and
        the form circle dashed. Returns the matplotlib Axes."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(4.6, 4.6))
        colours = {"root": "0.45", "fillet": "tab:orange", "involute": "tab:blue", "tip": "tab:green"}
        for seg, colour in colours.items():
            on = self.segment == seg
            if on.any():
                for sign in (1, -1):
                    ax.plot(sign * self.x_mm[on], self.y_mm[on], "-", lw=1.6, color=colour,
                            label=seg if sign > 0 else None)
        half = np.abs(self.x_mm).max() / max(self.r_form_mm, 1e-300) if self.exists else 0.1   # the drawing's width
        t = np.linspace(-half, half, 200)
        ax.plot(self.r_form_mm * np.sin(t), self.r_form_mm * np.cos(t), "--", color="0.3", lw=0.8,
                label=f"form circle d_Ff = {2 * self.r_form_mm:.4g} mm")
        ax.set_aspect("equal")
        ax.set_xlabel("mm")
        ax.set_title(f"{self._kind} m = {self.m:g} mm, z = {self.z}, x = {self.x:g}"
                     + (" (undercut)" if self.undercut else ""), fontsize=10)
        ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0)
        return ax

    def outline(self) -> tuple[np.ndarray, np.ndarray]:
        """The whole tooth from the left space middle to the right one (the left flank mirrored)."""
        return (np.concatenate([-self.x_mm, self.x_mm[-2::-1]]),
                np.concatenate([self.y_mm, self.y_mm[-2::-1]]))


def tooth_profile(m, z, x=0.0, rack: BasicRack | None = None, tip_diameter_mm=None,
                  points: int = 200) -> ToothProfile:
    """The generated profile of one tooth of an external spur gear (see the module docstring).

    ``tip_diameter_mm`` cuts the tooth at that circle (default d + 2(h_a* + x)·m, no tip
    shortening); ``points`` per segment. Where the cutter's corner cuts into the involute above
    the base circle (an undercut), the profile below the crossing is what the cutter leaves: at
    each radius, the angle where the material begins (found by testing points against every cutter
    position), and ``undercut`` is True.

    >>> p = tooth_profile(8, 17, 0.898)          # seed 000's pinion, tip not shortened
    >>> round(2 * p.r_form_mm, 3)                # the form circle d_Ff
    134.443
    """
    rack = require_rack(rack)
    m = one_number("m (module)", require_range("m (module)", m, 1e-4, 1e4, unit="mm"))
    z = require_count("z", z, 3, 100_000)
    x = one_number("x", require_range("x", x, -10.0, 10.0))
    n = require_count("points", points, 8, POINTS_MAX)
    cut = _Cutter.of(m, z, x, rack)
    r_a = m * z / 2.0 + (rack.ha + x) * m if tip_diameter_mm is None else one_number(
        "tip_diameter_mm", require_range("tip_diameter_mm", tip_diameter_mm, 0.0, 1e9, lo_open=True, unit="mm")) / 2.0
    if not r_a > cut.r_base:
        raise GearDesignError(f"the tip circle (d_a = {2 * r_a:.6g} mm) is inside the base circle "
                          f"(d_b = {2 * cut.r_base:.6g} mm): no involute to draw")

    s_top = cut.r * math.sin(cut.alpha)            # the contact at the base circle (N)
    s_form = cut.s_form()
    s_tip = float(cut.s_at_radius(r_a))
    r_cross = _undercut_radius(cut, m) if s_form > s_top - 1e-6 * m else None
    if r_cross is None:
        fx, fy = cut.fillet(np.linspace(-math.pi / 2, cut.tau_form(), n))
        s_start = min(s_form, s_top)
    else:   # the corner cuts the involute up to r_cross: below it the profile is what the cutter leaves
        r_f = cut.yc - cut.rho
        radii = r_f + (r_cross - r_f) * (1.0 - np.cos(np.linspace(0.0, math.pi / 2, n)))   # dense near r_cross
        radii[0] = r_f * (1.0 + 1e-12)
        fx, fy = _mirror(cut, *_polar(radii, material_angle(cut, radii)))
        s_start = float(cut.s_at_radius(r_cross))
    ix, iy = cut.flank(np.linspace(s_start, s_tip, n))
    r_form = float(np.hypot(ix[0], iy[0]))

    eta_tip = float(np.arctan2(ix[-1], iy[-1]))
    ang = np.linspace(eta_tip, 0.0, n)
    tx, ty = r_a * np.sin(ang), r_a * np.cos(ang)
    r_f = float(np.hypot(fx[0], fy[0]))
    rang = np.linspace(math.pi / z, float(np.arctan2(fx[0], fy[0])), max(2, n // 4))
    rx, ry = r_f * np.sin(rang), r_f * np.cos(rang)
    labels = np.array(["root"] * rx.size + ["fillet"] * fx.size + ["involute"] * ix.size + ["tip"] * tx.size)
    return ToothProfile(m=m, z=z, x=x, x_mm=np.concatenate([rx, fx, ix, tx]),
                        y_mm=np.concatenate([ry, fy, iy, ty]), segment=labels, r_form_mm=r_form,
                        undercut=r_cross is not None, tip_thickness_mm=2.0 * r_a * eta_tip,
                        tip_diameter_mm=2.0 * r_a, tip_unshortened=tip_diameter_mm is None)


def _polar(radius, eta):
    return radius * np.sin(eta), radius * np.cos(eta)


def _involute_eta(cut: _Cutter, radius):
    """Generation-frame polar angle of the flank's involute at ``radius`` (>= r_b)."""
    return _eta_gen(*cut.flank(cut.s_at_radius(radius)), cut)


def _eta_gen(ox, oy, cut: _Cutter):
    """Generation-frame angle of an output-frame point (undo :func:`_mirror`)."""
    return math.pi / cut.z - np.arctan2(ox, oy)


def _undercut_radius(cut: _Cutter, m: float):
    """The radius up to which the cutter removes the involute above the base circle, or None when it
    removes none of it (tested on the involute just above the base circle: the material test)."""
    r_b = cut.r_base
    tol = 1e-12 * m
    lo = r_b * (1.0 + 1e-9)
    if cut.max_depth(lo, _involute_eta(cut, lo))[0] <= tol:
        return None
    hi = r_b * 1.001
    while cut.max_depth(hi, _involute_eta(cut, hi))[0] > tol:
        hi = r_b + 2.0 * (hi - r_b)
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if cut.max_depth(mid, _involute_eta(cut, mid))[0] > tol:
            lo = mid
        else:
            hi = mid
    return hi


def material_angle(cut, radii):
    """Generation-frame angle where the material begins at each radius: the largest η any cutter
    position reaches (bisection on η between the space middle and the tooth centre π/z). ``cut``
    is a generating cutter (a rack's, or a ring's shaper) with ``z`` and ``max_depth(radii, η)``."""
    lo = np.zeros_like(radii)
    hi = np.full_like(radii, math.pi / cut.z)
    for _ in range(50):
        mid = 0.5 * (lo + hi)
        inside = cut.max_depth(radii, mid) > 0.0
        lo = np.where(inside, mid, lo)
        hi = np.where(inside, hi, mid)
    return 0.5 * (lo + hi)


def transverse_rack(rack: BasicRack, beta_deg: float) -> tuple[BasicRack, float]:
    """(the rack's transverse section as a rack of module m_t, cos β): α_t from tan α_t = tan α/cos β,
    h_a*, c*, ρ_f* times cos β (the same heights in mm over m_t = m/cos β); ρ_f* is kept within
    what fits the transverse rack's tip.

    >>> r, cb = transverse_rack(BasicRack(), 20.0)
    >>> round(r.alpha_deg, 6), round(r.ha, 6)     # atan(tan 20°/cos 20°), cos 20°
    (21.172832, 0.939693)
    """
    cb = math.cos(math.radians(beta_deg))
    if cb == 1.0:
        return rack, 1.0
    alpha_t = math.degrees(math.atan(math.tan(rack.alpha) / cb))
    loose = BasicRack(alpha_deg=alpha_t, ha=rack.ha * cb, c=rack.c * cb, rho_f=0.0)
    return BasicRack(alpha_deg=alpha_t, ha=loose.ha, c=loose.c, rho_f=min(rack.rho_f * cb, loose.rho_f_max)), cb
