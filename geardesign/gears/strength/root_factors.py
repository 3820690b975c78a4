"""The tooth-root factors of ISO 6336-3 besides Y_F and Y_S: one function per formula, vectorised.

Editions: ISO 6336-3:2019 (method B) unless a docstring says otherwise, the formulas as IACS UR M56 Rev.4
(2021, Corr.3 2025; "Marine gears - load capacity of involute parallel axis spur and helical gears", which takes
ISO 6336:2019 as its reference standard) prints them where it prints them (Y_β, Y_B, Y_DT, Y_δrelT, Y_RrelT, Y_X); the contact ratio factor Y_ε belongs
to method C only (ISO 6336-3:1996, DIN 3990-3), the tip-load form factors Y_Fa, Y_Sa. Material kinds are the
abbreviations of ISO 6336-5 / ISO 6336-3 (:data:`MATERIAL_KINDS`); each table below says which kinds share a
curve. Clause numbers are those of ISO 6336-3; the tables of the standard are quoted as the values they
print, not re-derived.
"""
from __future__ import annotations

import functools
import math

import numpy as np

from ...errors import GearDesignError
from ...validate import require_bool, require_choice, require_int, require_positive, require_range
from .defaults import EPS_BETA_MAX
from .ops import checked, ops_of

__all__ = ["MATERIAL_KINDS", "Y_ST", "helix_factor_Y_beta", "contact_ratio_factor_Y_eps", "deep_tooth_factor_Y_DT",
           "rim_factor_Y_B", "relative_notch_sensitivity_Y_delta_relT", "relative_surface_factor_Y_RrelT",
           "size_factor_Y_X", "life_factor_Y_NT"]

# The material kinds of ISO 6336-5 (abbreviations as ISO 6336-3's tables print them).
MATERIAL_KINDS = {
    "St": "structural steel (normalized, sigma_B < 800 MPa)",
    "V": "through-hardened wrought steel (quenched and tempered, sigma_B >= 800 MPa)",
    "GG": "grey cast iron",
    "GGG(perl)": "nodular (spheroidal graphite) cast iron, perlitic or bainitic",
    "GGG(ferr)": "nodular (spheroidal graphite) cast iron, ferritic",
    "GTS": "black malleable cast iron (perlitic)",
    "Eh": "case-hardened wrought steel",
    "IF": "flame or induction hardened wrought or cast steel (root hardened)",
    "NT": "nitriding steel, nitrided",
    "NV(nitr)": "through-hardening steel, nitrided",
    "NV(nitrocar)": "through-hardening steel, nitrocarburized",
}

# Nominal stress correction factor of the reference test gears (ISO 6336-3:2019, clause 3/11: sigma_FE =
# sigma_Flim * Y_ST).
Y_ST = 2.0


def _kind(material_kind) -> str:
    if type(material_kind) is str and material_kind in MATERIAL_KINDS:
        return material_kind
    return require_choice("material_kind", material_kind, MATERIAL_KINDS)


def helix_factor_Y_beta(eps_beta, beta_deg, *, edition: int = 2006):
    """Helix angle factor Y_β: Y_β = 1 − ε_β β/120°, with ε_β taken as 1 where it exceeds 1 and β as 30° where it
    exceeds 30° (so Y_β >= 0.75, the standard's Y_βmin); |β| is used.

    This is ISO 6336-3:2006 clause 8, and the formula IACS UR M56 Rev.4 (2021, Corr.3 2025) §M56.3.5 prints
    while citing ISO 6336-3:2019 as its reference standard. ``edition=2019`` divides it by cos³β, the form we
    understand the 2019 edition to give; that term is not confirmed by any text we could read (UR M56 omits it),
    so it is opt-in and stated as unconfirmed in docs/strength_root.md.

    >>> round(float(helix_factor_Y_beta(1.2, 15.0)), 4)
    0.875
    >>> round(float(helix_factor_Y_beta(0.5, 10.0, edition=2019)), 4)
    1.0034
    """
    if not (type(edition) is int and edition in (2006, 2019)):
        edition = int(require_choice("edition", str(edition), ["2006", "2019"]))
    eps_beta = checked("eps_beta", eps_beta, 0.0, EPS_BETA_MAX)
    beta_deg = checked("beta_deg", beta_deg, -45.0, 45.0, unit="deg")
    xp = ops_of(eps_beta, beta_deg)
    eb = xp.minimum(eps_beta, 1.0)
    b = xp.minimum(xp.abs(beta_deg), 30.0)
    y = 1.0 - eb * b / 120.0
    return y / xp.cos(xp.radians(b)) ** 3 if edition == 2019 else y


