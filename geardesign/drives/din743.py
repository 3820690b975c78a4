"""Fatigue and static safety of shafts after DIN 743-1/-2/-3:2012.

One function per formula, each with its equation; :func:`din743_safety` runs the chain for one cross-section
and :func:`shaft_safety` for the notches of an analysed shaft (:mod:`geardesign.drives.shaft_beam`).
Stresses in N/mm² (MPa), lengths in mm, forces in N, moments in N·m; roughness R_z in µm.

The chain (DIN 743-1 clause 4 and 5, DIN 743-2, DIN 743-3; the formulas as used in the TU Wien MEL1 exam
cases transcribed in github:hanslhansl/din743, whose printed safeties tests/test_din743.py reproduces):

- technological size factor K_1(d_eff) (DIN 743-2 eqs. (10)-(14)), the strengths at the part's size
  σ_B(d) = K_1·σ_B(d_B), σ_S(d) = K_1,S·σ_S(d_B);
- notch factor β: from formulas for key seats and press fits (DIN 743-2 Table 1, at d_BK = 40 mm, carried to
  d by K_3), and from the stress concentration factor α and the support number n = 1 + √G'·10^−(0.33 +
  σ_S(d)/712) for shoulders and round grooves (DIN 743-2 clause 4.3, Tables 2 and 3: α from the fitted
  formula, G' the relative stress gradient); other notches (cross bores, rectangular grooves, splines, …)
  come from tables and figures we do not carry: give their β (``beta_sigma``, ``beta_tau``);
- geometric size factor K_2(d), the surface factor K_F (for key seats and press fits included in β: K_F = 1),
  the surface hardening factor K_V (given; 1 without), the total factor K_σ = (β/K_2 + 1/K_F − 1)/K_V;
- the component fatigue limits σ_zdWK = 0.4·σ_B(d)/K_σ, σ_bWK = 0.5·σ_B(d)/K_σ, τ_tWK = 0.3·σ_B(d)/K_τ
  (DIN 743-1 eqs. (5)-(7) with DIN 743-3's σ_W(d_B) = 0.4, 0.5, 0.3·σ_B(d_B)), the mean-stress
  sensitivity ψ = σ_WK/(2 σ_B(d) − σ_WK), the amplitude strengths σ_ADK for load case F1 (mean stress
  constant) or F2 (mean/amplitude ratio constant, the default) with their upper limit at the yield point;
- the fatigue safety S_D = 1/√((σ_zda/σ_zdADK + σ_ba/σ_bADK)² + (τ_ta/τ_tADK)²), the static safety S_F
  likewise with the maximum stresses and the component yield strengths σ_FK = K_1,S·K_2F·γ_F·σ_S(d_B),
  τ_FK = σ_FK/√3 (DIN 743-1 clause 5, Tables 2 and 3); S_min = 1.2 for both (DIN 743-1 clause 4.1).

Stated simplifications: a compressive mean stress counts like a tensile one in σ_mv (conservative); the
equivalent mean stress is σ_mv = √((σ_zdm + σ_bm)² + 3 τ_tm²), τ_mv = σ_mv/√3 (DIN 743-1 eqs. (23), (24)).
"""
from __future__ import annotations

from typing import TYPE_CHECKING

import math
from dataclasses import dataclass, field

import numpy as np

from ..catalogs.tables import load_catalog
from ..errors import GearDesignError
from ..results import Result
from ..validate import _show, one_number, require_bool, require_choice, require_range

if TYPE_CHECKING:       # pandas loads with the first table (the command's start-up stays light)
    import pandas as pd


def _pandas():
    import pandas

    return pandas


__all__ = ["MATERIAL_KINDS", "NOTCH_KINDS", "S_MIN", "shaft_material", "K1", "K2", "K3", "surface_factor",
           "key_seat_beta", "press_fit_beta", "stress_concentration", "support_number", "total_factor",
           "amplitude_strength", "Notch", "din743_safety", "Din743Result", "ShaftNotch", "shaft_safety",
           "ShaftSafety", "least_diameter_mm", "least_shaft_scale"]

MATERIAL_KINDS = ("quenched_tempered", "case_hardening")
NOTCH_KINDS = ("smooth", "key", "press_fit", "shoulder", "groove", "given")
S_MIN = 1.2          # DIN 743-1:2012 clause 4.1: least safety for fatigue and for the static proof
D_EFF_MAX_MM = 500.0
_LG20 = math.log10(20.0)


def shaft_material(name: str) -> dict:
    """A row of the bundled table ``shaft_materials_din743`` (DIN 743-3): kind, σ_B, σ_S at d_B, d_B, source.

    >>> m = shaft_material("42CrMo4")
    >>> m["sigma_B_mpa"], m["sigma_S_mpa"], m["d_B_mm"]
    (1100.0, 900.0, 16.0)
    """
    table = load_catalog("shaft_materials_din743")
    names = table["material"].tolist()
    name = require_choice("material", name, names)
    row = table.loc[table["material"] == name].iloc[0]
    return {k: (float(row[k]) if k.endswith(("_mpa", "_mm")) else row[k]) for k in
            ("material", "kind", "sigma_B_mpa", "sigma_S_mpa", "d_B_mm", "source")}


def _material(material) -> dict:
    """A material by its name in the bundled table, or a dict with kind, sigma_B_mpa, sigma_S_mpa, d_B_mm."""
    if isinstance(material, str):
        return shaft_material(material)
    if not isinstance(material, dict):
        raise GearDesignError(f"material must be a name of the shaft_materials_din743 table or a dict, got "
                              f"{type(material).__name__}")
    missing = [k for k in ("kind", "sigma_B_mpa", "sigma_S_mpa", "d_B_mm") if k not in material]
    if missing:
        raise GearDesignError(f"material needs {', '.join(missing)} (kind, sigma_B_mpa, sigma_S_mpa, d_B_mm)")
    out = dict(material)
    out["kind"] = require_choice("material kind", out["kind"], MATERIAL_KINDS)
    for k, hi in (("sigma_B_mpa", 3000.0), ("sigma_S_mpa", 3000.0), ("d_B_mm", D_EFF_MAX_MM)):
        out[k] = float(one_number(k, require_range(k, out[k], 0.0, hi, lo_open=True)))
    if out["sigma_S_mpa"] >= out["sigma_B_mpa"]:
        raise GearDesignError(f"material sigma_S_mpa must be below sigma_B_mpa, got {out['sigma_S_mpa']:g} >= "
                              f"{out['sigma_B_mpa']:g}")
    return out


