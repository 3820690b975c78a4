"""The worm gear rating of ANSI/AGMA 6034-B92 as Budynas & Nisbett, *Shigley's Mechanical Engineering Design*
(ch. 15, §15-6 … §15-8, "Worm Gearing — AGMA Equation") print it: the allowable tangential load of the wheel
W_t,all = C_s·D_m^0.8·F_e·C_m·C_v with its materials, ratio and velocity factors, the friction force and the power
it takes, the heat loss, the oil sump temperature with Shigley's cooling coefficient and AGMA's smallest housing
area; and the allowable output torque of a worm pair at a speed (the load a given worm carries).

The book's formulas are in US units (inches, lbf, ft/min, hp, °F): every function here takes and returns the
project's units (mm, N, N·m, rpm, m/s, W, °C, W/(m²·K), m²) and converts inside. Equation numbers are those of
the Shigley edition restated in the course notes cited in ``tests/data/worm_agma_examples.md`` (the book itself
was not read); the tests reproduce its Example 15-4 (a 10 hp, 11:1 double-threaded worm on a sand-cast wheel) to
the printed digits.

What the method covers: a case-hardened alloy-steel worm against a bronze wheel (tin, nickel, lead, aluminium
or silicon bronze) cast in sand, in a static chill mould or centrifugally; Shigley: with these factors "lives
in excess of 25 000 h" result, and the friction curve is that of the same pair
(:func:`~geardesign.gears.worm.efficiency.friction_coefficient_agma`). It is not ISO/TS 14521 (whose wear,
pitting and oil-temperature methods could not be read: docs/worm_rating.md).
"""
from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np

from ...errors import GearDesignError
from ...validate import require_choice, require_positive, require_range
from .efficiency import FT_MIN_PER_M_S, efficiency_worm_driving, friction_coefficient_agma, sliding_speed

__all__ = ["MM_PER_IN", "N_PER_LBF", "CASTINGS", "HCR_SI_PER_US", "materials_factor", "ratio_correction_factor",
           "velocity_factor", "effective_face_width", "allowable_tangential_load", "friction_force",
           "friction_power", "heat_loss", "heat_transfer_coefficient_agma", "housing_area_min_agma",
           "design_tangential_load", "agma_capacity", "CAPACITY_FIELDS", "agma_load_float", "LOAD_FIELDS"]

MM_PER_IN = 25.4
N_PER_LBF = 4.4482216152605            # 1 lbf (avoirdupois pound-force, g_n = 9.80665 m/s²)
W_PER_FT_LBF_MIN = 0.3048 * N_PER_LBF / 60.0
# Shigley's cooling coefficient h_CR is in ft·lbf/(min·in²·°F): 1 of it is this many W/(m²·K)
HCR_SI_PER_US = W_PER_FT_LBF_MIN / ((MM_PER_IN / 1000.0) ** 2 * 5.0 / 9.0)
# the wheel's casting method of AGMA's materials factor C_s (Shigley: "sand-cast, chilled-cast, and centrifugally
# cast ... increases in the same order")
CASTINGS = ("sand", "chill", "centrifugal")
# (D_m in inches up to which C_s = 1000, the constant and the slope of C_s = A − B·log10 D_m beyond)
_CASTING_FACTORS = {"sand": (2.5, 1190.0, 477.0), "chill": (8.0, 1412.0, 456.0), "centrifugal": (25.0, 1251.0, 180.0)}
_CM_U_MAX = 1.1483 / 0.00658           # the third branch of C_m reaches 0 at m_G = 174.5
# the factors' formulas are written once (``_materials``, ``_ratio``, ``_velocity``) and run on arrays (numpy)
# or on one design's floats: numpy's per-call cost on 0-d arrays is ~1 µs a function, and one pair's AGMA row
# took some thirty of them. The float path keeps numpy's exp and log10 (on a float, ~0.5 µs each): the C
# library's differ from them by an ulp now and then, and C_s = A − B·log10 D cancels towards 0 for large wheels
# (5e-14 seen); with them, and u·u for numpy's u**2 (its square), the two paths agree to the bit.
_NP = SimpleNamespace(where=np.where, log10=np.log10, sqrt=np.sqrt, exp=np.exp, maximum=np.maximum,
                      square=lambda x: x ** 2)
