"""Conditions of internal meshes that external pairs do not have: the tips of pinion and ring
fouling each other as they enter and leave mesh, the pinion (or the cutter) unable to move in
radially, and the pinion-type shaper cutter that generates a ring.

Sources: SDP/SI–KHK, *Elements of Metric Gear Technology* (KHK Gear Technical Reference), §5.2,
eq. (5-4)–(5-10), reproduced against KHK's Tables 5-3 and 5-4 in
``docs/research/internal_helical.md``; the same trochoid condition in GOST 19274-73's textbook form
z1(inv α_a1 + δ1) − z2(inv α_a2 + δ2) + (z2 − z1) inv α_w >= 0.
"""
from __future__ import annotations

import contextlib
import functools
import math
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from ..renamed import renamed_keywords
from ..validate import one_number, require_int, require_range
from .involute import _tan_from_inv_float, inv, inv_from_tan, tan_from_inv

__all__ = ["ShaperCutter", "trochoid_margin", "trochoid_margin_gradient", "trimming_margin", "trimming_margin_gradient", "cutting_mesh", "cutting_mesh_slopes", "CuttingMesh",
           "CUTTER_DIAMETER_MM", "Z0_RANGE", "X0_RANGE", "HA0_RANGE"]

# Disc shaper cutters come in nominal reference diameters of 75/80, 100, 125, 160 and 200 mm
# (DIN 1825, GOST 9323-79); 100 mm is the common middle size. The cutter's tooth count for a module
# is then about 100/m. The standards' own z0-per-module tables could not be checked here
# (docs/research/internal_helical.md §3): the default is this stated assumption, not a table.
CUTTER_DIAMETER_MM = 100.0
# A ring too small for that cutter gets the largest cutter KHK's Table 5-3a admits for an
# unshifted cutter and ring: z2 − z0 >= 18 (19 for z0 = 15).
RING_MINUS_CUTTER_MIN = 18
Z0_RANGE = (8, 400)
X0_RANGE = (-1.0, 1.0)
HA0_RANGE = (0.5, 2.0)


@dataclass(frozen=True)
class ShaperCutter:
    """A pinion-type shaper cutter: ``z0`` teeth (None: see :meth:`teeth`), shift
    ``x0`` (0 for a new cutter; regrinding lowers it) and addendum coefficient ``ha0`` (1.25 =
    h_a* + c* of the standard rack, which KHK's Table 5-3a reproduces only with this value).
    The cutter has the rack's pressure angle and module; its tip is taken sharp."""

    z0: int | None = None
    x0: float = 0.0
    ha0: float = 1.25

    def __post_init__(self):
        if self.z0 is not None:
            object.__setattr__(self, "z0", int(require_int("z0", self.z0, *Z0_RANGE)))
        object.__setattr__(self, "x0", one_number("x0", require_range("x0", self.x0, *X0_RANGE)))
        object.__setattr__(self, "ha0", one_number("ha0", require_range("ha0", self.ha0, *HA0_RANGE)))

    @renamed_keywords(m_mm="m")
    def teeth(self, m, z2):
        """z0, or the default for module ``m`` (mm; ``m_mm=`` is its old name) and a ring of ``z2`` teeth: the
        100 mm cutter, round(100/m), or for a ring too small for it the largest one with z2 − z0 >= 18 (at least 8).

        >>> [int(c.teeth(4.0, z2)) for c, z2 in ((ShaperCutter(), 90), (ShaperCutter(), 30), (ShaperCutter(z0=30), 90))]
        [25, 12, 30]
        """
        return self._teeth(m, z2)

    def _teeth(self, m, z2):
        """:meth:`teeth` without its keyword check (the cutting mesh asks at every design a solver visits)."""
        one = type(z2) in (float, int) and type(m) in (float, int)   # no np.ndim on the optimisers' path
        if self.z0 is not None:
            return self.z0 if one else self.z0 + 0 * np.asarray(z2)
        if one or (np.ndim(m) == 0 and np.ndim(z2) == 0):   # one design: Python's round is numpy's (half to even)
            return max(Z0_RANGE[0], min(round(CUTTER_DIAMETER_MM / float(m)), int(z2) - RING_MINUS_CUTTER_MIN))
        return np.maximum(Z0_RANGE[0], np.minimum(np.round(CUTTER_DIAMETER_MM / np.asarray(m, dtype=float)),
                                                  np.asarray(z2) - RING_MINUS_CUTTER_MIN)).astype(int)


