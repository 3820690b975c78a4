"""Design checks of a gear pair as named constraints with signed, dimensionless margins.

Every check maps a geometry (the dict of :func:`geardesign.gears.geometry._core`, arrays or, on the
optimisers' single-design path, Python floats) to

* ``value`` — the checked quantity, ``limit`` — its bound (a parameter of the check),
* ``margin`` — signed and dimensionless, >= 0 where the check holds (lengths are divided
  by the module, so margins of different checks compare),
* ``gradient`` — ∂margin/∂x1 and ∂margin/∂x2, analytic (checked against finite differences
  in the tests), for the optimisers of :mod:`geardesign.shifts.optimize`.

A problem models only the checks asked for: build the list with :func:`make_checks`.

Helical pairs are checked in the normal section where it decides (undercut by the exact transverse
form x_min = h_l* − z sin²α_t/(2 cos β), the same as the virtual-gear rule without its
approximation; tip thickness s_an on the tip cylinder) and on the transverse contact ratio.
Internal pairs (gear 2 a ring) have their own checks for the ring: :class:`RingInterference`
and :class:`RingTip`; the pinion keeps undercut and interference at its root.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import functools

import numpy as np

from ..errors import GearDesignError
from ..validate import _show, one_number, require_bool, require_finite, require_positive, require_range

__all__ = [
    "Check", "Undercut", "Interference", "TipThickness", "ContactRatio", "TotalContactRatio", "Jamming",
    "RingInterference", "RingTip", "TipInterference", "RadialAssembly", "CutterTrimming", "CutterInterference",
    "ToothDifference",
    "CenterDistance", "CustomCheck",
    "make_checks", "evaluate", "DEFAULT_EPS_ALPHA_MIN", "DEFAULT_SA_MIN", "EPS_ALPHA_MIN_RANGE", "SA_MIN_RANGE",
    "EPS_GAMMA_MIN_RANGE",
]

DEFAULT_EPS_ALPHA_MIN = 1.2
DEFAULT_SA_MIN = 0.25
# The ranges a limit may take (the scene schema and the CLI read them from here): ε_α below 1
# gives gaps in the mesh but is allowed for studies; s_a above 1·m leaves no addendum to speak of.
EPS_ALPHA_MIN_RANGE = (0.0, 10.0)
SA_MIN_RANGE = (0.0, 2.0)
EPS_GAMMA_MIN_RANGE = (0.0, 20.0)   # ε_γ = ε_α + ε_β: wide helical gears reach 5 and more


def _other(gear: int) -> int:
    return 2 if gear == 1 else 1


def _drho_a(geo: dict, gear: int):
    """∂ρ_a/∂x1, ∂ρ_a/∂x2 of the tip radius of curvature ρ_a = √(r_a² − r_b²) of ``gear``.

    ∂ρ_a/∂r_a = r_a/ρ_a and ∂r_a/∂x_j = m(δ_gear,j − ∂Δy/∂x_Σ).
    """
    f = geo[f"_ra{gear}"] / geo[f"_rho_a{gear}"] * geo["_m"]
    own = f * (1.0 - geo["_dk"])
    other = -f * geo["_dk"]
    return (own, other) if gear == 1 else (other, own)


def _dg(geo: dict):
    """(∂N1N2/∂x1, ∂N1N2/∂x2) of N1N2 = a_w sin α_w: m sin α_t / sin²α_w per unit of x_Σ, where
    x_Σ = x1 + x2 (x2 − x1 for an internal pair, so ∂x_Σ/∂x1 = ``_sgn`` = −1)."""
    g = geo["_m"] * geo["_sa"] / geo["_sin_w"] ** 2
    return geo["_sgn"] * g, g


def _drho_p(geo: dict, gear: int):
    """(∂ρ_p/∂x1, ∂ρ_p/∂x2) at the start of the active profile of ``gear``: ρ_p1 = N1N2 − ρ_a2 and
    ρ_p2 = N1N2 − ρ_a1 externally; ρ_p1 = ρ_a2 − N1N2 and ρ_p2 = N1N2 + ρ_a1 for a ring pair."""
    sgn = geo["_sgn"]
    dm = _drho_a(geo, _other(gear))
    dn = _dg(geo)
    if gear == 1:
        return sgn * (dn[0] - dm[0]), sgn * (dn[1] - dm[1])
    return dn[0] - sgn * dm[0], dn[1] - sgn * dm[1]


def sliding_root_gradient(geo: dict, gear: int):
    """∂ϑ/∂x1, ∂ϑ/∂x2 of the specific sliding of ``gear`` at the start of its active profile.

    ϑ1 = 1 − ρ_a2/(u ρ_p1) and ϑ2 = 1 − u ρ_a1/ρ_p2 with ρ_p = N1N2 − ρ_a,mate and
    ∂N1N2/∂x_j = :func:`_dg`; the quotient rule on each.
    """
    o = _other(gear)
    rho_m, rho_p = geo[f"_rho_a{o}"], geo[f"rho_p{gear}"]
    u = geo["_z2"] / geo["_z1"]
    out = []
    for dm, dp in zip(_drho_a(geo, o), _drho_p(geo, gear)):
        if gear == 1:
            out.append(-(dm * rho_p - rho_m * dp) / (u * rho_p * rho_p))
        else:
            out.append(-u * (dm * rho_p - rho_m * dp) / (rho_p * rho_p))
    return tuple(out)


@dataclass(frozen=True)
class Check:
    """Base of all checks: a name, a readable label and a limit."""

    name: str = ""
    label: str = ""
    limit: float = 0.0

    # True for checks that read fields only reports need (geometry.REPORT_FIELDS): the solvers
    # then compute the full geometry
    needs_report_fields = False

    def value(self, geo: dict):
        raise NotImplementedError

    def limit_value(self, geo: dict):
        return self.limit

    def margin(self, geo: dict):
        return self.value(geo) - self.limit_value(geo)

    def gradient(self, geo: dict):
        raise NotImplementedError

    # The optimisers see each check as smooth parts whose minimum is its margin (one part
    # for most checks); a kink of the margin then becomes a corner between two parts.
    n_parts = 1

    def part_margins(self, geo: dict) -> list:
        return [self.margin(geo)]

    def part_gradients(self, geo: dict) -> list:
        return [self.gradient(geo)]


@dataclass(frozen=True)
class Undercut(Check):
    """No undercut of ``gear``: x >= x_min = h_l* − z sin²α/2 (margin x − x_min)."""

    gear: int = 1

    def __post_init__(self):
        object.__setattr__(self, "name", self.name or f"undercut{self.gear}")
        object.__setattr__(self, "label", self.label or f"no undercut of gear {self.gear} (x{self.gear} >= x_min)")

    def value(self, geo):
        return geo[f"_x{self.gear}"]

    def limit_value(self, geo):
        return geo[f"x_min{self.gear}"]

    def gradient(self, geo):
        return (1.0, 0.0) if self.gear == 1 else (0.0, 1.0)


@dataclass(frozen=True)
class Interference(Check):
    """No interference of the mate's tip with the fillet of ``gear`` (GOST 16532-70 "заклинивание").

    The start of the active profile (radius of curvature ρ_p = a_w sin α_w − ρ_a,mate) must lie
    on the generated involute, above its limit point ρ_l (and above the base circle, ρ >= 0, even
    for an undercut gear). Margin (ρ_p − max(ρ_l, 0))/m.
    """

    gear: int = 1

    def __post_init__(self):
        object.__setattr__(self, "name", self.name or f"interference{self.gear}")
        object.__setattr__(self, "label", self.label or
                           f"no interference of gear {_other(self.gear)}'s tip with gear {self.gear}'s fillet")

    n_parts = 2

    def value(self, geo):
        return geo[f"rho_p{self.gear}"] / geo["_m"]

    def limit_value(self, geo):
        rho_l = geo[f"rho_l{self.gear}"]
        return rho_l * (rho_l > 0) / geo["_m"]      # max(ρ_l, 0), for arrays and floats alike

    def gradient(self, geo):
        # the limit-point part where ρ_l > 0 (it is the smaller there), else the base-circle part
        g1, g2 = self.part_gradients(geo)[1]
        own = (geo[f"rho_l{self.gear}"] > 0) / geo["_sa"]
        return (g1 - own, g2) if self.gear == 1 else (g1, g2 - own)

    def part_margins(self, geo):
        """(ρ_p − ρ_l)/m and ρ_p/m: above the limit point and above the base circle."""
        m = geo["_m"]
        rho_p = geo[f"rho_p{self.gear}"]
        return [(rho_p - geo[f"rho_l{self.gear}"]) / m, rho_p / m]

    def part_gradients(self, geo):
        m = geo["_m"]
        dp1, dp2 = _drho_p(geo, self.gear)
        base = (dp1 / m, dp2 / m)
        # ∂ρ_l/∂x_gear = m / sin α
        lim = (base[0] - 1.0 / geo["_sa"], base[1]) if self.gear == 1 else (base[0], base[1] - 1.0 / geo["_sa"])
        return [lim, base]


@dataclass(frozen=True)
class TipThickness(Check):
    """Tip thickness s_a >= limit·m (limit = sa_min, 0.25 by default; 0.4 for case-hardened gears).

    Margin s_an/m − sa_min, in the normal section on the tip cylinder (s_an = s_at cos β_a; the
    transverse s_a of a spur gear); with sa_min = 0 it is the "not pointed" check.
    """

    gear: int = 1
    limit: float = DEFAULT_SA_MIN

    def __post_init__(self):
        require_range("sa_min", self.limit, *SA_MIN_RANGE)
        object.__setattr__(self, "name", self.name or f"tip_thickness{self.gear}")
        object.__setattr__(self, "label", self.label or f"tip thickness of gear {self.gear}: s_a{self.gear}/m >= sa_min (normal section)")

    def value(self, geo):
        return geo[f"san{self.gear}"] / geo["_m"]

    def gradient(self, geo):
        # s_a = d_a(ψ − inv α_a);  ∂inv α_a/∂d_a = tan α_a / d_a;  ∂ψ/∂x = 2 tan α_n / z.
        # A ring's tooth widens outward: s_a2 = d_a2(ψ + inv α_a2), ψ = s/d − inv α, ∂ψ/∂x2 = −2 tan α_n / z2.
        j = self.gear
        m = geo["_m"]
        dda_own = 2.0 * m * (1.0 - geo["_dk"])
        dda_other = -2.0 * m * geo["_dk"]
        if geo["_sgn"] < 0 and j == 2:
            coef = geo["_psi2"] + geo["_inv_a2"] + geo["_t_a2"]
            dpsi = -geo["da2"] * 2.0 * geo["_tn"] / geo["_z2"]
        else:
            coef = geo[f"_psi{j}"] - geo[f"_inv_a{j}"] - geo[f"_t_a{j}"]
            dpsi = geo[f"da{j}"] * 2.0 * geo["_tn"] / geo[f"_z{j}"]
        own = (dda_own * coef + dpsi) / m
        other = dda_other * coef / m
        if geo["_tan_beta"]:
            # s_an = s_a c, c = (1 + tb²)^(−1/2), tb = tan β d_a/d:  ∂c/∂d_a = −c³ tb tan β / d
            d = geo[f"d{j}"]
            tb = geo["_tan_beta"] * geo[f"da{j}"] / d
            c = 1.0 / (1.0 + tb * tb) ** 0.5
            dc = -c ** 3 * tb * geo["_tan_beta"] / d * geo[f"sa{j}"] / m
            own, other = own * c + dc * dda_own, other * c + dc * dda_other
        return (own, other) if j == 1 else (other, own)


@dataclass(frozen=True)
class ContactRatio(Check):
    """Transverse contact ratio ε_α >= limit (eps_alpha_min, 1.2 by default). Margin ε_α − limit."""

    limit: float = DEFAULT_EPS_ALPHA_MIN

    def __post_init__(self):
        require_range("eps_alpha_min", self.limit, *EPS_ALPHA_MIN_RANGE)
        object.__setattr__(self, "name", self.name or "contact_ratio")
        object.__setattr__(self, "label", self.label or "transverse contact ratio eps_alpha >= eps_alpha_min")

    def value(self, geo):
        return geo["eps_alpha"]

    def gradient(self, geo):
        # g_α = ρ_a1 + ρ_a2 − N1N2; for a ring pair ρ_a1 − ρ_a2 + N1N2
        sgn = geo["_sgn"]
        a1, b1 = _drho_a(geo, 1)
        a2, b2 = _drho_a(geo, 2)
        d1, d2 = _dg(geo)
        return (a1 + sgn * (a2 - d1)) / geo["p_b"], (b1 + sgn * (b2 - d2)) / geo["p_b"]


@dataclass(frozen=True)
class TotalContactRatio(Check):
    """Total contact ratio ε_γ = ε_α + ε_β >= limit (helical pairs; ε_β needs the face width).
    Margin ε_γ − limit; ε_β does not depend on the shifts, so the gradient is ε_α's."""

    limit: float = 2.0

    def __post_init__(self):
        require_range("eps_gamma_min", self.limit, *EPS_GAMMA_MIN_RANGE)
        object.__setattr__(self, "name", self.name or "total_contact_ratio")
        object.__setattr__(self, "label", self.label or "total contact ratio eps_gamma >= eps_gamma_min")

    def value(self, geo):
        return geo["eps_gamma"]

    def gradient(self, geo):
        return ContactRatio().gradient(geo)