def contact_ratio_factor_Y_eps(eps_alpha_n):
    """Contact ratio factor Y_ε = 0.25 + 0.75/ε_αn of method C only (ISO 6336-3:1996 clause 6.3 / DIN 3990-3:
    with the tip-load factors Y_Fa, Y_Sa). Method B (ISO 6336-3:2006/2019) has no Y_ε: do not combine it with
    Y_F, Y_S. ε_αn = ε_α/cos²β_b, refused below 1.

    >>> round(float(contact_ratio_factor_Y_eps(1.5)), 4)
    0.75
    """
    return 0.25 + 0.75 / checked("eps_alpha_n", eps_alpha_n, 1.0, 10.0)


def deep_tooth_factor_Y_DT(eps_alpha_n, accuracy_grade):
    """Deep tooth factor Y_DT (ISO 6336-3:2019, clause 10; UR M56 Rev.4 §M56.3.7): 1.0 where ε_αn <= 2.05 or the accuracy grade
    (ISO 1328-1) is coarser than 4; for grade <= 4: −0.666 ε_αn + 2.366 for 2.05 < ε_αn <= 2.5, and 0.7 above
    (the line's value at 2.5 is 0.701).

    >>> [round(float(deep_tooth_factor_Y_DT(e, 4)), 3) for e in (1.8, 2.3, 2.7)]
    [1.0, 0.834, 0.7]
    >>> float(deep_tooth_factor_Y_DT(2.3, 6))
    1.0
    """
    e = checked("eps_alpha_n", eps_alpha_n, 1.0, 10.0)
    q = accuracy_grade
    if (type(q) is int or type(q) is float) and 1 <= q <= 12 and q == int(q):
        q = float(q)
    else:
        q = require_int("accuracy_grade", accuracy_grade, 1, 12)
    xp = ops_of(e)
    if type(q) is float and q > 4:    # grades 5-12: 1 whatever ε_αn is
        return xp.like(e, 1.0)
    if xp is not ops_of(q):
        e, q = np.broadcast_arrays(e, q)
    line = xp.where(e > 2.5, 0.7, -0.666 * e + 2.366)
    return xp.where((e <= 2.05) | (q > 4), 1.0, line)


def rim_factor_Y_B(s_R_over_h_t=None, *, internal: bool = False, s_R_over_mn=None):
    """Rim thickness factor Y_B (ISO 6336-3:2019, clause 9; UR M56 Rev.4 §M56.3.6). Solid gears (``None``): 1.

    External gears, by s_R/h_t (rim thickness below the root over tooth depth): 1 for >= 1.2,
    1.6 ln(2.242 h_t/s_R) for 0.5 < s_R/h_t < 1.2. Internal gears, by s_R/m_n: 1 for >= 3.5,
    1.15 ln(8.324 m_n/s_R) for 1.75 < s_R/m_n < 3.5. Thinner rims (s_R/h_t <= 0.5, s_R/m_n <= 1.75) are
    outside the method and refused.

    >>> rim_factor_Y_B(), round(float(rim_factor_Y_B(0.8)), 4)
    (1.0, 1.6488)
    >>> round(float(rim_factor_Y_B(internal=True, s_R_over_mn=2.5)), 4)
    1.3833
    """
    internal = require_bool("internal", internal)
    if internal:
        if s_R_over_mn is None:
            return 1.0
        r = require_range("s_R_over_mn", s_R_over_mn, 1.75, 1e6, lo_open=True)
        return np.where(r >= 3.5, 1.0, 1.15 * np.log(8.324 / r))
    if s_R_over_h_t is None:
        return 1.0
    r = s_R_over_h_t if type(s_R_over_h_t) is float and 0.5 < s_R_over_h_t <= 1e6 else require_range(
        "s_R_over_h_t", s_R_over_h_t, 0.5, 1e6, lo_open=True)
    xp = ops_of(r)
    return xp.where(r >= 1.2, 1.0, 1.6 * xp.log(2.242 / r))