# The formulas below take arrays or, on the optimisers' one-design path, Python floats; these pick
# math for floats (numpy costs ~1-10 µs a call on one number) and give NaN where numpy would.
def _sqrt(v):
    if type(v) is float:
        return math.sqrt(v) if v >= 0.0 else math.nan
    return np.sqrt(v)


def _darccos_clipped(c, dc):
    """The change of :func:`_arccos_clipped` for a change dc of c: −dc/√(1 − c²) inside (−1, 1),
    0 where c is clipped."""
    if type(c) is float:
        return -dc / math.sqrt(1.0 - c * c) if -1.0 < c < 1.0 else 0.0
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(np.abs(c) < 1.0, -dc / np.sqrt(np.abs(1.0 - c * c)), 0.0)


def _darcsin_sqrt(s, ds):
    """The change of asin √s for a change ds of s: ds/(2√(s(1 − s))) (NaN outside 0 < s < 1)."""
    if type(s) is float:
        return ds / (2.0 * math.sqrt(s * (1.0 - s))) if 0.0 < s < 1.0 else math.nan
    with np.errstate(invalid="ignore", divide="ignore"):
        return ds / (2.0 * np.sqrt(s * (1.0 - s)))


def _arccos_clipped(c):
    """arccos of c clipped to [-1, 1] (NaN stays NaN)."""
    if type(c) is float:
        return math.acos(min(max(c, -1.0), 1.0))   # max(nan, -1.0) is nan
    return np.arccos(np.minimum(np.maximum(c, -1.0), 1.0))   # np.clip costs ~10 µs on one number


def _arcsin_sqrt(s):
    """asin √s, NaN outside 0 <= s <= 1 (arrays: √ of a negative and asin above 1 give the NaN)."""
    if type(s) is float:
        return math.asin(math.sqrt(s)) if 0.0 <= s <= 1.0 else math.nan
    with np.errstate(invalid="ignore"):
        return np.arcsin(np.sqrt(s))


def trochoid_margin(z1, z2, r_a1, r_a2, a_w, inv_a1, inv_a2, inv_aw):
    """Tip ("trochoid") interference of a pinion and a ring entering and leaving mesh, in radians
    of ring rotation, >= 0 where the tips clear each other (KHK eq. (5-6), (5-7)):

        [z1 (inv α_a1 + δ1) − z2 (inv α_a2 + δ2) + (z2 − z1) inv α_w] / z2,
        cos δ1 = (r_a2² − r_a1² − a_w²)/(2 a_w r_a1),  cos δ2 = (r_a2² − r_a1² + a_w²)/(2 a_w r_a2)

    (δ1, δ2: the angles at the centres to where the tip circles cross). Where they do not cross,
    the tips never meet: δ is taken at the limit of its range.

    >>> # KHK's internal pair 16/24, m 3, x 0/0.5 (r_a, a_w in mm; inv α_a1, inv α_a2, inv α_w)
    >>> round(float(trochoid_margin(16, 24, 27.0, 34.5, 13.1682677, 0.0760958, 0.0026109, 0.0604007)), 4)
    0.0401
    """
    d, a2, a_w2 = r_a2 * r_a2 - r_a1 * r_a1, a_w * a_w, 2.0 * a_w
    c1 = (d - a2) / (a_w2 * r_a1)
    c2 = (d + a2) / (a_w2 * r_a2)
    return (z1 * (inv_a1 + _arccos_clipped(c1)) - z2 * (inv_a2 + _arccos_clipped(c2)) + (z2 - z1) * inv_aw) / z2


