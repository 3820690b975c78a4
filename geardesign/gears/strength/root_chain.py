"""The root side of the factor chain (ISO 6336-3:2019): nominal and actual tooth-root stress, the stress
limit and the safety factor of each gear, from the form factors of :mod:`.root` and the factors of
:mod:`.root_factors`."""
from __future__ import annotations

import functools

import numpy as np

from ...errors import GearDesignError
from .materials import STRENGTH_NEEDED_KINDS
from .ops import once, ops_of, per_load_case

__all__ = ["root_side", "root_stress", "nominal_root_stress", "loaded_root_stress", "root_stress_limit", "Y_ST"]

Y_ST = 2.0   # stress correction factor of the reference test gears (ISO 6336-3:2019 clause 9)
# the chain's keys of each gear's root factors per method: Y_F, Y_S (or Y_Fa, Y_Sa), Y_B, Y_NT, Y_δrelT, Y_RrelT, Y_X
_ROOT_KEYS = {(method, i): tuple(k + i for k in (*names, "Y_B", "Y_NT", "Y_deltarelT", "Y_RrelT", "Y_X"))
              for method, names in (("B", ("Y_F", "Y_S")), ("C", ("Y_Fa", "Y_Sa"))) for i in "12"}
_FORM_KEYS = {"B": ("Y_F", "Y_S", "q_s", "in_range"), "C": ("Y_Fa", "Y_Sa", "q_s", "in_range")}   # of form_factors


def root_stress(F_t, b, m_n, form, K_A, K_gamma, K_v, K_Fbeta, K_Falpha):
    """σ_F = σ_F0·K_A K_γ K_v K_Fβ K_Fα with σ_F0 = F_t/(b m_n)·(product of the form, stress-correction, helix,
    rim and deep-tooth factors) in MPa (ISO 6336-3:2019 eq. (2), (3); method C: Y_Fa·Y_Sa·Y_ε·Y_β·Y_B).

    >>> round(float(root_stress(10000.0, 50.0, 4.0, 2.2 * 1.9, 1.0, 1.0, 1.1, 1.2, 1.0)), 2)
    275.88
    """
    return loaded_root_stress(nominal_root_stress(F_t, b, m_n, form), K_A, K_gamma, K_v, K_Fbeta, K_Falpha)


def nominal_root_stress(F_t, b, m_n, form):
    """σ_F0 = F_t/(b m_n)·(product of the form, stress-correction, helix, rim and deep-tooth factors) in MPa
    (ISO 6336-3:2019 eq. (3)).

    >>> round(float(nominal_root_stress(10000.0, 50.0, 4.0, 2.2 * 1.9)), 2)
    209.0
    """
    xp = ops_of(F_t, b)
    return xp.asarray(F_t) / (xp.asarray(b) * m_n) * form


def loaded_root_stress(sigma_F0, K_A, K_gamma, K_v, K_Fbeta, K_Falpha):
    """σ_F = σ_F0·K_A K_γ K_v K_Fβ K_Fα in MPa (ISO 6336-3:2019 eq. (2)).

    >>> round(float(loaded_root_stress(209.0, 1.0, 1.0, 1.1, 1.2, 1.0)), 2)
    275.88
    """
    return sigma_F0 * K_A * K_gamma * K_v * K_Fbeta * K_Falpha


def root_stress_limit(sigma_Flim, Y_NT, Y_deltarelT, Y_RrelT, Y_X, Y_ST=Y_ST):
    """σ_FG = σ_Flim·Y_ST·Y_NT·Y_δrelT·Y_RrelT·Y_X in MPa, the tooth-root stress limit with Y_ST = 2 of the
    reference test gear, not the gear's own Y_S (ISO 6336-3:2019 eq. (5)); S_F = σ_FG/σ_F (eq. (1)).

    >>> round(float(root_stress_limit(500.0, 1.0, 1.0, 1.0, 1.0)), 1)
    1000.0
    """
    return ops_of(sigma_Flim).asarray(sigma_Flim) * Y_ST * Y_NT * Y_deltarelT * Y_RrelT * Y_X


def _import_root_modules():
    try:
        from . import root, root_factors
    except ImportError:          # the form factors live in their own module; without it the root side is absent
        return None
    return root, root_factors


_ROOT_MODULES = _import_root_modules()


def _root_modules():
    return _ROOT_MODULES


@functools.lru_cache(maxsize=256)
def _surface_factor(Rz_root_um, kind):
    """Y_RrelT of a root roughness and a material kind (both numbers on either path): once for all calls."""
    return _ROOT_MODULES[1].relative_surface_factor_Y_RrelT(Rz_root_um, kind)


