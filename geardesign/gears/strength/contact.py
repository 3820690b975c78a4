"""ISO 6336-2:2019 surface durability (pitting): the zone, elasticity, contact ratio, helix angle and single
pair factors, the contact stress, the influence factors of the permissible stress and the safety factor.
Functions take numbers or numpy arrays (broadcast); stresses in MPa, lengths in mm, angles in degrees at the
interface."""
from __future__ import annotations

import math


from .ops import ops_of

__all__ = [
    "zone_factor", "zone_factor_of", "elasticity_factor", "contact_ratio_factor", "helix_angle_factor",
    "single_pair_factors", "single_pair_factors_of",
    "nominal_contact_stress", "contact_stress", "lubricant_factor", "velocity_factor", "roughness_factor",
    "work_hardening_factor", "SIZE_FACTOR_Z_X", "contact_stress_limit", "contact_safety", "relative_radius",
]

SIZE_FACTOR_Z_X = 1.0   # ISO 6336-2:2019 clause 14: Z_X = 1 unless experience says otherwise


def zone_factor(beta_b_deg, alpha_t_deg, alpha_wt_deg):
    """Z_H = √(2 cos β_b cos α_wt / (cos² α_t sin α_wt)) at the operating transverse pressure angle α_wt
    (ISO 6336-2:2019 eq. (8)).

    >>> round(float(zone_factor(0, 20, 20)), 4)                 # standard spur pair: 2.4946
    2.4946
    """
    xp = ops_of(beta_b_deg, alpha_t_deg, alpha_wt_deg)
    bb, at, awt = xp.radians(beta_b_deg), xp.radians(alpha_t_deg), xp.radians(alpha_wt_deg)
    return zone_factor_of(xp.cos(bb), xp.cos(at), xp.cos(awt), xp.sin(awt))


def zone_factor_of(cos_beta_b, cos_alpha_t, cos_alpha_wt, sin_alpha_wt):
    """:func:`zone_factor` from the cosines and the sine (the factor chain has cos α_wt = d_b1/d_w1 from the
    geometry: numpy's sin and cos are ~5x slower than a division and a square root).

    >>> round(float(zone_factor_of(1.0, 0.9396926, 0.9396926, 0.3420201)), 4)
    2.4946
    """
    return ops_of(cos_alpha_wt, sin_alpha_wt).sqrt(2.0 * cos_beta_b * cos_alpha_wt / (cos_alpha_t ** 2 * sin_alpha_wt))


def elasticity_factor(E1_mpa, nu1, E2_mpa, nu2):
    """Z_E = √(1 / (π[(1 − ν1²)/E1 + (1 − ν2²)/E2])) in √MPa (ISO 6336-2:2019 eq. (11)).

    >>> round(float(elasticity_factor(206000, 0.3, 206000, 0.3)), 4)   # steel on steel: 189.8 (ISO/TR 6336-30: 189.8117)
    189.8117
    """
    xp = ops_of(E1_mpa, nu1, E2_mpa, nu2)
    return xp.sqrt(1.0 / (math.pi * ((1.0 - xp.asarray(nu1) ** 2) / E1_mpa + (1.0 - xp.asarray(nu2) ** 2) / E2_mpa)))


def contact_ratio_factor(eps_alpha, eps_beta):
    """Z_ε (ISO 6336-2:2019 eq. (12)-(14)): spur √((4 − ε_α)/3); helical with ε_β < 1
    √((4 − ε_α)(1 − ε_β)/3 + ε_β/ε_α); ε_β ≥ 1: √(1/ε_α).

    >>> round(float(contact_ratio_factor(1.54908, 1.0835)), 4)          # ISO/TR 6336-30 ex. 1: 0.803
    0.8035
    """
    xp = ops_of(eps_alpha, eps_beta)
    ea = xp.asarray(eps_alpha)
    eb = xp.minimum(xp.asarray(eps_beta), 1.0)
    return xp.sqrt((4.0 - ea) * (1.0 - eb) / 3.0 + eb / ea)


