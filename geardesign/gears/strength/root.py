"""Tooth-root form and stress-correction factors of ISO 6336-3 (methods B and C), vectorised.

Method B (ISO 6336-3:2019 and 2006, clause 6.2 form factor Y_F, clause 7.2 stress-correction factor Y_S;
external gears with the 2006 edition's equations) loads the tooth at the outer point of single pair tooth
contact. Method C (ISO 6336-3:1996 method C, DIN 3990-3:1987 method C) loads it at the tip: Y_Fa, Y_Sa, to be
used with the contact ratio factor Y_ε = 0.25 + 0.75/ε_αn and never with method B's Y_F, Y_S.

Everything is dimensionless, in units of the normal module m_n, and computed for the virtual spur gear of
the normal section (z_n = z/(cos²β_b cos β)).

External gears: the critical section is where the 30° tangent touches the fillet that the basic rack's
tip rounding (radius ρ_fP) generates; its position follows from the standard's equation for θ (radians),
solved by Newton's method from the standard's start θ = π/6.

Internal gears: no negative virtual tooth count goes into that iteration. The internal gear's tooth is
treated as the tooth of its basic rack (z_n → ∞), as ISO 6336-3:2006 does: the critical section is where
the 60° tangent touches the fillet of the rack tooth, the fillet radius is the tool's ρ_fP, and the load
acts at the basic rack's pressure angle (α_Fen = α_n). ISO 6336-3:2019 instead derives an internal gear's
root from its actual generation by the pinion-type shaper cutter (after VDI 2737:2016); that needs the
cutter's data (teeth, shift, tip radius) and is not implemented here. See :func:`root_form_factors` and
docs/strength_root.md.
"""
from __future__ import annotations

import functools
import math
import operator

import numpy as np

from ...errors import GearDesignError
from ...validate import (broadcast_inputs, one_number, require_bool, require_choice, require_int,
                         require_positive, require_range)
from .ops import ArrayOps as _ArrayOps, FloatOps as _FloatOps, checked

__all__ = ["root_form_factors", "stress_correction_factor", "METHODS", "Q_S_RANGE", "Z_RANGE",
           "EPS_ALPHA_RANGE", "BETA_RANGE_DEG", "ALPHA_N_RANGE_DEG"]

METHODS = ("B", "C")
# ISO 6336-3:2019 clause 7.2: the Y_S formula is stated for 1 <= q_s < 8.
Q_S_RANGE = (1.0, 8.0)
Z_RANGE = (5, 100_000)                 # tooth counts accepted (a ring's count is positive here)
EPS_ALPHA_RANGE = (1.0, 3.0)           # transverse contact ratio of the pair
BETA_RANGE_DEG = (-45.0, 45.0)         # the hand does not matter: |β| is used
ALPHA_N_RANGE_DEG = (10.0, 35.0)
X_RANGE = (-3.0, 3.0)
HFP_RANGE = (0.5, 2.5)                 # basic rack dedendum h_fP*/m_n
RHOFP_RANGE = (0.0, 1.0)               # basic rack root radius ρ_fP*/m_n
SPR_RANGE = (0.0, 0.5)                 # protuberance residual s_pr*/m_n
_NEWTON_STEPS = 40
_FLOAT_MAX = float(np.finfo(float).max)
BLOCK = 16_000                         # designs per block of a large array call (cache-sized temporaries under
                                       # glibc's 128 kB mmap threshold: see geometry.BLOCK)
DESIGNS_MAX = 50_000_000               # designs in one call: ~20 output fields of 8 bytes each (~8 GB)


def stress_correction_factor(s_Fn, h_Fe, rho_F):
    """Y_S = (1.2 + 0.13 L) q_s^(1/(1.21 + 2.3/L)), L = s_Fn/h_Fe, q_s = s_Fn/(2 ρ_F).

    ISO 6336-3:2019 clause 7.2 (method B; valid for 1 <= q_s < 8). With the bending arm h_Fa of the
    tip load it gives method C's Y_Sa (ISO 6336-3:1996, DIN 3990-3 method C). No validation: the
    caller passes checked lengths (any common unit).

    >>> round(float(stress_correction_factor(2.0, 1.0, 0.5)), 4)    # L = 2, q_s = 2: 1.46·2^(1/2.36)
    1.9584
    """
    if not (type(s_Fn) is float and type(h_Fe) is float and type(rho_F) is float):
        s_Fn, h_Fe, rho_F = (np.asarray(v, dtype=float) for v in (s_Fn, h_Fe, rho_F))
    L = s_Fn / h_Fe
    q_s = s_Fn / (2.0 * rho_F)
    return (1.2 + 0.13 * L) * q_s ** (1.0 / (1.21 + 2.3 / L))