def K1(d_eff_mm, kind: str = "quenched_tempered", strength: str = "tensile", d_B_mm: float = 16.0):
    """Technological size factor K_1(d_eff) (DIN 743-2:2012 eqs. (10)-(14)): quenched and tempered steel
    1 − 0.26·lg(d_eff/d_B) for σ_B (0.67 from 300 mm), 1 − 0.34·lg(d_eff/d_B) for σ_S (0.57 from 300 mm);
    case hardening steel 1 − 0.41·lg(d_eff/d_B) for both (0.6 from 150 mm); 1 up to d_B.

    >>> round(float(K1(160.0)), 12), round(float(K1(160.0, strength="yield")), 12)   # lg 10 = 1
    (0.74, 0.66)
    """
    kind = require_choice("kind", kind, MATERIAL_KINDS)
    strength = require_choice("strength", strength, ("tensile", "yield"))
    d = np.asarray(require_range("d_eff_mm", d_eff_mm, 0.0, D_EFF_MAX_MM, lo_open=True, unit="mm"), dtype=float)
    if kind == "quenched_tempered":
        a, top, floor = (0.26, 300.0, 0.67) if strength == "tensile" else (0.34, 300.0, 0.57)
    else:
        a, top, floor = 0.41, 150.0, 0.6
    k = 1.0 - a * np.log10(np.maximum(d, d_B_mm) / d_B_mm)
    return np.where(d >= top, floor, k)


def K2(d_mm, loading: str = "bending"):
    """Geometric size factor K_2(d) (DIN 743-2:2012 eqs. (15), (16)): 1 for tension/compression; for bending
    and torsion 1 − 0.2·lg(d/7.5)/lg 20 for 7.5 <= d < 150 mm, 0.8 from 150 mm, 1 below 7.5 mm.

    >>> round(float(K2(150.0)), 12), float(K2(60.0, "tension"))
    (0.8, 1.0)
    """
    loading = require_choice("loading", loading, ("tension", "bending", "torsion"))
    d = np.asarray(d_mm, dtype=float)
    if loading == "tension":
        return np.ones_like(d)
    k = 1.0 - 0.2 * np.log10(np.clip(d, 7.5, 150.0) / 7.5) / _LG20
    return k


def K3(d_mm, beta_or_alpha):
    """Size factor of the notch K_3(d) (DIN 743-2:2012 eq. (17)) for carrying a notch factor measured at
    d_BK to d: 1 − 0.2·lg(β)·lg(d/7.5)/lg 20 for 7.5 <= d < 150 mm, 1 − 0.2·lg β from 150 mm.

    >>> round(float(K3(150.0, 10.0)), 12), float(K3(7.5, 2.0))
    (0.8, 1.0)
    """
    d = np.asarray(d_mm, dtype=float)
    return 1.0 - 0.2 * np.log10(np.asarray(beta_or_alpha, dtype=float)) * np.log10(np.clip(d, 7.5, 150.0) / 7.5) / _LG20


def surface_factor(Rz_um, sigma_B_d_mpa):
    """Surface roughness factors K_Fσ = 1 − 0.22·lg(R_z)·(lg(σ_B(d)/20) − 1) and K_Fτ = 0.575·K_Fσ + 0.425
    (DIN 743-2:2012 eqs. (18), (19)), R_z in µm; 1 for a polished surface (R_z = 1).

    >>> [round(float(v), 12) for v in surface_factor(10.0, 2000.0)]     # lg R_z = 1, lg(σ_B/20) − 1 = 1
    [0.78, 0.8735]
    """
    rz = np.asarray(Rz_um, dtype=float)
    kf = 1.0 - 0.22 * np.log10(rz) * (np.log10(np.asarray(sigma_B_d_mpa, dtype=float) / 20.0) - 1.0)
    return kf, 0.575 * kf + 0.425


def key_seat_beta(sigma_B_d_mpa, keys: int = 1):
    """Notch factors of a key seat at d_BK = 40 mm (DIN 743-2:2012 Table 1): β_σ = 3.0·(σ_B(d)/1000)^0.38
    (tension and bending), β_τ = 0.56·β_σ + 0.1; two keys: both × 1.15.

    >>> [round(float(v), 6) for v in key_seat_beta(1000.0)]
    [3.0, 1.78]
    """
    b = 3.0 * (np.asarray(sigma_B_d_mpa, dtype=float) / 1000.0) ** 0.38
    f = np.where(np.asarray(keys) == 2, 1.15, 1.0)
    return b * f, (0.56 * b + 0.1) * f


def press_fit_beta(sigma_B_d_mpa):
    """Notch factors of a press fit at d_BK = 40 mm (DIN 743-2:2012 Table 1): β_σ = 2.7·(σ_B(d)/1000)^0.43,
    β_τ = 0.65·β_σ.

    >>> [round(float(v), 6) for v in press_fit_beta(1000.0)]
    [2.7, 1.755]
    """
    b = 2.7 * (np.asarray(sigma_B_d_mpa, dtype=float) / 1000.0) ** 0.43
    return b, 0.65 * b


# (A, B, C, z) of α = 1 + 1/√(A r/t + 2B (r/d)(1 + 2r/d)² + C (r/t)^z d/D) (DIN 743-2:2012 Table 2) and the
# relative stress gradients G' = g(1 + φ)/r (tension, bending) and g_t/r (torsion) (Table 3)
_ALPHA = {
    "shoulder": {"tension": (0.62, 3.5, 0.0, 0.0), "bending": (0.62, 5.8, 0.2, 3.0), "torsion": (3.4, 19.0, 1.0, 2.0)},
    "groove": {"tension": (0.22, 1.37, 0.0, 0.0), "bending": (0.2, 2.75, 0.0, 0.0), "torsion": (0.7, 10.3, 0.0, 0.0)},
}
_GRADIENT = {"shoulder": (2.3, 1.15), "groove": (2.0, 1.0)}


