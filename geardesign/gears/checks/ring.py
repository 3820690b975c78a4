"""The checks of a ring (internal) pair beyond the pinion's: the ring's interference and tip, the tips'
trochoid interference, radial assembly, the shaper cutter's trimming and involute interference, and
the designer's smallest tooth difference (GOST 19274-73; KHK §5.2). Each is switched by
``interference`` (or its own option) and built only for internal pairs."""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...errors import GearDesignError
from ...validate import _show, require_range
from ..distinct import distinct_codes
from ..ring import (CuttingMesh, ShaperCutter, cutting_mesh, cutting_mesh_slopes, trimming_margin,
                    trimming_margin_gradient, trochoid_margin, trochoid_margin_gradient)
from .base import Check, Option, register
from .external import INTERFERENCE
from .gradients import _drho_p

__all__ = ["RingInterference", "RingTip", "TipInterference", "RadialAssembly", "CutterTrimming",
           "CutterInterference", "ToothDifference", "TOOTH_DIFFERENCE_RANGE"]

TOOTH_DIFFERENCE_RANGE = (1, 10_000)
RADIAL_ASSEMBLY = Option("radial_assembly", "flag", False,
                         "the pinion can be put into the ring radially (otherwise it goes in axially)",
                         source="KHK Gear Technical Reference §5.2, eq. (5-9)/(5-10)")
TOOTH_DIFFERENCE_MIN = Option("tooth_difference_min", "limit", None,
                              "smallest tooth difference z2 - z1 of a ring pair",
                              source="KHK's rule for unshifted standard gears: more than 9 "
                                     "(docs/research/internal_helical.md §2(d))",
                              range=TOOTH_DIFFERENCE_RANGE)


def _build_with_cutter(cls, value, context: dict) -> list:
    """The check of a cutter-dependent class for the context's ``cutter`` (None: the standard size)."""
    return [cls(cutter=context["cutter"])]


def _cutter(cutter):
    """The check's shaper cutter: the given one, or the default (standard size for the module)."""
    if cutter is None:
        return ShaperCutter()
    if not isinstance(cutter, ShaperCutter):
        raise GearDesignError(f"cutter must be a geardesign.ShaperCutter, got {_show(cutter)}")
    return cutter


def _cutting_mesh(geo: dict, cutter, slopes: bool = False):
    """The cutter–ring mesh (:func:`geardesign.gears.ring.cutting_mesh`) of the ring in ``geo``,
    kept in ``geo`` by cutter: the margins and gradients of one design share it. It depends on the
    ring's shift alone: a grid of one pair computes it once per distinct x2 (a column of the grid),
    and without its derivatives until a gradient asks for them (one design's come with it, cheaply)."""
    memo = geo.setdefault("_cutting_meshes", {})
    key = (cutter.z0, cutter.x0, cutter.ha0)   # equal cutters share it; a plain tuple hashes in C
    cm = memo.get(key)
    if cm is None or (slopes and cm.drho_form2_dx2 is None):
        m, z2, ra2, *rest = args = _mesh_args(geo, cutter)
        # the ring's tip angle as the geometry has it (one value for each fact)
        x2, t_a2, inv_a2 = geo["_x2"], geo["_t_a2"], geo["_inv_a2"]
        if type(x2) is float:
            cm = cutting_mesh(m, z2, x2, ra2, *rest, tip=(t_a2, inv_a2))
        elif cm is None:
            def mesh(x, r, t, i):
                return cutting_mesh(m, z2, x, r, *rest, slopes=slopes, tip=(t, i))

            one_pair = np.ndim(m) == 0 and np.ndim(z2) == 0 and np.ndim(rest[-1]) == 0
            cm = _per_ring_shift(mesh, x2, ra2, t_a2, inv_a2) if one_pair else mesh(x2, ra2, t_a2, inv_a2)
        else:
            cm = cutting_mesh_slopes(cm, *args, tip=(t_a2, inv_a2))
        memo[key] = cm
    return cm


def _mesh_args(geo: dict, cutter) -> tuple:
    """(m, z2, r_a2, cutter, α_t, tan α_n, cos β) of the cutting mesh of the ring in ``geo``."""
    ta, tn = geo["_ta"], geo["_tn"]   # tan α_t, tan α_n: one value for every design
    at = math.atan(ta) if type(ta) is float else float(np.arctan(np.ravel(ta)[0]))
    tn = tn if type(tn) is float else float(np.ravel(tn)[0])
    m, z2 = geo["_m"], geo["_z2"]
    return m, z2, geo["_ra2"], cutter, at, tn, m * z2 / geo["d2"]


