"""The manufactured state of an external gear pair: the geometric checks again with the teeth as the shop cuts
them (thinner than nominal by their tooth-thickness allowances) in a housing bored within its centre-distance
allowance.

A nominal design that sits on a check's boundary fails on the shop floor: every real gear is cut thinner than
its nominal tooth (the allowances that give it backlash), and the housing's bore distance scatters. The checks
move as follows (each the worst end of the allowances, the tips turned on the blank at their nominal diameter):

- ``contact_ratio`` (and ``total_contact_ratio``): at the largest centre distance a' = a_w + A_ae the path of
  contact shortens, ε_α' = [√(r_a1² − r_b1²) + √(r_a2² − r_b2²) − a' sin α'_wt] / p_bt with cos α'_wt =
  a cos α_t / a' (ISO 21771:2007 §5.4, eq. for g_α at any centre distance);
- ``interference1/2``: at the smallest centre distance a' = a_w + A_ai the mate's tip reaches deeper, ρ_p1' =
  a' sin α'_wt − √(r_a2² − r_b2²) (and ρ_p2' likewise) against the nominal form limit ρ_l (a thinner tooth's
  fillet lies lower, so the nominal ρ_l is on the safe side);
- ``undercut1/2``: the thinnest tooth is generated with x_E = x + A_sni/(2 m_n tan α_n) (ISO 21771:2007 §5.4,
  :func:`~geardesign.gears.measurement_formulas.generating_shift`), margin x_E − x_min;
- ``tip_thickness1/2``: the thinnest tooth's normal tip thickness s_an' = s_an + (d_a/d)(A_sni/cos β) cos β_a
  (the thickness at diameter d_y moves by d_y/d times the reference one; tan β_a = (d_a/d) tan β).

Allowances (:func:`shop_allowances`), each stated in the result: the centre-distance allowance ±f_a = ±IT8/2 of
the centre distance (ISO 286-1 js8; our assumption where DIN 3964's table could not be had: give
``center_distance_allowance_mm`` to replace it); the upper tooth-thickness allowances A_sne1 = A_sne2 that leave
GOST 1643-81's least normal backlash j_n,min of the mating type (default B, general engineering) at the tight
end of the centre distance (:func:`~geardesign.gears.backlash.allowances_for_backlash`); the thickness tolerance
T_sn = |A_sne| (our assumption, so that the lower allowance A_sni = 2 A_sne; give ``thickness_tolerance_mm``).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import GearDesignError
from ..results import compact_repr
from .backlash import GOST1643_TYPES, _pair_of, allowances_for_backlash, gost1643_jn_min
from .measurement_formulas import generating_shift

__all__ = ["ShopAllowances", "shop_allowances", "manufactured_margins", "MANUFACTURED_CHECKS",
           "DEFAULT_MATING_TYPE"]

DEFAULT_MATING_TYPE = "B"        # GOST 1643-81: the normal guaranteed backlash of general engineering
# the checks whose margins the allowances move (the others are taken as nominal)
MANUFACTURED_CHECKS = ("contact_ratio", "total_contact_ratio", "meshing", "interference1", "interference2",
                       "undercut1", "undercut2", "tip_thickness1", "tip_thickness2")


@dataclass(frozen=True)
class ShopAllowances:
    """The allowances a manufactured state assumes, mm: centre distance (a_ai lower, a_ae upper), tooth
    thickness per gear (a_sne upper, a_sni lower: both negative, thinner teeth), the mating type and its least
    normal backlash, and where each came from."""

    a_ai: float
    a_ae: float
    a_sne1: float
    a_sne2: float
    a_sni1: float
    a_sni2: float
    mating_type: str
    jn_min_mm: float
    source: str

    __repr__ = compact_repr

    def to_dict(self) -> dict:
        return {f: getattr(self, f) for f in self.__dataclass_fields__}

    def describe(self) -> str:
        """One line for reports: what the manufactured state assumes."""
        return (f"GOST 1643-81 mating type {self.mating_type} (j_n,min {self.jn_min_mm * 1000:.0f} µm), "
                f"tooth thickness allowances {self.a_sne1 * 1000:.0f}/{self.a_sni1 * 1000:.0f} µm (gear 1), "
                f"{self.a_sne2 * 1000:.0f}/{self.a_sni2 * 1000:.0f} µm (gear 2), centre distance "
                f"{self.a_ai * 1000:+.0f}/{self.a_ae * 1000:+.0f} µm")


def _it8_half_um(a_mm: float) -> float:
    """±IT8/2 of a centre distance [µm] from the GOST 1643 table's D column (= ISO 286-1 IT8 of its interval)."""
    return 0.5 * 1000.0 * gost1643_jn_min("D", a_mm)