def stress_concentration(kind: str, d_mm, D_mm, r_mm, loading: str):
    """Stress concentration factor α of a shoulder or a round groove (DIN 743-2:2012 Table 2),
    α = 1 + 1/√(A·r/t + 2B·(r/d)(1 + 2r/d)² + C·(r/t)^z·d/D), t = (D − d)/2; valid for r/t >= 0.03,
    d/D <= 0.98 (checked).

    The shoulder of the MEL1 2024W task 1 (d = 84, D = 100, r = 4 mm; its printed safeties are reproduced in
    tests/test_din743.py):

    >>> round(float(stress_concentration("shoulder", 84.0, 100.0, 4.0, "bending")), 4)
    2.0032
    """
    kind = require_choice("kind", kind, ("shoulder", "groove"))
    A, B, C, z = _ALPHA[kind][require_choice("loading", loading, ("tension", "bending", "torsion"))]
    scalar = np.ndim(d_mm) == 0 and np.ndim(D_mm) == 0 and np.ndim(r_mm) == 0
    out = _alpha(kind, np.asarray(d_mm, dtype=float), np.asarray(D_mm, dtype=float), np.asarray(r_mm, dtype=float),
                 A, B, C, z)
    return float(out) if scalar else out


def _alpha(kind, d, D, r, A, B, C, z):
    """α of Table 2 on arrays (the constants per element or shared), with the table's range checked."""
    t = (D - d) / 2.0
    bad = (t <= 0) | (d / D > 0.98)
    if np.any(bad):
        i = np.flatnonzero(np.broadcast_to(bad, np.broadcast(d, D).shape).ravel())[0]
        dd, DD = np.broadcast_to(d, bad.shape).ravel()[i], np.broadcast_to(D, bad.shape).ravel()[i]
        raise GearDesignError(f"the {kind} must have d/D <= 0.98 (DIN 743-2 Table 2), got d = {dd:g} mm, "
                              f"D = {DD:g} mm")
    small = r / t < 0.03
    if np.any(small):
        i = np.flatnonzero(np.broadcast_to(small, np.broadcast(r, t).shape).ravel())[0]
        rr, tt = np.broadcast_to(r, small.shape).ravel()[i], np.broadcast_to(t, small.shape).ravel()[i]
        raise GearDesignError(f"the {kind}'s radius must be r >= 0.03·t (DIN 743-2 Table 2), got r = {rr:g} mm, "
                              f"t = {tt:g} mm")
    return 1.0 + 1.0 / np.sqrt(A * r / t + 2.0 * B * r / d * (1.0 + 2.0 * r / d) ** 2 + C * (r / t) ** z * d / D)


def support_number(G_per_mm, sigma_S_d_mpa, hard_surface: bool = False):
    """Support number n = 1 + √G'·10^−(0.33 + σ_S(d)/712 MPa), with a hard surface layer 1 + √G'·10^−0.7
    (DIN 743-2:2012 eqs. (6), (7)), G' in 1/mm.

    >>> round(float(support_number(1.0, 712.0)), 6)
    1.046774
    """
    G = np.asarray(G_per_mm, dtype=float)
    exp = 0.7 if hard_surface else 0.33 + np.asarray(sigma_S_d_mpa, dtype=float) / 712.0
    return 1.0 + np.sqrt(G) * 10.0 ** (-exp)


def total_factor(beta, K2_d, K_F, K_V=1.0):
    """Total influence factor K = (β/K_2(d) + 1/K_F − 1)/K_V (DIN 743-1:2012 eqs. (8), (9)).

    >>> round(float(total_factor(2.0, 0.8, 1.0)), 6)
    2.5
    """
    return (np.asarray(beta) / np.asarray(K2_d) + 1.0 / np.asarray(K_F) - 1.0) / np.asarray(K_V)


def amplitude_strength(WK, FK, psi, mean, amplitude, load_case: int = 2):
    """Amplitude of the component fatigue strength σ_ADK (DIN 743-1:2012 eqs. (10)-(19)).

    F1 (mean stress constant): σ_WK − ψ·σ_mv while σ_mv <= (σ_FK − σ_WK)/(1 − ψ), else σ_FK − σ_mv;
    F2 (mean/amplitude constant): σ_WK/(1 + ψ·σ_mv/σ_a) while σ_mv/σ_a <= (σ_FK − σ_WK)/(σ_WK − σ_FK·ψ),
    else σ_FK/(1 + σ_mv/σ_a).

    >>> round(float(amplitude_strength(300.0, 600.0, 0.25, 0.0, 100.0)), 6)
    300.0
    """
    scalar = all(np.ndim(v) == 0 for v in (WK, FK, psi, mean, amplitude))
    WK, FK, psi, mean, amplitude = (np.asarray(v, dtype=float) for v in (WK, FK, psi, mean, amplitude))
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        if load_case == 1:
            limit = (FK - WK) / (1.0 - psi)
            out = np.where(mean <= limit, WK - psi * mean, FK - mean)
        else:
            ratio = np.where(amplitude > 0, mean / np.where(amplitude > 0, amplitude, 1.0),
                             np.where(mean > 0, np.inf, 0.0))
            limit = (FK - WK) / (WK - FK * psi)
            out = np.where(ratio <= limit, WK / (1.0 + psi * ratio), FK / (1.0 + ratio))
    return float(out) if scalar else out