def trochoid_margin_gradient(z1, z2, r_a1, r_a2, a_w, t_a1, t_a2, d_ra1, d_ra2, d_aw, d_inv_aw):
    """The derivative of :func:`trochoid_margin` along a change of the shifts, given the changes
    of its inputs (d_ra1, d_ra2, d_aw, d_inv_aw: mm and rad per unit of the shift). By the chain rule:
    d inv α_a = tan α_a dr_a / r_a (cos α_a = r_b/r_a), dδ = −dc/√(1 − c²) with c = N/D and
    dc = (dN − c dD)/D; 0 where the tip circles do not cross (δ at the limit of its range)."""
    n1 = r_a2 * r_a2 - r_a1 * r_a1 - a_w * a_w
    n2 = r_a2 * r_a2 - r_a1 * r_a1 + a_w * a_w
    c1, c2 = n1 / (2.0 * a_w * r_a1), n2 / (2.0 * a_w * r_a2)
    dn = 2.0 * (r_a2 * d_ra2 - r_a1 * d_ra1)
    dc1 = (dn - 2.0 * a_w * d_aw - c1 * 2.0 * (d_aw * r_a1 + a_w * d_ra1)) / (2.0 * a_w * r_a1)
    dc2 = (dn + 2.0 * a_w * d_aw - c2 * 2.0 * (d_aw * r_a2 + a_w * d_ra2)) / (2.0 * a_w * r_a2)
    dd1, dd2 = _darccos_clipped(c1, dc1), _darccos_clipped(c2, dc2)
    return (z1 * (t_a1 * d_ra1 / r_a1 + dd1) - z2 * (t_a2 * d_ra2 / r_a2 + dd2) + (z2 - z1) * d_inv_aw) / z2


def trimming_margin(z1, z2, cos_a1, cos_a2, inv_a1, inv_a2, inv_aw):
    """Trimming interference of a pinion (or cutter) moved radially into a ring, >= 0 where it can
    enter (KHK eq. (5-9), (5-10)), in radians of pinion rotation:

        θ1 + inv α_a1 − inv α_w − (z2/z1)(θ2 + inv α_a2 − inv α_w),
        θ1 = asin √[(1 − (cos α_a1/cos α_a2)²)/(1 − (z1/z2)²)],
        θ2 = asin √[((cos α_a2/cos α_a1)² − 1)/((z2/z1)² − 1)].

    Outside the arcsines' domain no radial path exists: NaN (a failing margin).
    """
    q = (cos_a1 / cos_a2) ** 2
    s1 = (1.0 - q) / (1.0 - (z1 / z2) ** 2)
    s2 = (1.0 / q - 1.0) / ((z2 / z1) ** 2 - 1.0)
    t1, t2 = _arcsin_sqrt(s1), _arcsin_sqrt(s2)   # NaN outside either arcsine's domain
    return t1 + inv_a1 - inv_aw - z2 / z1 * (t2 + inv_a2 - inv_aw)