# Slip-layer thickness rho' (mm) of the relative notch sensitivity (ISO 6336-3:2019, clause 13, method B, its
# table): (limit, rho') pairs, interpolated linearly in between. The limit is sigma_B for GG/GGG(ferr),
# sigma_0.2 for V/GGG(perl)/GTS, sigma_S (yield point) for St; no limit for the surface-hardened kinds.
# (St at 400 MPa is 0.0445 mm: a public implementation has 0.445, ten times too thick.)
_SLIP_LAYER_MM = {
    ("GG", "GGG(ferr)"): ((150.0, 0.3124), (300.0, 0.3095)),
    ("V", "GGG(perl)", "GTS"): ((500.0, 0.0281), (600.0, 0.0194), (800.0, 0.0064), (1000.0, 0.0014)),
    ("St",): ((300.0, 0.0833), (400.0, 0.0445)),
    ("NT", "NV(nitr)", "NV(nitrocar)"): 0.1005,
    ("Eh", "IF"): 0.0030,
}
_CHI_T = 1.2      # relative stress gradient chi*_T = (1 + 2 q_sT)/5 of the reference test gear, q_sT = 2.5


def _by_kind(table: dict) -> dict:
    """{kind: row} of a table whose keys are tuples of the kinds that share a row."""
    return {kind: row for kinds, row in table.items() for kind in kinds}


_SLIP_BY_KIND = _by_kind({k: v if isinstance(v, float) else (tuple(t[0] for t in v), tuple(t[1] for t in v))
                          for k, v in _SLIP_LAYER_MM.items()})


def _slip_layer(kind: str, limit_mpa):
    table = _SLIP_BY_KIND[kind]
    if isinstance(table, float):
        return table
    lo, hi = table[0][0], table[0][-1]
    if limit_mpa is None:
        raise GearDesignError(f"limit_mpa (the material's strength for kind {kind!r}) must be given, in "
                              f"[{lo:g}, {hi:g}] MPa, got None")
    s = checked("limit_mpa", limit_mpa, lo, hi, unit="MPa")
    return ops_of(s).interp(s, *table)


@functools.lru_cache(maxsize=256)
def _material_slip_layer(kind: str, limit_mpa):
    """:func:`_slip_layer` of one material's strength (a number or None): once per material."""
    return _slip_layer(kind, limit_mpa)


# Static relative notch sensitivity (ISO 6336-3:2019, clause 13, method B, N_L <= the static limit): linear in Y_S
# where the kind has no strength term: (a, b) of a Y_S + b.
_STATIC_LINEAR = {"Eh": (0.44, 0.12), "IF": (0.44, 0.12), "NT": (0.20, 0.60), "NV(nitr)": (0.20, 0.60),
                  "NV(nitrocar)": (0.20, 0.60), "GG": (0.0, 1.0), "GGG(ferr)": (0.0, 1.0)}
# with a strength term: Y = (1 + c (Y_S − 1)(s0/σ)^(1/4)) / (1 + c (s0/σ)^(1/4)): (c, s0). GTS goes with V and
# GGG(perl) as in the slip-layer table (DIN 3990-11's list, which has these rows, does not name GTS).
_STATIC_STRENGTH = {"St": (0.93, 200.0), "V": (0.82, 300.0), "GGG(perl)": (0.82, 300.0), "GTS": (0.82, 300.0)}


NOTCH_Q_S_RANGE = (0.1, 50.0)   # the notch parameters the fatigue form is taken over (far beyond the standard's 1..8)


