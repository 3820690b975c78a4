"""Independent 50-digit reference of external spur-pair geometry (mpmath), for the tests.

Written from the textbook formulas (ISO 21771:2007; GOST 16532-70, table 1), deliberately
*not* from geardesign's code: plain forms such as tan α − α, a·cos α / cos α_w,
√(r_a² − r_b²) and arccos(d_b/d_y) are used as printed, because at 50 digits their
cancellation costs nothing. The inputs are the same IEEE doubles the library sees
(``mp.mpf(float)`` is exact), and the pressure angle is the double ``math.radians(alpha_deg)``
the library works with, so any difference is the library's own rounding.

Lengths in the unit of the module (mm), angles in degrees for the ``*_deg`` fields.
"""
from __future__ import annotations

import math

import mpmath as mp

mp.mp.dps = 50

__all__ = ["inv", "inv_inverse", "pair_reference", "FIELD_SCALE", "field_scale"]


def inv(alpha):
    """inv α = tan α − α (α in radians, any mpmath-convertible number)."""
    alpha = mp.mpf(alpha)
    return mp.tan(alpha) - alpha


def inv_inverse(v):
    """The α in (0, π/2) with tan α − α = v (v > 0), by mpmath findroot on t = tan α.

    The start comes from a float Newton iteration of our own; findroot then polishes to
    50 digits and the residual is checked.
    """
    v = mp.mpf(v)
    if not v > 0:
        raise ValueError(f"inv_inverse needs v > 0, got {v}")
    fv = float(v)
    # float start: series inverse s(1 + s²/5), s = (3v)^(1/3), for small v; asymptote for large v
    s = (3.0 * fv) ** (1.0 / 3.0)
    t = s * (1.0 + s * s / 5.0) if fv < 0.5 else fv + math.pi / 2 - 1.0 / (fv + math.pi / 2)
    for _ in range(6):
        t = t - (t - math.atan(t) - fv) * (1.0 + t * t) / (t * t)
    # t − atan t cancels ~log10(1/t²) digits at small t: work with 20 guard digits
    with mp.workdps(mp.mp.dps + 20):
        t = mp.findroot(lambda tt: tt - mp.atan(tt) - v, mp.mpf(t))
        assert abs((t - mp.atan(t)) - v) <= v * mp.mpf(10) ** (-mp.mp.dps + 25), "inv_inverse did not converge"
        alpha = mp.atan(t)
    return +alpha


def _tip_thickness(d_y, d_b, psi):
    """Tooth thickness on the circle d_y: s_y = d_y (s/d + inv α − inv α_y), cos α_y = d_b/d_y."""
    alpha_y = mp.acos(d_b / d_y)
    return d_y * (psi - inv(alpha_y)), alpha_y


