"""The ISO 6336 factor chain of a gear pair, vectorised: geometry (from :func:`pair_geometry`), load, the
part-1 factors, contact (part 2) and root (part 3) stresses and the safety factors, for any number of
designs in one call; and the one-pair path that returns a :class:`StrengthResult`.
"""
from __future__ import annotations

import functools
import inspect
import math
import operator
from types import SimpleNamespace

import numpy as np

from ...errors import GearDesignError
from ...validate import broadcast_inputs, one_number, require_bool
from ..geometry import (DESIGNS_MAX, mesh_geometry, mesh_geometry_float, pair_geometry, validate_geometry,
                        validate_inputs)
from ..inputs import plain_inputs_ok
from ..mesh import Mesh, mesh_of, section_constants
from ..rack import STANDARD_RACK, BasicRack
from . import accuracy as acc
from . import contact as zc
from . import defaults as dflt
from . import factors as kf
from .blocks import BLOCK, batch_shape, in_blocks
from .life import contact_life_factor, load_cycles
from .load import Load
from .materials import Material, material as material_by_name
from .ops import ArrayOps, FloatOps, MixedOps, checked, once, per_load_case
from ...renamed import grouped_keywords
from .options import DEFAULT_OPTIONS, GROUPED, StrengthOptions, blank_option, gathered, shaft_option, transverse_option, validate_options
from .result import StrengthResult, from_chain, load_case
from .root_chain import root_side

__all__ = ["pair_strength", "strength", "chain_geometry", "GIVEN_FACTORS", "STRENGTH_FIELDS", "CHAIN_GEOMETRY_FIELDS"]

# Factors a caller may give instead of their computation (measured values, as the standard allows).
GIVEN_FACTORS = frozenset({
    "K_v", "K_Hbeta", "K_Fbeta", "K_Halpha", "K_Falpha", "c_prime", "c_gamma_alpha", "c_gamma_beta",
    "Z_H", "Z_E", "Z_eps", "Z_beta", "Z_B", "Z_D", "Z_NT1", "Z_NT2", "Z_L1", "Z_L2", "Z_v1", "Z_v2", "Z_R1",
    "Z_R2", "Z_W1", "Z_W2", "Z_X", "Y_F1", "Y_F2", "Y_S1", "Y_S2", "Y_Fa1", "Y_Fa2", "Y_Sa1", "Y_Sa2", "Y_eps",
    "Y_beta", "Y_B1", "Y_B2", "Y_DT", "Y_NT1", "Y_NT2", "Y_deltarelT1", "Y_deltarelT2", "Y_RrelT1", "Y_RrelT2",
    "Y_X1", "Y_X2", "f_pb", "f_falpha", "F_beta", "f_Hbeta", "f_sh", "f_ma", "C_a",
})
# The stresses and safety factors every call returns (MPa; S dimensionless).
STRENGTH_FIELDS = ("S_H1", "S_H2", "S_F1", "S_F2", "sigma_H0", "sigma_H1", "sigma_H2", "sigma_F1", "sigma_F2",
                   "sigma_HP1", "sigma_HP2", "sigma_FP1", "sigma_FP2")
# the geometry fields the chain reads (of pair_geometry, or of the caller's mesh_geometry dict)
CHAIN_GEOMETRY_FIELDS = ("a_w", "d1", "d2", "db1", "db2", "dw1", "dw2", "da1", "da2", "df1", "df2", "eps_alpha", "p_b")
_GEOMETRY = list(CHAIN_GEOMETRY_FIELDS)
_SMALL = 64   # designs: up to this many, the pair-wide fields are filled arrays instead of broadcast views
_PITTING_KEYS = {i: tuple(k + i for k in ("Z_NT", "Z_L", "Z_v", "Z_R", "Z_W", "N_L", "sigma_HG", "S_H", "sigma_H"))
                 for i in "12"}   # per gear
# factors of the materials, the rack and the options alone (numbers on either path): each computed once for all calls
_elasticity_factor = functools.lru_cache(maxsize=256)(zc.elasticity_factor)
_basic_rack_factor = functools.lru_cache(maxsize=256)(kf.basic_rack_factor)
_tip_relief_running_in = functools.lru_cache(maxsize=256)(kf.tip_relief_running_in)
_lubricant_factor = functools.lru_cache(maxsize=256)(zc.lubricant_factor)


class _Given(dict):
    """The factors given by the caller, by name, and which of them were used (read). A step of the chain takes a
    factor as ``G[name] if name in G else <its formula>``: nothing is computed for a given factor, and the usual
    case (nothing given) costs one look-up."""

    def __init__(self, factors):
        super().__init__()
        self.used = set()
        if factors is None:
            return
        if not isinstance(factors, dict):
            raise GearDesignError(f"factors must be a dict of factor names to values, got {type(factors).__name__}")
        for name, value in factors.items():
            if name not in GIVEN_FACTORS:
                raise GearDesignError(f"factors: unknown factor {name!r}; allowed: {', '.join(sorted(GIVEN_FACTORS))}")
            # deviations and stiffness (µm, N/(mm·µm)) and Z_E (√MPa) are not dimensionless factors near 1
            lo, hi = (0.0, 1e4) if name[0] in "fFCc" or name == "Z_E" else dflt.FACTOR_RANGE
            self[name] = checked(f"factors[{name!r}]", value, lo, hi)

    def __getitem__(self, name):
        self.used.add(name)
        return dict.__getitem__(self, name)


def _material(value, name):
    if isinstance(value, Material):
        return value
    if isinstance(value, str):
        return material_by_name(value)
    raise GearDesignError(f"{name} must be a geardesign Material or a material name, got {type(value).__name__}")