@dataclass(frozen=True)
class Notch:
    """The notch at a cross-section: ``kind`` one of :data:`NOTCH_KINDS`; ``r_mm`` the fillet or groove
    radius (shoulder, groove); ``t_mm`` the groove depth; ``keys`` 1 or 2 (key seat); ``beta_sigma`` and
    ``beta_tau`` (kind ``"given"``, or to override) the user's notch factors for notches whose factors
    DIN 743-2 gives only in tables and figures (rectangular grooves, cross bores, splines); with them
    ``alpha_sigma`` (for γ_F; 1 if unknown)."""

    kind: str = "smooth"
    r_mm: float | None = None
    t_mm: float | None = None
    keys: int = 1
    beta_sigma: float | None = None
    beta_tau: float | None = None
    alpha_sigma: float = 1.0

    def __post_init__(self):
        require_choice("notch kind", self.kind, NOTCH_KINDS)
        if self.kind in ("shoulder", "groove") and self.r_mm is None:
            raise GearDesignError(f"a {self.kind} notch needs its radius r_mm")
        if self.kind == "groove" and self.t_mm is None:
            raise GearDesignError("a groove notch needs its depth t_mm")
        # one number each (an array radius broke the notch table's array, fuzz)
        if self.r_mm is not None:
            object.__setattr__(self, "r_mm", one_number("r_mm", require_range("r_mm", self.r_mm, 0.0, 1e4,
                                                                              lo_open=True, unit="mm")))
        if self.t_mm is not None:
            object.__setattr__(self, "t_mm", one_number("t_mm", require_range("t_mm", self.t_mm, 0.0, 1e4,
                                                                              lo_open=True, unit="mm")))
        if self.keys not in (1, 2):
            raise GearDesignError(f"keys must be 1 or 2, got {self.keys!r}")
        if self.kind == "given" and (self.beta_sigma is None or self.beta_tau is None):
            raise GearDesignError("a notch of kind 'given' needs beta_sigma and beta_tau (DIN 743-2's tables)")
        for name in ("beta_sigma", "beta_tau"):
            if getattr(self, name) is not None:
                object.__setattr__(self, name, one_number(name, require_range(name, getattr(self, name), 1.0, 20.0)))
        object.__setattr__(self, "alpha_sigma", one_number("alpha_sigma", require_range("alpha_sigma", self.alpha_sigma,
                                                                                        1.0, 20.0)))


def _gamma_F(alpha):
    """Increase factor γ_F of the yield point at a circumferential notch (DIN 743-1:2012 Table 2)."""
    a = np.asarray(alpha, dtype=float)
    return np.where(a < 1.5, 1.0, np.where(a < 2.0, 1.05, np.where(a < 3.0, 1.1, 1.15)))


@dataclass(repr=False)
class Din743Result(Result):
    """Safety of one cross-section: ``S_D`` (fatigue), ``S_F`` (static), ``ok`` when both reach ``S_min``;
    ``factors``: every factor of the chain (quantity, symbol, tension, bending, torsion)."""

    S_D: float
    S_F: float
    S_min: float
    ok: bool
    message: str
    _rows: list = field(default_factory=list, repr=False)     # the factor table's rows, made a table when asked
    _cache: dict = field(default_factory=dict, repr=False)
    _success_field = "ok"
    _table_fields = ("factors",)

    @property
    def factors(self) -> pd.DataFrame:
        if "factors" not in self._cache:
            self._cache["factors"] = _pandas().DataFrame(self._rows, columns=["quantity", "symbol", "tension",
                                                                              "bending", "torsion"])
        return self._cache["factors"]

    def to_dict(self):
        from ..results import plain

        return {"S_D": plain(self.S_D), "S_F": plain(self.S_F), "S_min": plain(self.S_min), "ok": self.ok,
                "message": self.message, "factors": plain(self.factors), "status": self.status}

    def __repr__(self):
        return f"Din743Result(S_D={self.S_D:.4g}, S_F={self.S_F:.4g}, S_min={self.S_min:g}, ok={self.ok})"


def din743_safety(material, notch: Notch | None = None, *, d_mm, D_mm=None, bore_mm=0.0, d_eff_mm=None,
                  Rz_um=6.3, K_V=1.0, hard_surface=False, load_case=2,
                  F_zdm=0.0, F_zda=0.0, M_bm=0.0, M_ba=0.0, T_m=0.0, T_a=0.0,
                  F_zdmax=None, M_bmax=None, T_max=None, S_min=S_MIN) -> Din743Result:
    """Fatigue and static safety of one cross-section after DIN 743 (the chain: module docstring).

    ``material``: a name of the bundled table or a dict with kind, sigma_B_mpa, sigma_S_mpa, d_B_mm;
    ``d_mm``: the diameter at the section (the notch root: the smaller diameter of a shoulder, the groove
    root); ``D_mm``: the larger diameter of a shoulder (a groove: d + 2t by default); ``d_eff_mm``: the
    heat-treatment diameter (default the largest of d and D); forces N, moments N·m, mean (m), amplitude (a)
    and maximum (default |mean| + |amplitude|); ``load_case`` 1 or 2.

    A key seat in a 60 mm C50 shaft (TU Wien MEL1 exam 2024W task 2, github:hanslhansl/din743
    tests/test_1.py: S_D = 1.472, S_F = 2.568):

    >>> r = din743_safety("C50", Notch("key"), d_mm=60.0, d_eff_mm=80.0, Rz_um=25.0, hard_surface=True,
    ...                   M_ba=1402.294, T_m=1336.902, M_bmax=1.8 * 1402.294, T_max=1.8 * 1336.902)
    >>> round(r.S_D, 3), round(r.S_F, 3)
    (1.472, 2.568)
    """
    mat = _material(material)
    notch = Notch() if notch is None else notch
    if not isinstance(notch, Notch):
        raise GearDesignError(f"notch must be a Notch, got {type(notch).__name__}")
    hard_surface = require_bool("hard_surface", hard_surface)
    S_min = float(one_number("S_min", require_range("S_min", S_min, 0.0, 100.0, lo_open=True)))
    d = float(one_number("d_mm", require_range("d_mm", d_mm, 1.0, D_EFF_MAX_MM, unit="mm")))
    bore = float(one_number("bore_mm", require_range("bore_mm", bore_mm, 0.0, d, hi_open=True, unit="mm")))
    if notch.kind == "groove" and D_mm is None:
        D_mm = d + 2.0 * notch.t_mm
    D = d if D_mm is None else float(one_number("D_mm", require_range("D_mm", D_mm, d, 2 * D_EFF_MAX_MM, unit="mm")))
    d_eff = max(d, D) if d_eff_mm is None else float(d_eff_mm)
    F_zdmax = abs(F_zdm) + abs(F_zda) if F_zdmax is None else F_zdmax
    M_bmax = abs(M_bm) + abs(M_ba) if M_bmax is None else M_bmax
    T_max = abs(T_m) + abs(T_a) if T_max is None else T_max
    loads = {"F_zdm": F_zdm, "F_zda": F_zda, "M_bm": M_bm, "M_ba": M_ba, "T_m": T_m, "T_a": T_a,
             "F_zdmax": F_zdmax, "M_bmax": M_bmax, "T_max": T_max}
    c = _chain(mat, [notch], np.array([d]), np.array([D]), np.array([bore]), d_eff, Rz_um, K_V, hard_surface,
               load_case, {k: np.array([float(one_number(k, v))]) for k, v in loads.items()})
    return _result(c, 0, S_min)