def _cutter(cutter):
    """The check's shaper cutter: the given one, or the default (standard size for the module)."""
    from .ring import ShaperCutter
    if cutter is None:
        return ShaperCutter()
    if not isinstance(cutter, ShaperCutter):
        raise GearDesignError(f"cutter must be a geardesign.ShaperCutter, got {_show(cutter)}")
    return cutter


def _cutting_mesh(geo: dict, cutter):
    """The cutter–ring mesh (:func:`geardesign.gears.ring.cutting_mesh`) of the ring in ``geo``,
    kept in ``geo`` by cutter: the margins and gradients of one design share it."""
    memo = geo.setdefault("_cutting_meshes", {})
    key = (cutter.z0, cutter.x0, cutter.ha0)   # equal cutters share it; a plain tuple hashes in C
    if key not in memo:
        from .ring import cutting_mesh
        ta, tn = geo["_ta"], geo["_tn"]   # tan α_t, tan α_n: one value for every design
        at = math.atan(ta) if type(ta) is float else float(np.arctan(np.ravel(ta)[0]))
        cos_beta = geo["_m"] * geo["_z2"] / geo["d2"]
        memo[key] = cutting_mesh(geo["_m"], geo["_z2"], geo["_x2"], geo["_ra2"], cutter, at,
                                 tn if type(tn) is float else float(np.ravel(tn)[0]), cos_beta)
    return memo[key]