def _geometry(m, z1, z2, x1, x2, rack, beta_deg, internal, tip_shortening, plain):
    """The geometry fields the chain needs, from pair_geometry (validated there), and the section constants."""
    if plain and isinstance(rack, BasicRack):
        # one design in plain numbers: the float path of the geometry (validated as pair_geometry does)
        if not plain_inputs_ok(m, x1, x2):        # the tooth counts: Mesh's
            validate_inputs(m, z1, z2, x1, x2)
        mesh = Mesh(z1, z2, rack, tip_shortening, beta_deg, internal)
        geo = mesh_geometry_float(mesh, m, x1, x2, full=False, tips=False)
        if not (geo["inv_alpha_w"] > 0 and geo["_gap1"] > 0 and geo["_gap2"] > 0 and geo["df1"] > 0
                and geo["df2"] > 0):
            validate_geometry(mesh_geometry(mesh, m, x1, x2, full=False), mesh)
        return _derived({k: float(geo[k]) for k in _GEOMETRY}, float(z1), float(z2), rack, beta_deg, FloatOps)
    if np.size(x1) > 1 or np.size(x2) > 1:
        # pair_geometry(fields=...) of one pair (m, z1, z2 numbers) over more than one block of shifts fills the
        # pair-wide fields at the full size in each block and fails: give it m at the designs' shape instead
        m = np.broadcast_to(np.asarray(m, dtype=float), np.broadcast_shapes(np.shape(m), np.shape(x1), np.shape(x2)))
    geo = pair_geometry(m, z1, z2, x1, x2, rack=rack, tip_shortening=tip_shortening, fields=_GEOMETRY,
                        beta_deg=beta_deg, internal=internal)
    return _derived({k: np.asarray(getattr(geo, k), dtype=float) for k in _GEOMETRY}, np.asarray(z1, dtype=float),
                    np.asarray(z2, dtype=float), rack, beta_deg, ArrayOps)


def _derived(g, z1, z2, rack, beta_deg, xp):
    """α_wt (from d_b1/d_w1), α_t, β_b, z_n, tooth depths: what the chain reads besides pair_geometry's fields."""
    sc = section_constants(rack.alpha, math.radians(beta_deg))
    with xp.errstate(invalid="ignore"):
        g["cos_alpha_wt"] = xp.minimum(g["db1"] / g["dw1"], 1.0)
        g["alpha_wt_deg"] = xp.degrees(xp.arccos(g["cos_alpha_wt"]))
    g["alpha_t_deg"] = math.degrees(sc.alpha_t)
    g["beta_b_deg"] = math.degrees(sc.beta_b)
    zn = 1.0 / (sc.cos_beta_b ** 2 * sc.cos_beta)
    g["_z1"], g["_z2"] = z1, z2
    g["z_n1"], g["z_n2"] = z1 * zn, z2 * zn
    g["h1"] = (g["da1"] - g["df1"]) / 2.0
    g["h2"] = xp.abs(g["da2"] - g["df2"]) / 2.0
    return g


def chain_geometry(geo: dict, rack: BasicRack, beta_deg: float, xp=ArrayOps) -> dict:
    """The fields the chain reads, from a geometry dict of :func:`~geardesign.gears.geometry.mesh_geometry`
    (with its path of contact) instead of a validated :func:`pair_geometry`: designs that do not exist give
    NaN (the strength checks of the shift solvers mask them). ``xp`` :class:`FloatOps`: one design's dict of
    :func:`~geardesign.gears.geometry.mesh_geometry_float` (a :class:`~geardesign.GearPair`'s)."""
    with xp.errstate(invalid="ignore"):
        return _derived(dict(zip(_GEOMETRY, map(xp.asarray, map(geo.__getitem__, _GEOMETRY)))),
                        xp.asarray(geo["_z1"]), xp.asarray(geo["_z2"]), rack, beta_deg, xp)


def _widths(face_width_mm, face_width2_mm, m, xp):
    """(b, b1, b2): the common width for contact and each gear's width for its root stress, the wider gear
    counted at most one module wider on each side (ISO 6336-3:2019 clause 5, b)."""
    b1 = checked("face_width_mm", face_width_mm, *dflt.FACE_WIDTH_RANGE_MM, unit="mm")
    if face_width2_mm is None:      # one width: min(b1, b1 + 2m) is b1
        return b1, b1, b1
    b2 = checked("face_width2_mm", face_width2_mm, *dflt.FACE_WIDTH_RANGE_MM, unit="mm")
    b = xp.minimum(b1, b2)
    return b, xp.minimum(b1, b + 2.0 * m), xp.minimum(b2, b + 2.0 * m)


def _speeds(load: Load, z1, z2):
    """(T1 in N·m, n1, n2 in rpm): the load carried over to the pinion (gear 1); the given gear's as numbers (its
    life factors then are numbers too, one for all designs)."""
    u = z2 / z1
    if load.on_gear == 1:
        return load.torque_nm, load.n_rpm, load.n_rpm / u
    return load.torque_nm / u, load.n_rpm * u, load.n_rpm


def _deviations(G, m, g, b, grade, xp):
    """ISO 1328-1:1995 deviations of the pair (µm): f_pb, f_fα, F_β, f_Hβ — the larger gear's (the wheel's
    larger diameter gives the larger tolerance); f_pb = f_pt·cos α_t, the single pitch deviation on the base
    circle."""
    d = xp.maximum(g["d1"], g["d2"])
    cos_t = math.cos(math.radians(g["alpha_t_deg"]))
    return {"f_pb": G["f_pb"] if "f_pb" in G else acc.single_pitch_deviation(m, d, grade) * cos_t,
            "f_falpha": G["f_falpha"] if "f_falpha" in G else acc.profile_form_deviation(m, d, grade),
            "F_beta": G["F_beta"] if "F_beta" in G else acc.helix_deviation_total(d, b, grade),
            "f_Hbeta": G["f_Hbeta"] if "f_Hbeta" in G else acc.helix_slope_deviation(d, b, grade)}


def _stiffness(G, g, x1, x2, rack, beta_deg, w_A, internal, C_R, out):
    """c′_th, c′, c_γα, c_γβ (ISO 6336-1:2019 clause 9) and the regression's range flag. A ring's shift enters
    with ISO 21771's sign (x_ISO = −x of this project's GOST 19274 convention, as its tooth count is −z there).
    ``C_R``: the gear blank factor (1.0: solid disc gears)."""
    x2 = -x2 if internal else x2
    c_th = kf.theoretical_single_stiffness(g["z_n1"], g["z_n2"], x1, x2, internal)
    C_B = _basic_rack_factor(rack.ha + rack.c, rack.alpha_deg)
    c_prime = G["c_prime"] if "c_prime" in G else kf.single_stiffness(c_th, C_B, beta_deg, w_A, C_R=C_R)
    c_ga, c_gb = kf.mesh_stiffness(c_prime, g["eps_alpha"])
    out.update(c_th=c_th, C_B=C_B, C_R=C_R, c_prime=c_prime,
               c_gamma_alpha=G["c_gamma_alpha"] if "c_gamma_alpha" in G else c_ga,
               c_gamma_beta=G["c_gamma_beta"] if "c_gamma_beta" in G else c_gb)
    xs = x1 + x2
    lo, hi = kf.STIFFNESS_X_SUM_RANGE
    out["stiffness_out_of_range"] = (xs < lo) | (xs > hi) | (x1 < x2)