def _inv(a, ops):
    return ops.tan(a) - a


_NUMBER_TYPES = frozenset({int, float})


def _plain(values) -> bool:
    """True for Python ints or floats each inside its range of :data:`_PLAIN_RANGES` (x, da_over_mn, eps_alpha,
    beta_deg, alpha_n_deg, hfp_star, rhofp_star, spr_star; the first four alone when four are given): the common
    case, checked without numpy."""
    return (_NUMBER_TYPES.issuperset(map(type, values)) and all(map(operator.le, _PLAIN_LO, values))
            and all(map(operator.le, values, _PLAIN_HI)))


_PLAIN_RANGES = (X_RANGE, (1e-300, 1e300), EPS_ALPHA_RANGE, BETA_RANGE_DEG, ALPHA_N_RANGE_DEG, HFP_RANGE, RHOFP_RANGE,
                 SPR_RANGE)
_PLAIN_LO, _PLAIN_HI = tuple(r[0] for r in _PLAIN_RANGES), tuple(r[1] for r in _PLAIN_RANGES)
_FLOAT_TYPE = frozenset({float})


@functools.lru_cache(maxsize=64, typed=True)   # typed: internal=1 is refused, not taken for True
def _float_rack(alpha_n_deg, hfp_star, rhofp_star, spr_star, internal, method):
    """The rack tuple of :func:`_factors` for the rack's floats, ``internal`` and ``method`` of the one-design path,
    checked once per rack as :func:`_check_inputs` and :func:`form_factors` check them; None where one is refused
    (their checks then name it)."""
    values = (alpha_n_deg, hfp_star, rhofp_star, spr_star)
    if not (type(internal) is bool and type(method) is str and method in METHODS
            and all(lo <= v <= hi for v, (lo, hi) in zip(values, _PLAIN_RANGES[4:]))
            and not (internal and rhofp_star <= 0.0)):
        return None
    try:
        return _rack(math.radians(alpha_n_deg), hfp_star, rhofp_star, spr_star, internal, method)
    except GearDesignError:
        return None


def _rack(alpha_n, hfp, rho, spr, internal, method) -> tuple:
    """The rack tuple of :func:`_factors`: α_n, h_fP*, ρ_fP*, E/m_n, ``internal``, ``method`` and the rack's cos α_n,
    tan α_n, inv α_n (the virtual gears' constants, once per call of :func:`form_factors`, not per formula)."""
    return (alpha_n, hfp, rho, _rack_fillet_centre(alpha_n, hfp, rho, spr), internal, method, math.cos(alpha_n),
            math.tan(alpha_n), _inv(alpha_n, math))