def _result(c, i, S_min) -> Din743Result:
    """Section ``i`` of a :func:`_chain` as a :class:`Din743Result`."""
    S_D, S_F = float(c["S_D"][i]), float(c["S_F"][i])
    ok = S_D >= S_min and S_F >= S_min
    worst = "fatigue" if S_D <= S_F else "static"
    msg = (f"S_D = {S_D:.4g}, S_F = {S_F:.4g} {'>=' if ok else 'not both >='} S_min = {S_min:g}"
           + ("" if ok else f" ({worst} safety {min(S_D, S_F):.4g} < {S_min:g})"))
    one = lambda v: float(v[i])     # noqa: E731
    rows = [("K_1 (tensile, yield)", "K1", c["K1B"], c["K1B"], c["K1S"]),
            ("strength at size", "sigma_B(d)", c["sB_d"], c["sB_d"], c["sS_d"]),
            ("stress concentration", "alpha", *(c["alpha"][k] for k in LOADINGS))]
    for label, sym in (("notch factor", "beta"), ("size factor", "K2"), ("surface factor", "K_F"),
                       ("total factor", "K"), ("fatigue limit", "WK"), ("mean stress sensitivity", "psi"),
                       ("component yield", "FK"), ("mean stress", "m"), ("equivalent mean", "mv"),
                       ("amplitude", "a"), ("amplitude strength", "ADK"), ("maximum stress", "max")):
        rows.append((label, sym, *(c[sym][k] for k in LOADINGS)))
    rows = [(label, sym, one(t), one(b), one(tor)) for label, sym, t, b, tor in rows]
    return Din743Result(S_D, S_F, float(S_min), bool(ok), msg, _rows=rows)


LOADINGS = ("tension", "bending", "torsion")