def _dynamic(G, g, mats, n1, w_A, dev, tip_relief_um, bore, eps_gamma, internal, v, xp, out):
    """K_v by method B with the running-in allowance y_α (ISO 6336-1:2019 6.5.9)."""
    y_a = _pair_mean(mats, lambda mat: kf.running_in_alpha(dev["f_pb"], mat.sigma_Hlim_mpa, mat.kind, v))
    C_a = (G["C_a"] if "C_a" in G else tip_relief_um if tip_relief_um is not None else
           _pair_mean(mats, lambda mat: _tip_relief_running_in(mat.sigma_Hlim_mpa)))
    d_m1 = (g["da1"] + g["df1"]) / 2.0
    m_red = kf.reduced_mass(d_m1, g["db1"], g["d2"] / g["d1"], bore[0], bore[1], internal=internal)
    n_E1 = kf.resonance_speed(g["_z1"], out["c_gamma_alpha"], m_red)
    N = kf.resonance_ratio(n1, n_E1)
    c = out["c_prime"]
    B_p = c * xp.maximum(dev["f_pb"] - y_a, 0.0) / w_A
    B_f = c * xp.maximum(dev["f_falpha"] - y_a, 0.0) / w_A
    B_k = xp.abs(1.0 - out["c_gamma_alpha"] * C_a / w_A)
    N_S = kf.subcritical_limit(w_A)
    K_v = G["K_v"] if "K_v" in G else kf.dynamic_factor(N, eps_gamma, B_p, B_f, B_k, w_A, N_S=N_S)
    out.update(y_alpha=y_a, C_a=C_a, m_red=m_red, n_E1=n_E1, N=N, K_v=K_v, K_v_resonance=(N > N_S) & (N < 1.5))


def _pair_mean(mats, f):
    """(f(material1) + f(material2))/2, the pair's value of a per-material allowance (ISO 6336-1: the mean of the two
    gears'); one evaluation for one material on both gears ((a + a)/2 is a, exactly)."""
    a = f(mats[0])
    return a if mats[1] is mats[0] else (a + f(mats[1])) / 2.0


def _face_load(G, g, mats, F_t, b, K_A, dev, v, shaft, xp, out):
    """K_Hβ by method C from F_βy (ISO 6336-1:2019 7.6; f_sh, F_βx, y_β per 2006/Cor.1:2008) and K_Fβ."""
    w_m = F_t * K_A * out["K_v"] / b

    def compute():
        f_sh = G["f_sh"] if "f_sh" in G else kf.shaft_misalignment(w_m, b, g["d1"], **shaft)
        f_ma = G["f_ma"] if "f_ma" in G else dev["f_Hbeta"]
        F_bx = kf.helix_misalignment(f_sh, f_ma, w_m, dev["F_beta"])
        y_b = _pair_mean(mats, lambda mat: kf.running_in_beta(F_bx, mat.sigma_Hlim_mpa, mat.kind, v))
        out.update(f_sh=f_sh, f_ma=f_ma, F_betax=F_bx, y_beta=y_b, F_betay=F_bx - y_b)
        return kf.face_load_factor_H(F_bx - y_b, out["c_gamma_beta"], w_m)

    K_Hb = G["K_Hbeta"] if "K_Hbeta" in G else compute()
    b_over_h = xp.minimum(b / g["h1"], b / g["h2"])
    N_F = kf.face_load_exponent(b_over_h)
    out.update(K_Hbeta=K_Hb, N_F=N_F, K_Fbeta=G["K_Fbeta"] if "K_Fbeta" in G else kf.face_load_factor_F(K_Hb, N_F))


def _transverse(G, g, F_t, b, K_A, dev, eps_gamma, Z_eps, root_method, which, xp, out):
    """K_Hα and K_Fα by method B, limited to their ranges (ISO 6336-1:2019 8.3.2-8.3.4); ``which`` deviation enters
    (:func:`~.factors.transverse_deviation`: the larger of f_pb and f_fα, or f_pb)."""
    w_H = F_t * K_A * out["K_v"] * out["K_Hbeta"] / b
    f_alpha = kf.transverse_deviation(dev["f_pb"], dev["f_falpha"], which)
    out["f_Kalpha"] = f_alpha
    raw = kf.transverse_load_factor(eps_gamma, out["c_gamma_alpha"], f_alpha - out["y_alpha"], w_H)
    hi_H, hi_F = kf.transverse_load_limits(eps_gamma, g["eps_alpha"], Z_eps)
    if root_method == "C":   # ISO 6336-1:2006 eq. (76): ε_γ/(ε_α Y_ε) with the tip-load method's Y_ε
        hi_F = eps_gamma / (g["eps_alpha"] * (0.25 + 0.75 / out["eps_alpha_n"]))
    hi_H, hi_F = xp.maximum(hi_H, 1.0), xp.maximum(hi_F, 1.0)
    out.update(K_Halpha=G["K_Halpha"] if "K_Halpha" in G else xp.clip(raw, 1.0, hi_H),
               K_Falpha=G["K_Falpha"] if "K_Falpha" in G else xp.clip(raw, 1.0, hi_F),
               K_Halpha_limited=raw > hi_H, K_Falpha_limited=raw > hi_F)