def trimming_margin_gradient(z1, z2, cos_a1, cos_a2, r_a2, t_a2, d_ra2, d_inv_aw, r_a1=None, t_a1=None,
                             d_ra1=None):
    """The derivative of :func:`trimming_margin` when the ring's tip radius changes by d_ra2 (mm)
    and inv α_w by d_inv_aw, and with ``r_a1, t_a1, d_ra1`` the pinion's tip radius by d_ra1 (else the
    pinion, or cutter, is fixed). Chain rule: q = (cos α_a1/cos α_a2)², cos α_a = r_b/r_a, so
    dq = 2q (dr_a2/r_a2 − dr_a1/r_a1); ds1 = −dq/(1 − (z1/z2)²), ds2 = −(dq/q²)/((z2/z1)² − 1);
    dθ = ds/(2√(s(1 − s))); d inv α_a = tan α_a dr_a/r_a."""
    q = (cos_a1 / cos_a2) ** 2
    s1 = (1.0 - q) / (1.0 - (z1 / z2) ** 2)
    s2 = (1.0 / q - 1.0) / ((z2 / z1) ** 2 - 1.0)
    dq = 2.0 * q * d_ra2 / r_a2
    if d_ra1 is not None:
        dq = dq - 2.0 * q * d_ra1 / r_a1
    ds1 = -dq / (1.0 - (z1 / z2) ** 2)
    ds2 = -dq / (q * q) / ((z2 / z1) ** 2 - 1.0)
    dt1, dt2 = _darcsin_sqrt(s1, ds1), _darcsin_sqrt(s2, ds2)   # outside the arcsines' domain: NaN
    if d_ra1 is not None:
        dt1 = dt1 + t_a1 * d_ra1 / r_a1
    return dt1 - d_inv_aw - z2 / z1 * (dt2 + t_a2 * d_ra2 / r_a2 - d_inv_aw)


class CuttingMesh(NamedTuple):
    """The cutter–ring mesh of :func:`cutting_mesh` (lengths in mm, arrays like the inputs)."""

    z0: object          # the cutter's teeth
    a_w0: object        # cutter–ring centre distance at zero backlash
    r_a0: object        # the cutter's tip radius
    inv_w0: object      # inv α_w0
    trimming: object    # margin of :func:`trimming_margin`, rad
    dtrimming_dx2: object   # ∂trimming/∂x2, rad
    d_f2: object        # the ring's root diameter, 2 a_w0 + d_a0
    rho_form2: object   # radius of curvature where the ring's involute starts (its form circle), mm
    drho_form2_dx2: object   # ∂rho_form2/∂x2, mm
    n0n2: object        # a_w0 sin α_w0: on the ring, the cutter's interference point N0, mm
    tan_w0: object      # tan α_w0


class _CutterRing(NamedTuple):
    """The parts of the cutter–ring mesh that do not depend on the ring's shift (:func:`_cutter_ring`)."""

    z0: object          # the cutter's teeth (NaN where it has as many as the ring or more)
    inv_t: object       # inv α_t
    tan_n: object       # tan α_n
    z_diff: object      # z2 − z0
    dinv_dx2: object    # ∂inv α_w0/∂x2 = 2 tan α_n/(z2 − z0)
    half_span: object   # m_t (z2 − z0) cos α_t / 2: a_w0 = half_span/cos α_w0, N0N2 = half_span tan α_w0
    r_a0: object        # the cutter's tip radius
    rho_a0: object      # √(r_a0² − r_b0²)
    cos_a0: object      # cos α_a0 = r_b0/r_a0
    inv_a0: object      # inv α_a0
    r_b2: object        # the ring's base radius
    drho_scale: object  # m_t cos α_t tan α_n: ∂N0N2/∂x2 = drho_scale (1 + tan²α_w0)/tan²α_w0


def _cutter_ring(m_n, z2, z0, x0, ha0, alpha_t, tan_n, cos_beta) -> _CutterRing:
    """The shift-free parts of :func:`cutting_mesh` (floats, or arrays over many rings; z0 NaN where
    the cutter cannot cut the ring)."""
    m_t = m_n / cos_beta
    cos_t = math.cos(alpha_t)
    r_a0 = m_t * z0 / 2.0 + (ha0 + x0) * m_n
    r_b0 = m_t * z0 / 2.0 * cos_t
    rho_a0 = _sqrt((r_a0 - r_b0) * (r_a0 + r_b0))   # inv α_a0 from tan α_a0 = ρ_a0/r_b0: no arccos near 1
    return _CutterRing(z0, inv(alpha_t), tan_n, z2 - z0, 2.0 * tan_n / (z2 - z0), m_t * (z2 - z0) * cos_t / 2.0,
                       r_a0, rho_a0, r_b0 / r_a0, inv_from_tan(rho_a0 / r_b0), m_t * z2 / 2.0 * cos_t,
                       m_t * cos_t * tan_n)


