"""The checks of an external pair (and the pinion of a ring pair): undercut, interference, tip
thickness, contact ratios, seed 000's jamming rows, the housing's centre distance and a user's own
check. Helical pairs are checked in the normal section where it decides (undercut by the exact
transverse form x_min = h_l* − z sin²α_t/(2 cos β), the same as the virtual-gear rule without its
approximation; tip thickness s_an on the tip cylinder) and on the transverse contact ratio."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np

from ...errors import GearDesignError
from ...validate import require_finite, require_positive, require_range
from .base import Check, Option, register
from .gradients import _dg, _drho_a, _drho_p, _other

__all__ = ["Undercut", "Interference", "TipThickness", "ContactRatio", "TotalContactRatio", "Jamming",
           "CenterDistance", "CustomCheck", "DEFAULT_EPS_ALPHA_MIN", "DEFAULT_SA_MIN", "EPS_ALPHA_MIN_RANGE",
           "SA_MIN_RANGE", "EPS_GAMMA_MIN_RANGE"]

DEFAULT_EPS_ALPHA_MIN = 1.2
DEFAULT_SA_MIN = 0.25
# The ranges a limit may take: ε_α below 1 gives gaps in the mesh but is allowed for studies;
# s_a above 1·m leaves no addendum to speak of; ε_γ = ε_α + ε_β of wide helical gears reaches 5 and more.
EPS_ALPHA_MIN_RANGE = (0.0, 10.0)
SA_MIN_RANGE = (0.0, 2.0)
EPS_GAMMA_MIN_RANGE = (0.0, 20.0)

UNDERCUT = Option("undercut", "flag", True, "no undercut of either gear (x >= x_min; a ring pair: the pinion)",
                  source="ISO 21771:2007 (x_min = h_a* − z sin²α_t/(2 cos β)); GOST 16532-70")
INTERFERENCE = Option("interference", "flag", True,
                      "no interference of a tip with the mate's fillet (a ring pair: the ring's and the cutter's checks too)",
                      source="GOST 16532-70 (external), GOST 19274-73 and KHK §5.2 (internal)")
JAMMING = Option("jamming", "flag", False, "seed 000's r_a,mate < O_mate N_gear rows (implied by interference)",
                 source="seed 000 (course work); implied by the interference check")
SA_MIN = Option("sa_min", "limit", DEFAULT_SA_MIN, "minimum tip thickness / module (normal section for helical gears)",
                source="s_a >= 0.25·m: Drivetrain Hub gear notes (Eritenel), ch. 2; 0.4·m for case-hardened "
                       "teeth is common practice (not verified against a standard)",
                range=SA_MIN_RANGE, sweep=True)
EPS_ALPHA_MIN = Option("eps_alpha_min", "limit", DEFAULT_EPS_ALPHA_MIN, "minimum transverse contact ratio eps_alpha",
                       source="the project's default after common design practice (>= 1.2 for spur gears; "
                              "no standard retrieved that fixes it)",
                       range=EPS_ALPHA_MIN_RANGE, sweep=True)
EPS_GAMMA_MIN = Option("eps_gamma_min", "limit", None,
                       "minimum total contact ratio eps_alpha + eps_beta (helical; needs the face width)",
                       source="ISO 21771:2007 (ε_γ = ε_α + ε_β); the limit is the designer's", range=EPS_GAMMA_MIN_RANGE)


@register
@dataclass(frozen=True)
class Undercut(Check):
    """No undercut of ``gear``: x >= x_min = h_l* − z sin²α/2 (margin x − x_min)."""

    option, per_gear, colour, order = UNDERCUT, {"external": (1, 2), "internal": (1,)}, "tab:blue", 10

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


@register
@dataclass(frozen=True)
class Interference(Check):
    """No interference of the mate's tip with the fillet of ``gear`` (GOST 16532-70 "заклинивание").

    The start of the active profile (radius of curvature ρ_p = a_w sin α_w − ρ_a,mate) must lie
    on the generated involute, above its limit point ρ_l (and above the base circle, ρ >= 0, even
    for an undercut gear). Margin (ρ_p − max(ρ_l, 0))/m.
    """

    option, per_gear, colour, order = INTERFERENCE, {"external": (1, 2), "internal": (1,)}, "tab:red", 20

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


@register
@dataclass(frozen=True)
class TipThickness(Check):
    """Tip thickness s_a >= limit·m (limit = sa_min, 0.25 by default; 0.4 for case-hardened gears).

    Margin s_an/m − sa_min, in the normal section on the tip cylinder (s_an = s_at cos β_a; the
    transverse s_a of a spur gear); with sa_min = 0 it is the "not pointed" check.
    """

    option, per_gear, colour, order = SA_MIN, {"external": (1, 2), "internal": (1, 2)}, "tab:orange", 50

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


@register
@dataclass(frozen=True)
class ContactRatio(Check):
    """Transverse contact ratio ε_α >= limit (eps_alpha_min, 1.2 by default). Margin ε_α − limit."""

    option, colour, order = EPS_ALPHA_MIN, "tab:purple", 60

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


@register
@dataclass(frozen=True)
class TotalContactRatio(Check):
    """Total contact ratio ε_γ = ε_α + ε_β >= limit (helical pairs; ε_β needs the face width).
    Margin ε_γ − limit; ε_β does not depend on the shifts, so the gradient is ε_α's."""

    option, colour, order = EPS_GAMMA_MIN, "indigo", 70

    limit: float = 2.0

    def __post_init__(self):
        require_range("eps_gamma_min", self.limit, *EPS_GAMMA_MIN_RANGE)
        object.__setattr__(self, "name", self.name or "total_contact_ratio")
        object.__setattr__(self, "label", self.label or "total contact ratio eps_gamma >= eps_gamma_min")

    def value(self, geo):
        return geo["eps_gamma"]

    def gradient(self, geo):
        return ContactRatio().gradient(geo)


@register
@dataclass(frozen=True)
class Jamming(Check):
    """Seed 000's jamming test r_a,mate < O_mate N_gear (the mate's tip stays short of the
    interference point N on the base circle of ``gear``). Margin (O N − r_a)/m. Implied by
    :class:`Interference`; reported for comparison with hand calculations.
    """

    needs_report_fields = True   # O2N1, O1N2
    option, pair_kinds, per_gear, colour, order = JAMMING, ("external",), {"external": (1, 2)}, "tab:brown", 40

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


@dataclass(frozen=True)
class CenterDistance(Check):
    """The proposed shifts fit the housing: their own operating centre distance a_w (zero
    backlash) equals the housing's ``limit`` (mm) within ``tol_mm``. Margin
    (tol − |a_w − a_housing|)/m. A report check: the optimisers take a housing a_w as a fixed
    x-sum instead (``a_w=`` of :func:`geardesign.optimize_shifts`).

    ``tol_mm`` defaults to 1e-3·m, a tenth or less of the centre-distance tolerance f_a of
    ISO 1328 accuracy grades 6–8 for such gears (DIN 3964 tables).
    """

    colour, kind_name = "tab:cyan", "center_distance"

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
    fd_gradient = True

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