@dataclass(frozen=True)
class RingInterference(Check):
    """No interference of the pinion's tip with the ring's root (internal pairs): the contact on the
    ring ends at ρ_p2 = N1N2 + ρ_a1, which must stay on the involute the shaper ``cutter``
    generated, below its form limit ρ_F2 = ρ_a0 + a_w0 sin α_w0 near the root (the ring's
    counterpart of the external condition, GOST 19274-73; the form limit from the cutter–ring
    mesh, :func:`geardesign.gears.ring.cutting_mesh`). Margin (ρ_F2 − ρ_p2)/m.

    The geometry's ``rho_l2`` is the rack-equivalent limit (the cutter of infinite teeth, KHK's
    d_f2 = d_a2 + 2h): a real shaper starts the ring's involute lower down the flank — on KHK's
    16/24 pair with a 12-tooth cutter ρ_F2 is 3 mm below it — so the check uses the cutter."""

    cutter: object = None

    def __post_init__(self):
        object.__setattr__(self, "cutter", _cutter(self.cutter))
        object.__setattr__(self, "name", self.name or "interference2")
        object.__setattr__(self, "label", self.label or "no interference of gear 1's tip with the ring's root")

    def value(self, geo):
        return geo["rho_p2"] / geo["_m"]

    def limit_value(self, geo):
        return _cutting_mesh(geo, self.cutter).rho_form2 / geo["_m"]

    def margin(self, geo):
        return (_cutting_mesh(geo, self.cutter).rho_form2 - geo["rho_p2"]) / geo["_m"]

    def gradient(self, geo):
        # ρ_F2 depends on x2 alone, through α_w0 (:class:`~geardesign.gears.ring.CuttingMesh`)
        dp1, dp2 = _drho_p(geo, 2)
        m = geo["_m"]
        return -dp1 / m, (_cutting_mesh(geo, self.cutter).drho_form2_dx2 - dp2) / m