_MATH = SimpleNamespace(where=lambda cond, yes, no: yes if cond else no, log10=lambda x: float(np.log10(x)),
                        sqrt=math.sqrt, exp=lambda x: float(np.exp(x)), maximum=max, square=lambda x: x * x)


def _casting(casting):
    return require_choice("casting", casting, CASTINGS)


def materials_factor(a, d_2, casting="sand"):
    """AGMA materials factor C_s of a bronze wheel (in the book's units, lbf/in^1.8) from the centre distance
    ``a`` and the wheel's mean diameter ``d_2`` (mm), by the casting method (Shigley ch. 15, Eqs. (15-32) …
    (15-35) as restated): with C = a and D_m = d_2 in inches,

    * C <= 3 in: C_s = 720 + 10.37·C³;
    * sand-cast: 1000 for D_m <= 2.5 in, else 1190 − 477·log10 D_m;
    * static chill cast: 1000 for D_m <= 8 in, else 1412 − 456·log10 D_m;
    * centrifugally cast: 1000 for D_m <= 25 in, else 1251 − 180·log10 D_m.

    Example 15-4 (sand-cast, D = 10.504 in, C = 6.502 in) prints C_s = 702.8:

    >>> round(float(materials_factor(6.502 * 25.4, 10.504 * 25.4, "sand")), 1)
    702.8
    """
    kind = _casting(casting)
    C = require_positive("a (center distance)", a, unit="mm") / MM_PER_IN
    D = require_positive("d_2", d_2, unit="mm") / MM_PER_IN
    return _materials(_NP, C, D, kind)


def _materials(ops, C, D, kind):
    d_lim, A, B = _CASTING_FACTORS[kind]
    by_casting = ops.where(D <= d_lim, 1000.0, A - B * ops.log10(ops.maximum(D, d_lim)))
    return ops.where(C <= 3.0, 720.0 + 10.37 * C ** 3, by_casting)


def ratio_correction_factor(u):
    """AGMA ratio correction factor C_m from the gear ratio m_G = u (Shigley Eq. (15-36) as restated):
    0.02·√(−u² + 40u − 76) + 0.46 for 3 <= u <= 20; 0.0107·√(−u² + 56u + 5145) for 20 < u <= 76;
    1.1483 − 0.00658·u above. The book's range starts at u = 3; beyond u = 174.5 the last branch is not
    positive, so u outside [3, 174) is refused.

    Example 15-4 (u = 11) prints C_m = 0.772:

    >>> round(float(ratio_correction_factor(11.0)), 3)
    0.772
    """
    return _ratio(_NP, require_range("u (gear ratio)", u, 3.0, _CM_U_MAX, hi_open=True))


def _ratio(ops, u):
    # both radicands are >= 0 on their own branch; the maximum keeps the other branch's values real
    low = 0.02 * ops.sqrt(ops.maximum(-ops.square(u) + 40.0 * u - 76.0, 0.0)) + 0.46
    mid = 0.0107 * ops.sqrt(ops.maximum(-ops.square(u) + 56.0 * u + 5145.0, 0.0))
    return ops.where(u <= 20.0, low, ops.where(u <= 76.0, mid, 1.1483 - 0.00658 * u))


def velocity_factor(v_g):
    """AGMA velocity factor C_v from the sliding speed v_g (m/s; V_s in ft/min inside, Shigley Eq. (15-37) as
    restated): 0.659·exp(−0.0011·V_s) below 700 ft/min; 13.31·V_s^−0.571 from 700 to 3000; 65.52·V_s^−0.774
    above.

    Example 15-4 (V_s = 1205.1 ft/min) prints C_v = 0.232:

    >>> round(float(velocity_factor(1205.1 / (60 / 0.3048))), 3)
    0.232
    """
    return _velocity(_NP, require_range("v_g", v_g, 0.0, 100.0, lo_open=True, unit="m/s") * FT_MIN_PER_M_S)