def helix_angle_factor(beta_deg):
    """Z_β = 1/√(cos β) (ISO 6336-2:2019 eq. (15); the 2006 edition had √(cos β)).

    >>> round(float(helix_angle_factor(15.8)), 5)                       # ISO/TR 6336-30 ex. 1: 1.01944
    1.01944
    """
    xp = ops_of(beta_deg)
    return 1.0 / xp.sqrt(xp.cos(xp.radians(beta_deg)))


def relative_radius(rho1, rho2, internal=False):
    """ρ_red = ρ1ρ2/(ρ2 ± ρ1) of two flanks in contact (+ external, − internal: the ring's flank is concave)."""
    return rho1 * rho2 / (rho2 - rho1 if internal else rho2 + rho1)


def single_pair_factors(db1, db2, da1, da2, alpha_wt_deg, a_w, eps_alpha, eps_beta, p_bt, internal=False, u=None):
    """(Z_B, Z_D): the single pair tooth contact factors that carry σ_H from the pitch point C to the inner
    points of single pair contact B (pinion) and D (wheel) (ISO 6336-2:2019 clause 6, eq. (9), (10)):
    M1 = √(ρ_C1 ρ_C2/(ρ_B1 ρ_B2)), M2 = √(ρ_C1 ρ_C2/(ρ_D1 ρ_D2)) with the radii of curvature on the line of
    action (the standard's tan-form written with radii, valid for internal pairs too). Spur: Z = M when M > 1
    else 1; ε_β ≥ 1: 1; 0 < ε_β < 1: Z = M − ε_β(M − 1), not below 1. Z_D = 1 for internal gears and for u > 1.5
    (ISO 6336-2:2019 6.1: M2 < 1 there), the rule on the gear ratio u = z2/z1, not on the tooth counts.

    >>> [round(float(z), 4) for z in single_pair_factors(42.28617, 84.57234, 50, 95, 20, 67.5, 1.611106, 0, 7.380329)]
    [1.0772, 1.0]
    """
    xp = ops_of(db1, db2, da1, da2, alpha_wt_deg, a_w, eps_beta, p_bt)
    awt = xp.radians(alpha_wt_deg)
    return single_pair_factors_of(db1, db2, da1, da2, xp.sin(awt), xp.tan(awt), a_w, eps_alpha, eps_beta, p_bt,
                                  internal, u)


def single_pair_factors_of(db1, db2, da1, da2, sin_alpha_wt, tan_alpha_wt, a_w, eps_alpha, eps_beta, p_bt,
                           internal=False, u=None):
    """:func:`single_pair_factors` from sin α_wt and tan α_wt (the factor chain's, from cos α_wt = d_b1/d_w1)."""
    xp = ops_of(db1, db2, da1, da2, sin_alpha_wt, a_w, eps_beta, p_bt)
    db1, db2, da1, da2 = xp.asarray(db1), xp.asarray(db2), xp.asarray(da1), xp.asarray(da2)
    T1T2 = xp.asarray(a_w) * sin_alpha_wt
    rc1 = db1 / 2.0 * tan_alpha_wt
    rc2 = T1T2 + rc1 if internal else T1T2 - rc1
    ra1 = xp.sqrt((da1 / 2.0) ** 2 - (db1 / 2.0) ** 2)   # pinion tip on the line of action
    rb1 = ra1 - p_bt                                       # point B: one base pitch inside
    rb2 = T1T2 + rb1 if internal else T1T2 - rb1
    rc12 = rc1 * rc2
    M1 = xp.sqrt(rc12 / (rb1 * rb2))
    eb = xp.minimum(xp.asarray(eps_beta), 1.0)
    Z_B = xp.maximum(M1 - eb * (M1 - 1.0), 1.0)
    u = db2 / db1 if u is None else u   # give u = z2/z1: exact at the rule's 1.5
    if internal or xp.all(u > 1.5):     # Z_D = 1 there: M2 is not needed (nor its square root)
        return Z_B, xp.like(Z_B, 1.0)
    ra2 = xp.sqrt((da2 / 2.0) ** 2 - (db2 / 2.0) ** 2)
    rd2 = ra2 - p_bt
    rd1 = T1T2 - rd2
    M2 = xp.sqrt(rc12 / (rd1 * rd2))
    Z_D = xp.maximum(M2 - eb * (M2 - 1.0), 1.0)
    return Z_B, xp.where(u > 1.5, 1.0, Z_D)