def _per_ring_shift(mesh, x2, ra2, *tip):
    """``mesh(x2, ra2, *tip)`` of one pair, computed once per distinct x2 where x2 repeats. The ring's tip
    radius r_a2 (and its angle with it) follows x2, except where the pair does not exist (no operating
    angle: the geometry makes r_a2 NaN there, and with it the trimming, which alone reads the tip):
    checked on r_a2, not assumed."""
    found = distinct_codes(x2) if all(np.shape(v) == np.shape(x2) for v in (ra2, *tip)) else None
    if found is None:
        return mesh(x2, ra2, *tip)
    codes, first = found
    flat_ra2 = ra2.reshape(-1)
    gone = np.isnan(flat_ra2)
    if gone.any():   # stand for each x2 by a node where the pair exists, where it has one
        live = np.flatnonzero(~gone)
        first = first.copy()
        first[codes[live]] = live
    ra2_first = flat_ra2[first]
    if not ((ra2_first[codes] == flat_ra2) | gone).all():
        return mesh(x2, ra2, *tip)
    cm = mesh(x2.reshape(-1)[first], ra2_first, *(v.reshape(-1)[first] for v in tip))
    codes = codes.reshape(x2.shape)
    cm = CuttingMesh(*(f.take(codes) if np.ndim(f) else f for f in cm))
    if gone.any():
        gone = gone.reshape(x2.shape)
        cm = cm._replace(**{k: np.where(gone, np.nan, getattr(cm, k)) for k in ("trimming", "dtrimming_dx2")
                            if getattr(cm, k) is not None})
    return cm


@register
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

    option, pair_kinds, colour, order = INTERFERENCE, ("internal",), "tab:red", 21

    cutter: object = None
    build = classmethod(_build_with_cutter)

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
        return -dp1 / m, (_cutting_mesh(geo, self.cutter, True).drho_form2_dx2 - dp2) / m


@register
@dataclass(frozen=True)
class RingTip(Check):
    """The ring's tip circle lies outside its base circle, so its tip flank is involute (internal
    pairs; GOST 19274-73): margin (r_a2 − r_b2)/m = z2 sin²(α_t/2)/cos β − h_a* + x2."""

    option, pair_kinds, colour, order = INTERFERENCE, ("internal",), "darkgreen", 22

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




def _cos_tip(geo: dict, gear: int):
    """cos α_a of ``gear`` from tan α_a (r_b/r_a)."""
    t = geo[f"_t_a{gear}"]
    return 1.0 / (1.0 + t * t) ** 0.5




@register
@dataclass(frozen=True)
class TipInterference(Check):
    """No tip ("trochoid") interference of pinion and ring as teeth enter and leave mesh
    (internal pairs; KHK §5.2 eq. (5-6)/(5-7), GOST 19274-73): margin in radians of ring rotation,
    :func:`geardesign.gears.ring.trochoid_margin`, its gradient
    :func:`~geardesign.gears.ring.trochoid_margin_gradient`."""

    option, pair_kinds, colour, order = INTERFERENCE, ("internal",), "magenta", 23

    needs_report_fields = False

    def __post_init__(self):
        object.__setattr__(self, "name", self.name or "tip_interference")
        object.__setattr__(self, "label", self.label or "the tips of pinion and ring clear each other (trochoid)")

    def value(self, geo):
        return self.margin(geo)

    def margin(self, geo):
        return trochoid_margin(geo["_z1"], geo["_z2"], geo["_ra1"], geo["_ra2"], geo["a_w"],
                               geo["_inv_a1"], geo["_inv_a2"], geo["inv_alpha_w"])

    def gradient(self, geo):
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