def _velocity(ops, vs):
    return ops.where(vs < 700.0, 0.659 * ops.exp(-0.0011 * vs),
                     ops.where(vs < 3000.0, 13.31 * vs ** -0.571, 65.52 * vs ** -0.774))


def effective_face_width(b_2, d_m1):
    """Effective face width of the wheel F_e (mm): its face width, "but not to exceed 0.67 d_m", the worm's mean
    diameter (Shigley §15-6; Example 15-4 writes the bound as 2d/3).

    >>> float(effective_face_width(40.0, 50.0)), float(effective_face_width(30.0, 50.0))
    (33.5, 30.0)
    """
    b = require_positive("b_2", b_2, unit="mm")
    return np.minimum(b, 0.67 * require_positive("d_m1", d_m1, unit="mm"))


def allowable_tangential_load(C_s, d_2, F_e, C_m, C_v):
    """Allowable tangential load of the wheel W_t,all = C_s·D_m^0.8·F_e·C_m·C_v (N), ANSI/AGMA 6034-B92 as
    Shigley Eq. (15-28) prints it (lbf with D_m = d_2 and F_e in inches; converted here from mm and to N).

    Example 15-4: C_s 702.8, D = 10.504 in, F_e = 1.5 in, C_m 0.772, C_v 0.232 print W_t,all = 1239 lbf:

    >>> round(float(allowable_tangential_load(702.8, 10.504 * 25.4, 1.5 * 25.4, 0.772, 0.232)) / N_PER_LBF)
    1239
    """
    cs = require_positive("C_s", C_s)
    D = require_positive("d_2", d_2, unit="mm") / MM_PER_IN
    F = require_positive("F_e", F_e, unit="mm") / MM_PER_IN
    return cs * D ** 0.8 * F * require_positive("C_m", C_m) * require_positive("C_v", C_v) * N_PER_LBF


def _gamma_alpha(gamma_m_deg, alpha_n_deg):
    g = np.radians(require_range("gamma_m_deg", gamma_m_deg, 0.0, 45.0, lo_open=True, unit="deg"))
    a = np.radians(require_range("alpha_n_deg", alpha_n_deg, 0.0, 45.0, hi_open=True, unit="deg"))
    return g, a


def friction_force(F_t2, mu, gamma_m_deg, alpha_n_deg=20.0):
    """The friction force along the flanks |W_f| = μ·W_t2/|μ sin λ − cos φ_n cos λ| (N) of a wheel tangential
    force W_t2 = F_t2 (N), λ = γ_m the lead angle, φ_n = α_n (Shigley §15-6; the book prints the signed
    W_f = μW_t/(μ sin λ − cos φ_n cos λ), negative, Example 15-4: W_f = −26.8 lbf for 1222 lbf, μ = 0.0191,
    λ = 20.905°):

    >>> round(float(friction_force(1222.0, 0.0191, 20.905, 20.0)), 1)
    26.8
    """
    f = require_range("F_t2", F_t2, 0.0, 1e12, unit="N")
    m = require_range("mu", mu, 0.0, 1.0)
    g, a = _gamma_alpha(gamma_m_deg, alpha_n_deg)
    den = np.cos(a) * np.cos(g) - m * np.sin(g)
    if np.any(den <= 0.0):
        raise GearDesignError("mu·tan(gamma_m) must stay below cos(alpha_n): the friction locks the mesh")
    return m * f / den