def _contact(G, g, mats, F_t, b, K_A, K_gamma, v, n12, life_h, nu40, Rz, life_opts, internal, xp, out):
    """σ_H0, σ_H1,2 and the pitting side of each gear (ISO 6336-2:2019)."""
    m1, m2 = mats
    # α_wt's sine and tangent from its cosine d_b1/d_w1 (numpy's sin and cos cost ~5 divisions each)
    c_w = g["cos_alpha_wt"]
    s_w = xp.sqrt((1.0 - c_w) * (1.0 + c_w))
    t_w = s_w / c_w
    out["Z_H"] = G["Z_H"] if "Z_H" in G else zc.zone_factor_of(math.cos(math.radians(g["beta_b_deg"])),
                                                                 math.cos(math.radians(g["alpha_t_deg"])), c_w, s_w)
    out["Z_E"] = G["Z_E"] if "Z_E" in G else _elasticity_factor(m1.E_mpa, m1.nu, m2.E_mpa, m2.nu)
    ZB, ZD = zc.single_pair_factors_of(g["db1"], g["db2"], g["da1"], g["da2"], s_w, t_w, g["a_w"], g["eps_alpha"],
                                       out["eps_beta"], g["p_b"], internal, g["_z2"] / g["_z1"])
    out["Z_B"], out["Z_D"] = G["Z_B"] if "Z_B" in G else ZB, G["Z_D"] if "Z_D" in G else ZD
    s0 = zc.nominal_contact_stress(F_t, g["d1"], b, g["d2"] / g["d1"], out["Z_H"], out["Z_E"], out["Z_eps"],
                                   out["Z_beta"], internal)
    K = (K_A, K_gamma, out["K_v"], out["K_Hbeta"], out["K_Halpha"])
    out["sigma_H0"] = s0
    out["sigma_H1"], out["sigma_H2"] = zc.contact_stress(s0, out["Z_B"], *K), zc.contact_stress(s0, out["Z_D"], *K)
    rho_red = zc.relative_radius(g["db1"] / 2.0 * t_w, g["db2"] / 2.0 * t_w, internal)
    out["Z_X"] = G["Z_X"] if "Z_X" in G else zc.SIZE_FACTOR_Z_X
    hard = (m1.surface_hardened, m2.surface_hardened)
    memo = {}
    for i, mat, n, softer in zip("12", mats, n12, ((not hard[0]) and hard[1], (not hard[1]) and hard[0])):
        _pitting(G, mat, i, n, life_h, nu40, Rz, v, rho_red, softer, life_opts, s0, xp, out, memo)


def _pitting(G, mat, i, n, life_h, nu40, Rz, v, rho_red, softer, life_opts, s0, xp, out, memo):
    """Z_NT, Z_L, Z_v, Z_R, Z_W, σ_HG and S_H of gear ``i`` (ISO 6336-2:2019 clauses 10-14); Z_L, Z_v, Z_R depend
    on the gear through σ_Hlim alone (``memo``: computed once for two gears of one σ_Hlim; Z_L, of the material and
    the lubricant alone, once for all calls)."""
    s = mat.sigma_Hlim_mpa
    N_L = None if life_h is None else load_cycles(n, life_h)
    nt, zl, zv, zr, zw, nl, hg, sh, sigma_H = _PITTING_KEYS[i]
    Z_NT = G[nt] if nt in G else 1.0 if N_L is None else per_load_case(contact_life_factor, N_L, mat.kind, *life_opts)
    Z_L = G[zl] if zl in G else _lubricant_factor(nu40, s)
    Z_v = G[zv] if zv in G else once(memo, ("Z_v", s), zc.velocity_factor, v, s)
    Z_R = G[zr] if zr in G else once(memo, ("Z_R", s), zc.roughness_factor, Rz, Rz, rho_red, s)
    Z_W = G[zw] if zw in G else zc.work_hardening_factor(mat.brinell, softer)
    sigma_HG = zc.contact_stress_limit(s, Z_NT, Z_L, Z_v, Z_R, Z_W, out["Z_X"])
    out.update({nt: Z_NT, zl: Z_L, zv: Z_v, zr: Z_R, zw: Z_W, nl: math.nan if N_L is None else N_L,
                hg: sigma_HG, sh: zc.contact_safety(sigma_HG, out[sigma_H])})