@dataclass(frozen=True)
class RingTip(Check):
    """The ring's tip circle lies outside its base circle, so its tip flank is involute (internal
    pairs; GOST 19274-73): margin (r_a2 − r_b2)/m = z2 sin²(α_t/2)/cos β − h_a* + x2."""

    def __post_init__(self):
        object.__setattr__(self, "name", self.name or "ring_tip")
        object.__setattr__(self, "label", self.label or "the ring's tip circle outside its base circle")

    def value(self, geo):
        return geo["_ra2"] / geo["_m"]

    def limit_value(self, geo):
        return geo["db2"] / 2.0 / geo["_m"]

    def margin(self, geo):
        return geo["_gap2"] / geo["_m"]

    def gradient(self, geo):
        return 0.0, 1.0


@dataclass(frozen=True)
class Jamming(Check):
    """Seed 000's jamming test r_a,mate < O_mate N_gear (the mate's tip stays short of the
    interference point N on the base circle of ``gear``). Margin (O N − r_a)/m. Implied by
    :class:`Interference`; reported for comparison with hand calculations.
    """

    needs_report_fields = True   # O2N1, O1N2

    gear: int = 1

    def __post_init__(self):
        o = _other(self.gear)
        object.__setattr__(self, "name", self.name or f"jamming{self.gear}")
        object.__setattr__(self, "label", self.label or f"r_a{o} < O{o}N{self.gear} (tip of gear {o} short of N{self.gear})")

    def value(self, geo):
        return geo[f"_ra{_other(self.gear)}"] / geo["_m"]

    def limit_value(self, geo):
        return geo[f"o{_other(self.gear)}n{self.gear}"] / geo["_m"]

    def margin(self, geo):
        return self.limit_value(geo) - self.value(geo)

    def gradient(self, geo):
        # O2N1² = r_b2² + g², ∂(O2N1)/∂x = g/O2N1 · ∂g/∂x;  ∂r_a2/∂x_j = m(δ2j − ∂Δy/∂x_Σ)
        o = _other(self.gear)
        m = geo["_m"]
        g = geo[f"_rho_a{o}"] + geo[f"rho_p{self.gear}"]
        don = g / geo[f"o{o}n{self.gear}"] * _dg(geo)[1]      # external pairs only
        dra_own = m * (1.0 - geo["_dk"])
        dra_other = -m * geo["_dk"]
        d_o = (don - dra_own) / m
        d_n = (don - dra_other) / m
        return (d_n, d_o) if o == 2 else (d_o, d_n)