def _check_inputs(z, x, da_over_mn, eps_alpha, beta_deg, alpha_n_deg, hfp_star, rhofp_star, spr_star,
                  internal, method):
    """The validated inputs: Python floats for one design given as plain numbers (the fast path), else
    broadcast float arrays; and the ops that go with them."""
    if not (type(method) is str and method in METHODS):
        method = require_choice("method", method, METHODS)
    if type(internal) is not bool:
        internal = require_bool("internal", internal)
    if ((type(z) is int or type(z) is float and z.is_integer()) and Z_RANGE[0] <= z <= Z_RANGE[1]
            and _plain((x, da_over_mn, eps_alpha, beta_deg, alpha_n_deg, hfp_star, rhofp_star, spr_star))):
        return (float(z), float(x), float(da_over_mn), float(eps_alpha), abs(float(beta_deg)),
                math.radians(alpha_n_deg), float(hfp_star), float(rhofp_star), float(spr_star), internal, method,
                _FloatOps)
    if not (type(z) is np.ndarray and z.dtype == np.float64 and z.size and Z_RANGE[0] <= z.min()
            and z.max() <= Z_RANGE[1] and (np.rint(z) == z).all()):      # (the factor chain's: its geometry's z)
        z = require_int("z", z, *Z_RANGE).astype(float)
    x = checked("x", x, *X_RANGE)
    da = da_over_mn
    if not (type(da) is np.ndarray and da.dtype == np.float64 and da.size and da.min() > 0.0
            and da.max() <= _FLOAT_MAX):
        da = require_positive("da_over_mn", da_over_mn)
    eps = checked("eps_alpha", eps_alpha, *EPS_ALPHA_RANGE)
    beta = checked("beta_deg", beta_deg, *BETA_RANGE_DEG, unit="deg")
    alpha_n = one_number("alpha_n_deg", require_range("alpha_n_deg", alpha_n_deg, *ALPHA_N_RANGE_DEG,
                                                      unit="deg"))
    hfp = one_number("hfp_star", require_range("hfp_star", hfp_star, *HFP_RANGE))
    rho = one_number("rhofp_star", require_range("rhofp_star", rhofp_star, *RHOFP_RANGE))
    spr = one_number("spr_star", require_range("spr_star", spr_star, *SPR_RANGE))
    beta_0 = beta
    if not (z.shape == np.shape(x) == np.shape(da) == np.shape(eps) and np.ndim(beta) == 0):   # else: the chain's
        z, x, da, eps, beta = broadcast_inputs(z=z, x=x, da_over_mn=da, eps_alpha=eps, beta_deg=beta)
    if np.ndim(beta_0) == 0:     # one helix angle for all: its trigonometry once, not per design
        beta = np.asarray(beta_0, dtype=float)
    if z.size > DESIGNS_MAX:
        raise GearDesignError(f"z, x, da_over_mn, eps_alpha, beta_deg broadcast to {z.size} designs; at most "
                              f"{DESIGNS_MAX} in one call (split the batch)")
    return z, x, da, eps, np.abs(beta), math.radians(alpha_n), hfp, rho, spr, internal, method, _ArrayOps


@functools.lru_cache(maxsize=64)
def _rack_fillet_centre(alpha_n, hfp, rho, spr):
    """E/m_n, the distance of the generating rack's fillet centre from its tooth's centre line (ISO 6336-3:2019
    clause 6.2): E = π m_n/4 − h_fP tan α_n + s_pr/cos α_n − (1 − sin α_n) ρ_fP/cos α_n."""
    ca, sa = math.cos(alpha_n), math.sin(alpha_n)
    E = math.pi / 4.0 - hfp * math.tan(alpha_n) + spr / ca - (1.0 - sa) * rho / ca
    if E < -1e-12:
        raise GearDesignError(
            f"rhofp_star must be <= {(math.pi / 4 - hfp * math.tan(alpha_n) + spr / ca) * ca / (1 - sa):.4g} "
            f"for hfp_star={hfp:g}, spr_star={spr:g}, alpha_n_deg={math.degrees(alpha_n):g} (the root "
            f"rounding must fit on the basic rack's tip), got {rho!r}")
    return max(E, 0.0)


def _first(values, bad) -> str:
    """The first value where ``bad`` holds, for an error message."""
    values, bad = np.broadcast_arrays(np.asarray(values, dtype=float), np.asarray(bad))
    return repr(values[tuple(np.argwhere(bad)[0])].item()) if values.ndim else repr(values.item())


_SQRT_3 = math.sqrt(3.0)
_PI_6 = math.pi / 6.0
_TAN_PI_6 = math.tan(_PI_6)
_SEC2_PI_6 = 1.0 + _TAN_PI_6 * _TAN_PI_6