def pair_reference(m, z1, z2, x1, x2, alpha_deg=20.0, ha=1.0, c=0.25, rho_f=0.38, tip_shortening=True,
                   beta_deg=0.0, face_width_mm=None, internal=False):
    """All geometry fields of one pair as mpmath numbers, or None if the geometry does not exist.

    Returns ``(fields, reason)``: ``fields`` is a dict keyed like
    ``geardesign.GEOMETRY_FIELDS`` (None when the design does not exist) and ``reason`` a
    string saying why not ("inv_alpha_w <= 0", "tip1 inside base circle", "d_f2 <= 0", ...).

    Helical pairs (ISO 21771:2007 §4–5): ``m`` is the normal module, x1/x2 normal shift
    coefficients, the rack is given in the normal section; the circles, angles, thicknesses and the
    path of contact are transverse (α_t = atan(tan α_n / cos β), m_t = m_n / cos β); heights are in
    m_n. β = 0 is the spur pair.

    Internal pairs (``internal=True``, gear 2 a ring of z2 > z1 teeth; GOST 19274-73 and KHK's
    convention: a positive x2 moves the ring's flanks away from its axis): inv α_w = inv α +
    2 (x2 − x1) tan α / (z2 − z1), a = m (z2 − z1)/2, d_a2 = d2 − 2 m (h_a* − x2), d_f2 = d2 +
    2 m (h_a* + c* + x2), s2 = m (π/2 − 2 x2 tan α), the path of contact
    g_α = ρ_a1 − ρ_a2 + a_w sin α_w; no tip shortening.
    """
    if internal:
        return _internal_reference(m, z1, z2, x1, x2, alpha_deg, ha, c, rho_f, beta_deg, face_width_mm)
    m, z1, z2, x1, x2 = (mp.mpf(float(v)) for v in (m, z1, z2, x1, x2))
    ha, c, rho_f = mp.mpf(float(ha)), mp.mpf(float(c)), mp.mpf(float(rho_f))
    alpha = mp.mpf(math.radians(float(alpha_deg)))   # the same double the library uses
    beta = mp.mpf(math.radians(float(beta_deg)))
    sin_a, tan_a = mp.sin(alpha), mp.tan(alpha)
    cos_b = mp.cos(beta)
    alpha_t = mp.atan(tan_a / cos_b)                  # ISO 21771 (13)
    m_t = m / cos_b                                   # ISO 21771 (11)
    sin_t, cos_t = mp.sin(alpha_t), mp.cos(alpha_t)
    beta_b = mp.atan(mp.tan(beta) * cos_t)            # ISO 21771 (17)

    inv_t = inv(alpha_t)
    inv_aw = inv_t + 2 * (x1 + x2) * tan_a / (z1 + z2)
    if inv_aw <= 0:
        return None, "inv_alpha_w <= 0"
    alpha_w = inv_inverse(inv_aw)
    cos_w, sin_w = mp.cos(alpha_w), mp.sin(alpha_w)

    a = m_t * (z1 + z2) / 2
    a_w = a * cos_t / cos_w
    y = (a_w - a) / m
    dy = x1 + x2 - y
    k = dy if tip_shortening else mp.mpf(0)

    d1, d2 = m_t * z1, m_t * z2
    db1, db2 = d1 * cos_t, d2 * cos_t
    dw1, dw2 = d1 * cos_t / cos_w, d2 * cos_t / cos_w
    da1 = d1 + 2 * m * (ha + x1 - k)
    da2 = d2 + 2 * m * (ha + x2 - k)
    df1 = d1 - 2 * m * (ha + c - x1)
    df2 = d2 - 2 * m * (ha + c - x2)
    if da1 <= db1:
        return None, "tip1 inside base circle"
    if da2 <= db2:
        return None, "tip2 inside base circle"
    if df1 <= 0:
        return None, "d_f1 <= 0"
    if df2 <= 0:
        return None, "d_f2 <= 0"

    s1 = m_t * (mp.pi / 2 + 2 * x1 * tan_a)           # transverse, on the reference circle
    s2 = m_t * (mp.pi / 2 + 2 * x2 * tan_a)
    psi1 = s1 / d1 + inv_t
    psi2 = s2 / d2 + inv_t
    sw1, _ = _tip_thickness(dw1, db1, psi1)
    sw2, _ = _tip_thickness(dw2, db2, psi2)
    sa1, alpha_a1 = _tip_thickness(da1, db1, psi1)
    sa2, alpha_a2 = _tip_thickness(da2, db2, psi2)

    rb1, rb2, ra1, ra2 = db1 / 2, db2 / 2, da1 / 2, da2 / 2
    rf1, rf2 = df1 / 2, df2 / 2
    rho_a1 = mp.sqrt(ra1 ** 2 - rb1 ** 2)
    rho_a2 = mp.sqrt(ra2 ** 2 - rb2 ** 2)
    n1n2 = a_w * sin_w
    p_b = mp.pi * m_t * cos_t
    g_alpha = rho_a1 + rho_a2 - n1n2
    rho_p1 = n1n2 - rho_a2
    rho_p2 = n1n2 - rho_a1

    # the straight flank of the rack ends h_l·m above its tip line; in the transverse section its
    # generating line of action leans at α_t from the pitch line, the reference radius is z m_t / 2
    h_l = ha + c - rho_f * (1 - sin_a)
    x_min1 = h_l - z1 * sin_t ** 2 / (2 * cos_b)
    x_min2 = h_l - z2 * sin_t ** 2 / (2 * cos_b)
    rho_l1 = m * (x1 - x_min1) / sin_t
    rho_l2 = m * (x2 - x_min2) / sin_t

    u = z2 / z1
    rw1, rw2 = dw1 / 2, dw2 / 2
    rho_w1, rho_w2 = rw1 * sin_w, rw2 * sin_w
    eps_alpha = g_alpha / p_b
    # ε_β = b sin β / (π m_n) (ISO 21771 (83)); without a face width it is unknown, except for spur
    # pairs, where it is 0 whatever b is
    if face_width_mm is None:
        eps_beta = mp.mpf(0) if beta == 0 else mp.nan
    else:
        eps_beta = mp.mpf(float(face_width_mm)) * mp.sin(beta) / (mp.pi * m)

    out = {
        "alpha_w_deg": mp.degrees(alpha_w),
        "inv_alpha_w": inv_aw,
        "a": a, "a_w": a_w, "y": y, "dy": dy,
        "d1": d1, "d2": d2, "db1": db1, "db2": db2, "dw1": dw1, "dw2": dw2,
        "da1": da1, "da2": da2, "df1": df1, "df2": df2,
        "s1": s1, "s2": s2, "sw1": sw1, "sw2": sw2, "sa1": sa1, "sa2": sa2,
        "p_b": p_b, "p_w": mp.pi * dw1 / z1,
        "g_alpha": g_alpha, "eps_alpha": eps_alpha,
        "alpha_a1_deg": mp.degrees(alpha_a1), "alpha_a2_deg": mp.degrees(alpha_a2),
        "clearance1": a_w - ra1 - rf2, "clearance2": a_w - ra2 - rf1,
        "x_min1": x_min1, "x_min2": x_min2,
        "rho_l1": rho_l1, "rho_l2": rho_l2, "rho_p1": rho_p1, "rho_p2": rho_p2,
        # limit circle: on the involute at ρ_l, or the base circle if undercut
        "d_l1": 2 * mp.sqrt(rb1 ** 2 + max(rho_l1, 0) ** 2),
        "d_l2": 2 * mp.sqrt(rb2 ** 2 + max(rho_l2, 0) ** 2),
        "d_p1": 2 * mp.sqrt(rb1 ** 2 + rho_p1 ** 2),
        "d_p2": 2 * mp.sqrt(rb2 ** 2 + rho_p2 ** 2),
        "o2n1": mp.sqrt(rb2 ** 2 + n1n2 ** 2), "o1n2": mp.sqrt(rb1 ** 2 + n1n2 ** 2),
        # specific sliding ϑ1 = 1 − ρ2/(u ρ1), ϑ2 = 1 − u ρ1/ρ2 at both ends of the path of contact:
        # at gear 1's root ρ1 = ρ_p1, ρ2 = ρ_a2; at gear 1's tip ρ1 = ρ_a1, ρ2 = ρ_p2
        "sliding1_root": 1 - rho_a2 / (u * rho_p1),
        "sliding2_tip": 1 - u * rho_p1 / rho_a2,
        "sliding1_tip": 1 - rho_p2 / (u * rho_a1),
        "sliding2_root": 1 - u * rho_a1 / rho_p2,
        # in the normal section the radii of curvature are ρ_t / cos β_b
        "spec_pressure_pitch": m * mp.cos(beta_b) * (rho_w1 + rho_w2) / (rho_w1 * rho_w2),
        "alpha_t_deg": mp.degrees(alpha_t), "beta_b_deg": mp.degrees(beta_b), "m_t": m_t,
        "z_n1": z1 / (mp.cos(beta_b) ** 2 * cos_b), "z_n2": z2 / (mp.cos(beta_b) ** 2 * cos_b),
        "eps_beta": eps_beta, "eps_gamma": eps_alpha + eps_beta,
        # normal tip thickness on the tip cylinder: s_an = s_at cos β_a, tan β_a = tan β d_a / d
        "san1": sa1 * mp.cos(mp.atan(mp.tan(beta) * da1 / d1)),
        "san2": sa2 * mp.cos(mp.atan(mp.tan(beta) * da2 / d2)),
    }
    return out, ""