def _cos_tip(geo: dict, gear: int):
    """cos α_a of ``gear`` from tan α_a (r_b/r_a)."""
    t = geo[f"_t_a{gear}"]
    return 1.0 / (1.0 + t * t) ** 0.5


@dataclass(frozen=True)
class TipInterference(Check):
    """No tip ("trochoid") interference of pinion and ring as teeth enter and leave mesh
    (internal pairs; KHK §5.2 eq. (5-6)/(5-7), GOST 19274-73): margin in radians of ring rotation,
    :func:`geardesign.gears.ring.trochoid_margin`, its gradient
    :func:`~geardesign.gears.ring.trochoid_margin_gradient`."""

    needs_report_fields = False

    def __post_init__(self):
        object.__setattr__(self, "name", self.name or "tip_interference")
        object.__setattr__(self, "label", self.label or "the tips of pinion and ring clear each other (trochoid)")

    def value(self, geo):
        return self.margin(geo)

    def margin(self, geo):
        from .ring import trochoid_margin
        return trochoid_margin(geo["_z1"], geo["_z2"], geo["_ra1"], geo["_ra2"], geo["a_w"],
                               geo["_inv_a1"], geo["_inv_a2"], geo["inv_alpha_w"])

    def gradient(self, geo):
        from .ring import trochoid_margin_gradient
        m, sgn = geo["_m"], geo["_sgn"]
        # ∂r_a/∂x_j = m(δ_gear,j − ∂Δy/∂x_Σ ∂x_Σ/∂x_j); ∂a_w/∂x_Σ = m sin α_t / sin α_w (as
        # CenterDistance); ∂inv α_w/∂x_Σ = 2 tan α_n / z_Σ; ∂x_Σ/∂x1 = sgn, ∂x_Σ/∂x2 = 1
        zs = geo["_z2"] - geo["_z1"] if sgn < 0 else geo["_z1"] + geo["_z2"]
        daw, dinv = m * geo["_sa"] / geo["_sin_w"], 2.0 * geo["_tn"] / zs
        out = []
        for j, dxs in ((1, sgn), (2, 1.0)):
            d_ra1 = m * ((j == 1) - geo["_dk"] * dxs)
            d_ra2 = m * ((j == 2) - geo["_dk"] * dxs)
            out.append(trochoid_margin_gradient(geo["_z1"], geo["_z2"], geo["_ra1"], geo["_ra2"], geo["a_w"],
                                                geo["_t_a1"], geo["_t_a2"], d_ra1, d_ra2, daw * dxs, dinv * dxs))
        return tuple(out)


@dataclass(frozen=True)
class RadialAssembly(Check):
    """The pinion can be put into the ring radially (internal pairs; KHK §5.2 eq. (5-9)/(5-10), the
    trimming condition at the operating centre distance): margin in radians of pinion rotation;
    failing means the pinion goes in axially. Optional. Gradient by central differences."""

    def __post_init__(self):
        object.__setattr__(self, "name", self.name or "radial_assembly")
        object.__setattr__(self, "label", self.label or "the pinion enters the ring radially (no trimming)")

    def value(self, geo):
        return self.margin(geo)

    def margin(self, geo):
        from .ring import trimming_margin
        return trimming_margin(geo["_z1"], geo["_z2"], _cos_tip(geo, 1), _cos_tip(geo, 2), geo["_inv_a1"],
                               geo["_inv_a2"], geo["inv_alpha_w"])

    def gradient(self, geo):
        return None