# one ring (a pair's solve evaluates the cutting mesh at every design it visits): once per ring and cutter
_cutter_ring_once = functools.lru_cache(maxsize=256)(_cutter_ring)


def _setup(m_n, z2, x2, r_a2, cutter: ShaperCutter, alpha_t, tan_n, cos_beta):
    """(scalar, the shift-free parts, m_n, z2, x2, r_a2): one design in Python floats (numpy's per-call
    cost would dominate the optimisers' path), one ring's parts cached, arrays over many rings as given."""
    scalar = (type(x2) is float and type(r_a2) is float and type(m_n) is float and type(z2) is float) or \
        all(type(v) in (float, int) or np.ndim(v) == 0 for v in (m_n, z2, x2, r_a2))
    z0 = cutter._teeth(m_n, z2)
    if scalar or all(type(v) in (float, int) or np.ndim(v) == 0 for v in (m_n, z2, cos_beta)):   # one ring
        # all Python floats (a 0-d array's cos β would make numpy scalars, whose √ of a negative warns)
        m_n, z2 = float(m_n), float(z2)
        k = _cutter_ring_once(m_n, z2, float(z0) if z2 > z0 else math.nan, cutter.x0, cutter.ha0, float(alpha_t),
                              float(tan_n), float(cos_beta))
    else:
        with np.errstate(invalid="ignore", divide="ignore"):
            k = _cutter_ring(m_n, z2, np.where(np.asarray(z2) > z0, z0, np.nan), cutter.x0, cutter.ha0, alpha_t,
                             tan_n, cos_beta)
    if scalar:
        x2, r_a2 = float(x2), float(r_a2)
    return scalar, k, m_n, z2, x2, r_a2


def cutting_mesh(m_n, z2, x2, r_a2, cutter: ShaperCutter, alpha_t: float, tan_n: float,
                 cos_beta: float = 1.0, slopes: bool = True, tip=None) -> CuttingMesh:
    """The cutter–ring mesh at zero backlash (GOST 19274-73; KHK §5.2): inv α_w0 = inv α_t +
    2 (x2 − x0) tan α_n /(z2 − z0), a_w0 = m_t (z2 − z0) cos α_t /(2 cos α_w0); the ring's root
    d_f2 = 2 a_w0 + d_a0, and its form limit: the cutter's tip generates the ring's involute down
    to the point where the cutter's tip circle meets their line of action, so on the ring
    ρ_F2 = ρ_a0 + a_w0 sin α_w0, ρ_a0 = √(r_a0² − r_b0²) (both centres on one side, as in
    docs/research/internal_helical.md §1.4 and §3). NaN where the cutter has as many teeth as the
    ring or more (it cannot cut it). Without ``slopes`` the two derivatives are None (a grid's margins
    do without them; :func:`cutting_mesh_slopes` adds them). ``tip``: (tan α_a2, inv α_a2) of the ring's
    tip where the caller has them (the pair's geometry), else computed from r_a2.

    >>> c = cutting_mesh(3.0, 24, 0.0, 33.0, ShaperCutter(z0=12), math.radians(20), math.tan(math.radians(20)))
    >>> round(float(c.d_f2), 6)               # x0 = x2 = 0: d2 + 2 (h_a* + c*) m
    79.5
    """
    scalar, k, m_n, z2, x2, r_a2 = _setup(m_n, z2, x2, r_a2, cutter, alpha_t, tan_n, cos_beta)
    inv_w0 = k.inv_t + 2.0 * (x2 - cutter.x0) * k.tan_n / k.z_diff
    if scalar:
        t_w0 = _tan_from_inv_float(inv_w0) if inv_w0 > 0 else math.nan
        # a ring tip inside its base circle: NaN, a failing margin (_sqrt gives the NaN itself)
        t_a2, inv_a2 = _ring_tip(k, r_a2, tip)
        trim = trimming_margin(k.z0, z2, k.cos_a0, k.r_b2 / r_a2, k.inv_a0, inv_a2, inv_w0)
    else:
        t_w0 = tan_from_inv(np.where(inv_w0 > 0, inv_w0, np.nan), validate=False)
        with np.errstate(invalid="ignore"):
            t_a2, inv_a2 = _ring_tip(k, r_a2, tip)
            trim = trimming_margin(k.z0, z2, k.cos_a0, k.r_b2 / r_a2, k.inv_a0, inv_a2, inv_w0)
    a_w0 = k.half_span / (1.0 / _sqrt(1.0 + t_w0 * t_w0))   # half_span / cos α_w0
    n0n2 = k.half_span * t_w0                        # N0N2 = a_w0 sin α_w0 = half_span tan α_w0
    dtrim, drho = _slopes(k, m_n, z2, r_a2, t_a2, t_w0, scalar) if slopes else (None, None)
    return CuttingMesh(k.z0, a_w0, k.r_a0, inv_w0, trim, dtrim, 2.0 * a_w0 + 2.0 * k.r_a0, k.rho_a0 + n0n2, drho,
                       n0n2, t_w0)