@register
@dataclass(frozen=True)
class RadialAssembly(Check):
    """The pinion can be put into the ring radially (internal pairs; KHK §5.2 eq. (5-9)/(5-10), the
    trimming condition at the operating centre distance): margin in radians of pinion rotation;
    failing means the pinion goes in axially. Optional. Gradient by the chain rule,
    :func:`geardesign.gears.ring.trimming_margin_gradient`."""

    option, pair_kinds, colour, order = RADIAL_ASSEMBLY, ("internal",), "slategray", 30

    def __post_init__(self):
        object.__setattr__(self, "name", self.name or "radial_assembly")
        object.__setattr__(self, "label", self.label or "the pinion enters the ring radially (no trimming)")

    def value(self, geo):
        return self.margin(geo)

    def margin(self, geo):
        return trimming_margin(geo["_z1"], geo["_z2"], _cos_tip(geo, 1), _cos_tip(geo, 2), geo["_inv_a1"],
                               geo["_inv_a2"], geo["inv_alpha_w"])

    def gradient(self, geo):
        # as TipInterference: ∂r_a/∂x_j = m(δ_gear,j − ∂Δy/∂x_Σ ∂x_Σ/∂x_j), ∂inv α_w/∂x_Σ = 2 tan α_n / z_Σ
        m, sgn, z1, z2 = geo["_m"], geo["_sgn"], geo["_z1"], geo["_z2"]
        dinv = 2.0 * geo["_tn"] / (z2 - z1)
        c1, c2 = _cos_tip(geo, 1), _cos_tip(geo, 2)
        out = []
        for j, dxs in ((1, sgn), (2, 1.0)):
            d_ra1 = m * ((j == 1) - geo["_dk"] * dxs)
            d_ra2 = m * ((j == 2) - geo["_dk"] * dxs)
            out.append(trimming_margin_gradient(z1, z2, c1, c2, geo["_ra2"], geo["_t_a2"], d_ra2, dinv * dxs,
                                                geo["_ra1"], geo["_t_a1"], d_ra1))
        return tuple(out)


@register
@dataclass(frozen=True)
class CutterTrimming(Check):
    """The shaper cutter generates the ring without trimming its tips (internal pairs; KHK eq.
    (5-9)/(5-10) with the cutter in place of the pinion, in the cutter–ring mesh at zero backlash;
    KHK's Table 5-3a of the smallest ring per cutter follows from it). ``cutter``: a
    :class:`~geardesign.gears.ring.ShaperCutter` (default: the standard-size one for the module).
    Depends on the ring only: gradient (0, ∂/∂x2), :func:`geardesign.gears.ring.trimming_margin_gradient`."""

    option, pair_kinds, colour, order = INTERFERENCE, ("internal",), "saddlebrown", 24

    cutter: object = None
    build = classmethod(_build_with_cutter)

    def __post_init__(self):
        object.__setattr__(self, "cutter", _cutter(self.cutter))
        object.__setattr__(self, "name", self.name or "cutter_trimming")
        object.__setattr__(self, "label", self.label or "the shaper cutter generates the ring without trimming")

    def value(self, geo):
        return self.margin(geo)

    def margin(self, geo):
        return _cutting_mesh(geo, self.cutter).trimming

    def gradient(self, geo):
        return 0.0, _cutting_mesh(geo, self.cutter, True).dtrimming_dx2


@register
@dataclass(frozen=True)
class CutterInterference(Check):
    """The shaper cutter generates the ring's whole flank with its involute (internal pairs): in
    the cutter–ring mesh the ring's tip point ρ_a2 must lie beyond the cutter's interference point
    N0, ρ_a2 >= N0N2 = a_w0 sin α_w0 — KHK eq. (5-4), z0/z2 >= 1 − tan α_a2/tan α_w0, with the
    cutter in place of the pinion. Otherwise the cutter's tip region runs below its base circle and
    cuts the ring's tips away (the generated ring shows it: :func:`geardesign.profiles.ring.ring_profile`
    sets ``cutting_interference``). Margin (ρ_a2 − N0N2)/m, N0N2 = a_w0 sin α_w0 from the
    cutting mesh. Depends on the ring only: gradient (0, (m r_a2/ρ_a2 − ∂ρ_F2/∂x2)/m)."""

    option, pair_kinds, colour, order = INTERFERENCE, ("internal",), "olive", 25

    cutter: object = None
    build = classmethod(_build_with_cutter)

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
        return 0.0, (m * geo["_ra2"] / geo["_rho_a2"] - _cutting_mesh(geo, self.cutter, True).drho_form2_dx2) / m


@register
@dataclass(frozen=True)
class ToothDifference(Check):
    """The smallest tooth difference z2 − z1 of an internal pair a designer or shop allows
    (``limit``; KHK's rule for unshifted standard gears is "more than 9", recomputed in
    docs/research/internal_helical.md §2(d)). The physical limits are the interference checks; this
    one is the rule of thumb on top. Not differentiable in x: gradient 0."""

    option, pair_kinds, colour, order = TOOTH_DIFFERENCE_MIN, ("internal",), "black", 31

    limit: float = 10.0

    def __post_init__(self):
        require_range("tooth_difference_min", self.limit, *TOOTH_DIFFERENCE_RANGE)
        object.__setattr__(self, "name", self.name or "tooth_difference")
        object.__setattr__(self, "label", self.label or "z2 - z1 >= tooth_difference_min")

    def value(self, geo):
        return geo["_z2"] - geo["_z1"]

    def gradient(self, geo):
        return 0.0, 0.0