def nominal_contact_stress(F_t, d1, b, u, Z_H, Z_E, Z_eps, Z_beta, internal=False):
    """σ_H0 = Z_H Z_E Z_ε Z_β √(F_t/(d1 b)·(u ± 1)/u) in MPa at the pitch point (ISO 6336-2:2019 eq. (4));
    u = z2/z1 > 0, minus for an internal pair (ISO's negative u). b is the common face width.

    >>> round(float(nominal_contact_stress(127352.4, 141.3401, 100.0, 103/17, 2.39533, 189.8117, 0.80346, 1.01944)), 1)
    1206.6
    """
    xp = ops_of(F_t, d1, b, u)
    uu = xp.asarray(u)
    ratio = (uu - 1.0) / uu if internal else (uu + 1.0) / uu
    return Z_H * Z_E * Z_eps * Z_beta * xp.sqrt(xp.asarray(F_t) / (xp.asarray(d1) * b) * ratio)


def contact_stress(sigma_H0, Z_BD, K_A, K_gamma, K_v, K_Hbeta, K_Halpha):
    """σ_H = Z_B (or Z_D)·σ_H0·√(K_A K_γ K_v K_Hβ K_Hα) in MPa (ISO 6336-2:2019 eq. (2), (3)).

    >>> round(float(contact_stress(1206.58207, 1.0, 1.0, 1.0, 1.003, 1.16, 1.0)), 2)   # TR 6336-30: 1301.35 (K_v rounded)
    1301.48
    """
    xp = ops_of(sigma_H0, K_A, K_gamma, K_v, K_Hbeta, K_Halpha)
    return Z_BD * xp.asarray(sigma_H0) * xp.sqrt(K_A * K_gamma * xp.asarray(K_v) * K_Hbeta * K_Halpha)


def _c_zl(sigma_Hlim):
    """C_ZL (ISO 6336-2:2019 eq. (22)-(24)): 0.83 below 850 MPa, 0.91 above 1200, σ_Hlim/4375 + 0.6357 between."""
    xp = ops_of(sigma_Hlim)
    s = xp.asarray(sigma_Hlim)
    return xp.where(s < 850.0, 0.83, xp.where(s > 1200.0, 0.91, s / 4375.0 + 0.6357))


def lubricant_factor(nu40_mm2_s, sigma_Hlim_mpa):
    """Z_L = C_ZL + 4(1 − C_ZL)/(1.2 + 134/ν40)² (ISO 6336-2:2019 eq. (21)), ν40 the lubricant's kinematic
    viscosity at 40 °C in mm²/s.

    >>> round(float(lubricant_factor(320, 1500)), 5)                    # ISO/TR 6336-30 ex. 1: 1.04739
    1.04739
    """
    c = _c_zl(sigma_Hlim_mpa)
    return c + 4.0 * (1.0 - c) / (1.2 + 134.0 / ops_of(nu40_mm2_s).asarray(nu40_mm2_s)) ** 2