def shop_allowances(pair, mating_type: str = DEFAULT_MATING_TYPE, center_distance_allowance_mm=None,
                    thickness_tolerance_mm=None) -> ShopAllowances:
    """The allowances of an external pair's manufactured state (see the module docstring).

    >>> from geardesign import GearPair
    >>> a = shop_allowances(GearPair(3, 20, 61, 0.3, 0.2))      # a_w 124.6 mm (80-125): IT8 54 µm, B 140 µm
    >>> round(a.a_ae, 4), round(a.jn_min_mm, 3)
    (0.027, 0.14)
    """
    if pair.mesh.internal:
        raise GearDesignError("the manufactured state is for external pairs (an internal pair: give its allowances "
                              "to pair_backlash and check it there)")
    if mating_type not in GOST1643_TYPES:
        raise GearDesignError(f"mating_type must be one of {', '.join(GOST1643_TYPES)} (GOST 1643-81), "
                              f"got {mating_type!r}")
    a_w = pair.geometry().a_w
    if center_distance_allowance_mm is None:
        f = _it8_half_um(a_w) / 1000.0
        ai, ae, fa_src = -f, f, "±IT8/2 (ISO 286-1 js8, our assumption)"
    else:       # one number f: ±|f| (as pair_backlash reads it)
        ai, ae = _pair_of("center_distance_allowance_mm", center_distance_allowance_mm)
        if not isinstance(center_distance_allowance_mm, (tuple, list)):
            ai, ae = -abs(ai), abs(ai)
        fa_src = "given"
    jn = float(gost1643_jn_min(mating_type, a_w))
    up = allowances_for_backlash(pair, jn, (ai, ae))
    if thickness_tolerance_mm is None:
        t1, t2, t_src = abs(up["a_sne1"]), abs(up["a_sne2"]), "T_sn = |A_sne| (our assumption)"
    else:
        t1, t2 = _pair_of("thickness_tolerance_mm", thickness_tolerance_mm, 0.0, 1e4)
        t_src = "given"
    return ShopAllowances(a_ai=ai, a_ae=ae, a_sne1=up["a_sne1"], a_sne2=up["a_sne2"], a_sni1=up["a_sne1"] - t1,
                          a_sni2=up["a_sne2"] - t2, mating_type=mating_type, jn_min_mm=jn,
                          source=f"centre distance {fa_src}; A_sne for GOST 1643-81 j_n,min at a_w + A_ai; {t_src}")


class _Row:
    __slots__ = ("margin", "limit")

    def __init__(self, margin: float, limit: float):
        self.margin, self.limit = margin, limit


def _path_at(geo, a_prime: float):
    """(√(r_a1² − r_b1²), √(r_a2² − r_b2²), a' sin α'_wt) of the pair of ``geo`` run at centre distance a'."""
    ra1, ra2, rb1, rb2 = geo.da1 / 2, geo.da2 / 2, geo.db1 / 2, geo.db2 / 2
    cos_w = (rb1 + rb2) / a_prime           # r_b1 + r_b2 = a cos α_t for an external pair
    sin_w = math.sqrt((1.0 - cos_w) * (1.0 + cos_w))
    return (math.sqrt((ra1 - rb1) * (ra1 + rb1)), math.sqrt((ra2 - rb2) * (ra2 + rb2)), a_prime * sin_w)


def manufactured_margins(pair, checks_table, allowances: ShopAllowances) -> dict:
    """{check: margin} of the checks in ``checks_table`` (the pair's :meth:`~geardesign.GearPair.checks` table,
    or a dict {check: (nominal margin, limit)}) at the manufactured state of ``allowances``; checks the
    allowances do not move keep their nominal margin.

    >>> from geardesign import GearPair
    >>> p = GearPair(3, 20, 61, 0.3, 0.2)
    >>> t = p.checks(jamming=False)
    >>> mm = manufactured_margins(p, t, shop_allowances(p))
    >>> bool(mm["contact_ratio"] < float(t.set_index("check").loc["contact_ratio", "margin"]))
    True
    """
    geo = pair.geometry()
    m, beta = pair.m, math.radians(pair.mesh.beta_deg)
    alpha_n = pair.rack.alpha
    if isinstance(checks_table, dict):
        rows = {k: _Row(float(v[0]), float(v[1])) for k, v in checks_table.items()}
    else:
        rows = {c: _Row(float(mg), float(lim)) for c, mg, lim in zip(checks_table["check"], checks_table["margin"],
                                                                      checks_table["limit"])}
    out = {name: r.margin for name, r in rows.items()}
    e1, e2, n_hi = _path_at(geo, geo.a_w + allowances.a_ae)
    eps = (e1 + e2 - n_hi) / geo.p_b
    for name in ("contact_ratio", "meshing"):
        if name in rows:
            out[name] = eps - float(rows[name].limit)
    if "total_contact_ratio" in rows:
        out["total_contact_ratio"] = eps + geo.eps_beta - float(rows["total_contact_ratio"].limit)
    e1, e2, n_lo = _path_at(geo, geo.a_w + allowances.a_ai)
    for j, e_mate in ((1, e2), (2, e1)):
        name = f"interference{j}"
        if name in rows:
            rho_l = getattr(geo, f"rho_l{j}")
            out[name] = ((n_lo - e_mate) - max(rho_l, 0.0)) / m
    for j, a_sni in ((1, allowances.a_sni1), (2, allowances.a_sni2)):
        x, d, da = getattr(pair, f"x{j}"), getattr(geo, f"d{j}"), getattr(geo, f"da{j}")
        if f"undercut{j}" in rows:
            out[f"undercut{j}"] = float(generating_shift(x, a_sni, m, alpha_n)) - getattr(geo, f"x_min{j}")
        if f"tip_thickness{j}" in rows:
            cos_ba = math.cos(math.atan(da / d * math.tan(beta)))
            san = getattr(geo, f"san{j}") + da / d * a_sni / math.cos(beta) * cos_ba
            out[f"tip_thickness{j}"] = san / m - float(rows[f"tip_thickness{j}"].limit)
    return out