def cutting_mesh_slopes(cm: CuttingMesh, m_n, z2, r_a2, cutter: ShaperCutter, alpha_t: float, tan_n: float,
                        cos_beta: float = 1.0, tip=None) -> CuttingMesh:
    """``cm`` (of :func:`cutting_mesh` with ``slopes=False``, the same arguments) with its derivatives
    ∂trimming/∂x2 and ∂ρ_F2/∂x2."""
    scalar, k, m_n, z2, _, r_a2 = _setup(m_n, z2, cm.inv_w0, r_a2, cutter, alpha_t, tan_n, cos_beta)
    with (contextlib.nullcontext() if scalar else np.errstate(invalid="ignore")):
        t_a2 = _ring_tip(k, r_a2, tip)[0]
    dtrim, drho = _slopes(k, m_n, z2, r_a2, t_a2, cm.tan_w0, scalar)
    return cm._replace(dtrimming_dx2=dtrim, drho_form2_dx2=drho)


def _ring_tip(k: _CutterRing, r_a2, tip=None):
    """(tan α_a2, inv α_a2) of the ring's tip: ``tip`` when given, else tan α_a2 = ρ_a2/r_b2 and inv α_a2
    from it (no arccos near 1)."""
    if tip is not None:
        return tip
    r_b2 = k.r_b2
    t_a2 = _sqrt((r_a2 - r_b2) * (r_a2 + r_b2)) / r_b2
    return t_a2, inv_from_tan(t_a2)


def _slopes(k: _CutterRing, m_n, z2, r_a2, t_a2, t_w0, scalar: bool) -> tuple:
    """(∂trimming/∂x2, ∂ρ_F2/∂x2): x2 moves the ring's tip by m_n (r_a2 = r2 − m_n(h_a* − x2)) and inv α_w0
    by 2 tan α_n/(z2 − z0); ∂N0N2/∂x2 = drho_scale (1 + t²)/t², t = tan α_w0 (d tan/d inv = (1 + t²)/t²)."""
    with (contextlib.nullcontext() if scalar else np.errstate(invalid="ignore", divide="ignore")):
        dtrim = trimming_margin_gradient(k.z0, z2, k.cos_a0, k.r_b2 / r_a2, r_a2, t_a2, m_n, k.dinv_dx2)
        drho = k.drho_scale * (1.0 + t_w0 * t_w0) / (t_w0 * t_w0)
    return dtrim, drho
