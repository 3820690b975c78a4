"""The formulas of the measuring sizes of one involute gear, one function each, vectorised (numpy broadcasting).

Lengths in mm (or the unit of the module), angles in radians unless the name says ``_deg``. The module ``m_n``
and shift ``x`` are normal values; a helical gear's sizes follow ISO 21771:2007 §5 (and DIN 3960:1987 §3.6),
where the spur gear is the case β = 0.

Internal gears carry the project's sign convention (GOST 19274-73, KHK): a ring has a positive tooth count
and a positive x moves its flanks away from its axis (its teeth get thinner, its spaces wider). ISO 21771
writes the same ring with z < 0 and the opposite x: ``z_ISO = −z``, ``x_ISO = −x`` (the datum line moves
toward the ring's axis for a positive ISO shift, which thickens its teeth). A ring's space is then bounded
by the same involutes as the tooth of an external gear with z teeth and shift x, which is why the span
formula is the same for both and the ball formulas differ only in the sign of the ball and π/(2z) terms
(notes, trap 1).
"""
from __future__ import annotations

import math

import numpy as np

from .involute import inv, tan_from_inv

__all__ = [
    "tan_from_inv", "base_tangent_length", "span_teeth_for_diameter", "span_contact_diameter", "normal_tooth_thickness",
    "ball_center_inv", "ball_center_diameter", "dimension_over_balls", "ball_contact_diameter",
    "ball_for_contact", "chordal_thickness", "chordal_height", "generating_shift", "virtual_diameter",
]


def _out(v):
    return float(v) if np.ndim(v) == 0 else v


def base_tangent_length(m_n, z, x, k, alpha_n, alpha_t):
    """Base tangent length (span) W_k over k teeth, mm.

    W_k = m_n cos α_n [(k − 0.5) π + z inv α_t] + 2 x m_n sin α_n
    (ISO 21771:2007 §5.6, DIN 3960:1987 eq. 3.6.1; for a ring, over k spaces with the project's x sign).
    It does not depend on the centre distance or the tip shortening (notes, trap 10).

    >>> a = math.radians(20)
    >>> round(base_tangent_length(2, 20, 0.0, 3, a, a), 3)   # MachineCalcs worked example: 15.321 mm
    15.321
    """
    k = np.asarray(k, dtype=float)
    return _out(m_n * math.cos(alpha_n) * ((k - 0.5) * math.pi + np.asarray(z) * inv(alpha_t))
                + 2.0 * np.asarray(x) * m_n * math.sin(alpha_n))


def span_contact_diameter(w_k, d_b, cos_beta_b):
    """Diameter where the span's anvils touch the flanks, mm.

    The anvils lie on a base-tangent plane; in the transverse section the contacts are W_k/(2 cos β_b) from the
    point of tangency, so d_Wk = √(d_b² + (W_k / cos β_b)²).

    >>> round(span_contact_diameter(15.321, 40 * math.cos(math.radians(20)), 1.0), 2)   # MachineCalcs: 40.59 mm
    40.59
    """
    return _out(np.hypot(d_b, np.asarray(w_k) / cos_beta_b))


def span_teeth_for_diameter(m_n, z, x, d_y, d_b, alpha_n, alpha_t, cos_beta_b):
    """The (fractional) number of teeth k whose span touches on the circle d_y: W_k = d_b tan α_y cos β_b solved
    for k, k = (d_b tan α_y cos β_b − 2 x m_n sin α_n) / (π m_n cos α_n) − z inv α_t / π + 0.5
    (the exact transverse form of DIN 3960's k = z α_y/π ... + 0.5 rule; tan α_y = √(d_y² − d_b²)/d_b).

    >>> a = math.radians(20)
    >>> round(span_teeth_for_diameter(2, 20, 0.0, 40.59, 40 * math.cos(a), a, a, 1.0), 2)   # ~3 for the contact above
    3.0
    """
    d_y, d_b = np.asarray(d_y, dtype=float), np.asarray(d_b, dtype=float)
    w_t = np.sqrt(np.maximum((d_y - d_b) * (d_y + d_b), 0.0))
    return _out((w_t * cos_beta_b - 2.0 * np.asarray(x) * m_n * math.sin(alpha_n)) / (math.pi * m_n * math.cos(alpha_n))
                - np.asarray(z) * inv(alpha_t) / math.pi + 0.5)


