"""The root side of the factor chain (ISO 6336-3:2019): nominal and actual tooth-root stress, the stress
limit and the safety factor of each gear, from the form factors of :mod:`.root` and the factors of
:mod:`.root_factors`."""
from __future__ import annotations

import numpy as np

from ...errors import GearDesignError
from .materials import STRENGTH_NEEDED_KINDS

__all__ = ["root_side", "root_stress", "root_stress_limit", "Y_ST"]

Y_ST = 2.0   # stress correction factor of the reference test gears (ISO 6336-3:2019 clause 9)


def root_stress(F_t, b, m_n, form, K_A, K_gamma, K_v, K_Fbeta, K_Falpha):
    """σ_F = σ_F0·K_A K_γ K_v K_Fβ K_Fα with σ_F0 = F_t/(b m_n)·(product of the form, stress-correction, helix,
    rim and deep-tooth factors) in MPa (ISO 6336-3:2019 eq. (2), (3); method C: Y_Fa·Y_Sa·Y_ε·Y_β·Y_B).

    >>> round(float(root_stress(10000.0, 50.0, 4.0, 2.2 * 1.9, 1.0, 1.0, 1.1, 1.2, 1.0)), 2)
    275.88
    """
    return np.asarray(F_t) / (np.asarray(b) * m_n) * form * K_A * K_gamma * K_v * K_Fbeta * K_Falpha


def root_stress_limit(sigma_Flim, Y_NT, Y_deltarelT, Y_RrelT, Y_X, Y_ST=Y_ST):
    """σ_FG = σ_Flim·Y_ST·Y_NT·Y_δrelT·Y_RrelT·Y_X in MPa, the tooth-root stress limit with Y_ST = 2 of the
    reference test gear, not the gear's own Y_S (ISO 6336-3:2019 eq. (5)); S_F = σ_FG/σ_F (eq. (1)).

    >>> round(float(root_stress_limit(500.0, 1.0, 1.0, 1.0, 1.0)), 1)
    1000.0
    """
    return np.asarray(sigma_Flim, dtype=float) * Y_ST * Y_NT * Y_deltarelT * Y_RrelT * Y_X


def _root_modules():
    try:
        from . import root, root_factors
    except ImportError:          # the form factors live in their own module; without it the root side is absent
        return None
    return root, root_factors


def root_side(G, g, mats, F_t, widths, m, xs, rack, beta_deg, internal, K_A, K_gamma, grade, Rz_root, n12, life_h,
              method, out, rim=(None, None), refuse=True):
    """Fill ``out`` with the root factors, σ_F1,2, σ_FG1,2 and S_F1,2 of both gears (``refuse`` False: NaN
    for a design without a root section, see :func:`~.root.root_form_factors`)."""
    mods = _root_modules()
    if mods is None:
        for i in (1, 2):
            out[f"sigma_F{i}"] = out[f"sigma_FG{i}"] = out[f"S_F{i}"] = np.full_like(F_t, np.nan)
        out["root_unavailable"] = True
        return
    root, rf = mods
    _root_factors(G, g, mats, F_t, widths, m, xs, rack, beta_deg, internal, K_A, K_gamma, grade, Rz_root, n12,
                  life_h, method, out, root, rf, rim, refuse)