def friction_power(W_f, v_g):
    """Power the friction takes, H_f = |W_f|·V_s (W; Shigley §15-6 writes |W_f|·V_s/33 000 hp): the friction
    force W_f (N) times the sliding speed v_g (m/s). Example 15-4: 26.8 lbf at 1205.1 ft/min is 0.979 hp:

    >>> round(float(friction_power(26.8 * N_PER_LBF, 1205.1 * 0.3048 / 60)) / 745.6999, 3)
    0.979
    """
    return require_range("W_f", W_f, 0.0, 1e12, unit="N") * require_range("v_g", v_g, 0.0, 100.0, unit="m/s")


def heat_loss(P_in, eta):
    """Heat the gearbox must shed, H_loss = (1 − e)·H_in (W) of the input power P_in (W) at efficiency η
    (Shigley §15-7: 33 000(1 − e)H_in ft·lbf/min). Example 15-4: H_in = 16.9 hp at e = 0.942 is 32 347 ft·lbf/min:

    >>> round(float(heat_loss(16.9 * 745.6999, 0.942)) / (0.3048 * N_PER_LBF / 60))
    32347
    """
    p = require_range("P_in", P_in, 0.0, 1e12, unit="W")
    return p * (1.0 - require_range("eta", eta, 0.0, 1.0, lo_open=True))


def heat_transfer_coefficient_agma(n1, fan=False):
    """Shigley's overall cooling coefficient of a worm gear case h̄_CR (W/(m²·K)) from the worm speed n1 (rpm):
    n1/6494 + 0.13 without a fan on the worm shaft, n1/3939 + 0.13 with one, in ft·lbf/(min·in²·°F) (Shigley
    Eq. (15-50) as restated), converted (1 ft·lbf/(min·in²·°F) = 63.05 W/(m²·K)). Example 15-4: 1720 rpm, no fan,
    h̄_CR = 0.395 in the book's units:

    >>> round(float(heat_transfer_coefficient_agma(1720.0)) / HCR_SI_PER_US, 3)
    0.395
    """
    n = require_positive("n1", n1, unit="rpm")
    if not isinstance(fan, (bool, np.bool_)):
        raise GearDesignError(f"fan must be True or False, got {fan!r}")
    return (n / (3939.0 if fan else 6494.0) + 0.13) * HCR_SI_PER_US


def housing_area_min_agma(a):
    """AGMA's smallest lateral area of a worm gear case, A_min = 43.20·C^1.7 in² (C = a in inches; Shigley
    Eq. (15-52) as restated), in m². Example 15-4: C = 6.502 in gives 1041.5 in²:

    >>> round(float(housing_area_min_agma(6.502 * 25.4)) / (25.4e-3) ** 2, 1)
    1041.5
    """
    C = require_positive("a (center distance)", a, unit="mm") / MM_PER_IN
    return 43.20 * C ** 1.7 * (MM_PER_IN / 1000.0) ** 2


def design_tangential_load(T2, d_2, eta, K_A=1.0):
    """The wheel's tangential load the AGMA rating compares with W_t,all: W_t = K_A·F_t2/η (N), F_t2 = 2000·T2/d_2
    the tangential force of the output torque T2 (N·m) on the wheel's reference diameter d_2 (mm), η the mesh
    efficiency (Shigley Eq. (15-58) as restated: W_t,G = 33 000·n_d·H_0·K_a/(V_G·e), the design factor n_d left
    to the required safety). Example 15-4: 10 hp at V_G = 430.0 ft/min, e = 0.942, K_a 1.25, n_d 1.2 gives 1222 lbf:

    >>> F_t2 = 10 * 33000 / 430.0 * N_PER_LBF          # the output power's tangential force, N
    >>> round(float(design_tangential_load(F_t2 * 200.0 / 2000, 200.0, 0.942, 1.25)) * 1.2 / N_PER_LBF)
    1222
    """
    t2 = require_range("T2", T2, 0.0, 1e9, unit="N·m")
    k = require_range("K_A", K_A, 1.0, 10.0)
    return k * 2000.0 * t2 / require_positive("d_2", d_2, unit="mm") / require_range("eta", eta, 0.0, 1.0,
                                                                                     lo_open=True)