def velocity_factor(v_m_s, sigma_Hlim_mpa):
    """Z_v = C_Zv + 2(1 − C_Zv)/√(0.8 + 32/v), C_Zv = C_ZL + 0.02 (ISO 6336-2:2019 eq. (25), (26)); v the
    pitch-line velocity in m/s.

    >>> round(float(velocity_factor(2.6642, 1500)), 5)                  # ISO/TR 6336-30 ex. 1: 0.96911
    0.96911
    """
    c = _c_zl(sigma_Hlim_mpa) + 0.02
    xp = ops_of(v_m_s, c)
    v = xp.asarray(v_m_s)
    # 1/√(0.8 + 32/v) written as √(v/(0.8v + 32)): the same value, and a standing gear (v = 0, e.g. a subnormal
    # speed) gives Z_v = C_Zv without dividing by zero
    return c + 2.0 * (1.0 - c) * xp.sqrt(v / (0.8 * v + 32.0))


def roughness_factor(Rz1_um, Rz2_um, rho_red_mm, sigma_Hlim_mpa):
    """Z_R = (3/R_z10)^C_ZR, R_z10 = R_z·(10/ρ_red)^(1/3), R_z = (R_z1 + R_z2)/2 (ISO 6336-2:2019 eq. (27)-(29));
    C_ZR = 0.15 below 850 MPa, 0.32 − 0.0002 σ_Hlim to 1200, 0.08 above (eq. (30)-(32)).

    >>> round(float(roughness_factor(6.0, 6.0, 10.0, 1500)), 5)
    0.94606
    """
    xp = ops_of(Rz1_um, Rz2_um, rho_red_mm, sigma_Hlim_mpa)
    rz10 = (xp.asarray(Rz1_um) + Rz2_um) / 2.0 * xp.cbrt(10.0 / xp.asarray(rho_red_mm))
    s = xp.asarray(sigma_Hlim_mpa)
    c = xp.where(s < 850.0, 0.15, xp.where(s > 1200.0, 0.08, 0.32 - 0.0002 * s))
    return (3.0 / rz10) ** c


def work_hardening_factor(HB_softer, applies):
    """Z_W of the softer, through-hardened gear meshing a surface-hardened mate (ISO 6336-2:2006 clause 13,
    eq. (29)): 1.2 − (HB − 130)/1700, 1.2 below 130 HB, 1.0 above 470 HB; 1.0 where ``applies`` is False.
    (ISO 6336-2:2019 adds a roughness term for the hard flank; the 2006 form is used here.)

    >>> round(float(work_hardening_factor(300, True)), 12), float(work_hardening_factor(300, False))
    (1.1, 1.0)
    """
    xp = ops_of(HB_softer)
    hb = xp.clip(xp.asarray(HB_softer), 130.0, 470.0)
    return xp.where(applies, 1.2 - (hb - 130.0) / 1700.0, 1.0)


def contact_stress_limit(sigma_Hlim, Z_NT, Z_L, Z_v, Z_R, Z_W, Z_X=SIZE_FACTOR_Z_X):
    """σ_HG = σ_Hlim Z_NT Z_L Z_v Z_R Z_W Z_X in MPa, the pitting stress limit (ISO 6336-2:2019 eq. (6)); the
    permissible stress is σ_HP = σ_HG/S_Hmin (eq. (5)).

    >>> round(float(contact_stress_limit(1500, 0.91, 1.04739, 0.96911, 0.96599, 1.0)), 1)   # TR 6336-30: 1338.5
    1338.4
    """
    return ops_of(sigma_Hlim).asarray(sigma_Hlim) * Z_NT * Z_L * Z_v * Z_R * Z_W * Z_X


def contact_safety(sigma_HG, sigma_H):
    """S_H = σ_HG/σ_H with σ_HG = σ_Hlim·Z_NT·Z_L·Z_v·Z_R·Z_W·Z_X (ISO 6336-2:2019 eq. (1)): the limit carries
    σ_Hlim.

    >>> round(float(contact_safety(1338.48, 1301.35)), 4)               # ISO/TR 6336-30 ex. 1: 1.02853
    1.0285
    """
    return ops_of(sigma_HG).asarray(sigma_HG) / sigma_H