@grouped_keywords("options", StrengthOptions, GROUPED)
def pair_strength(m, z1=None, z2=None, x1=0.0, x2=0.0, *, load: Load, material1, material2=None, face_width_mm=None,
                  face_width2_mm=None, beta_deg: float = 0.0, internal: bool = False, rack: BasicRack | None = None,
                  tip_shortening: bool = True, root: bool = True, geometry: dict | None = None,
                  options: StrengthOptions | None = None, fields=None, mesh: Mesh | None = None) -> dict:
    """ISO 6336 load capacity of gear pairs, vectorised: m (normal module, mm), z1, z2, x1, x2 and the face
    widths broadcast like :func:`~geardesign.gears.geometry.pair_geometry`, whose geometry (operating
    pressure angle, ε_α, diameters) is used as it is. Returns a dict of float arrays: the stresses and safety
    factors of :data:`STRENGTH_FIELDS`, every factor by its ASCII symbol (per gear with a suffix 1 or 2),
    flags of ranges left (``stiffness_out_of_range``, ``K_v_resonance``, ``K_Halpha_limited``, ...) and
    ``given``, the names of the factors taken from ``factors`` instead of computed.

    ``load``: a :class:`Load` (torque or power at the speed of the gear it is given on). ``material1``,
    ``material2``: :class:`Material` or catalog names (``material2`` defaults to ``material1``).
    ``face_width_mm`` (gear 1, both if ``face_width2_mm`` is None). ``accuracy_grade``: ISO 1328-1:1995
    grade (0-12). ``nu40``: lubricant viscosity at 40 °C, mm²/s. ``Rz_flank_um``, ``Rz_root_um``: mean peak-to-
    valley roughness; ``Rz_flank_um`` is the mean of the two gears' flanks, R_z = (R_z1 + R_z2)/2 of Z_R
    (ISO 6336-2:2019 eq. (29)): give that mean when the flanks differ. ``root_method``: "B" (ISO 6336-3:2019) or "C" (tip load, Y_ε). ``factors``: measured or
    agreed values of any of :data:`GIVEN_FACTORS`. ``K_gamma``: mesh load factor (planetary sets).
    ``tip_relief_um``: C_a (default C_ay of running-in). ``bore_ratio``: (q1, q2) for the reduced mass.
    ``shaft``: the pinion shaft of ISO 6336-1 eq. (44), a dict of numbers ``K_prime``, ``l_mm``, ``s_mm``, ``d_sh_mm``
    (their ranges: :data:`~geardesign.gears.strength.options.SHAFT_RANGES`; see
    :func:`~geardesign.gears.strength.factors.shaft_misalignment`).
    ``pitting_permitted``, ``optimum_life``: choose the Z_NT curve (ISO 6336-2:2019 Table 2). ``S_Hmin``,
    ``S_Fmin``: the minimum safety factors for σ_HP = σ_HG/S_Hmin and σ_FP = σ_FG/S_Fmin (defaults and their
    source: :mod:`~geardesign.gears.strength.defaults`). ``cycles_per_rev``: load cycles of a tooth per revolution of
    each gear (a sun among N planets: N). ``rim_mm``: (s_R1, s_R2) rim thickness under the root for Y_B (None: solid).
    ``options``: a :class:`~geardesign.gears.strength.options.StrengthOptions` holding the options above (from
    ``accuracy_grade`` to ``rim_mm``) in one object, instead of the keywords (giving both is refused).
    ``root=False`` leaves the root side out (no S_F, σ_F, Y fields): half the work where only contact is asked.
    ``geometry``: the pair's geometry dict when the caller has it (:func:`~geardesign.gears.geometry.mesh_geometry`
    of these designs: the strength checks of the shift solvers); it is used unvalidated, so designs that do not
    exist, or (given as arrays) have no root section, give NaN rather than an error. A batch larger than
    :data:`~.blocks.BLOCK` runs in blocks, its per-design fields rows of one array per dtype (copy one to keep alone).
    ``gear_blank``: None (solid disc gears, C_R = 1) or the webbed wheels' (b_s/b, s_R/m_n), web thickness over face
    width and rim thickness over module, for the gear blank factor C_R of c′ (ISO 6336-1:2019 9.3.3); per gear
    ``((b_s/b, s_R/m_n) or None, (b_s/b, s_R/m_n) or None)`` takes the mean of the two gears' C_R.
    ``transverse_deviation``: the deviation of K_Hα, K_Fα, ``"larger"`` of f_pb and f_fα (ISO 6336-1:2006 8.3.2) or
    ``"f_pb"`` (see :func:`~geardesign.gears.strength.factors.transverse_deviation`).
    ``fields``: names of the result to return (with ``given`` and ``given_unused``), None for all: a large batch
    then keeps only those at full size (10⁷ designs: ~0.6 GB for two fields instead of ~5.7 GB for every one);
    a name the result does not have is refused with the list of those it has.
    ``mesh``: a :class:`~geardesign.gears.mesh.Mesh` instead of z1, z2, ``rack``, ``tip_shortening``, ``beta_deg``,
    ``internal`` and ``face_width_mm`` (its face width is the pair's; giving both ways is refused by name).
    """
    if mesh is not None or z1 is None or z2 is None:
        mesh = mesh_of(mesh, z1, z2, rack, tip_shortening, beta_deg, internal, face_width_mm)
        z1, z2, rack, tip_shortening = mesh.z1, mesh.z2, mesh.rack, mesh.tip_shortening
        beta_deg, internal, face_width_mm = mesh.beta_deg, mesh.internal, mesh.face_width_mm
    if face_width_mm is None:
        raise GearDesignError("face_width_mm (mm) is needed for the load capacity: give it, or a mesh= with its "
                              "face_width_mm")
    if options is None:
        options = DEFAULT_OPTIONS
    elif not isinstance(options, StrengthOptions):
        raise GearDesignError(f"options must be a geardesign StrengthOptions, got {type(options).__name__}")
    (accuracy_grade, nu40, Rz_flank_um, Rz_root_um, root_method, factors, K_gamma, tip_relief_um, bore_ratio, shaft,
     pitting_permitted, optimum_life, S_Hmin, S_Fmin, cycles_per_rev, rim_mm, gear_blank,
     transverse_deviation) = (getattr(options, k) for k in GROUPED)
    rack = STANDARD_RACK if rack is None else rack
    if not isinstance(load, Load):
        raise GearDesignError(f"load must be a geardesign Load, got {type(load).__name__}")
    mats = (_material(material1, "material1"), _material(material1 if material2 is None else material2, "material2"))
    raw = (accuracy_grade, nu40, Rz_flank_um, Rz_root_um, K_gamma, root_method, S_Hmin, S_Fmin, cycles_per_rev, rim_mm,
           bore_ratio, tip_relief_um)
    # the defaults (the very objects of the signature) were checked once, at import
    checked_options = _DEFAULTS_CHECKED if all(map(operator.is_, raw, _DEFAULTS)) else validate_options(*raw)
    grade, nu40, Rz, Rz_root, K_gamma, root_method, S_min, cpr, rim_mm, bore_ratio, tip_relief_um = checked_options
    designs = (m, z1, z2, x1, x2, face_width_mm, face_width2_mm)
    plain = _plain_numbers(designs[:6]) and (face_width2_mm is None or _plain_numbers(designs[6:]))
    if geometry is None and not plain and not _plain_numbers(designs[:5]):
        # ragged lists and shapes that do not broadcast refused by name before any work (arrays' values are
        # checked by the geometry, once)
        if not all(isinstance(v, (np.ndarray, int, float, np.number)) for v in (m, z1, z2, x1, x2)):
            validate_inputs(m, z1, z2, x1, x2)
        try:
            np.broadcast_shapes(*(np.shape(v) for v in (m, z1, z2, x1, x2, face_width_mm)))
        except ValueError:
            broadcast_inputs(m=m, z1=z1, z2=z2, x1=x1, x2=x2, face_width_mm=face_width_mm)
    o = SimpleNamespace(load=load, mats=mats, grade=grade, nu40=nu40, Rz=Rz, Rz_root=Rz_root, K_gamma=K_gamma,
                        root_method=root_method, cpr=cpr, tip_relief_um=tip_relief_um, bore=bore_ratio,
                        shaft=shaft_option(shaft),
                        life=(pitting_permitted, optimum_life), rim=rim_mm,
                        root=require_bool("root", root), S_min=S_min, rack=rack, beta_deg=beta_deg,
                        internal=internal, tip_shortening=tip_shortening, geometry=geometry,
                        C_R=blank_option(gear_blank), transverse_deviation=transverse_option(transverse_deviation))
    float_geometry = geometry is None or _FLOAT.issuperset(map(type, map(geometry.__getitem__, _GEOMETRY)))
    o.refuse = float_geometry          # a pair's own (validated) geometry: a design without a root section is refused
    G = _Given(factors)
    o.keep = None if fields is None else _field_names(fields)
    if plain and float_geometry:
        # one design in Python floats: the formulas on math, not numpy (see .ops); a load whose torque or speed is an
        # array (the bins of a spectrum, service_life's) with the design's own factors on math and the bins' on numpy
        bins = type(load.torque_nm) is np.ndarray or type(load.n_rpm) is np.ndarray
        try:
            return _only(_finite(_evaluate(_floats(designs), G, o, MixedOps if bins else FloatOps), designs, o,
                                 plain=not bins), o.keep)
        except GearDesignError:
            raise
        except (ArithmeticError, ValueError):   # math's domain error where numpy gives NaN: the array path says why
            G.used.clear()
    with np.errstate(all="ignore"):            # what is not finite is refused by name below (or is NaN on purpose)
        return _only(_evaluate_batch(designs, G, o), o.keep)