@dataclass(frozen=True)
class CutterTrimming(Check):
    """The shaper cutter generates the ring without trimming its tips (internal pairs; KHK eq.
    (5-9)/(5-10) with the cutter in place of the pinion, in the cutter–ring mesh at zero backlash;
    KHK's Table 5-3a of the smallest ring per cutter follows from it). ``cutter``: a
    :class:`~geardesign.gears.ring.ShaperCutter` (default: the standard-size one for the module).
    Depends on the ring only: gradient (0, ∂/∂x2), :func:`geardesign.gears.ring.trimming_margin_gradient`."""

    cutter: object = None

    def __post_init__(self):
        object.__setattr__(self, "cutter", _cutter(self.cutter))
        object.__setattr__(self, "name", self.name or "cutter_trimming")
        object.__setattr__(self, "label", self.label or "the shaper cutter generates the ring without trimming")

    def value(self, geo):
        return self.margin(geo)

    def margin(self, geo):
        return _cutting_mesh(geo, self.cutter).trimming

    def gradient(self, geo):
        return 0.0, _cutting_mesh(geo, self.cutter).dtrimming_dx2


@dataclass(frozen=True)
class CutterInterference(Check):
    """The shaper cutter generates the ring's whole flank with its involute (internal pairs): in
    the cutter–ring mesh the ring's tip point ρ_a2 must lie beyond the cutter's interference point
    N0, ρ_a2 >= N0N2 = a_w0 sin α_w0 — KHK eq. (5-4), z0/z2 >= 1 − tan α_a2/tan α_w0, with the
    cutter in place of the pinion. Otherwise the cutter's tip region runs below its base circle and
    cuts the ring's tips away (the generated ring shows it: :func:`geardesign.profiles.ring.ring_profile`
    sets ``cutting_interference``). Margin (ρ_a2 − N0N2)/m, N0N2 = a_w0 sin α_w0 from the
    cutting mesh. Depends on the ring only: gradient (0, (m r_a2/ρ_a2 − ∂ρ_F2/∂x2)/m)."""

    cutter: object = None

    def __post_init__(self):
        object.__setattr__(self, "cutter", _cutter(self.cutter))
        object.__setattr__(self, "name", self.name or "cutter_interference")
        object.__setattr__(self, "label", self.label or "the shaper cutter's involute generates the ring's tip "
                                                         "(no involute interference in cutting)")

    def value(self, geo):
        return geo["_rho_a2"] / geo["_m"]

    def limit_value(self, geo):
        return _cutting_mesh(geo, self.cutter).n0n2 / geo["_m"]

    def margin(self, geo):
        return (geo["_rho_a2"] - _cutting_mesh(geo, self.cutter).n0n2) / geo["_m"]

    def gradient(self, geo):
        m = geo["_m"]
        # ρ_a2² = r_a2² − r_b2², ∂r_a2/∂x2 = m (the ring's tip moves out with x2);
        # ∂N0N2/∂x2 = ∂ρ_F2/∂x2 (ρ_a0 is the cutter's)
        return 0.0, (m * geo["_ra2"] / geo["_rho_a2"] - _cutting_mesh(geo, self.cutter).drho_form2_dx2) / m


@dataclass(frozen=True)
class ToothDifference(Check):
    """The smallest tooth difference z2 − z1 of an internal pair a designer or shop allows
    (``limit``; KHK's rule for unshifted standard gears is "more than 9", recomputed in
    docs/research/internal_helical.md §2(d)). The physical limits are the interference checks; this
    one is the rule of thumb on top. Not differentiable in x: gradient 0."""

    limit: float = 10.0

    def __post_init__(self):
        require_range("tooth_difference_min", self.limit, 1, 10_000)
        object.__setattr__(self, "name", self.name or "tooth_difference")
        object.__setattr__(self, "label", self.label or "z2 - z1 >= tooth_difference_min")

    def value(self, geo):
        return geo["_z2"] - geo["_z1"]

    def gradient(self, geo):
        return 0.0, 0.0


@dataclass(frozen=True)
class CenterDistance(Check):
    """The proposed shifts fit the housing: their own operating centre distance a_w (zero
    backlash) equals the housing's ``limit`` (mm) within ``tol_mm``. Margin
    (tol − |a_w − a_housing|)/m. A report check: the optimisers take a housing a_w as a fixed
    x-sum instead (``a_w=`` of :func:`geardesign.optimize_shifts`).

    ``tol_mm`` defaults to 1e-3·m, a tenth or less of the centre-distance tolerance f_a of
    ISO 1328 accuracy grades 6–8 for such gears (DIN 3964 tables).
    """

    tol_mm: float | None = None

    def __post_init__(self):
        require_positive("a_w housing (center distance)", self.limit, unit="mm")
        if self.tol_mm is not None:
            require_positive("center distance tolerance", self.tol_mm, unit="mm")
        object.__setattr__(self, "name", self.name or "center_distance")
        object.__setattr__(self, "label", self.label or f"a_w of x1 + x2 = housing a_w {self.limit:.10g} mm")

    def value(self, geo):
        return geo["a_w"]

    def _tol(self, geo):
        return 1e-3 * geo["_m"] if self.tol_mm is None else self.tol_mm

    def margin(self, geo):
        return (self._tol(geo) - abs(geo["a_w"] - self.limit)) / geo["_m"]

    def gradient(self, geo):
        # ∂a_w/∂x_Σ = m sin α_t / sin α_w (ISO 21771 eq. (62) differentiated); ∂x_Σ/∂x1 = −1 internally
        g = -np.sign(geo["a_w"] - self.limit) * geo["_sa"] / geo["_sin_w"]
        return geo["_sgn"] * g, g