# the quantities agma_capacity returns (arrays over the designs)
CAPACITY_FIELDS = ("v_g", "mu", "eta_z", "C_s", "C_m", "C_v", "F_e", "W_t_all", "T2_all")


def agma_capacity(geo: dict, n1, casting="sand", application_factor=1.0) -> dict:
    """The AGMA rating of worm pairs at worm speed ``n1`` (rpm), over arrays: ``geo`` a
    :func:`~geardesign.gears.worm.geometry.worm_geometry` dict (``a``, ``d_m1``, ``d_2``, ``b_2``, ``u``,
    ``gamma_m_deg``, ``alpha_n_deg``; broadcast with ``n1``). Returns :data:`CAPACITY_FIELDS`: the sliding
    speed, the AGMA friction μ and mesh efficiency η_z there, C_s, C_m, C_v, F_e (mm), W_t,all (N) and the
    allowable output torque T2_all = W_t,all·η_z·d_2/(2000·K_A) (N·m, K_A = ``application_factor``), the wheel
    torque at which :func:`design_tangential_load` reaches W_t,all (the load the pair carries at this speed for
    the lives Shigley quotes, over 25 000 h). The efficiency is the sliding-speed friction's; the torque does not
    change it (Shigley's friction depends on V_s only)."""
    k = require_range("application_factor", application_factor, 1.0, 10.0)
    v_g = sliding_speed(geo["d_m1"], n1, geo["gamma_m_deg"])
    mu = friction_coefficient_agma(v_g)
    eta = efficiency_worm_driving(geo["gamma_m_deg"], mu, geo["alpha_n_deg"])
    C_s = materials_factor(geo["a"], geo["d_2"], casting)
    C_m = ratio_correction_factor(geo["u"])
    C_v = velocity_factor(v_g)
    F_e = effective_face_width(geo["b_2"], geo["d_m1"])
    W = allowable_tangential_load(C_s, geo["d_2"], F_e, C_m, C_v)
    return {"v_g": v_g, "mu": mu, "eta_z": eta, "C_s": C_s, "C_m": C_m, "C_v": C_v, "F_e": F_e, "W_t_all": W,
            "T2_all": W * eta * geo["d_2"] / (2000.0 * k)}


# the quantities agma_load_float returns
LOAD_FIELDS = ("C_s", "C_m", "C_v", "F_e", "W_t_all", "W_t", "W_f", "P_f")