def _chain(mat, notches, d, D, bore, d_eff, Rz_um, K_V, hard_surface, load_case, loads) -> dict:
    """The DIN 743 chain (module docstring) for n sections at once: ``notches`` a list of n :class:`Notch`,
    ``d``, ``D``, ``bore`` arrays (n,) (D = d where the notch has none), ``d_eff`` a number or (n,), ``loads``
    the nine loads of :func:`din743_safety` as arrays (n,). Every factor as an array per loading, S_D, S_F."""
    n = d.size
    kind = mat["kind"]
    sB, sS, dB = (mat[k] for k in ("sigma_B_mpa", "sigma_S_mpa", "d_B_mm"))
    d_eff = np.broadcast_to(np.asarray(d_eff, dtype=float), (n,))
    require_range("d_eff_mm", d_eff, 1.0, D_EFF_MAX_MM, unit="mm")
    require_range("Rz_um", Rz_um, 1.0, 200.0, unit="µm")
    require_range("K_V", K_V, 0.5, 3.0)
    if np.ndim(load_case) != 0 or load_case not in (1, 2):    # an array: one case for every section (fuzz)
        raise GearDesignError(f"load_case must be 1 (mean stress constant) or 2 (mean/amplitude constant), "
                              f"got {_show(load_case)}")
    for name, v in loads.items():
        if not np.all(np.abs(v) <= 1e12):      # NaN fails too: then the one check that names it
            require_range(name, v, -1e12, 1e12)
    K1B = K1(d_eff, kind, "tensile", dB)
    K1S = K1(d_eff, kind, "yield", dB)
    sB_d, sS_d = K1B * sB, K1S * sS
    kinds = np.array([nt.kind for nt in notches])
    ones = np.ones(n)
    # notch factors β and stress concentration α (for γ_F) per loading
    alpha_sigma = np.array([nt.alpha_sigma for nt in notches], dtype=float)
    alpha = {"tension": alpha_sigma.copy(), "bending": alpha_sigma.copy(), "torsion": ones.copy()}
    beta = {k: ones.copy() for k in LOADINGS}
    fits = (kinds == "key") | (kinds == "press_fit")
    if fits.any():
        keys = np.array([nt.keys for nt in notches])
        bs_k, bt_k = key_seat_beta(sB_d, keys)
        bs_p, bt_p = press_fit_beta(sB_d)
        key = kinds == "key"
        bs, bt = np.where(key, bs_k, bs_p), np.where(key, bt_k, bt_p)
        d_BK = 40.0
        b_sigma = np.where(fits, bs * K3(d_BK, bs) / K3(d, bs), 1.0)
        b_tau = np.where(fits, bt * K3(d_BK, bt) / K3(d, bt), 1.0)
        for k, b in zip(LOADINGS, (b_sigma, b_sigma, b_tau)):
            beta[k] = np.where(fits, b, beta[k])
            alpha[k] = np.where(fits, 1.0, alpha[k])
    round_notch = (kinds == "shoulder") | (kinds == "groove")
    if round_notch.any():
        thin = round_notch & (D <= d)
        if thin.any():
            i = int(np.flatnonzero(thin)[0])
            raise GearDesignError(f"a {kinds[i]} needs D_mm > d_mm, got d = {d[i]:g}, D = {D[i]:g} mm")
        j = np.flatnonzero(round_notch)
        dj, Dj = d[j], D[j]
        r = np.array([float(notches[i].r_mm) for i in j])
        t = (Dj - dj) / 2.0
        phi = np.where(dj / Dj > 0.67, 1.0 / (4.0 * np.sqrt(t / r) + 2.0), 0.0)
        shoulder = kinds[j] == "shoulder"
        g = np.where(shoulder, _GRADIENT["shoulder"][0], _GRADIENT["groove"][0])
        g_t = np.where(shoulder, _GRADIENT["shoulder"][1], _GRADIENT["groove"][1])
        for k in LOADINGS:
            consts = np.where(shoulder[:, None], _ALPHA["shoulder"][k], _ALPHA["groove"][k])
            a = np.empty(j.size)
            for name, rows in (("shoulder", shoulder), ("groove", ~shoulder)):
                if rows.any():
                    A, B, C, z = (consts[rows, m] for m in range(4))
                    a[rows] = _alpha(name, dj[rows], Dj[rows], r[rows], A, B, C, z)
            G = g_t / r if k == "torsion" else g * (1.0 + phi) / r
            nn = np.minimum(support_number(G, sS_d[j], hard_surface), a)
            beta[k][j] = a / nn
            alpha[k][j] = a
        alpha["torsion"][j] = 1.0
    bsig = np.array([np.nan if nt.beta_sigma is None else nt.beta_sigma for nt in notches], dtype=float)
    btau = np.array([np.nan if nt.beta_tau is None else nt.beta_tau for nt in notches], dtype=float)
    # kind "given": the user's β; for the other kinds a given β overrides the computed one
    for k, b in zip(LOADINGS, (bsig, bsig, btau)):
        beta[k] = np.where(~np.isnan(b), b, beta[k])
    kfs, kft = surface_factor(Rz_um, sB_d)
    KF = {"tension": np.where(fits, 1.0, kfs), "bending": np.where(fits, 1.0, kfs),   # DIN 743-2 Table 1: in β
          "torsion": np.where(fits, 1.0, kft)}
    K2_bending = K2(d, "bending")            # K_2 of torsion is that of bending (DIN 743-2 eq. (16))
    K2d = {"tension": np.ones(n), "bending": K2_bending, "torsion": K2_bending}
    K = {k: total_factor(beta[k], K2d[k], KF[k], K_V) for k in LOADINGS}
    WK = {"tension": 0.4 * sB_d / K["tension"], "bending": 0.5 * sB_d / K["bending"],
          "torsion": 0.3 * sB_d / K["torsion"]}
    psi = {k: WK[k] / (2.0 * sB_d - WK[k]) for k in LOADINGS}
    hollow = bore > 0
    K2F = ({"tension": ones, "bending": ones, "torsion": ones} if hard_surface else
           {"tension": ones, "bending": np.where(hollow, 1.1, 1.2), "torsion": np.where(hollow, 1.0, 1.2)})
    circumferential = np.isin(kinds, ("shoulder", "groove", "smooth", "given"))
    gF = {k: (ones if (hard_surface or k == "torsion") else np.where(circumferential, _gamma_F(alpha[k]), 1.0))
          for k in LOADINGS}
    FK = {k: K1S * K2F[k] * gF[k] * sS for k in LOADINGS}
    FK["torsion"] = FK["torsion"] / math.sqrt(3.0)
    # nominal stresses
    area = math.pi / 4.0 * (d * d - bore * bore)
    Wb = math.pi / 32.0 * (d ** 4 - bore ** 4) / d
    Wt = 2.0 * Wb
    L = loads
    m = {"tension": L["F_zdm"] / area, "bending": 1000.0 * L["M_bm"] / Wb, "torsion": 1000.0 * L["T_m"] / Wt}
    a = {"tension": np.abs(L["F_zda"]) / area, "bending": 1000.0 * np.abs(L["M_ba"]) / Wb,
         "torsion": 1000.0 * np.abs(L["T_a"]) / Wt}
    mx = {"tension": np.abs(L["F_zdmax"]) / area, "bending": 1000.0 * np.abs(L["M_bmax"]) / Wb,
          "torsion": 1000.0 * np.abs(L["T_max"]) / Wt}
    s_mv = np.sqrt((m["tension"] + m["bending"]) ** 2 + 3.0 * m["torsion"] ** 2)
    mv = {"tension": s_mv, "bending": s_mv, "torsion": s_mv / math.sqrt(3.0)}
    ADK = {k: amplitude_strength(WK[k], FK[k], psi[k], mv[k], a[k], load_case) for k in LOADINGS}

    def _safety(num, den):
        with np.errstate(divide="ignore", invalid="ignore"):
            # a stress over its strength; no stress: no share, whatever the strength
            q = {k: np.where(num[k] == 0, 0.0, np.where(den[k] > 0, num[k] / den[k], np.inf)) for k in LOADINGS}
            s = np.hypot(q["tension"] + q["bending"], q["torsion"])
            return np.where(s == 0, np.inf, 1.0 / s)

    return {"K1B": K1B, "K1S": K1S, "sB_d": sB_d, "sS_d": sS_d, "alpha": alpha, "beta": beta, "K2": K2d,
            "K_F": KF, "K": K, "WK": WK, "psi": psi, "FK": FK, "m": m, "mv": mv, "a": a, "ADK": ADK, "max": mx,
            "S_D": _safety(a, ADK), "S_F": _safety(mx, FK)}