def _theta(G, H, z_n, x, ops, refuse=True):
    """Root of θ = (2G/z_n) tan θ − H (radians; ISO 6336-3:2019 clause 6.2), Newton from θ = π/6, and tan θ.

    The standard's fixed-point iteration converges to the root where (2G/z_n)/cos²θ < 1, the root
    Newton finds here; where there is none (a shift so large that G = ρ_fP* − h_fP* + x approaches
    z_n cos²θ/2) the design is refused."""
    k = 2.0 * G / z_n
    tan, maximum, minimum = ops.tan, ops.maximum, ops.minimum     # θ clipped to [-1.2, 1.2] by these two
    # the first step from π/6 takes its tan and cos as constants (1/cos²θ = 1 + tan²θ throughout)
    th = minimum(maximum(_PI_6 - (_PI_6 - k * _TAN_PI_6 + H) / maximum(1.0 - k * _SEC2_PI_6, 0.05), -1.2), 1.2)
    for i in range(_NEWTON_STEPS):
        t = tan(th)
        slope = maximum(1.0 - k * (1.0 + t * t), 0.05)    # > 1 wherever G < 0, the usual case
        step = (th - k * t + H) / slope
        th = minimum(maximum(th - step, -1.2), 1.2)
        # Newton's error after a step is ~(f''/2f')·step² with |f''/2f'| < 1 here: a step below 1e-9 leaves
        # ~1e-18 (three steps after the first, for z_n 8 to 400 and x -0.5 to 1.2: no check before the third);
        # the residual below checks it
        if i >= 2 and ops.all(ops.abs(step) <= 1e-9):
            break
    t = ops.tan(th)
    ok = (ops.abs(th - k * t + H) <= 1e-12) & (1.0 - k * (1.0 + t * t) > 0.0)
    if not ops.all(ok) and not refuse:
        return np.where(ok, th, np.nan), np.where(ok, t, np.nan)
    if not ops.all(ok):
        bad = ~np.asarray(ok)
        raise GearDesignError(
            "x must leave the 30-degree tangent on the generated fillet (the theta equation of "
            "ISO 6336-3 clause 6.2 needs rho_fP* - h_fP* + x < z_n cos^2(theta)/2), got "
            f"x={_first(x, bad)} with z_n={_first(z_n, bad)}")
    return th, t


def _load_point(z_n, da_n, cos_n, eps_n, internal, method, ops, refuse=True):
    """d_en/m_n (method B, outer point of single pair contact) or d_an/m_n (method C, the tip) of the
    virtual gear; ISO 6336-3:2019 clause 6.2: d_en = 2 √{[√((d_an/2)² − (d_bn/2)²) ∓ π m_n cos α_n
    (ε_αn − 1)]² + (d_bn/2)²} (− for an external gear; + for an internal one, whose point of single
    pair contact lies outward of its tip)."""
    d_bn = z_n * cos_n
    if method == "C":
        return da_n
    rho_a = ops.sqrt((da_n - d_bn) * (da_n + d_bn)) / 2.0
    p_bn = math.pi * cos_n
    rho_e = rho_a + p_bn * (eps_n - 1.0) if internal else rho_a - p_bn * (eps_n - 1.0)
    if ops.any(bad := rho_e <= 0.0) and not refuse:
        rho_e = np.where(rho_e > 0.0, rho_e, np.nan)
    elif ops.any(bad):
        bad = np.asarray(bad)
        most = eps_n + rho_e / p_bn       # ε_αn = 1 + ρ_a/p_bn puts the point on the base circle (external only:
        #                                   a ring's point lies outward of its tip)
        raise GearDesignError(
            f"eps_alpha must give eps_alpha_n < {float(_first(most, bad)):.6g} (the outer point of single pair "
            f"contact above the base circle), got eps_alpha_n={_first(eps_n, bad)}")
    return 2.0 * ops.sqrt(rho_e * rho_e + d_bn * d_bn / 4.0)


