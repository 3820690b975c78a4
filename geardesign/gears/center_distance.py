"""The operating centre distance and the shift sum: one from the other (ISO 21771:2007 eq. (62), (63);
GOST 19274-73 for internal pairs), the smallest centre distance, and the undercut limit."""
from __future__ import annotations

import math

import numpy as np

from .involute import inv, inv_from_tan, tan_from_inv
from .mesh import section_constants
from .rack import BasicRack

__all__ = ["inv_operating_angle", "undercut_x_min", "x_sum_from_center_distance", "min_center_distance",
           "center_distance_from_x_sum"]


def inv_operating_angle(z1, z2, x1, x2, alpha):
    """inv α_w = inv α + 2 (x1 + x2) tan α / (z1 + z2)  (ISO 21771:2007 eq. (62); GOST 16532-70 Table 1).

    >>> round(float(inv_operating_angle(12, 24, 0.6, 0.36, math.radians(20))), 6)   # KHK: 0.034316
    0.034316
    """
    return inv(alpha) + 2.0 * (np.asarray(x1) + x2) * math.tan(alpha) / (np.asarray(z1) + z2)


def undercut_x_min(z, rack: BasicRack = BasicRack(), beta_deg: float = 0.0):
    """Smallest profile shift without undercut, x_min = h_l* − z sin²α_t / (2 cos β).

    h_l* = h_a* + c* − ρ_f*(1 − sin α) is where the cutter's straight flank ends (see
    :attr:`BasicRack.h_limit`); with ρ_f* = c*/(1 − sin α) it equals h_a*, the textbook form
    x_min = h_a* − z sin²α/2 (KHK; Litvin & Fuentes §10.5). A helical gear is generated in its
    transverse section by the rack's transverse profile (α_t, reference radius z m_t/2): the
    exact form, not the virtual-gear approximation.

    >>> r = BasicRack(rho_f=0.25 / (1 - math.sin(math.radians(20))))
    >>> [round(float(undercut_x_min(z, r)), 5) for z in (12, 24)]   # KHK: 0.29813, -0.40373
    [0.29813, -0.40373]
    """
    sc = section_constants(rack.alpha, math.radians(beta_deg))
    return rack.h_limit - np.asarray(z, dtype=float) / sc.cos_beta * sc.sin_t ** 2 / 2.0


def _sums(z1, z2, internal: bool):
    """z_Σ = z1 + z2, or z2 − z1 for an internal pair (the ring's count positive)."""
    return np.asarray(z2) - np.asarray(z1) if internal else np.asarray(z1) + np.asarray(z2)


def x_sum_from_center_distance(m, z1, z2, a_w, rack: BasicRack = BasicRack(), beta_deg: float = 0.0,
                               internal: bool = False):
    """The shift sum x_Σ (x1 + x2; x2 − x1 for an internal pair) that gives the operating centre
    distance a_w (zero backlash).

    cos α_w = a cos α_t / a_w;  x_Σ = z_Σ (inv α_w − inv α_t) / (2 tan α_n)
    (ISO 21771:2007 eq. (62) solved for x_Σ; GOST 19274-73 for internal pairs).

    >>> round(x_sum_from_center_distance(3, 12, 24, 56.4999), 6)   # KHK: 0.960013
    0.960013
    >>> round(x_sum_from_center_distance(3, 16, 24, 13.1683, internal=True), 4)   # KHK internal: x2 − x1 = 0.5
    0.5
    """
    sc = section_constants(rack.alpha, math.radians(beta_deg))
    zs = _sums(z1, z2, internal)
    a = np.asarray(m, dtype=float) / sc.cos_beta * zs / 2.0
    cos_w = a * sc.cos_t / np.asarray(a_w, dtype=float)
    # tan α_w = √((1 − c)(1 + c))/c keeps digits when a_w is close to a cos α
    one_minus = (a_w - a * sc.cos_t) / a_w
    tan_w = np.sqrt(one_minus * (1.0 + cos_w)) / cos_w
    out = zs * (inv_from_tan(tan_w) - inv(sc.alpha_t)) / (2.0 * sc.tan_n)
    return float(out) if np.ndim(out) == 0 else out


def min_center_distance(m, z1, z2, rack: BasicRack = BasicRack(), beta_deg: float = 0.0, internal: bool = False):
    """a·cos α_t (mm): the centre distance approached as inv α_w → 0; every a_w exceeds it
    (cos α_w = a cos α_t / a_w < 1).

    >>> round(float(min_center_distance(2.5, 12, 31)), 6)      # 53.75·cos 20°
    50.508478
    """
    sc = section_constants(rack.alpha, math.radians(beta_deg))
    return np.asarray(m, dtype=float) / sc.cos_beta * _sums(z1, z2, internal) / 2.0 * sc.cos_t


def center_distance_from_x_sum(m, z1, z2, x_sum, rack: BasicRack = BasicRack(), beta_deg: float = 0.0,
                               internal: bool = False):
    """Operating centre distance a_w (mm) at zero backlash for the shift sum ``x_sum`` (x1 + x2;
    x2 − x1 for an internal pair).

    inv α_w = inv α_t + 2 x_Σ tan α_n / z_Σ;  a_w = a cos α_t / cos α_w
    (ISO 21771:2007 eq. (62) and (63)). NaN where inv α_w <= 0 (no such pair).

    >>> round(float(center_distance_from_x_sum(3, 12, 24, 0.960013)), 4)   # KHK: a_w = 56.4999 mm
    56.4999
    """
    sc = section_constants(rack.alpha, math.radians(beta_deg))
    zs = np.asarray(_sums(z1, z2, internal), dtype=float)
    inv_w = inv(sc.alpha_t) + 2.0 * np.asarray(x_sum, dtype=float) * sc.tan_n / zs
    ok = inv_w > 0
    t_w = np.where(ok, tan_from_inv(np.where(ok, inv_w, 1.0)), np.nan)
    # a cos α / cos α_w = a cos α · √(1 + tan²α_w)
    out = np.asarray(m, dtype=float) / sc.cos_beta * zs / 2.0 * sc.cos_t * np.hypot(1.0, t_w)
    return float(out) if np.ndim(out) == 0 else out