def least_diameter_mm(material, notch: Notch | None = None, *, S_min=S_MIN, D_over_d=None, r_over_d=None,
                      d_lo=5.0, d_hi=D_EFF_MAX_MM, tol_mm=1e-3, **loads) -> float:
    """The least diameter d (mm) at which the section reaches S_D and S_F >= S_min (bisection over d; the
    safety rises with d). A shoulder or groove keeps its shape: ``D_over_d`` (D/d) and ``r_over_d`` (r/d;
    a groove's depth follows from D/d); ``loads``: the forces and moments of :func:`din743_safety`. d_eff
    follows the section (the larger of d and D) unless given.

    >>> d = least_diameter_mm("42CrMo4", M_ba=500.0, T_m=800.0)
    >>> r = din743_safety("42CrMo4", d_mm=d, M_ba=500.0, T_m=800.0)
    >>> round(min(r.S_D, r.S_F), 3)
    1.2
    """
    notch = Notch() if notch is None else notch
    if notch.kind in ("shoulder", "groove") and (D_over_d is None or r_over_d is None):
        raise GearDesignError(f"a {notch.kind} keeps its shape as d varies: give D_over_d and r_over_d")
    if D_over_d is not None:
        require_range("D_over_d", D_over_d, 1.0, 10.0, lo_open=True)
    if r_over_d is not None:
        require_range("r_over_d", r_over_d, 0.0, 10.0, lo_open=True)

    def safety(d):
        kw = dict(loads)
        nt = notch
        if notch.kind in ("shoulder", "groove"):
            kw["D_mm"] = d * D_over_d
            nt = Notch(notch.kind, r_over_d * d, (D_over_d - 1.0) * d / 2.0 if notch.kind == "groove" else None,
                       notch.keys, notch.beta_sigma, notch.beta_tau, notch.alpha_sigma)
        r = din743_safety(material, nt, d_mm=d, S_min=S_min, **kw)
        return min(r.S_D, r.S_F)

    top = d_hi / (D_over_d or 1.0)
    if safety(top) < S_min:
        raise GearDesignError(f"no diameter up to {top:g} mm reaches S_min = {S_min:g} (DIN 743 holds to "
                              f"d_eff = {D_EFF_MAX_MM:g} mm)")
    lo, hi = d_lo, top
    if safety(lo) >= S_min:
        return lo
    while hi - lo > tol_mm:
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if safety(mid) >= S_min else (mid, hi)
    return hi


@dataclass(frozen=True)
class ShaftNotch:
    """A cross-section of a shaft to check: its position ``x_mm`` and :class:`Notch`. At a shoulder the
    section is on the thinner side of the step at x; a groove's root is d − 2t of the shaft's d at x."""

    x_mm: float
    notch: Notch = field(default_factory=Notch)
    name: str = ""


@dataclass(repr=False)
class ShaftSafety(Result):
    """DIN 743 safeties at each checked section of an analysed shaft: ``table`` one row per section
    (x, notch, d, D, the moment, torque and axial force there, S_D, S_F, ok); ``ok`` when every section
    reaches S_min; ``results`` the :class:`Din743Result` of each (both made when first asked for)."""

    ok: bool
    message: str
    S_min: float
    _columns: dict = field(default_factory=dict, repr=False)     # the table's columns
    _chain: dict = field(default_factory=dict, repr=False)       # every factor of every section
    _cache: dict = field(default_factory=dict, repr=False)
    _success_field = "ok"
    _table_fields = ("table",)

    @property
    def table(self) -> pd.DataFrame:
        if "table" not in self._cache:
            self._cache["table"] = _pandas().DataFrame(self._columns, columns=list(_TABLE_COLUMNS))
        return self._cache["table"]

    @property
    def results(self) -> tuple:
        if "results" not in self._cache:
            self._cache["results"] = tuple(_result(self._chain, i, self.S_min)
                                           for i in range(len(self._columns["x_mm"])))
        return self._cache["results"]

    def to_dict(self):
        from ..results import plain

        return {"ok": self.ok, "message": self.message, "S_min": plain(self.S_min), "table": plain(self.table),
                "status": self.status}

    def __repr__(self):
        return f"ShaftSafety(ok={self.ok}, {self.message})"


_TABLE_COLUMNS = ("name", "x_mm", "notch", "d_mm", "D_mm", "M_nm", "T_nm", "N_n", "S_D", "S_F", "ok")