@dataclass(frozen=True)
class CustomCheck(Check):
    """A user's own check: ``func(geo) -> value`` with ``value >= limit`` required
    (``sense=">="``) or ``value <= limit`` (``sense="<="``). ``geo`` is the dict of geometry
    arrays (the :data:`~geardesign.gears.geometry.GEOMETRY_FIELDS` names). The gradient, when an
    optimiser needs one, is taken by central differences.
    """

    needs_report_fields = True   # a user's func may read any field

    func: Callable | None = None
    sense: str = ">="
    scale: float = 1.0

    def __post_init__(self):
        if not callable(self.func):
            raise GearDesignError(f"CustomCheck {self.name!r}: func must be callable, got {self.func!r}")
        if self.sense not in (">=", "<="):
            raise GearDesignError(f"CustomCheck {self.name!r}: sense must be '>=' or '<=', got {self.sense!r}")
        if not self.name:
            raise GearDesignError("CustomCheck needs a name")
        require_finite("limit", self.limit)
        object.__setattr__(self, "label", self.label or f"{self.name} {self.sense} {self.limit:g}")

    def value(self, geo):
        return np.asarray(self.func(geo), dtype=float)

    def margin(self, geo):
        d = self.value(geo) - self.limit
        return (d if self.sense == ">=" else -d) / self.scale

    def gradient(self, geo):
        return None  # the optimiser differentiates numerically


def make_checks(eps_alpha_min: float | None = DEFAULT_EPS_ALPHA_MIN, sa_min: float | None = DEFAULT_SA_MIN,
                undercut: bool = True, interference: bool = True, jamming: bool = False,
                extra=(), eps_gamma_min: float | None = None, internal: bool = False, cutter=None,
                radial_assembly: bool = False, tooth_difference_min: float | None = None) -> tuple[Check, ...]:
    """The list of checks a case asks for (defaults: no undercut, no interference, s_a >= 0.25·m, ε_α >= 1.2).

    ``eps_alpha_min=None`` or ``sa_min=None`` drops that check; ``undercut=False`` allows
    undercut; ``eps_gamma_min`` adds the total contact ratio of a helical pair; ``extra`` adds
    :class:`Check` objects (e.g. a :class:`CustomCheck`). ``internal``: the checks of a ring pair —
    undercut of the pinion only, the ring's :class:`RingInterference` and :class:`RingTip`, the tips'
    :class:`TipInterference`, the cutter's :class:`CutterTrimming` (``cutter``: a
    :class:`~geardesign.gears.ring.ShaperCutter`, the standard size for the module by default), and
    on request :class:`RadialAssembly` and :class:`ToothDifference`; no jamming rows (seed 000's
    test is for external pairs).

    >>> [c.name for c in make_checks(sa_min=0.4, undercut=False)]
    ['interference1', 'interference2', 'tip_thickness1', 'tip_thickness2', 'contact_ratio']
    >>> [c.name for c in make_checks(internal=True)][:6]
    ['undercut1', 'interference1', 'interference2', 'ring_tip', 'tip_interference', 'cutter_trimming']
    """
    for flag, value in (("undercut", undercut), ("interference", interference), ("jamming", jamming),
                        ("internal", internal)):
        require_bool(flag, value)
    out: list[Check] = []
    if undercut:
        out += [Undercut(gear=1)] if internal else [Undercut(gear=1), Undercut(gear=2)]
    for flag, value in (("radial_assembly", radial_assembly),):
        require_bool(flag, value)
    if interference and internal:
        out += [Interference(gear=1), RingInterference(cutter=cutter), RingTip(), TipInterference(),
                CutterTrimming(cutter=cutter), CutterInterference(cutter=cutter)]
    elif interference:
        out += [Interference(gear=1), Interference(gear=2)]
    if internal and radial_assembly:
        out += [RadialAssembly()]
    if internal and tooth_difference_min is not None:
        out += [ToothDifference(limit=one_number("tooth_difference_min", require_range(
            "tooth_difference_min", tooth_difference_min, 1, 10_000)))]
    if jamming and not internal:
        out += [Jamming(gear=1), Jamming(gear=2)]
    if sa_min is not None:
        sa_min = one_number("sa_min", require_range("sa_min", sa_min, *SA_MIN_RANGE))
        out += [TipThickness(gear=1, limit=sa_min), TipThickness(gear=2, limit=sa_min)]
    if eps_alpha_min is not None:
        out += [ContactRatio(limit=one_number("eps_alpha_min", require_range("eps_alpha_min", eps_alpha_min, *EPS_ALPHA_MIN_RANGE)))]
    if eps_gamma_min is not None:
        out += [TotalContactRatio(limit=one_number("eps_gamma_min", require_range(
            "eps_gamma_min", eps_gamma_min, *EPS_GAMMA_MIN_RANGE)))]
    if isinstance(extra, Check):
        extra = (extra,)
    if not isinstance(extra, (list, tuple)):
        raise GearDesignError(f"extra must be a list of geardesign.gears.checks.Check objects, got {_show(extra)}")
    for c in extra:
        if not isinstance(c, Check):
            raise GearDesignError(f"extra checks must be geardesign.gears.checks.Check objects, got {c!r}")
        out.append(c)
    names = [c.name for c in out]
    dup = {n for n in names if names.count(n) > 1}
    if dup:
        raise GearDesignError(f"check names must be unique, got duplicates {sorted(dup)}")
    return tuple(out)