def normal_tooth_thickness(m_n, x, alpha_n, internal: bool = False):
    """Normal tooth thickness on the reference circle, mm: s_n = m_n (π/2 + 2 x tan α_n) (ISO 21771:2007 eq. (45));
    a ring's tooth m_n (π/2 − 2 x tan α_n) (GOST 19274-73 sign).

    >>> round(normal_tooth_thickness(10, 0.3, math.radians(20)), 4)   # SDP/SI T-81 Table 10-1: 17.8918 mm
    17.8918
    """
    sign = -1.0 if internal else 1.0
    return _out(m_n * (math.pi / 2.0 + sign * 2.0 * np.asarray(x) * math.tan(alpha_n)))


def generating_shift(x, thickness_allowance_mm, m_n, alpha_n, internal: bool = False):
    """The generating profile shift x_E that a tooth-thickness allowance A_sn amounts to:
    x_E = x + A_sn / (2 m_n tan α_n) (ISO 21771:2007 §5.4; DIN 3960 eq. 3.4.4); for a ring (GOST sign, a positive x
    thins its teeth) x_E = x − A_sn / (2 m_n tan α_n).

    >>> round(generating_shift(0.0, -0.1, 2.5, math.radians(20)), 6)   # thinner teeth: a smaller shift
    -0.05495
    """
    sign = -1.0 if internal else 1.0
    return _out(np.asarray(x) + sign * np.asarray(thickness_allowance_mm) / (2.0 * m_n * math.tan(alpha_n)))


def ball_center_inv(m_n, z, x, ball_mm, alpha_n, alpha_t, internal: bool = False):
    """inv α_Mt of the circle through the ball centres (transverse pressure angle there).

    External: inv α_Mt = inv α_t + D_M/(m_n z cos α_n) − π/(2z) + 2 x tan α_n / z;
    internal (GOST x): inv α_Mt = inv α_t − D_M/(m_n z cos α_n) + π/(2z) + 2 x tan α_n / z
    (ISO 21771:2007 §5.7, DIN 3960:1987 eq. 3.6.5; KHK Gear Technical Reference, internal gears). The ball
    term D_M/(m_n z cos α_n) = D_M/(d_b cos β_b) makes the ball exact on a helical gear.
    """
    z = np.asarray(z, dtype=float)
    sign = -1.0 if internal else 1.0
    return _out(inv(alpha_t) + sign * (np.asarray(ball_mm) / (m_n * z * math.cos(alpha_n)) - math.pi / (2.0 * z))
                + 2.0 * np.asarray(x) * math.tan(alpha_n) / z)


def ball_center_diameter(d_b, inv_alpha_m):
    """Diameter of the circle through the ball centres, d_M = d_b / cos α_Mt = d_b √(1 + tan² α_Mt), mm."""
    return _out(np.asarray(d_b) * np.hypot(1.0, tan_from_inv(inv_alpha_m, validate=False)))


def dimension_over_balls(d_m, ball_mm, z, internal: bool = False):
    """Dimension over (external) or between (internal) two balls or pins, mm.

    Even z: M_d = d_M ± D_M; odd z: M_d = d_M cos(π/(2z)) ± D_M (+ external, − internal: M_d = d_M − D_M)
    (ISO 21771:2007 §5.7; DIN 3960:1987 eq. 3.6.6-7).
    """
    z = np.asarray(z)
    centre = np.where(z % 2 == 0, np.asarray(d_m), np.asarray(d_m) * np.cos(math.pi / (2.0 * z)))
    return _out(centre - np.asarray(ball_mm) if internal else centre + np.asarray(ball_mm))


def ball_contact_diameter(d_b, inv_alpha_m, ball_mm, cos_beta_b, internal: bool = False):
    """Diameter where the ball touches the flanks, mm. The flank's normal through the ball centre lies in a plane
    tangent to the base cylinder, inclined β_b to the transverse plane, so its transverse projection is tangent to
    the base circle and D_M/2 along it projects to (D_M/2) cos β_b: tan α_c = tan α_Mt ∓ D_M cos β_b / d_b
    (− external, + internal) and d_c = d_b √(1 + tan² α_c) (checked against the sphere tangent to the helicoid in
    the tests; the ball sits off the contact's transverse plane)."""
    t_m = tan_from_inv(inv_alpha_m, validate=False)
    sign = 1.0 if internal else -1.0
    t_c = t_m + sign * np.asarray(ball_mm) * cos_beta_b / np.asarray(d_b)
    return _out(np.asarray(d_b) * np.hypot(1.0, t_c))


