"""The transverse tooth profile of an internal (ring) gear as its pinion-type shaper cutter generates it.

The cutter (:class:`~geardesign.gears.ring.ShaperCutter`: z0 teeth, shift x0, addendum h_a0*·m,
the rack's module and pressure angle) is taken as the ring checks take it: an involute gear with its
involute whole down to its base circle (radial below it, down to its root r0 − (h_a* + c* − x0)·m),
its tip sharp, cut at its tip circle r_a0 = r0 + (h_a0* + x0)·m. (A cutter ground by a rack of the
pair's own addendum would lose the involute below r0 − (h_a* − x0)·m and, with few teeth, be
undercut; real shaper cutters are ground deeper, and the checks' form limit ρ_F2 assumes the whole
involute.) It turns about a
centre a_w0 from the ring's, both centres on one side of the pitch point I, and rolls its operating
pitch circle r_w0 = a_w0·z0/(z − z0) inside the ring's R = a_w0·z/(z − z0) (the cutter–ring mesh at
zero backlash of :func:`~geardesign.gears.ring.cutting_mesh`: inv α_w0 = inv α + 2(x − x0) tan α/(z − z0)).

The ring is the envelope of the cutter in that rolling, found by the law of gearing as
:mod:`geardesign.profiles.tooth` finds the rack's: a point P of the cutter with normal n cuts the ring
at the cutter rotation that puts I on P's normal line, i.e. where that line crosses the cutter's
pitch circle r_w0 (on the same side of its foot from the centre as P; Litvin & Fuentes, *Gear
Geometry and Applied Theory*, 2nd ed., §10.5). The cutter's involute flank envelops the ring's
involute, its sharp tip corner — whose normals fan from the tip circle's (radial) to the flank's —
sweeps the root fillet (a hypotrochoid of the corner), and its tip circle cuts the root circle
r_f = a_w0 + r_a0. This is the generation itself rather than the ring's analytic involute plus the
corner's trochoid: the same code makes both parts from one cutter, so the ring's involute, its
thickness and its form circle come out of the cutting motion and can test the analytic ring
formulas of :mod:`geardesign.gears.geometry` and :mod:`geardesign.gears.ring` (they share only the
cutting centre distance a_w0).

The ring's tips are its blank's bore, the tip circle d_a2 (inside d2), not generated. The whole ring
is an annulus: the toothed inner outline inside a rim circle of diameter d_f + 2·s_R, s_R =
``RIM_MODULES``·m below the root (ISO 6336-3:2006 §8: the rim thickness factor of an internal gear is 1
from s_R = 3.5 m_n up).

Coordinates as in :mod:`geardesign.profiles.tooth`: mm, the ring's centre at the origin, the tooth's
centre line along +y (its tip toward the centre, at the smaller radius), the right flank at x > 0,
from the middle of the space (at the root) to the tip. A ring whose tip circle reaches
inside the cutter's interference point (ρ_a2 < a_w0 sin α_w0: no cutter involute meets it there,
or the cutter's teeth rolling out cut into it) is drawn as cut: past the involute the flank is what the cutter leaves, found by a material
test over every cutter position (``cutting_interference``). A tip circle inside the base circle is refused
with one line; the trimming of the ring's tips as the cutter feeds radially in (the ``cutter_trimming``
check) is not drawn: the profile is the one the cutter leaves at full depth.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import GearDesignError
from ..gears.mesh import BETA_RANGE_DEG
from ..gears.rack import BasicRack, require_rack
from ..gears.ring import ShaperCutter, cutting_mesh
from ..validate import one_number, require_count, require_range
from .export import gear_outline
from .tooth import POINTS_MAX, ToothProfile, material_angle, transverse_rack

__all__ = ["RingProfile", "ring_profile", "RIM_MODULES", "rim_circle"]

RIM_MODULES = 3.5           # rim below the root, in modules (ISO 6336-3:2006 §8, internal gears: Y_B = 1)
RIM_CHORD_MODULES = 1e-4    # the rim polygon departs from its circle by at most this, in modules


@dataclass(frozen=True, eq=False, repr=False)    # ToothProfile's short repr
class RingProfile(ToothProfile):
    """One tooth of a ring gear as its shaper cutter generates it (the fields of
    :class:`~geardesign.profiles.tooth.ToothProfile`, ``m``, ``x`` and ``x0`` transverse for a helical ring;
    ``undercut`` is always False), and the cutting:
    ``z0``, ``x0`` the cutter, ``a_w0_mm`` the cutting centre distance, ``r_root_mm`` = a_w0 + r_a0
    the root radius the cutter's tip circle cuts, ``rim_diameter_mm`` the outer rim.
    ``cutting_interference``: the ring's flank runs past the end of its involute toward its tip (past the
    cutting mesh's interference point N0, or where the cutter's teeth rolling out cut into it): the
    points labelled "interference" are what the cutter leaves there, found by a material test."""

    _kind = "ring gear"

    z0: int = 0
    x0: float = 0.0
    a_w0_mm: float = 0.0
    r_root_mm: float = 0.0
    rim_diameter_mm: float = 0.0
    cutting_interference: bool = False

    def _repr_extra(self) -> list:
        return [f"  cut by a z0 = {self.z0} shaper (x0 = {self.x0:.4g}) at a_w0 = {self.a_w0_mm:.6g} mm; root "
                f"d_f = {2 * self.r_root_mm:.6g} mm, rim {self.rim_diameter_mm:.6g} mm; "
                f"{'CUTTING INTERFERENCE' if self.cutting_interference else 'no cutting interference'}"]

    def outlines(self, name: str = "ring") -> list:
        """The annulus as two closed outlines: ``name`` (the toothed bore) and ``name + "_rim"``."""
        return [(name, *gear_outline(self)), (f"{name}_rim", *rim_circle(self.rim_diameter_mm / 2.0, self.m))]


def rim_circle(radius_mm: float, m: float) -> tuple[np.ndarray, np.ndarray]:
    """A closed polygon on the circle, its chords within ``RIM_CHORD_MODULES``·m of the arc (sagitta
    r(1 − cos(π/n)) <= tol), counter-clockwise from +y; the last point repeats the first."""
    n = math.ceil(math.pi / math.acos(max(1.0 - RIM_CHORD_MODULES * m / radius_mm, -1.0)))
    n = max(n, 64)
    t = np.linspace(0.0, 2.0 * math.pi, n + 1)
    x, y = -radius_mm * np.sin(t), radius_mm * np.cos(t)
    x[-1], y[-1] = x[0], y[0]
    return x, y


def _e(angle):
    """Unit vector at polar angle ``angle`` measured from +y toward +x."""
    return np.sin(angle), np.cos(angle)


@dataclass(frozen=True)
class _Cutting:
    """The cutter at rotation 0 (a tooth centred on +y, the ring's space there) and its rolling."""

    z: int
    z0: int
    r_b0: float
    r_a0: float
    r_w0: float       # the cutter's operating pitch radius in the cutting mesh
    a_w0: float
    psi_b0: float     # half the cutter tooth's angle on its base circle (s0/(2 r0) + inv α)
    r_f0: float       # the cutter's root circle: solid below it

    def envelope(self, px, py, nx, ny):
        """Ring points (generation frame: the space on +y) cut by cutter points (px, py) with unit
        normals (nx, ny) (cutter frame)."""
        pn = px * nx + py * ny
        t = -pn + np.sign(pn) * np.sqrt(self.r_w0 ** 2 - (px * px + py * py) + pn * pn)
        phi0 = np.arctan2(px + t * nx, py + t * ny)          # turns the foot of I onto +y
        c, s = np.cos(phi0), np.sin(phi0)
        fx, fy = c * px - s * py, s * px + c * py + self.a_w0
        phi2 = phi0 * self.z0 / self.z                          # r_w0 φ0 = R φ2, both turning one way
        c, s = np.cos(phi2), np.sin(phi2)
        return c * fx + s * fy, -s * fx + c * fy

    def flank(self, t):
        """The cutter's right flank by its roll t = tan α_y (radius r_b0 √(1 + t²)), with its normal."""
        theta = self.psi_b0 - t
        bx, by = _e(theta)
        nx, ny = _e(theta + math.pi / 2.0)
        return self.r_b0 * (bx + t * nx), self.r_b0 * (by + t * ny), nx, ny

    def halfwidth(self, rho):
        """Half the cutter tooth's angle at radius ρ: its involute, radial below the base circle;
        π/z0 (solid) under its root, negative above its tip."""
        t = np.sqrt(np.maximum(rho * rho - self.r_b0 ** 2, 0.0)) / self.r_b0
        w = np.where(rho >= self.r_f0, self.psi_b0 - (t - np.arctan(t)), math.pi / self.z0)
        return np.where(rho <= self.r_a0, w, -1.0)

    def depth(self, gx, gy, phi2):
        """How deep (mm, > 0 inside) ring points (generation frame) lie in the cutter's teeth when the
        ring has turned by φ2 (and the cutter by φ2·z/z0)."""
        c, s = np.cos(phi2), np.sin(phi2)
        fx, fy = c * gx - s * gy, s * gx + c * gy - self.a_w0
        c, s = np.cos(phi2 * self.z / self.z0), np.sin(phi2 * self.z / self.z0)
        x, y = c * fx + s * fy, -s * fx + c * fy
        rho = np.hypot(x, y)
        pitch = 2.0 * math.pi / self.z0
        delta = np.abs(np.arctan2(x, y) - pitch * np.round(np.arctan2(x, y) / pitch))
        return np.minimum(self.r_a0 - rho, rho * (self.halfwidth(rho) - delta))

    def max_depth(self, r, eta):
        """The deepest any cutter position reaches the ring point at radius r, angle η (generation
        frame): the ring turns only while the point is within the cutter's tip circle; a grid over
        that span, then two finer grids about the best."""
        r, eta = np.broadcast_arrays(np.asarray(r, dtype=float), np.asarray(eta, dtype=float))
        r, eta = r.reshape(-1, 1), eta.reshape(-1, 1)
        cos_span = np.clip((r * r + self.a_w0 ** 2 - self.r_a0 ** 2) / (2.0 * r * self.a_w0), -1.0, 1.0)
        span = np.arccos(cos_span) + 1e-9
        u = np.linspace(-1.0, 1.0, 801)[None, :]
        phi, step = eta + span * u, 2.0 * span / 800
        gx, gy = r * np.sin(eta), r * np.cos(eta)
        for _ in range(3):
            d = self.depth(gx, gy, phi)
            best = phi[np.arange(phi.shape[0]), np.argmax(d, axis=1)][:, None]
            phi = best + 2.0 * step * np.linspace(-1.0, 1.0, 41)[None, :]
            step = step / 10.0
        return self.depth(gx, gy, phi).max(axis=1)


def _mirror(z, gx, gy):
    """Generation-frame points (left flank of the ring tooth at η = π/z) onto the right flank of the
    tooth on +y."""
    radius, eta = np.hypot(gx, gy), math.pi / z - np.arctan2(gx, gy)
    return radius * np.sin(eta), radius * np.cos(eta)


def ring_profile(m, z, x=0.0, cutter: ShaperCutter | None = None, rack: BasicRack | None = None,
                 tip_diameter_mm=None, rim_mm=None, points: int = 200, beta_deg: float = 0.0) -> RingProfile:
    """The generated profile of one tooth of a ring gear with ``z`` teeth, shift ``x`` (see the module
    docstring). ``cutter``: the :class:`~geardesign.gears.ring.ShaperCutter` (default: the standard
    size for the module); ``rack``: α (the cutter's pressure angle) and h_a* for the default tip
    d − 2(h_a* − x)·m; ``tip_diameter_mm`` cuts the ring's tips there instead; ``rim_mm``: the rim
    below the root (default ``RIM_MODULES``·m); ``points`` per segment. ``beta_deg``: a helical ring
    (and cutter), drawn in its transverse section (``m``, ``x``, the cutter's x0 and h_a0* normal; the
    rack's transverse section as :func:`~geardesign.profiles.tooth.transverse_rack` gives it).

    >>> from geardesign import GearPair
    >>> p = ring_profile(2, 60, 0.6)              # the default cutter for m = 2 mm has 42 teeth
    >>> g = GearPair(2, 20, 60, 0.3, 0.6, internal=True).geometry()
    >>> p.z0, abs(p.tip_thickness_mm - g.sa2) < 1e-9, round(2 * p.r_root_mm, 4), round(g.df2, 4)
    (42, True, 127.0326, 127.4)
    """
    rack = require_rack(rack)
    cutter = ShaperCutter() if cutter is None else cutter
    if not isinstance(cutter, ShaperCutter):
        raise GearDesignError(f"cutter must be a geardesign.ShaperCutter, got {type(cutter).__name__}")
    m = one_number("m (module)", require_range("m (module)", m, 1e-4, 1e4, unit="mm"))
    z = require_count("z", z, 3, 100_000)
    x = one_number("x", require_range("x", x, -10.0, 10.0))
    n = require_count("points", points, 8, POINTS_MAX)
    beta = one_number("beta_deg", require_range("beta_deg", beta_deg, *BETA_RANGE_DEG, unit="deg"))
    rack_t, cb = transverse_rack(rack, beta)
    m_t, alpha = m / cb, rack_t.alpha            # the transverse module and pressure angle α_t
    r_a = (m_t * z / 2.0 - (rack.ha - x) * m if tip_diameter_mm is None else one_number(
        "tip_diameter_mm", require_range("tip_diameter_mm", tip_diameter_mm, 0.0, 1e9, lo_open=True, unit="mm")) / 2.0)
    rim = RIM_MODULES * m if rim_mm is None else one_number(
        "rim_mm", require_range("rim_mm", rim_mm, 0.0, 1e9, lo_open=True, unit="mm"))
    cut, t_a0, psi_a0, r_b, r_f = _cutter_in_place(m, z, x, r_a, cutter, rack, alpha, m_t, cb)
    # fillet: the corner's normal turns from the radial (it cuts the root) to the flank's (the form point)
    cx, cy = (cut.r_a0 * v for v in _e(psi_a0))
    chi = np.linspace(psi_a0, psi_a0 + math.pi / 2.0 - math.atan(t_a0), n)
    fx, fy = _mirror(z, *cut.envelope(cx, cy, *_e(chi)))
    ix, iy, eta_tip, t_cross = _flank(cut, z, r_a, r_b, t_a0, m, n)
    tang = np.linspace(eta_tip, 0.0, n)
    tx, ty = r_a * np.sin(tang), r_a * np.cos(tang)
    rang = np.linspace(math.pi / z, float(np.arctan2(fx[0], fy[0])), max(2, n // 4))
    rx, ry = r_f * np.sin(rang), r_f * np.cos(rang)
    labels = np.array(["root"] * rx.size + ["fillet"] * fx.size + ["involute"] * n
                      + ["interference"] * (ix.size - n) + ["tip"] * tx.size)
    return RingProfile(m=m_t, z=z, x=x * cb, x_mm=np.concatenate([rx, fx, ix, tx]), y_mm=np.concatenate([ry, fy, iy, ty]),
                       segment=labels, r_form_mm=float(np.hypot(ix[0], iy[0])), undercut=False,
                       cutting_interference=t_cross is not None,
                       tip_thickness_mm=2.0 * r_a * eta_tip, z0=cut.z0, x0=cutter.x0 * cb, a_w0_mm=cut.a_w0, r_root_mm=r_f,
                       rim_diameter_mm=2.0 * (r_f + rim), tip_diameter_mm=2.0 * r_a)


def _cutter_in_place(m, z, x, r_a, cutter: ShaperCutter, rack: BasicRack, alpha, m_t, cb):
    """The cutter at full depth in the ring (the cutting mesh at zero backlash): its motion, tan α at
    its tip and its tip's half-angle ψ_a0, the ring's base and root radii; the
    designs with no cutting position, a pointed cutter or no ring tooth refused by name."""
    z0 = int(cutter.teeth(m, z))
    if z0 >= z:
        raise GearDesignError(f"the shaper cutter has z0 = {z0} teeth, the ring z = {z}: a cutter needs fewer "
                              "teeth than the ring it cuts")
    cm = cutting_mesh(m, z, x, r_a, cutter, alpha, math.tan(rack.alpha), cb)
    a_w0, r_a0 = float(cm.a_w0), float(cm.r_a0)
    if not a_w0 > 0.0:
        raise GearDesignError(f"x = {x:g}: the cutter (z0 = {z0}, x0 = {cutter.x0:g}) has no cutting position in "
                              f"this ring (inv α_w0 = {float(cm.inv_w0):.6g} <= 0); raise x")
    r0, r_b = m_t * z0 / 2.0, m_t * z / 2.0 * math.cos(alpha)
    r_b0 = r0 * math.cos(alpha)
    # s0/(2 r0) + inv α_t, the cutter's transverse thickness s0 = m_t π/2 + 2 x0 m tan α_n
    psi_b0 = (math.pi / 2.0 + 2.0 * cutter.x0 * math.tan(rack.alpha)) / z0 + (math.tan(alpha) - alpha)
    if not r_a0 > r_b0:
        raise GearDesignError(f"the shaper cutter z0 = {z0}, x0 = {cutter.x0:g}, h_a0* = {cutter.ha0:g} has its tip "
                              f"circle (d_a0 = {2 * r_a0:.6g} mm) inside its base circle (d_b0 = {2 * r_b0:.6g} mm): "
                              "no involute to cut with; choose more teeth, a larger x0 or h_a0*")
    t_a0 = math.sqrt((r_a0 - r_b0) * (r_a0 + r_b0)) / r_b0
    psi_a0 = psi_b0 - (t_a0 - math.atan(t_a0))
    if not psi_a0 > 0.0:
        raise GearDesignError(f"the shaper cutter z0 = {z0}, x0 = {cutter.x0:g}, h_a0* = {cutter.ha0:g} is pointed "
                              "before its tip circle: choose a cutter with more teeth or a smaller x0")
    if not r_a > r_b:
        raise GearDesignError(f"the ring's tip circle (d_a2 = {2 * r_a:.6g} mm) is inside its base circle "
                              f"(d_b2 = {2 * r_b:.6g} mm): no involute to draw")
    r_w0 = a_w0 * z0 / (z - z0)
    cut = _Cutting(z, z0, r_b0, r_a0, r_w0, a_w0, psi_b0, r0 + (cutter.x0 - rack.ha - rack.c) * m)
    r_f = a_w0 + r_a0
    if not r_a < r_f:
        raise GearDesignError(f"the ring's tip circle (d_a2 = {2 * r_a:.6g} mm) is outside its root "
                              f"(d_f2 = {2 * r_f:.6g} mm): no tooth to draw")
    return cut, t_a0, psi_a0, r_b, r_f


def _flank(cut: "_Cutting", z: int, r_a, r_b, t_a0, m, n: int):
    """The ring's flank from its form point to its tip circle: the envelope of the cutter's involute,
    continued where the cutter cuts into it by what the cutter leaves (x, y, the tip's half-angle η_tip,
    and the cutter's roll where the interference begins, None without). A tooth pointed before its
    tip circle is refused by name."""
    a_w0, r_w0, r_b0 = cut.a_w0, cut.r_w0, cut.r_b0
    # the flank point that cuts the ring's tip circle lies on the cutting mesh's line of action:
    # ρ0 = ρ_a2 − a_w0 sin α_w0. Where that is below the cutter's base circle (past N0), or the
    # cutter's teeth rolling out cut into the involute, the ring is what the cutter leaves
    t_tip = (math.sqrt((r_a - r_b) * (r_a + r_b)) - a_w0 * math.sqrt((r_w0 - r_b0) * (r_w0 + r_b0)) / r_w0) / r_b0
    t_lo = max(t_tip, 1e-9 * t_a0)
    t_cross = _interference_roll(cut, t_lo, t_a0, m)
    if t_cross is None and t_tip < t_lo:    # the ring's tip lies where no cutter involute reaches
        t_cross = t_lo
    if t_cross is None:
        ix, iy = _mirror(z, *cut.envelope(*cut.flank(np.linspace(t_a0, t_tip, n))))
        eta_tip = float(np.arctan2(ix[-1], iy[-1]))
        tip_kept = eta_tip > 0.0
    else:
        ix, iy = _mirror(z, *cut.envelope(*cut.flank(np.linspace(t_a0, t_cross, n))))
        r_cross = float(np.hypot(ix[-1], iy[-1]))
        radii = r_cross - (r_cross - r_a) * (1.0 - np.cos(np.linspace(0.0, math.pi / 2, n)))[1:]  # dense near r_cross
        radii[-1] = r_a
        eta_m = math.pi / z - material_angle(cut, radii)
        mx, my = radii * np.sin(eta_m), radii * np.cos(eta_m)
        ix, iy = np.concatenate([ix, mx]), np.concatenate([iy, my])
        eta_tip = float(eta_m[-1])
        tip_kept = eta_tip > 0.0 and not np.any(eta_m <= 0.0)
    if not tip_kept:
        raise GearDesignError(f"the ring's tooth is pointed (or cut away) before its tip circle (d_a2 = {2 * r_a:.6g} mm): "
                              "lower its tip or change its shift or the cutter")
    return ix, iy, eta_tip, t_cross


def _interference_roll(cut: _Cutting, t_lo: float, t_hi: float, m: float):
    """The cutter roll t below which the generated ring involute is cut away again by the cutter's
    teeth rolling out (tested from t_lo, where the ring's tip is, up), or None if nothing is."""
    tol = 1e-10 * m

    def cut_away(t):
        gx, gy = cut.envelope(*cut.flank(np.array([t])))
        r, eta = np.hypot(gx, gy), np.arctan2(gx, gy)
        return cut.max_depth(r, eta)[0] > tol

    if not cut_away(t_lo):
        return None
    lo, hi = t_lo, t_hi
    if cut_away(hi):
        raise GearDesignError("the shaper cutter cuts away the whole involute of the ring it generates: "
                              "the cutter does not fit this ring")
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if cut_away(mid) else (lo, mid)
    return hi