def _field_names(fields) -> tuple:
    """``fields`` of :func:`pair_strength`: a name or names (text)."""
    names = (fields,) if isinstance(fields, str) else tuple(fields) if hasattr(fields, "__iter__") else None
    if not names or not all(isinstance(f, str) for f in names):
        raise GearDesignError(f"fields must be names of pair_strength's result (such as "
                              f"{', '.join(STRENGTH_FIELDS[:4])}), got {fields!r}")
    return names


def _only(out: dict, keep) -> dict:
    """The fields ``keep`` of a result (with the given factors' names), all with None; a name it lacks refused."""
    if keep is None:
        return out
    missing = [k for k in keep if k not in out]
    if missing:
        raise GearDesignError(f"fields: {', '.join(map(repr, missing))} not in pair_strength's result; it has "
                              f"{', '.join(k for k in out if not k.startswith('given'))}")
    return {**{k: out[k] for k in keep}, "given": out["given"], "given_unused": out["given_unused"]}


# the factors whose formulas can leave their domain for a design that exists (first named when one does)
_DOMAIN_FACTORS = ("Z_B", "Z_D", "Z_H", "Z_eps", "K_v", "K_Hbeta", "K_Halpha", "Y_F1", "Y_F2", "Y_S1", "Y_S2",
                   "Y_Fa1", "Y_Fa2", "Y_Sa1", "Y_Sa2", "Y_deltarelT1", "Y_deltarelT2")


def _finite(out: dict, designs, o, plain=False) -> dict:
    """``out`` when its stresses and safety factors are finite, or where NaN is asked for (a caller's unvalidated
    geometry); else a refusal that names the design and the first factor out of its formula's domain (an
    undercut pinion whose inner point of single contact lies below its base circle: Z_B, say). ``plain``: one
    design in numbers, whose sum is finite when each is (a NaN or an infinity carries into it)."""
    if not o.refuse or plain and math.isfinite(sum(_PLAIN_STRESSES[o.root](out))):
        return out
    # the fields as the chain left them where fields= was given (see _finish): a pair-wide one at its own shape
    stresses = [np.asarray(out[k], dtype=float) for k in STRENGTH_FIELDS if k in out]
    bad = np.zeros(np.broadcast_shapes(*(v.shape for v in stresses)), dtype=bool)
    for v in stresses:
        bad |= ~np.isfinite(v)
    if not bad.any():
        return out
    at = tuple(np.argwhere(bad)[0]) if bad.ndim else ()
    factor = next((k for k in _DOMAIN_FACTORS if k in out and not np.all(np.isfinite(
        np.broadcast_to(np.asarray(out[k]), bad.shape)[at] if np.ndim(out[k]) else out[k]))), "a stress")
    values = ", ".join(f"{n}={np.asarray(v, dtype=float)[at] if np.ndim(v) else v}"
                       for n, v in zip(("m", "z1", "z2", "x1", "x2"), designs[:5]))
    raise GearDesignError(f"no ISO 6336 result for the design {values}: {factor} is not finite there (outside its "
                          f"formula's domain: an undercut pinion, a contact below a base circle, an extreme load)")


_FLOAT, _INT_FLOAT = frozenset({float}), frozenset({int, float})
# the stresses and safety factors of one design, with the root side (root=True) and without it
_PLAIN_STRESSES = {True: operator.itemgetter(*STRENGTH_FIELDS),
                   False: operator.itemgetter(*(k for k in STRENGTH_FIELDS if "_F" not in k))}


def _plain_numbers(values) -> bool:
    """True when every value is a Python int or float (one design in plain numbers)."""
    return _INT_FLOAT.issuperset(map(type, values))


def check_options(options: dict) -> dict:
    """``options`` for :func:`pair_strength`, refused by name when one is not one of its keywords or when a
    number, a given factor or the shaft is out of its range (before any work: a checks dict's strength checks
    would otherwise fail at every design rather than say why)."""
    if not options.keys() <= _OPTION_SET:
        raise GearDesignError(f"unknown strength option {', '.join(map(repr, sorted(set(options) - _OPTION_SET)))}; "
                              f"allowed: {', '.join(_OPTION_NAMES)}")
    if options.keys() & _VALIDATED:
        validate_options(*(options.get(k, d) for k, d in zip(_VALIDATED, _DEFAULTS)))
    _Given(options.get("factors"))
    shaft_option(options.get("shaft"))
    return options


def _floats(designs):
    """The designs' numbers as Python floats (the tooth counts as given: the geometry checks them)."""
    m, z1, z2, x1, x2, b1, b2 = designs
    return float(m), z1, z2, float(x1), float(x2), float(b1), None if b2 is None else float(b2)