def _root_factors(G, g, mats, F_t, widths, m, xs, rack, beta_deg, internal, K_A, K_gamma, grade, Rz_root, n12,
                  life_h, method, out, root, rf, rim, refuse):
    names = ("Y_F", "Y_S") if method == "B" else ("Y_Fa", "Y_Sa")
    out["Y_beta"] = np.asarray(G.pick("Y_beta", lambda: rf.helix_factor_Y_beta(out["eps_beta"], beta_deg)))
    if method == "B":
        out["Y_DT"] = np.asarray(G.pick("Y_DT", lambda: rf.deep_tooth_factor_Y_DT(out["eps_alpha_n"], grade)))
        extra = out["Y_DT"]
    else:
        out["Y_eps"] = np.asarray(G.pick("Y_eps", lambda: rf.contact_ratio_factor_Y_eps(out["eps_alpha_n"])))
        extra = out["Y_eps"]
    K = (K_A, K_gamma, out["K_v"], out["K_Fbeta"], out["K_Falpha"])
    for i, (mat, z_key, x, b, n) in enumerate(zip(mats, ("z1", "z2"), xs, widths, n12), start=1):
        da = g[f"da{i}"]
        ff = root.root_form_factors(g[f"_{z_key}"], x, da / m, eps_alpha=g["eps_alpha"], beta_deg=beta_deg,
                                    alpha_n_deg=rack.alpha_deg, hfp_star=rack.ha + rack.c, rhofp_star=rack.rho_f,
                                    internal=internal and i == 2, method=method, refuse=refuse)
        YF = np.asarray(G.pick(f"{names[0]}{i}", lambda: ff[names[0]]))
        YS = np.asarray(G.pick(f"{names[1]}{i}", lambda: ff[names[1]]))
        YB = np.asarray(G.pick(f"Y_B{i}", lambda: _rim(rf, rim[i - 1], g[f"h{i}"], m, internal and i == 2)))
        kind = _root_kind(mat.kind, rf)
        N_L = None if life_h is None else 60.0 * n * life_h
        Y_NT = np.asarray(G.pick(f"Y_NT{i}", lambda: np.ones_like(F_t) if N_L is None else rf.life_factor_Y_NT(N_L, kind)))
        Y_d = np.asarray(G.pick(f"Y_deltarelT{i}", lambda: _notch(rf, ff["q_s"], mat, out, i, refuse)))
        Y_R = np.asarray(G.pick(f"Y_RrelT{i}", lambda: rf.relative_surface_factor_Y_RrelT(Rz_root, kind)))
        Y_X = np.asarray(G.pick(f"Y_X{i}", lambda: rf.size_factor_Y_X(m, kind)))
        out.update({f"{names[0]}{i}": YF, f"{names[1]}{i}": YS, f"Y_B{i}": YB, f"Y_NT{i}": Y_NT,
                    f"Y_deltarelT{i}": Y_d, f"Y_RrelT{i}": Y_R, f"Y_X{i}": Y_X, f"q_s{i}": np.asarray(ff["q_s"]),
                    f"root_out_of_range{i}": ~np.asarray(ff.get("in_range", True), dtype=bool)})
        out[f"sigma_F0{i}"] = root_stress(F_t, b, m, YF * YS * out["Y_beta"] * YB * extra, 1.0, 1.0, 1.0, 1.0, 1.0)
        out[f"sigma_F{i}"] = root_stress(F_t, b, m, YF * YS * out["Y_beta"] * YB * extra, *K)
        out[f"sigma_FG{i}"] = root_stress_limit(mat.sigma_Flim_mpa, Y_NT, Y_d, Y_R, Y_X, rf.Y_ST)
        out[f"S_F{i}"] = out[f"sigma_FG{i}"] / out[f"sigma_F{i}"]


def _root_kind(kind, rf):
    """The root module's name of a material kind (one list for the package: materials.MATERIAL_KINDS is it)."""
    return kind


def _rim(rf, s_R_mm, h_t, m, internal):
    """Y_B from the rim thickness s_R (mm) below the root; None: a solid gear (1)."""
    if s_R_mm is None:
        return 1.0
    return rf.rim_factor_Y_B(s_R_mm / h_t) if not internal else rf.rim_factor_Y_B(internal=True, s_R_over_mn=s_R_mm / m)


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
    out[f"strength_clipped{i}"] = limit != mat.yield_mpa
    return rf.relative_notch_sensitivity_Y_delta_relT(q_s, mat.kind, limit_mpa=limit)


# the strength range of the slip-layer table of ISO 6336-3:2019 clause 13 per kind (MPa)
_SLIP_RANGE = {"V": (500.0, 1000.0), "GGG(perl)": (500.0, 1000.0), "GTS": (500.0, 1000.0), "St": (300.0, 400.0),
               "GG": (150.0, 300.0), "GGG(ferr)": (150.0, 300.0)}