def _external_section(z_n, x, d_e, rack, ops, refuse=True):
    """s_Fn, ρ_F, h_Fe, α_Fen, θ (lengths /m_n) and cos α_Fen of an external gear: ISO 6336-3:2019 clause 6.2,
    G = ρ_fP/m_n − h_fP/m_n + x, H = 2/z_n (π/2 − E/m_n) − π/3, θ = (2G/z_n) tan θ − H,
    s_Fn/m_n = z_n sin(π/3 − θ) + √3 (G/cos θ − ρ_fP/m_n),
    ρ_F/m_n = ρ_fP/m_n + 2G²/(cos θ (z_n cos²θ − 2G)),
    α_e = arccos(d_bn/d_e), γ_e = (π/2 + 2x tan α_n)/z_n + inv α_n − inv α_e, α_Fen = α_e − γ_e,
    h_Fe/m_n = ½[(cos γ_e − sin γ_e tan α_Fen) d_e/m_n − z_n cos(π/3 − θ) − G/cos θ + ρ_fP/m_n].

    Evaluated with cos γ_e − sin γ_e tan α_Fen = cos α_e/cos α_Fen (so its first term is d_bn/cos α_Fen),
    inv α_e with tan α_e = √(d_e² − d_bn²)/d_bn, cos θ, sin θ, cos(π/3 − θ), sin(π/3 − θ) from tan θ and
    cos α_Fen = 1/√(1 + tan² α_Fen) (|α_Fen| < π/2; numpy's tan is ~5x faster than its cos): fewer trigonometric
    functions, the same values to a few ulp."""
    _, hfp, rho, E, _, _, cos_n, tan_n, inv_n = rack
    G = rho - hfp + x
    H = 2.0 / z_n * (math.pi / 2.0 - E) - math.pi / 3.0
    th, t = _theta(G, H, z_n, x, ops, refuse)
    c = 1.0 / ops.sqrt(1.0 + t * t)              # |θ| < π/2: cos θ > 0
    s = t * c
    r3 = _SQRT_3
    G_c, G2 = G / c, 2.0 * G
    s_Fn = z_n * (0.5 * r3 * c - 0.5 * s) + r3 * (G_c - rho)
    rho_F = rho + G2 * G / (c * (z_n * c * c - G2))
    d_bn = z_n * cos_n
    alpha_e = ops.arccos(d_bn / d_e)
    tan_e = ops.sqrt((d_e - d_bn) * (d_e + d_bn)) / d_bn
    gamma_e = (math.pi / 2.0 + 2.0 * x * tan_n) / z_n + inv_n - (tan_e - alpha_e)
    alpha_F = alpha_e - gamma_e
    t_F = ops.tan(alpha_F)
    cos_F = 1.0 / ops.sqrt(1.0 + t_F * t_F)
    h_Fe = 0.5 * (d_bn / cos_F - z_n * (0.5 * c + 0.5 * r3 * s) - G_c + rho)
    return s_Fn, rho_F, h_Fe, alpha_F, th, cos_F


# The internal gear's critical section: the tangent at 60° to the tooth centre line (30° external).
_TANGENT_INTERNAL = math.pi / 3.0


def _internal_section(z_n, x, d_e, rack, ops, refuse=True):
    """s_Fn, ρ_F, h_Fe, α_Fen, θ (lengths /m_n) and cos α_Fen of an internal gear treated, as ISO 6336-3:2006
    does, as its basic rack (z_n → ∞) with the 60° tangent.

    The ring's tooth is the rack tooth between two cutter teeth; the cutter's fillet centre lies
    E/m_n from the cutter tooth's centre line, so π/2 − E/m_n from the ring tooth's, and h_fP − ρ_fP
    below the datum line (x m_n outward of the reference circle in this project's sign). Where the
    60° tangent touches that circle: s_Fn = π − 2E/m_n − 2ρ_fP cos 60°, at depth h_fP − ρ_fP + ρ_fP sin 60°;
    ρ_F = ρ_fP; the load acts along the rack's flank normal (α_Fen = α_n) at depth
    h_e = d_e/2 − z_n/2 − x, where the half tooth is π/4 + h_e tan α_n, and meets the centre line
    (π/4 + h_e tan α_n) tan α_n deeper: h_Fe is the rest of the way to the chord. θ is reported as
    the limit of the external equation for z_n → ∞ with this tangent, π/2 − 60°."""
    alpha_n, hfp, rho, E, _, _, cos_n, t, _ = rack
    depth_chord = hfp - rho + rho * math.sin(_TANGENT_INTERNAL)
    h_e = (d_e - z_n) / 2.0 - x
    h_Fe = depth_chord - h_e - (math.pi / 4.0 + h_e * t) * t
    s_Fn = math.pi - 2.0 * E - 2.0 * rho * math.cos(_TANGENT_INTERNAL)
    return (ops.like(h_Fe, s_Fn), ops.like(h_Fe, rho), h_Fe, ops.like(h_Fe, alpha_n),
            ops.like(h_Fe, math.pi / 2.0 - _TANGENT_INTERNAL), cos_n)