def _evaluate_batch(designs, G, o) -> dict:
    """:func:`_evaluate` of arrays, refused by :func:`_finite` where not finite: more than one block of designs in
    blocks (see :mod:`.blocks`; every option, given factor and accuracy grade one number for all), each block's
    stresses checked while in the caches, where a refusal is found again by the whole batch's call, so that it
    names what the batch's call names."""
    geo_keys = () if o.geometry is None else (*_GEOMETRY, "_z1", "_z2")
    values = [*designs, *(o.geometry[k] for k in geo_keys)]
    shape = batch_shape(values)
    if (shape is None or not BLOCK < math.prod(shape) <= DESIGNS_MAX or np.ndim(o.grade)
            or any(np.ndim(v) for v in G.values()) or np.ndim(o.load.torque_nm)):   # a load per design: whole
        return _finite(_evaluate(designs, G, o, ArrayOps), designs, o)
    finite = [True]

    def block(vals):
        geo = None if o.geometry is None else dict(zip(geo_keys, vals[len(designs):]))
        part = _evaluate(tuple(vals[:len(designs)]), G, SimpleNamespace(**{**vars(o), "geometry": geo}), ArrayOps,
                         finish=False)
        finite[0] = finite[0] and (not o.refuse or all(np.isfinite(part[k]).all() for k in STRENGTH_FIELDS
                                                       if k in part))
        if o.keep is not None and finite[0]:   # only the fields asked for reach full size
            if not set(o.keep) <= part.keys():
                raise GearDesignError("fields")    # the whole batch's call below names what is missing
            part = {k: part[k] for k in o.keep}
        return part

    try:
        out = in_blocks(block, values, shape)
    except GearDesignError:
        out = None
    if out is None:
        G.used.clear()
        return _finite(_evaluate(designs, G, o, ArrayOps), designs, o)
    if not finite[0] and o.keep is not None:   # the refusal names what the batch's call names
        G.used.clear()
        return _finite(_evaluate(designs, G, o, ArrayOps), designs, o)
    out = _finish(out, shape, G)
    return out if finite[0] else _finite(out, designs, o)


def _evaluate(designs, G, o, xp, finish=True) -> dict:
    """The chain of :func:`pair_strength` on validated options ``o``, in floats (``xp`` :class:`FloatOps`, one
    design) or arrays; ``finish`` False: its fields as computed, before :func:`_finish`."""
    m, z1, z2, x1, x2, face_width_mm, face_width2_mm = designs
    plain = xp is not ArrayOps        # the design in Python floats (MixedOps: with arrays of load cases)
    beta_deg = float(o.beta_deg) if plain and type(o.beta_deg) is int else o.beta_deg
    g = (_geometry(m, z1, z2, x1, x2, o.rack, beta_deg, o.internal, o.tip_shortening, plain) if o.geometry is None
         else chain_geometry(o.geometry, o.rack, beta_deg, xp))
    m_arr = xp.asarray(m)
    b, b1, b2 = _widths(face_width_mm, face_width2_mm, m_arr, xp)
    if not plain:
        x1, x2 = np.asarray(x1, dtype=float), np.asarray(x2, dtype=float)
        if len({np.shape(v) for v in (m, z1, z2, x1, b)} | {x2.shape}) > 1:    # one shape: nothing to check
            broadcast_inputs(m=m, z1=z1, z2=z2, x1=x1, x2=x2, face_width_mm=b)
    out = _kinematics(o.load, g, b, m_arr, beta_deg, o.K_gamma)
    F_t, v, n1, eps_gamma = out["F_t"], out["v"], out["n1"], out["eps_gamma"]
    K_A, mats, n12 = o.load.application_factor, o.mats, (n1 * o.cpr[0], out["n2"] * o.cpr[1])
    w_A = F_t * K_A / b
    dev = _deviations(G, m_arr, g, b, o.grade, xp)
    out.update(dev)
    _stiffness(G, g, x1, x2, o.rack, beta_deg, w_A, o.internal, o.C_R, out)
    _dynamic(G, g, mats, n1, w_A, dev, o.tip_relief_um, o.bore, eps_gamma, o.internal, v, xp, out)
    _face_load(G, g, mats, F_t, b, K_A, dev, v, o.shaft, xp, out)
    out["Z_eps"] = G["Z_eps"] if "Z_eps" in G else zc.contact_ratio_factor(g["eps_alpha"], out["eps_beta"])
    out["Z_beta"] = G["Z_beta"] if "Z_beta" in G else zc.helix_angle_factor(beta_deg)
    _transverse(G, g, F_t, b, K_A, dev, eps_gamma, out["Z_eps"], o.root_method, o.transverse_deviation, xp, out)
    _contact(G, g, mats, F_t, b, K_A, o.K_gamma, v, n12, o.load.life_h, o.nu40, o.Rz, o.life, o.internal, xp, out)
    if o.root:
        root_side(G, g, mats, F_t, (b1, b2), m_arr, (x1, x2), o.rack, beta_deg, o.internal, K_A, o.K_gamma, o.grade,
                  o.Rz_root, n12, o.load.life_h, o.root_method, out, o.rim, xp, o.refuse)
    _permissible(out, *o.S_min)
    if not finish:
        return out
    return _finish(out, () if xp is FloatOps else np.broadcast_shapes(np.shape(F_t), np.shape(b)), G, o.keep)


def _kinematics(load, g, b, m, beta_deg, K_gamma) -> dict:
    """F_t, v, the speeds and the contact ratios: the first fields of the chain's dict."""
    T1, n1, n2 = _speeds(load, g["_z1"], g["_z2"])
    F_t = kf.tangential_load(T1, g["d1"])
    eps_beta = b * math.sin(math.radians(beta_deg)) / (math.pi * m) if beta_deg else 0.0   # spur: one number
    if beta_deg and (eps_beta > dflt.EPS_BETA_MAX if type(eps_beta) is float else
                     np.any(np.asarray(eps_beta) > dflt.EPS_BETA_MAX)):
        raise GearDesignError(f"face_width_mm must give an overlap ratio eps_beta = b sin(beta)/(pi m) <= "
                              f"{dflt.EPS_BETA_MAX:g} (ISO 6336's factors are taken up to there), got eps_beta = "
                              f"{float(np.max(eps_beta)):.4g} with beta_deg = {beta_deg:g}")
    return {"F_t": F_t, "v": kf.pitch_line_velocity(g["d1"], n1), "K_A": load.application_factor,
            "K_gamma": K_gamma, "n1": n1, "n2": n2, "alpha_wt_deg": g["alpha_wt_deg"],
            "eps_alpha": g["eps_alpha"], "z_n1": g["z_n1"], "z_n2": g["z_n2"], "eps_beta": eps_beta,
            # a spur pair's ε_γ and ε_αn are its ε_α (ε_β = 0, cos β_b = 1): one array, not three equal ones
            "eps_gamma": g["eps_alpha"] + eps_beta if beta_deg else g["eps_alpha"],
            "eps_alpha_n": (g["eps_alpha"] / math.cos(math.radians(g["beta_b_deg"])) ** 2 if beta_deg else
                            g["eps_alpha"])}