def _internal_reference(m, z1, z2, x1, x2, alpha_deg, ha, c, rho_f, beta_deg, face_width_mm):
    """The internal pair, written out on its own (see :func:`pair_reference`)."""
    m, z1, z2, x1, x2 = (mp.mpf(float(v)) for v in (m, z1, z2, x1, x2))
    ha, c, rho_f = mp.mpf(float(ha)), mp.mpf(float(c)), mp.mpf(float(rho_f))
    alpha = mp.mpf(math.radians(float(alpha_deg)))
    beta = mp.mpf(math.radians(float(beta_deg)))
    cos_b = mp.cos(beta)
    alpha_t = mp.atan(mp.tan(alpha) / cos_b)
    m_t = m / cos_b
    sin_t, cos_t = mp.sin(alpha_t), mp.cos(alpha_t)
    beta_b = mp.atan(mp.tan(beta) * cos_t)
    inv_t = inv(alpha_t)
    inv_aw = inv_t + 2 * (x2 - x1) * mp.tan(alpha) / (z2 - z1)
    if inv_aw <= 0:
        return None, "inv_alpha_w <= 0"
    alpha_w = inv_inverse(inv_aw)
    cos_w, sin_w = mp.cos(alpha_w), mp.sin(alpha_w)
    a = m_t * (z2 - z1) / 2
    a_w = a * cos_t / cos_w
    y = (a_w - a) / m
    d1, d2 = m_t * z1, m_t * z2
    db1, db2 = d1 * cos_t, d2 * cos_t
    dw1, dw2 = db1 / cos_w, db2 / cos_w
    da1 = d1 + 2 * m * (ha + x1)
    da2 = d2 - 2 * m * (ha - x2)
    df1 = d1 - 2 * m * (ha + c - x1)
    df2 = d2 + 2 * m * (ha + c + x2)
    if da1 <= db1:
        return None, "tip1 inside base circle"
    if da2 <= db2:
        return None, "tip2 inside base circle"
    if df1 <= 0:
        return None, "d_f1 <= 0"
    s1 = m_t * (mp.pi / 2 + 2 * x1 * mp.tan(alpha))
    s2 = m_t * (mp.pi / 2 - 2 * x2 * mp.tan(alpha))
    psi1 = s1 / d1 + inv_t
    psi2 = s2 / d2 - inv_t          # a ring tooth widens outward: s_y = d_y (s/d − inv α + inv α_y)
    alpha_a1, alpha_a2 = mp.acos(db1 / da1), mp.acos(db2 / da2)
    rb1, rb2, ra1, ra2 = db1 / 2, db2 / 2, da1 / 2, da2 / 2
    rho_a1, rho_a2 = mp.sqrt(ra1 ** 2 - rb1 ** 2), mp.sqrt(ra2 ** 2 - rb2 ** 2)
    n1n2 = a_w * sin_w
    p_b = mp.pi * m_t * cos_t
    g_alpha = rho_a1 - rho_a2 + n1n2
    rho_p1, rho_p2 = rho_a2 - n1n2, rho_a1 + n1n2      # the ring's radius of curvature is the pinion's + N1N2
    h_l = ha + c - rho_f * (1 - mp.sin(alpha))
    x_min1 = h_l - z1 * sin_t ** 2 / (2 * cos_b)
    rho_l1 = m * (x1 - x_min1) / sin_t
    rho_l2 = d2 / 2 * sin_t + (h_l + x2) * m / sin_t   # the counter-rack's flank end, outside the pitch line
    u = z2 / z1
    rho_w1, rho_w2 = dw1 / 2 * sin_w, dw2 / 2 * sin_w
    eps_alpha = g_alpha / p_b
    if face_width_mm is None:
        eps_beta = mp.mpf(0) if beta == 0 else mp.nan
    else:
        eps_beta = mp.mpf(float(face_width_mm)) * mp.sin(beta) / (mp.pi * m)
    sa1 = da1 * (psi1 - inv(alpha_a1))
    sa2 = da2 * (psi2 + inv(alpha_a2))
    out = {
        "alpha_w_deg": mp.degrees(alpha_w), "inv_alpha_w": inv_aw, "a": a, "a_w": a_w, "y": y,
        "dy": x2 - x1 - y, "d1": d1, "d2": d2, "db1": db1, "db2": db2, "dw1": dw1, "dw2": dw2,
        "da1": da1, "da2": da2, "df1": df1, "df2": df2, "s1": s1, "s2": s2,
        "sw1": dw1 * (psi1 - inv_aw), "sw2": dw2 * (psi2 + inv_aw), "sa1": sa1, "sa2": sa2,
        "p_b": p_b, "p_w": mp.pi * dw1 / z1, "g_alpha": g_alpha, "eps_alpha": eps_alpha,
        "alpha_a1_deg": mp.degrees(alpha_a1), "alpha_a2_deg": mp.degrees(alpha_a2),
        "clearance1": df2 / 2 - a_w - ra1, "clearance2": ra2 - a_w - df1 / 2,
        "x_min1": x_min1, "x_min2": mp.nan, "rho_l1": rho_l1, "rho_l2": rho_l2, "rho_p1": rho_p1, "rho_p2": rho_p2,
        "d_l1": 2 * mp.sqrt(rb1 ** 2 + max(rho_l1, 0) ** 2), "d_l2": 2 * mp.sqrt(rb2 ** 2 + rho_l2 ** 2),
        "d_p1": 2 * mp.sqrt(rb1 ** 2 + rho_p1 ** 2), "d_p2": 2 * mp.sqrt(rb2 ** 2 + rho_p2 ** 2),
        "o2n1": mp.sqrt(rb2 ** 2 + n1n2 ** 2), "o1n2": mp.sqrt(rb1 ** 2 + n1n2 ** 2),
        "sliding1_root": 1 - rho_a2 / (u * rho_p1), "sliding2_tip": 1 - u * rho_p1 / rho_a2,
        "sliding1_tip": 1 - rho_p2 / (u * rho_a1), "sliding2_root": 1 - u * rho_a1 / rho_p2,
        "spec_pressure_pitch": m * mp.cos(beta_b) * (1 / rho_w1 - 1 / rho_w2),
        "alpha_t_deg": mp.degrees(alpha_t), "beta_b_deg": mp.degrees(beta_b), "m_t": m_t,
        "z_n1": z1 / (mp.cos(beta_b) ** 2 * cos_b), "z_n2": z2 / (mp.cos(beta_b) ** 2 * cos_b),
        "eps_beta": eps_beta, "eps_gamma": eps_alpha + eps_beta,
        "san1": sa1 * mp.cos(mp.atan(mp.tan(beta) * da1 / d1)), "san2": sa2 * mp.cos(mp.atan(mp.tan(beta) * da2 / d2)),
    }
    return out, ""


# Natural scale of each field, in units of the module (lengths) or absolute (angles,
# coefficients): the tolerance is 1e-12 · max(|reference|, scale), i.e. relative 1e-12
# except where the value itself is near zero.
FIELD_SCALE: dict[str, str] = {
    "alpha_w_deg": "alpha_deg",     # α_w compares with α
    "inv_alpha_w": "inv_alpha",     # inv α_w = inv α + 2 x_Σ tan α / z_Σ
    "y": "1", "dy": "1", "x_min1": "1", "x_min2": "1",
    "eps_alpha": "1",
    "sliding1_root": "1", "sliding1_tip": "1", "sliding2_root": "1", "sliding2_tip": "1",
    "spec_pressure_pitch": "0",
    "alpha_a1_deg": "0", "alpha_a2_deg": "0",
}


def field_scale(name: str, m: float, alpha_deg: float) -> float:
    """The absolute scale below which a field counts as 'near zero' (see FIELD_SCALE)."""
    kind = FIELD_SCALE.get(name, "m")
    if kind == "m":
        return float(m)
    if kind == "alpha_deg":
        return float(alpha_deg)
    if kind == "inv_alpha":
        return float(inv(math.radians(alpha_deg)))
    return float(kind)