def root_form_factors(z, x, da_over_mn, *, eps_alpha, beta_deg=0.0, alpha_n_deg=20.0, hfp_star=1.25,
                      rhofp_star=0.38, spr_star=0.0, internal=False, method="B", refuse=True) -> dict:
    """ISO 6336-3 tooth form factor and stress-correction factor of one gear, over arrays.

    Parameters (broadcast together; lengths in units of the normal module m_n)
    ----------
    z : the gear's tooth count, a whole number in [5, 100000] (a ring's count positive).
    x : its profile shift coefficient. For a ring (``internal=True``) this project's sign (GOST 19274):
        positive x moves the ring's flanks outward (thinner teeth, larger tip and root diameters);
        ISO 21771 writes the same ring with x_ISO = −x (and z_ISO = −z).
    da_over_mn : actual tip diameter / m_n (after any tip shortening; a ring's inner tip diameter).
    eps_alpha : the pair's transverse contact ratio ε_α in [1, 3]; ε_αn = ε_α/cos²β_b.
    beta_deg : helix angle (|β| is used), alpha_n_deg : normal pressure angle of the basic rack.
    hfp_star, rhofp_star, spr_star : the generating basic rack's dedendum h_fP/m_n (h_a* + c* of
        :class:`~geardesign.gears.rack.BasicRack`), its root radius ρ_fP/m_n (``rho_f``) and the
        protuberance residual s_pr/m_n (0 without protuberance).
    internal : True for a ring gear: ISO 6336-3:2006's rack treatment with the 60° tangent (the 2019
        edition's shaper-cutter treatment is not implemented; see the module docstring).
    method : "B" (load at the outer point of single pair contact, ISO 6336-3:2019: Y_F, Y_S) or "C"
        (load at the tip, ISO 6336-3:1996 / DIN 3990-3 method C: Y_Fa, Y_Sa, to be used with Y_ε).
    refuse : False gives NaN, instead of an error, for designs of valid inputs that have no root section
        (the shift solvers' strength checks, whose designs the geometry's own checks judge).

    Returns
    -------
    dict of float arrays: "Y_F", "Y_S" (method B) or "Y_Fa", "Y_Sa" (method C); "s_Fn" root chord,
    "h_Fe" bending arm (h_Fa for method C), "rho_F" fillet radius at the critical section, "d_en" the
    load point's diameter (d_an for method C), all /m_n of the virtual gear; "alpha_Fen_rad", "theta_rad",
    "q_s" = s_Fn/(2ρ_F), "z_n", "eps_alpha_n", and "in_range": True where 1 <= q_s < 8, the range
    ISO 6336-3 states for the Y_S formula. Outside it the formula's value is still returned (the
    standard gives no other) and in_range is False: the caller decides.

    Refused (GearDesignError naming the input): values outside the ranges above, a tip at or below the
    base circle, a contact ratio that puts the load point below the base circle, a root radius that does
    not fit on the rack tip, a shift with no 30° tangent on the fillet, and ρ_fP = 0 for a ring.

    A standard 20-tooth spur gear, its tips uncut, in a pair with ε_α = 1.557:

    >>> r = root_form_factors(20, 0.0, 22.0, eps_alpha=1.557)
    >>> round(float(r["Y_F"]), 3), round(float(r["Y_S"]), 3), bool(r["in_range"])
    (1.712, 1.776, True)
    >>> c = root_form_factors(20, 0.0, 22.0, eps_alpha=1.557, method="C")
    >>> round(float(c["Y_Fa"]), 2), round(float(c["Y_Sa"]), 2)
    (2.8, 1.55)
    """
    out = form_factors(z, x, da_over_mn, eps_alpha, beta_deg, alpha_n_deg, hfp_star, rhofp_star, spr_star, internal,
                       method, refuse=require_bool("refuse", refuse))
    if type(out["z_n"]) is float:                     # numpy scalars: the same interface as arrays
        return {k: (np.bool_(v) if k == "in_range" else np.float64(v)) for k, v in out.items()}
    return out