def _permissible(out, S_Hmin, S_Fmin) -> dict:
    """The permissible stresses σ_HP = σ_HG/S_Hmin, σ_FP = σ_FG/S_Fmin and the minimum safety factors."""
    for i in "12":
        out["sigma_HP" + i] = out["sigma_HG" + i] / S_Hmin
        if "sigma_FG" + i in out:
            out["sigma_FP" + i] = out["sigma_FG" + i] / S_Fmin
    out["S_Hmin"], out["S_Fmin"] = S_Hmin, S_Fmin
    return out


def _finish(out, shape, G, keep=None) -> dict:
    """Every field at the designs' shape (``keep``: only those, the rest dropped by :func:`_only` after
    :func:`_finite`, which reads them as they are), and the names of the given factors."""
    if shape:
        # the pair-wide fields at the designs' shape: read-only views of a large batch, copies of a small one
        # (np.full costs a quarter of np.broadcast_to there)
        small = math.prod(shape) <= _SMALL
        for k, val in (out.items() if keep is None else [(k, out[k]) for k in keep if k in out]):
            if isinstance(val, np.ndarray) and val.shape != shape:
                out[k] = np.full(shape, val) if small and val.ndim == 0 else np.broadcast_to(val, shape)
            elif isinstance(val, float):
                out[k] = np.full(shape, val) if small else np.broadcast_to(np.float64(val), shape)
    if not G:
        out["given"] = out["given_unused"] = ()
        return out
    out["given"] = tuple(sorted(G.used))
    out["given_unused"] = tuple(sorted(set(G) - G.used))   # e.g. f_sh with K_Hbeta given, Y_eps with method B
    return out


def strength(pair, load: Load, material=None, *, material2=None, face_width_mm=None, **options) -> StrengthResult:
    """ISO 6336 load capacity of one :class:`~geardesign.GearPair` as a :class:`StrengthResult`.

    ``material`` (both gears, or gear 1 with ``material2`` for gear 2): a :class:`Material` or a catalog
    name. ``face_width_mm``: defaults to the pair's ``face_width_mm``. ``options``: the keyword arguments of
    :func:`pair_strength` (accuracy grade, lubricant, roughness, given factors, root method, ...).

    >>> from geardesign import GearPair
    >>> pair = GearPair(m=4, z1=20, z2=60, x1=0.3, x2=0.1, face_width_mm=40)
    >>> r = strength(pair, Load(torque_nm=400, n_rpm=1000, life_h=20000), material="42CrMo4")
    >>> round(r.S_H1, 3), r.governing[0], list(r.factors.columns)
    (0.615, 'contact1', ['symbol', 'gear', 'value', 'clause'])
    """
    if material is None:
        raise GearDesignError("material is needed (a geardesign Material or a name such as '42CrMo4')")
    check_options(options)
    if options.get("root", True) is not True:
        raise GearDesignError(f"root={options['root']!r}: strength() reports every factor of both sides; the contact "
                              f"side alone is pair_strength(..., root=False)")
    b = pair.face_width_mm if face_width_mm is None else face_width_mm
    if b is None:
        raise GearDesignError("face_width_mm is needed: give it, or build the GearPair with face_width_mm=")
    if type(b) is not float and np.ndim(b) != 0:    # one pair: one width (numbers pass as they are)
        one_number("face_width_mm", b)
    # the pair's own geometry (validated when it was built): the chain need not compute it again
    options.setdefault("geometry", getattr(pair, "_geo", None))
    out = pair_strength(pair.m, pair.z1, pair.z2, pair.x1, pair.x2, load=load, material1=material,
                        material2=material2, face_width_mm=b, beta_deg=pair.beta_deg, internal=pair.internal,
                        rack=pair.rack, tip_shortening=pair.tip_shortening, **gathered(options))
    return from_chain(out, title=f"{pair.z1}/{pair.z2} m={pair.m:g}", case=strength_case(material, material2, **options))


def strength_case(material, material2=None, **options) -> dict:
    """The inputs a :class:`StrengthResult` names (:func:`~.result.load_case`: each gear's material with σ_Hlim
    and σ_Flim, the accuracy grade, ν40, Rz) from the arguments of :func:`strength` (``options`` as
    :func:`pair_strength` takes them, loose or grouped in one ``options`` object with those attributes; the others
    are ignored, the defaults filled in)."""
    mat1 = _material(material, "material")
    group = options.get("options")
    pick = (lambda k, d: options.get(k, d)) if group is None else (lambda k, d: getattr(group, k, d))
    return load_case(mat1, mat1 if material2 is None else _material(material2, "material2"),
                     *(pick(k, d) for k, d in (("accuracy_grade", dflt.ACCURACY_GRADE), ("nu40", dflt.NU40_MM2_S),
                                               ("Rz_flank_um", dflt.RZ_FLANK_UM), ("Rz_root_um", dflt.RZ_ROOT_UM))))


# the keywords of pair_strength a caller's options may set (the design and the load case are given apart)
_OPTION_NAMES = GROUPED + tuple(k for k in inspect.signature(pair_strength).parameters
                                if k not in ("m", "z1", "z2", "x1", "x2", "load", "material1", "material2",
                                             "face_width_mm", "fields"))
_OPTION_SET = frozenset(_OPTION_NAMES)
# the defaults of the options validate_options checks (the very objects every default StrengthOptions holds), and
# their checked values
_VALIDATED = tuple(inspect.signature(validate_options).parameters)
_DEFAULTS = tuple(getattr(DEFAULT_OPTIONS, k) for k in _VALIDATED)
_DEFAULTS_CHECKED = validate_options(*_DEFAULTS)