def shaft_safety(analysis, notches, material, *, peak_factor=1.0, torque_amplitude=0.0, Rz_um=6.3,
                 hard_surface=False, K_V=1.0, load_case=2, S_min=S_MIN, d_eff_mm=None) -> ShaftSafety:
    """DIN 743 safety at each :class:`ShaftNotch` of a :class:`~geardesign.drives.shaft_beam.ShaftAnalysis`.

    The shaft rotates under fixed loads: the bending stress is fully reversed (amplitude = the resultant
    moment, mean 0); the torque is steady with the amplitude ``torque_amplitude``·T; the axial force is a
    steady mean. Maximum loads for the static proof: ``peak_factor`` × (mean + amplitude). d_eff defaults to
    the shaft's largest diameter (a shaft turned from one bar). All sections go through the chain in one
    vectorised pass."""
    from .shaft_beam import ShaftAnalysis

    if not isinstance(analysis, ShaftAnalysis):
        raise GearDesignError(f"analysis must be a ShaftAnalysis, got {type(analysis).__name__}")
    # one number each for the whole shaft (an array would broadcast against the notches, or not at all)
    peak_factor = one_number("peak_factor", require_range("peak_factor", peak_factor, 1.0, 100.0))
    torque_amplitude = one_number("torque_amplitude", require_range("torque_amplitude", torque_amplitude, 0.0, 10.0))
    Rz_um = one_number("Rz_um", require_range("Rz_um", Rz_um, 1.0, 200.0, unit="µm"))
    K_V = one_number("K_V", require_range("K_V", K_V, 0.5, 3.0))
    if d_eff_mm is not None:
        d_eff_mm = one_number("d_eff_mm", require_range("d_eff_mm", d_eff_mm, 1.0, D_EFF_MAX_MM, unit="mm"))
    mat = _material(material)
    hard_surface = require_bool("hard_surface", hard_surface)
    S_min = float(one_number("S_min", require_range("S_min", S_min, 0.0, 100.0, lo_open=True)))
    model = analysis.model
    notches = list(notches)
    if not notches:
        raise GearDesignError("notches must list at least one section to check")
    for i, sn in enumerate(notches):
        if not isinstance(sn, ShaftNotch):
            raise GearDesignError(f"notches[{i}] must be a ShaftNotch, got {type(sn).__name__}")
        one_number(f"notches[{i}].x_mm", require_range(f"notches[{i}].x_mm", sn.x_mm, 0.0, model.length_mm, unit="mm"))
    diag = analysis._arrays["diagrams"]
    x = diag["x_mm"]
    xs = np.array([float(sn.x_mm) for sn in notches])
    M_all, T_all, N_all = diag["M_nm"], np.abs(diag["T_nm"]), diag["N_n"]
    # between nodes the diagrams are linear: interpolate (exact); at a node (a load, a step) the larger of its
    # left and right limits (the axial force: the one of larger magnitude)
    Mb, T, N = np.interp(xs, x, M_all), np.abs(np.interp(xs, x, diag["T_nm"])), np.interp(xs, x, N_all)
    at = x[:, None] == xs[None, :]
    node = at.any(axis=0)
    if node.any():
        Mb = np.where(node, np.where(at, M_all[:, None], -np.inf).max(axis=0), Mb)
        T = np.where(node, np.where(at, T_all[:, None], -np.inf).max(axis=0), T)
        pick = np.where(at, np.abs(N_all)[:, None], -1.0).argmax(axis=0)
        N = np.where(node, N_all[pick], N)
    (dl, bl), (dr, br) = model.diameter_at(xs, "left"), model.diameter_at(xs, "right")
    kinds = np.array([sn.notch.kind for sn in notches])
    shoulder, groove = kinds == "shoulder", kinds == "groove"
    flat = shoulder & (dl == dr)
    if flat.any():
        i = int(np.flatnonzero(flat)[0])
        raise GearDesignError(f"notches[{i}]: no diameter step at x = {xs[i]:g} mm for a shoulder")
    t_groove = np.array([sn.notch.t_mm if sn.notch.kind == "groove" else 0.0 for sn in notches], dtype=float)
    thin = np.minimum(dl, dr)
    bore_thin = np.where(dl <= dr, bl, br)
    d = np.where(groove, dr - 2.0 * t_groove, thin)
    D = np.where(shoulder, np.maximum(dl, dr), np.where(groove, dr, d))
    bore = np.where(groove, br, bore_thin)
    d_eff = max(s[1] for s in model.sections) if d_eff_mm is None else d_eff_mm
    require_range("d_mm", d, 1.0, D_EFF_MAX_MM, unit="mm")
    through = groove & (d <= bore)
    if through.any():     # the root inside the bore: d² − bore² and d⁴ − bore⁴ <= 0, stresses of no section
        i = int(np.flatnonzero(through)[0])
        raise GearDesignError(f"notches[{i}]: the groove's depth t_mm = {t_groove[i]:g} cuts through the wall: root "
                              f"d − 2t = {d[i]:g} mm <= bore {bore[i]:g} mm")
    loads = {"F_zdm": N, "F_zda": np.zeros_like(N), "M_bm": np.zeros_like(N), "M_ba": Mb, "T_m": T,
             "T_a": torque_amplitude * T, "F_zdmax": peak_factor * np.abs(N), "M_bmax": peak_factor * Mb,
             "T_max": peak_factor * T * (1.0 + torque_amplitude)}
    c = _chain(mat, [sn.notch for sn in notches], d, D, bore, d_eff, Rz_um, K_V, hard_surface, load_case, loads)
    S_D, S_F = c["S_D"], c["S_F"]
    ok_rows = (S_D >= S_min) & (S_F >= S_min)
    names = [sn.name or f"{sn.notch.kind} at {sn.x_mm:g}" for sn in notches]
    columns = {"name": names, "x_mm": xs, "notch": kinds, "d_mm": d, "D_mm": D, "M_nm": Mb, "T_nm": T, "N_n": N,
               "S_D": S_D, "S_F": S_F, "ok": ok_rows}
    ok = bool(ok_rows.all())
    w = int(np.argmin(np.minimum(S_D, S_F)))
    msg = (f"least safety {min(S_D[w], S_F[w]):.4g} at {names[w]} "
           f"(S_D {S_D[w]:.4g}, S_F {S_F[w]:.4g}; S_min {S_min:g})")
    return ShaftSafety(ok, msg, float(S_min), _columns=columns, _chain=c)


def least_shaft_scale(model, notches, material, *, S_min=S_MIN, tol=1e-4, **kw) -> float:
    """The least factor on every diameter of ``model`` (with the notches' radii and depths, and d_eff, in
    proportion) at which every section of ``notches`` reaches S_min (bisection; the safety rises with the
    scale). ``kw``: the options of :func:`shaft_safety`. Multiply the section diameters by it for the least
    shaft of this shape."""
    from .shaft_beam import analyse_shaft

    def least(s):
        m = model.with_diameters(s)
        sn = [ShaftNotch(n.x_mm, Notch(n.notch.kind, None if n.notch.r_mm is None else n.notch.r_mm * s,
                                       None if n.notch.t_mm is None else n.notch.t_mm * s, n.notch.keys,
                                       n.notch.beta_sigma, n.notch.beta_tau, n.notch.alpha_sigma), n.name)
              for n in notches]
        t = shaft_safety(analyse_shaft(m, points=20, shaft_mass=False), sn, material, S_min=S_min, **kw)._columns
        return float(np.minimum(t["S_D"], t["S_F"]).min())

    dmax, dmin = max(s[1] for s in model.sections), min(s[1] for s in model.sections)
    lo, hi = 2.0 / dmin, D_EFF_MAX_MM / dmax   # the thinnest section at 2 mm … d_eff at DIN 743's limit
    if least(hi) < S_min:
        raise GearDesignError(f"no scale up to {hi:.4g} (d_eff <= {D_EFF_MAX_MM:g} mm) reaches S_min = {S_min:g}")
    if least(lo) >= S_min:
        return lo
    while hi - lo > tol * hi:
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if least(mid) >= S_min else (mid, hi)
    return hi