def resolve_checks(checks, internal: bool = False) -> tuple[Check, ...]:
    """Accept None (defaults), a dict of :func:`make_checks` keywords, or a sequence of Checks;
    ``internal`` picks the ring pair's checks where the caller leaves the choice to the defaults."""
    if checks is None:
        return _DEFAULT_CHECKS_INTERNAL if internal else _DEFAULT_CHECKS
    if isinstance(checks, dict):
        try:
            return make_checks(**{"internal": internal, **checks})
        except TypeError as exc:
            raise GearDesignError(
                f"checks: unknown option in {sorted(checks)}; allowed: eps_alpha_min, sa_min, "
                f"undercut, interference, jamming, extra, eps_gamma_min") from exc
    if isinstance(checks, (str, bytes, Check)) or not hasattr(checks, "__iter__"):
        raise GearDesignError(f"checks must be None, a dict of make_checks options or a list of Check objects, "
                              f"got {_show(checks)}")
    try:
        checks = tuple(checks)
    except TypeError:    # a 0-d array has __iter__ but does not iterate
        raise GearDesignError(f"checks must be None, a dict of make_checks options or a list of Check objects, "
                              f"got {_show(checks)}") from None
    for c in checks:
        if not isinstance(c, Check):
            raise GearDesignError(f"checks must be Check objects, got {c!r}")
    return checks


_DEFAULT_CHECKS = make_checks()
_DEFAULT_CHECKS_INTERNAL = make_checks(internal=True)


@functools.cache
def _check_table_class():
    """CheckTable, built on first use: pandas is imported only when a table is asked for."""
    import pandas as pd

    class CheckTable(pd.DataFrame):
        """The checks of one design, a DataFrame whose printout leaves out the long ``label``
        column, so that check, margin and ok fit a plain terminal (the labels stay in the frame)."""

        @property
        def _constructor(self):
            return CheckTable

        def __repr__(self) -> str:
            cols = [c for c in self.columns if c != "label"]
            text = pd.DataFrame(self[cols]).to_string(float_format=lambda v: f"{v:.6g}")
            return text + ("\n(each check's meaning: the 'label' column)" if "label" in self.columns else "")

    return CheckTable


UNDEFINED = " (undefined for this design: a quantity the check needs does not exist here, so it fails)"


def evaluate(geo: dict, checks):
    """Rows ``check, label, value, limit, margin, ok`` for one design (geo of 0-d arrays). A
    margin that does not exist (NaN: e.g. no cutter–ring mesh at this ring shift) is −inf, a
    failing check, and its label says so, as :func:`margins` treats it in the solvers."""
    rows = []
    for c in checks:
        value = float(np.asarray(c.value(geo)))
        limit = float(np.asarray(c.limit_value(geo)))
        margin = float(np.asarray(c.margin(geo)))
        label = c.label
        if math.isnan(margin):
            margin, label = -math.inf, label + UNDEFINED
        rows.append((c.name, label, value, limit, margin, bool(margin >= 0)))
    return _check_table_class()(rows, columns=["check", "label", "value", "limit", "margin", "ok"])


def margins(geo: dict, checks) -> dict[str, np.ndarray]:
    """Margin arrays by check name; NaN geometry (designs that do not exist) gives −inf."""
    out = {}
    for c in checks:
        out[c.name] = np.fmax(c.margin(geo), -np.inf)   # fmax passes the number where one is NaN
    return out