def form_factors(z, x, da_over_mn, eps_alpha, beta_deg, alpha_n_deg, hfp_star, rhofp_star, spr_star, internal, method,
                 keys=None, refuse=True) -> dict:
    """:func:`root_form_factors` (positional, the same checks) with Python floats for one design given in plain
    numbers; ``keys``: only these fields are kept of an array call (the factor chain's); ``refuse`` as there."""
    if (_FLOAT_TYPE.issuperset(map(type, (alpha_n_deg, hfp_star, rhofp_star, spr_star)))
            and (rack := _float_rack(alpha_n_deg, hfp_star, rhofp_star, spr_star, internal, method)) is not None
            and (type(z) is int or type(z) is float and z.is_integer()) and Z_RANGE[0] <= z <= Z_RANGE[1]
            and _plain((x, da_over_mn, eps_alpha, beta_deg))):
        # one design and a rack checked before (the factor chain's two gears): the checks of the design alone
        return _factors(float(z), float(x), float(da_over_mn), float(eps_alpha), abs(float(beta_deg)), rack, _FloatOps)
    (z, x, da, eps, beta, alpha_n, hfp, rho, spr, internal, method,
     ops) = _check_inputs(z, x, da_over_mn, eps_alpha, beta_deg, alpha_n_deg, hfp_star, rhofp_star, spr_star,
                          internal, method)
    if internal and rho <= 0.0:
        raise GearDesignError("rhofp_star must be > 0 for an internal gear (its fillet radius is "
                              f"rho_fP itself), got {rho!r}")
    rack = _rack(alpha_n, hfp, rho, spr, internal, method)
    if ops is _FloatOps or z.size <= BLOCK:
        return _factors(z, x, da, eps, beta, rack, ops, refuse or ops is _FloatOps)
    # block by block: ~60 temporaries of BLOCK doubles stay in the caches (as geometry.mesh_geometry does),
    # each block's fields written into the full-size outputs
    flat = [v.reshape(-1) if v.ndim else v for v in (z, x, da, eps, beta)]
    out = {}
    for i in range(0, z.size, BLOCK):
        part = _factors(*(v[i:i + BLOCK] if v.ndim else v for v in flat), rack, ops, refuse)
        for k in (part if keys is None else keys):
            if k not in out:
                out[k] = np.empty(z.size, dtype=part[k].dtype)
            out[k][i:i + BLOCK] = part[k]
    return {k: v.reshape(z.shape) for k, v in out.items()}


def _factors(z, x, da, eps, beta, rack, ops, refuse=True) -> dict:
    """Every field of :func:`root_form_factors` for validated inputs (arrays of one shape, or floats)."""
    alpha_n, _, _, _, internal, method, cos_n, _, _ = rack
    if (type(beta) is float or type(beta) is np.ndarray and beta.ndim == 0) and beta == 0.0:
        cos_beta = 1.0
        z_n, eps_n = z * 1.0, eps * 1.0               # spur: the divisions by cos β = cos²β_b = 1 below (new arrays:
        #                                                 the result's z_n is not the caller's z)
        da_n = z_n + da - z
    else:
        cos_beta = ops.cos(beta * (math.pi / 180.0))
        sin_bb = ops.sin(beta * (math.pi / 180.0)) * cos_n
        cos_bb2 = 1.0 - sin_bb * sin_bb               # cos²β_b
        z_n = z / (cos_bb2 * cos_beta)
        eps_n = eps / cos_bb2
        da_n = z_n + da - z / cos_beta                # d_an = d_n + d_a − d
    if ops.any(bad := da_n <= z_n * cos_n) and not refuse:
        da_n = np.where(bad, np.nan, da_n)
    elif ops.any(bad):
        least = z / cos_beta - z_n * (1.0 - cos_n)      # d_an = d_bn
        raise GearDesignError(
            f"da_over_mn must be > {float(_first(least, bad)):.6g} (the tip above the base circle: d_an > d_bn of "
            f"the virtual gear), got {_first(da, bad)}")
    d_e = _load_point(z_n, da_n, cos_n, eps_n, internal, method, ops, refuse)
    section = _internal_section if internal else _external_section
    s_Fn, rho_F, h_Fe, alpha_F, th, cos_F = section(z_n, x, d_e, rack, ops, refuse)
    if ops.any(bad := (s_Fn <= 0.0) | (h_Fe <= 0.0)) and not refuse:
        s_Fn = np.where(bad, np.nan, s_Fn)
    elif ops.any(bad):
        raise GearDesignError(f"x gives no root section (s_Fn or h_Fe <= 0), got x={_first(x, bad)}")
    Y_F = 6.0 * h_Fe * cos_F / (s_Fn * s_Fn * cos_n)
    Y_S = stress_correction_factor(s_Fn, h_Fe, rho_F)
    q_s = s_Fn / (2.0 * rho_F)
    names = ("Y_F", "Y_S") if method == "B" else ("Y_Fa", "Y_Sa")
    return {names[0]: Y_F, names[1]: Y_S, "s_Fn": s_Fn, "h_Fe": h_Fe, "rho_F": rho_F, "alpha_Fen_rad": alpha_F,
            "q_s": q_s, "theta_rad": th, "z_n": z_n, "d_en": d_e, "eps_alpha_n": eps_n,
            "in_range": (q_s >= Q_S_RANGE[0]) & (q_s < Q_S_RANGE[1])}