def relative_notch_sensitivity_Y_delta_relT(q_s, material_kind, *, limit_mpa=None, static: bool = False,
                                            Y_S=None):
    """Relative notch sensitivity factor Y_δrelT (ISO 6336-3:2019, clause 13, method B; the fatigue form and the
    steels' slip layers as UR M56 Rev.4 §M56.3.11 prints them).

    Fatigue (``static=False``): Y_δrelT = (1 + √(ρ′ χ*)) / (1 + √(ρ′ χ*_T)), χ* = (1 + 2 q_s)/5 (mm⁻¹),
    χ*_T = 1.2 (q_sT = 2.5); ρ′ the slip-layer thickness of the kind (the standard's table, linear in between:
    ``limit_mpa`` is σ_B for GG/GGG(ferr) in [150, 300], σ_0.2 for V/GGG(perl)/GTS in [500, 1000], σ_S for St in
    [300, 400]; not needed for Eh, IF, NT, NV).

    Static (``static=True``, from the stress correction factor ``Y_S``; these rows are also DIN 3990-11's):
    Eh, IF 0.44 Y_S + 0.12; NT, NV 0.20 Y_S + 0.60; GG, GGG(ferr) 1.0; St (1 + 0.93 (Y_S − 1)(200/σ_S)^¼) /
    (1 + 0.93 (200/σ_S)^¼); V, GGG(perl), GTS (1 + 0.82 (Y_S − 1)(300/σ_0.2)^¼) / (1 + 0.82 (300/σ_0.2)^¼), with
    ``limit_mpa`` = σ_S or σ_0.2. All give 1 at the test gear (q_s = 2.5, Y_S = Y_ST = 2).

    >>> round(float(relative_notch_sensitivity_Y_delta_relT(2.5, "St", limit_mpa=400)), 12)
    1.0
    >>> round(float(relative_notch_sensitivity_Y_delta_relT(1.8, "Eh")), 4)
    0.993
    >>> round(float(relative_notch_sensitivity_Y_delta_relT(None, "Eh", static=True, Y_S=1.9)), 3)
    0.956
    """
    kind = _kind(material_kind)
    if static is not False and require_bool("static", static):
        if Y_S is None:
            raise GearDesignError("Y_S must be given for the static relative notch sensitivity, got None")
        ys = require_range("Y_S", Y_S, 1.0, 5.0)
        if kind in _STATIC_LINEAR:
            a, b = _STATIC_LINEAR[kind]
            return a * ys + b
        c, s0 = _STATIC_STRENGTH[kind]
        if limit_mpa is None:
            raise GearDesignError(f"limit_mpa (yield strength for kind {kind!r}) must be given for the static "
                                  "relative notch sensitivity, > 0 MPa, got None")
        k = c * (s0 / require_positive("limit_mpa", limit_mpa, "MPa")) ** 0.25
        return (1.0 + k * (ys - 1.0)) / (1.0 + k)
    qs = checked("q_s", q_s, *NOTCH_Q_S_RANGE)
    rho = (_material_slip_layer(kind, limit_mpa) if limit_mpa is None or type(limit_mpa) is float else
           _slip_layer(kind, limit_mpa))
    xp = ops_of(qs, rho)
    return (1.0 + xp.sqrt(rho * (1.0 + 2.0 * qs) / 5.0)) / (1.0 + xp.sqrt(rho * _CHI_T))


# Relative surface factor (ISO 6336-3:2019, clause 14, method B): for 1 <= Rz <= 40 um, a − b (Rz + 1)^c;
# below 1 um the constant. Kinds sharing a curve.
_SURFACE = {("V", "GGG(perl)", "GTS", "Eh", "IF"): (1.674, 0.529, 0.1, 1.120),
            ("St",): (5.306, 4.203, 0.01, 1.070),
            ("GG", "GGG(ferr)", "NT", "NV(nitr)", "NV(nitrocar)"): (4.299, 3.259, 0.0058, 1.025)}
RZ_MAX_UM = 40.0
_SURFACE_BY_KIND = _by_kind(_SURFACE)


def relative_surface_factor_Y_RrelT(Rz_um, material_kind, *, static: bool = False):
    """Relative surface factor Y_RrelT (ISO 6336-3:2019, clause 14, method B; UR M56 Rev.4 §M56.3.12), from the root's mean roughness
    Rz (µm, 0 <= Rz <= 40): V, GGG(perl), GTS, Eh, IF: 1.674 − 0.529 (Rz + 1)^0.1 (1.120 below 1 µm);
    St: 5.306 − 4.203 (Rz + 1)^0.01 (1.070); GG, GGG(ferr), NT, NV: 4.299 − 3.259 (Rz + 1)^0.0058 (1.025).
    Static stress: 1.0. (At Rz = 1 the first curve gives 1.107, not its constant 1.120: as printed.)

    >>> round(float(relative_surface_factor_Y_RrelT(10.0, "Eh")), 4)
    1.0017
    >>> float(relative_surface_factor_Y_RrelT(0.5, "St"))
    1.07
    """
    kind = _kind(material_kind)
    rz = checked("Rz_um", Rz_um, 0.0, RZ_MAX_UM, unit="um")
    xp = ops_of(rz)
    if static is not False and require_bool("static", static):
        return xp.like(rz, 1.0)
    a, b, c, low = _SURFACE_BY_KIND[kind]
    return xp.where(rz < 1.0, low, a - b * (rz + 1.0) ** c)


# Size factor (ISO 6336-3:2019, clause 15, method B): 1 up to 5 mm, then a − b m_n down to a floor.
_SIZE = {("St", "V", "GGG(perl)", "GTS"): (1.03, 0.006, 0.85),
         ("Eh", "IF", "NT", "NV(nitr)", "NV(nitrocar)"): (1.05, 0.01, 0.80),
         ("GG", "GGG(ferr)"): (1.075, 0.015, 0.70)}