def agma_load_float(a, d_2, d_m1, b_2, u, v_g, gamma_m_deg, alpha_n_deg, mu, T2, eta, casting="sand",
                    application_factor=1.0) -> dict:
    """The AGMA row of one pair's rating in Python floats: :data:`LOAD_FIELDS`, i.e. :func:`materials_factor`,
    :func:`ratio_correction_factor`, :func:`velocity_factor`, :func:`effective_face_width`,
    :func:`allowable_tangential_load`, :func:`design_tangential_load` (W_t at the output torque ``T2``, N·m, and
    the mesh efficiency ``eta``), :func:`friction_force` (of F_t2 = 2000·T2/d_2 with the friction ``mu``) and
    :func:`friction_power`, in that order, with the same formulas (the factors' are shared code) on ``math``
    instead of numpy arrays: several times faster on one design (:func:`~geardesign.gears.worm.rating.worm_rating`
    uses it) and equal to the array functions (bit for bit on 2·10⁴ random designs on the machine this was
    written on; the tests hold the two to 1e-12 on random designs, the bound a C library's cos or pow that
    differs from numpy's by an ulp could not break).

    Inputs are the rating's validated geometry (mm, m/s, degrees); any input outside the array functions' ranges
    (or not a plain number) goes through them instead, which refuse it by name.

    Example 15-4 (Shigley): C_s 702.8, C_m 0.772, C_v 0.232, W_t,all 1239 lbf from the rounded factors:

    >>> r = agma_load_float(6.502 * 25.4, 10.504 * 25.4, 2.5 * 25.4, 1.5 * 25.4, 11.0, 1205.1 * 0.3048 / 60,
    ...                     20.905, 20.0, 0.0191, 1000.0, 0.942, "sand")
    >>> round(r["C_s"], 1), round(r["C_m"], 3), round(r["C_v"], 3)
    (702.8, 0.772, 0.232)
    """
    args = (a, d_2, d_m1, b_2, u, v_g, gamma_m_deg, alpha_n_deg, mu, T2, eta, application_factor)
    if casting in _CASTING_FACTORS and all(type(x) is float or type(x) is int for x in args):
        F_t2 = 2000.0 * T2 / d_2 if d_2 > 0.0 else math.nan
        if (a > 0.0 and d_2 > 0.0 and d_m1 > 0.0 and b_2 > 0.0 and 3.0 <= u < _CM_U_MAX and 0.0 < v_g <= 100.0
                and 0.0 < gamma_m_deg <= 45.0 and 0.0 <= alpha_n_deg < 45.0 and 0.0 <= mu <= 1.0
                and 0.0 <= T2 <= 1e9 and 0.0 < eta <= 1.0 and 1.0 <= application_factor <= 10.0
                and 0.0 <= F_t2 <= 1e12):
            out = _load(_MATH, a, d_2, d_m1, b_2, u, v_g, gamma_m_deg, alpha_n_deg, mu, T2, F_t2, eta, casting,
                        application_factor)
            # the array functions' remaining ranges: positive factors, an unlocked mesh, finite results
            if (out["C_s"] > 0.0 and out["C_m"] > 0.0 and out["_den"] > 0.0 and 0.0 <= out["W_f"] <= 1e12
                    and math.isfinite(out["P_f"]) and math.isfinite(out["W_t_all"])):
                del out["_den"]
                return out
    require_range("application_factor", application_factor, 1.0, 10.0)
    C_s = materials_factor(a, d_2, casting)
    C_m = ratio_correction_factor(u)
    C_v = velocity_factor(v_g)
    F_e = effective_face_width(b_2, d_m1)
    W_t = design_tangential_load(T2, d_2, eta, application_factor)         # T2 and d_2 checked here
    W_f = friction_force(2000.0 * np.asarray(T2, float) / np.asarray(d_2, float), mu, gamma_m_deg, alpha_n_deg)
    values = (C_s, C_m, C_v, F_e, allowable_tangential_load(C_s, d_2, F_e, C_m, C_v), W_t, W_f,
              friction_power(W_f, v_g))
    return {k: float(v) for k, v in zip(LOAD_FIELDS, values)}


def _load(ops, a, d_2, d_m1, b_2, u, v_g, gamma_m_deg, alpha_n_deg, mu, T2, F_t2, eta, casting, K_A) -> dict:
    """The chain of :func:`agma_load_float` on validated floats, each step as its array function writes it."""
    C_s = _materials(ops, a / MM_PER_IN, d_2 / MM_PER_IN, casting)
    C_m = _ratio(ops, u)
    C_v = _velocity(ops, v_g * FT_MIN_PER_M_S)
    F_e = min(b_2, 0.67 * d_m1)
    W_all = C_s * (d_2 / MM_PER_IN) ** 0.8 * (F_e / MM_PER_IN) * C_m * C_v * N_PER_LBF
    W_t = K_A * 2000.0 * T2 / d_2 / eta
    g, al = math.radians(gamma_m_deg), math.radians(alpha_n_deg)
    den = math.cos(al) * math.cos(g) - mu * math.sin(g)
    W_f = mu * F_t2 / den if den > 0.0 else math.nan
    return {"C_s": C_s, "C_m": C_m, "C_v": C_v, "F_e": F_e, "W_t_all": W_all, "W_t": W_t, "W_f": W_f,
            "P_f": W_f * v_g, "_den": den}