def root_side(G, g, mats, F_t, widths, m, xs, rack, beta_deg, internal, K_A, K_gamma, grade, Rz_root, n12, life_h,
              method, out, rim=(None, None), xp=None, refuse=True):
    """Fill ``out`` with the root factors, σ_F1,2, σ_FG1,2 and S_F1,2 of both gears (``refuse`` False: NaN
    for a design without a root section, see :func:`~.root.root_form_factors`)."""
    mods = _root_modules()
    if mods is None:
        for i in "12":
            out["sigma_F" + i] = out["sigma_FG" + i] = out["S_F" + i] = np.full_like(F_t, np.nan)
        out["root_unavailable"] = True
        return
    root, rf = mods
    names = _FORM_KEYS[method]      # Y_F, Y_S (or Y_Fa, Y_Sa) first
    out["Y_beta"] = G["Y_beta"] if "Y_beta" in G else rf.helix_factor_Y_beta(out["eps_beta"], beta_deg)
    if method == "B":
        out["Y_DT"] = extra = G["Y_DT"] if "Y_DT" in G else rf.deep_tooth_factor_Y_DT(out["eps_alpha_n"], grade)
    else:
        out["Y_eps"] = extra = G["Y_eps"] if "Y_eps" in G else rf.contact_ratio_factor_Y_eps(out["eps_alpha_n"])
    gear = (G, g, F_t, m, rack, beta_deg, internal, method, names, out, root, rf, xp or ops_of(F_t), {}, refuse)
    for i, mat, x, b, n, s_R in zip("12", mats, xs, widths, n12, rim):
        YF, YS, YB, Y_NT, Y_delta, Y_R, Y_X = _gear_root(gear, i, mat, x, b, n, s_R, Rz_root, life_h)
        s0 = nominal_root_stress(F_t, b, m, YF * YS * out["Y_beta"] * YB * extra)
        sF = loaded_root_stress(s0, K_A, K_gamma, out["K_v"], out["K_Fbeta"], out["K_Falpha"])
        sFG = root_stress_limit(mat.sigma_Flim_mpa, Y_NT, Y_delta, Y_R, Y_X, rf.Y_ST)
        out.update({"sigma_F0" + i: s0, "sigma_F" + i: sF, "sigma_FG" + i: sFG, "S_F" + i: sFG / sF})


def _gear_root(gear, i, mat, x, b, n, s_R, Rz_root, life_h):
    """Y_F, Y_S (or Y_Fa, Y_Sa), Y_B, Y_NT, Y_δrelT, Y_RrelT, Y_X and q_s of gear ``i`` into the chain's dict; the
    factors, in that order."""
    G, g, F_t, m, rack, beta_deg, internal, method, names, out, root, rf, xp, memo, refuse = gear
    ring = internal and i == "2"
    ff = root.form_factors(g["_z" + i], x, g["da" + i] / m, g["eps_alpha"], beta_deg, rack.alpha_deg, rack.ha + rack.c,
                           rack.rho_f, 0.0, ring, method, names, refuse)
    kind = mat.kind
    N_L = None if life_h is None else 60.0 * n * life_h
    in_range = ff["in_range"]
    kF, kS, kB, kN, kd, kR, kX = _ROOT_KEYS[method, i]
    Y = {kF: G[kF] if kF in G else ff[names[0]],
         kS: G[kS] if kS in G else ff[names[1]],
         kB: G[kB] if kB in G else _rim(rf, s_R, g["h" + i], m, ring),
         kN: G[kN] if kN in G else 1.0 if N_L is None else per_load_case(rf.life_factor_Y_NT, N_L, kind),
         kd: G[kd] if kd in G else _notch(rf, ff["q_s"], mat, out, i, refuse),
         kR: G[kR] if kR in G else _surface_factor(Rz_root, kind),
         kX: G[kX] if kX in G else once(memo, ("Y_X", kind), rf.size_factor_Y_X, m, kind)}
    out.update(Y)
    out["q_s" + i] = ff["q_s"]
    out["root_out_of_range" + i] = (not in_range) if type(in_range) is bool else ~np.asarray(in_range, dtype=bool)
    return tuple(Y.values())


def _rim(rf, s_R_mm, h_t, m, internal):
    """Y_B from the rim thickness s_R (mm) below the root; None: a solid gear (1). A rim thinner than the method
    takes (s_R/h_t <= 0.5, a ring's s_R/m_n <= 1.75) is refused by the caller's name, rim_mm."""
    if s_R_mm is None:
        return 1.0
    ratio, least = (s_R_mm / m, 1.75) if internal else (s_R_mm / h_t, 0.5)
    if ratio <= least if type(ratio) is float else np.any(np.asarray(ratio) <= least):
        base = "m_n" if internal else "h_t"
        raise GearDesignError(f"rim_mm must be > {least:g}·{base} = {float(np.max(least * (m if internal else h_t))):.4g} "
                              f"mm for ISO 6336-3's rim factor Y_B, got {s_R_mm!r}")
    return rf.rim_factor_Y_B(ratio) if not internal else rf.rim_factor_Y_B(internal=True, s_R_over_mn=ratio)


def _notch(rf, q_s, mat, out, i, refuse=True):
    """Y_δrelT; the strength the slip-layer table needs is clipped to the table's range and the result says so.
    ``refuse`` False: NaN where q_s is undefined or outside the form's range (designs without a root section)."""
    if not refuse:
        lo, hi = rf.NOTCH_Q_S_RANGE
        bad = ~((q_s >= lo) & (q_s <= hi))
        if np.any(bad):
            return np.where(bad, np.nan, _notch(rf, np.where(bad, lo, q_s), mat, out, i))
    if mat.kind not in STRENGTH_NEEDED_KINDS:
        return rf.relative_notch_sensitivity_Y_delta_relT(q_s, mat.kind)
    if mat.yield_mpa is None:
        raise GearDesignError(f"material {mat.name!r} (kind {mat.kind}) needs yield_mpa for the relative notch "
                              "sensitivity Y_deltarelT (ISO 6336-3:2019 clause 13): give it to material() or Material()")
    lo, hi = _SLIP_RANGE[mat.kind]
    limit = min(max(mat.yield_mpa, lo), hi)
    out["strength_clipped" + i] = limit != mat.yield_mpa
    return rf.relative_notch_sensitivity_Y_delta_relT(q_s, mat.kind, limit_mpa=limit)


# the strength range of the slip-layer table of ISO 6336-3:2019 clause 13 per kind (MPa)
_SLIP_RANGE = {"V": (500.0, 1000.0), "GGG(perl)": (500.0, 1000.0), "GTS": (500.0, 1000.0), "St": (300.0, 400.0),
               "GG": (150.0, 300.0), "GGG(ferr)": (150.0, 300.0)}