_SIZE_BY_KIND = _by_kind(_SIZE)


def size_factor_Y_X(m_n_mm, material_kind, *, static: bool = False):
    """Size factor Y_X (ISO 6336-3:2019, clause 15, method B; UR M56 Rev.4 §M56.3.13 for the steels) from the
    normal module m_n (mm): 1.0 for m_n <= 5; St, V, GGG(perl), GTS: 1.03 − 0.006 m_n, 0.85 from 30 mm; Eh, IF,
    NT, NV: 1.05 − 0.01 m_n, 0.8 from 25 mm; GG, GGG(ferr): 1.075 − 0.015 m_n, 0.7 from 25 mm (each line meets
    1.0 at 5 mm and its floor; UR M56 prints "1.03 − 0.06 m_n", a slip: it would give 0.73 at 5 mm).
    Static stress: 1.0.

    >>> [round(float(size_factor_Y_X(m, "Eh")), 3) for m in (3, 8, 30)]
    [1.0, 0.97, 0.8]
    """
    kind = _kind(material_kind)
    m = m_n_mm if type(m_n_mm) is float and 0.0 < m_n_mm <= 1000.0 else require_range(
        "m_n_mm", m_n_mm, 0.0, 1000.0, lo_open=True, unit="mm")
    xp = ops_of(m)
    if static is not False and require_bool("static", static):
        return xp.like(m, 1.0)
    a, b, floor = _SIZE_BY_KIND[kind]
    if xp.all(m <= 5.0):        # modules up to 5 mm: 1
        return xp.like(m, 1.0)
    return xp.where(m <= 5.0, 1.0, xp.maximum(a - b * m, floor))


# Life factor (ISO 6336-3:2019, clause 12, method B): static value up to N_static, 1.0 at 3e6, 0.85 at 1e10,
# straight lines in log-log in between (the standard prints them as (3e6/N_L)^e, e = 0.16, 0.115, 0.059,
# 0.012 above and 0.02 below 1.0: these exponents rounded).
_LIFE = {("St", "V", "GGG(perl)", "GTS"): (1e4, 2.5),
         ("Eh", "IF"): (1e3, 2.5),
         ("GG", "GGG(ferr)", "NT", "NV(nitr)"): (1e3, 1.6),
         ("NV(nitrocar)",): (1e3, 1.1)}
N_ENDURANCE = 3e6
N_LONG = 1e10
_LN_ENDURANCE, _LN_LONG = math.log(N_ENDURANCE), math.log(N_LONG)
_LIFE_BY_KIND = _by_kind(_LIFE)


def life_factor_Y_NT(N_L, material_kind, *, optimum: bool = False):
    """Life factor Y_NT (ISO 6336-3:2019, clause 12, method B) for N_L load cycles (>= 1).

    St, V, GGG(perl), GTS: 2.5 up to 1e4 cycles; Eh, IF: 2.5 up to 1e3; GG, GGG(ferr), NT, NV(nitr): 1.6 up to
    1e3; NV(nitrocar): 1.1 up to 1e3; then a straight line in log-log to 1.0 at 3e6 and on to 0.85 at 1e10
    (``optimum=True``: 1.0 from 3e6 on, for optimum material, manufacturing and experience). Beyond 1e10 the
    curve's end value is kept (the standard's curve stops there).

    >>> [round(float(life_factor_Y_NT(n, "Eh")), 3) for n in (1e3, 3e6, 1e10)]
    [2.5, 1.0, 0.85]
    >>> round(float(life_factor_Y_NT(1e5, "St")), 4)
    1.727
    """
    kind = _kind(material_kind)
    n = checked("N_L", N_L, 1.0, 1e30)
    n_static, y_static = _LIFE_BY_KIND[kind]
    y_long = 1.0 if optimum is not False and require_bool("optimum", optimum) else 0.85
    xp = ops_of(n)
    ln = xp.log(xp.clip(n, n_static, N_LONG))
    long = ln > _LN_ENDURANCE
    lower = math.log(y_long) * (ln - _LN_ENDURANCE) / (_LN_LONG - _LN_ENDURANCE)
    if xp.all(long):                # every gear beyond the endurance knee (the usual case): one line
        return xp.exp(lower)
    upper = math.log(y_static) * (_LN_ENDURANCE - ln) / (_LN_ENDURANCE - math.log(n_static))
    return xp.exp(xp.where(ln <= _LN_ENDURANCE, upper, lower))