def ball_for_contact(m_n, z, x, d_y, d_b, alpha_n, alpha_t, cos_beta_b, internal: bool = False):
    """The ball (or pin) diameter D_M that touches the flanks on the circle d_y, mm.

    With u = D_M/(d_b cos β_b), t_c = tan α_y, A the ball-free part of :func:`ball_center_inv` and s = +1
    external, −1 internal: inv α_Mt = A + s u and tan α_Mt = t_c + s u cos² β_b (:func:`ball_contact_diameter`),
    so atan(tan α_Mt) = t_c − A − s u sin² β_b and u solves tan(t_c − A − s u sin² β_b) = t_c + s u cos² β_b.
    Spur (β_b = 0): u = s (tan(t_c − A) − t_c) in closed form (KHK Table 10-13's ideal pin); helical: Newton from
    it (the residual is monotone in u).
    """
    z = np.asarray(z, dtype=float)
    sign = -1.0 if internal else 1.0
    a_free = inv(alpha_t) - sign * math.pi / (2.0 * z) + 2.0 * np.asarray(x) * math.tan(alpha_n) / z
    d_y = np.asarray(d_y, dtype=float)
    t_c = np.sqrt(np.maximum((d_y - d_b) * (d_y + d_b), 0.0)) / d_b
    c2 = cos_beta_b * cos_beta_b
    s2 = 1.0 - c2
    u = sign * (np.tan(t_c - a_free) - t_c)
    for _ in range(50 if s2 > 0.0 else 0):
        ang = t_c - a_free - sign * u * s2
        res = np.tan(ang) - t_c - sign * u * c2
        step = res / (sign * (s2 / np.cos(ang) ** 2 + c2))
        u = u + step
        if np.all(np.abs(step) <= 1e-16 * np.maximum(np.abs(u), 1e-300)):
            break
    return _out(u * np.asarray(d_b) * cos_beta_b)


def virtual_diameter(m_n, z, cos_beta, cos_beta_b):
    """Reference diameter of the virtual spur gear in the normal section, d_n = m_n z / (cos² β_b cos β), mm
    (ISO 21771:2007 eq. (20): z_n = z/(cos² β_b cos β)). KHK and SDP/SI use the approximation z/cos³ β."""
    return _out(m_n * np.asarray(z, dtype=float) / (cos_beta_b * cos_beta_b * cos_beta))


def chordal_thickness(d_n, s_n):
    """Chordal tooth thickness on the (virtual) reference circle, s̄_n = d_n sin(s_n / d_n), mm
    (ISO 21771:2007 §5.5; KHK/SDP-SI Table 10-1 with d_n = z m).

    >>> round(chordal_thickness(120.0, 17.8918), 4)        # SDP/SI T-81 Table 10-1 (m 10, z 12, x 0.3): 17.8256
    17.8256
    """
    d_n = np.asarray(d_n, dtype=float)
    return _out(d_n * np.sin(np.asarray(s_n) / d_n))


def chordal_height(d_n, s_n, h_a, internal: bool = False, d_a=None, tip_half_angle=None):
    """Chordal height from the tip to the chord, mm: h̄ = h_a + (d_n/2)(1 − cos(s_n/d_n)) for an external gear
    (h_a = (d_a − d)/2; KHK/SDP-SI Table 10-1, ISO 21771:2007 §5.5). A ring's (h_a = (d − d_a)/2): the chord lies
    nearer its axis than the arc, and the caliper's flat tongue rests on the two corners of the concave tip, which
    lie (d_a/2)(1 − cos η_a) nearer the axis than the tip's middle (η_a the tooth's half-angle on the tip circle):
    h̄ = h_a − (d_n/2)(1 − cos(s_n/d_n)) + (d_a/2)(1 − cos η_a). 1 − cos is taken as 2 sin²(·/2) (no cancellation
    for large z).

    >>> round(chordal_height(120.0, 17.8918, 13.0), 4)     # SDP/SI T-81 Table 10-1: 13.6657
    13.6657
    """
    d_n = np.asarray(d_n, dtype=float)
    sag = d_n * np.sin(np.asarray(s_n) / (2.0 * d_n)) ** 2      # (d_n/2)(1 − cos ψ) = d_n sin²(ψ/2)
    if not internal:
        return _out(np.asarray(h_a) + sag)
    corners = 0.0 if d_a is None else np.asarray(d_a) * np.sin(np.asarray(tip_half_angle) / 2.0) ** 2
    return _out(np.asarray(h_a) - sag + corners)
