"""Gear-pair geometry, spur and helical, external and internal (ISO 21771:2007, GOST 16532-70, GOST 19274-73),
vectorised.

One call evaluates any number of designs: every argument broadcasts (numpy rules) over
m, z1, z2, x1, x2; the rack is one :class:`~geardesign.gears.rack.BasicRack`. Lengths are in mm
(or in the unit of ``m``), angles in degrees at the interface and radians inside.

Cancellation-free forms are used where the textbook form loses digits:
y = z_Σ/2 · (cos α − cos α_w)/cos α_w from Δt = tan α_w − tan α, which is refined itself (no difference of
near-equal cosines);
r_a² − r_b² = (r_a − r_b)(r_a + r_b) with r_a − r_b = m(z sin²(α/2) + h_a* + x − Δy) [GOST tip];
inv α_a − inv α as a step from tan α_a − tan α (no arccos near 1, no two involutes subtracted).
"""
from __future__ import annotations

import math
import operator
from dataclasses import dataclass, fields
from types import SimpleNamespace

import numpy as np

from ..errors import GearDesignError
from ..validate import broadcast_inputs, ndim, require_bool
from .center_distance import (center_distance_from_x_sum, inv_operating_angle, min_center_distance,  # noqa: F401
                              undercut_x_min, x_sum_from_center_distance)
from .distinct import per_distinct, exact_sum_nodes  # noqa: F401
from .inputs import (_VALIDATION_FIELDS, A_W_RANGE_MM, DESIGNS_MAX, M_RANGE_MM, X_ABS_MAX, plain_inputs_ok,  # noqa: F401
                     require_module, validate_geometry, validate_inputs)
from .fields import CONTACT_FIELDS, GEOMETRY_FIELDS, INTERNAL_FIELDS, REPORT_FIELDS, TIP_FIELDS  # noqa: F401
from .involute import _tan_from_inv_float, t_minus_atan, t_minus_atan_float, tan_from_inv
from .mesh import Z_MAX, Z_MIN, Mesh, mesh_of, section_tuple as _section_constants
from .rack import BasicRack

__all__ = [
    "Geometry",
    "pair_geometry",
    "mesh_geometry",
    "mesh_geometry_float",
    "x_sum_from_center_distance",
    "center_distance_from_x_sum",
    "min_center_distance",
    "undercut_x_min",
    "GEOMETRY_FIELDS",
    "Z_MIN",
    "Z_MAX",
    "M_RANGE_MM", "A_W_RANGE_MM",
    "X_ABS_MAX",
]


# --- formulas ---------------------------------------------------------------------------


# --- the core: one set of formulas, two backends ---------------------------------------


def _float_sqrt(v: float) -> float:
    return math.sqrt(v) if v >= 0.0 else math.nan


def _float_tan_from_inv(v: float) -> float:
    return _tan_from_inv_float(v, polish=False) if v > 0.0 else math.nan


# Elementwise functions for arrays (numpy) and for one design in Python floats: the same
# formulas run on either; floats skip numpy's per-call overhead (~1 µs a call), which is
# what a single-pair optimiser pays ~200 times per evaluation.
_ARRAY_OPS = SimpleNamespace(
    sqrt=np.sqrt, atan=np.arctan, degrees=np.degrees,
    positive=lambda v: np.maximum(v, 0.0), t_minus_atan=t_minus_atan,
    tan_from_inv=lambda v: tan_from_inv(np.where(v > 0, v, np.nan), validate=False, polish=False),
    per_distinct=per_distinct)
_FLOAT_OPS = SimpleNamespace(
    sqrt=_float_sqrt, atan=math.atan, degrees=math.degrees,
    positive=lambda v: v if v > 0.0 else 0.0 * v, t_minus_atan=t_minus_atan_float,
    tan_from_inv=_float_tan_from_inv, per_distinct=lambda func, v: func(v))


# Designs per block of the vectorised path: ~60 temporaries of 16 k doubles stay in the caches,
# where one pass over a million-element array goes to memory (measured 1.7x on 1 M designs
# against unblocked, and 16 k 1.1-1.3x faster per design than 64 k). Below 16 384 (128 kB of doubles, glibc's
# mmap threshold): where that threshold is fixed (a Dask worker's MALLOC_TRIM_THRESHOLD_ fixes it) every
# temporary of 16 384 doubles was mapped and unmapped afresh, and an atlas on a worker cost 2.4x its serial CPU.
BLOCK = 16_000


def mesh_geometry(mesh: Mesh, m, x1, x2, full: bool = True, then=None, contact: bool = True, tips: bool = True) -> dict:
    """All geometry fields of ``mesh`` at module ``m`` (mm) and shifts x1, x2 as float arrays
    (broadcast with the mesh's tooth counts), no validation: designs that do not exist give NaN.
    Internal quantities the checks and gradients use carry a leading underscore. ``full=False``
    leaves out the fields only reports use (:data:`REPORT_FIELDS`), and with it ``contact=False`` those of
    the path of contact (:data:`CONTACT_FIELDS`), and with ``tips=False`` (not ``full``) those of :data:`TIP_FIELDS`
    (the fields are absent). Large inputs are evaluated
    in blocks of :data:`BLOCK` designs. ``then``: a function of the geometry dict (e.g. the
    checks' margins) applied block by block, whose dict of arrays (the designs along their last
    axis) is returned instead: only what it returns is stored at full size, not the ~50 fields. For one
    pair (m, z1 and z2 numbers) ``then`` sees the fields that depend on them alone as numbers: a grid of
    one pair computes them once (its output must broadcast them, as :meth:`Problem.margins` does)."""
    one_pair = then is not None and all(np.ndim(v) == 0 for v in (m, mesh.z1, mesh.z2))
    if one_pair:
        x1, x2 = np.broadcast_arrays(np.asarray(x1, dtype=float), np.asarray(x2, dtype=float))
        m, z1, z2 = float(m), float(mesh.z1), float(mesh.z2)
    else:
        m, z1, z2, x1, x2 = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (m, mesh.z1, mesh.z2, x1, x2)))
    with np.errstate(invalid="ignore", divide="ignore"):
        if x1.size <= BLOCK:
            geo = _formulas(mesh, m, z1, z2, x1, x2, _ARRAY_OPS, full, contact, tips)
            return geo if then is None else then(geo)
        shape = x1.shape
        flat = [v if one_pair else v.reshape(-1) for v in (m, z1, z2)] + [x1.reshape(-1), x2.reshape(-1)]
        out = {}
        for s in range(0, x1.size, BLOCK):
            part = _formulas(mesh, *(v if np.ndim(v) == 0 else v[s:s + BLOCK] for v in flat), _ARRAY_OPS, full,
                             contact, tips)
            if then is not None:
                part = then(part)
            for k, v in part.items():
                if np.ndim(v) == 0:
                    out[k] = v
                    continue
                if k not in out:
                    out[k] = np.empty(v.shape[:-1] + (x1.size,), dtype=v.dtype)
                out[k][..., s:s + v.shape[-1]] = v
        return {k: (v.reshape(v.shape[:-1] + shape) if np.ndim(v) else v) for k, v in out.items()}


def mesh_geometry_float(mesh: Mesh, m: float, x1: float, x2: float, full: bool = True, tips: bool = True) -> dict:
    """:func:`mesh_geometry` of one design in Python floats: the same fields, ~20× faster than a
    one-element array call (designs that do not exist give NaN here too); ``tips`` as there."""
    try:
        return _formulas(mesh, float(m), float(mesh.z1), float(mesh.z2), float(x1), float(x2), _FLOAT_OPS, full,
                         True, tips)
    except (ZeroDivisionError, OverflowError):
        return {k: v if k == "_mesh" else float(v)
                for k, v in mesh_geometry(mesh, m, x1, x2, full, tips=tips).items()}


def _operating_angle(D, ta, inv_a, ops):
    """inv α_w, tan α_w and tan α_w − tan α from D = inv α_w − inv α = 2 x_Σ tan α / z_Σ."""
    inv_aw = inv_a + D
    t_w = ops.tan_from_inv(inv_aw)
    # Refine Δt = tan α_w − tan α itself, so that α_w − α keeps its digits when it is small:
    # inv α_w − inv α = Δt·t t_w/(1 + t t_w) + (u − atan u), u = Δt/(1 + t t_w), two terms
    # of one sign; Newton with d(inv α_w)/dΔt = t_w²/(1 + t_w²). The start is within a few ulp
    # of tan α_w in absolute terms, so one step (quadratic) leaves ~ulp² of error in Δt.
    dt = t_w - ta
    q = 1.0 + ta * t_w
    resid = dt * ta * t_w / q + ops.t_minus_atan(dt / q) - D
    dt = dt - resid * (1.0 + t_w * t_w) / (t_w * t_w)
    return inv_aw, ta + dt, dt


def _formulas(mesh: Mesh, m, z1, z2, x1, x2, ops, full: bool = True, contact: bool = True, tips: bool = True) -> dict:
    """Every field of the pair; ``m`` is the normal module, x1/x2 normal shifts, and the circles,
    angles, thicknesses and the path of contact are transverse (ISO 21771:2007 §4–5). A spur
    pair is a helical one with z/cos β = z and every factor cos β or cos β_b = 1.0. The path of
    contact is left out with ``contact=False`` unless ``full`` (the reports read it), the fields of
    :data:`TIP_FIELDS` with ``tips=False`` unless ``full``.
    The steps hand their values on as tuples (the float path of the optimisers runs this ~10⁴
    times a second, where dicts between the steps cost a sixth of its time)."""
    rack, internal = mesh.rack, mesh.internal
    c = _section_constants(rack, mesh.beta_deg)
    sa, ta, tn = c[1], c[3], c[7]
    om = _operating_mesh(mesh, c, m, z1, z2, x1, x2, ops)
    _, inv_aw, t_w, _, cos_w, sin_w, a, y, a_w, dy, k = om
    tips = tips or full
    g1 = _gear(rack, c, m, z1, x1, k, cos_w, ops, tips=tips)
    g2 = _gear(rack, c, m, z2, x2, k, cos_w, ops, ring=internal, tips=tips)
    _, d1, db1, _, rw1, _, da1, df1, ra1, gap1, psi1, x_min1, rho_l1, rho_a1, t_a1, sa1, inv_a1 = g1
    _, d2, db2, _, rw2, _, da2, df2, ra2, gap2, psi2, x_min2, rho_l2, rho_a2, t_a2, sa2, inv_a2 = g2

    eps_beta = _overlap_ratio(mesh, m, ops)
    out = {
        "inv_alpha_w": inv_aw,
        "a": a, "a_w": a_w, "y": y, "dy": dy,
        "d1": d1, "d2": d2, "db1": db1, "db2": db2, "dw1": 2.0 * rw1, "dw2": 2.0 * rw2,
        "da1": da1, "da2": da2, "df1": df1, "df2": df2, "sa1": sa1, "sa2": sa2,
        "x_min1": x_min1, "x_min2": x_min2, "rho_l1": rho_l1, "rho_l2": rho_l2, "eps_beta": eps_beta,
        "san1": _normal_tip_thickness(sa1, da1, d1, mesh), "san2": _normal_tip_thickness(sa2, da2, d2, mesh),
        # internals used by checks and gradients (not reported)
        "_ra1": ra1, "_ra2": ra2, "_rho_a1": rho_a1, "_rho_a2": rho_a2,
        "_sin_w": sin_w, "_cos_w": cos_w, "_t_w": t_w, "_t_a1": t_a1, "_t_a2": t_a2, "_psi1": psi1, "_psi2": psi2,
        "_gap1": gap1, "_gap2": gap2, "_k": k,
        # ∂Δy/∂(x1 + x2) = 1 − sin α / sin α_w (∂y/∂x_Σ = sin α / sin α_w), 0 without shortening
        "_dk": (1.0 - sa / sin_w) if mesh.tip_shortening and not internal else 0.0 * sin_w, "_sa": sa, "_ta": ta,
        "_inv_a1": inv_a1, "_inv_a2": inv_a2, "_m": m, "_z1": z1, "_z2": z2, "_x1": x1, "_x2": x2,
        # ∂x_Σ/∂x1 (−1 for an internal pair, where x_Σ = x2 − x1), tan α_n and tan β for the gradients
        "_sgn": -1.0 if internal else 1.0, "_tn": tn, "_tan_beta": math.tan(math.radians(mesh.beta_deg)),
        "_mesh": mesh,
    }
    if not tips:
        for key in TIP_FIELDS.intersection(out):
            del out[key]
    if not (contact or full):
        return out
    out.update(_contact_fields(internal, c, m, z1, z2, om, g1, g2, eps_beta, tips))
    if not full:
        return out
    # the fields no check or objective of the library needs: only for reports
    out.update(_report_fields(mesh, c, m, z1, z2, om, g1, g2, out, ops))
    return out


def _contact_fields(internal: bool, c, m, z1, z2, om, g1, g2, eps_beta, ends: bool = True) -> dict:
    """The path of contact: p_b, g_α, ε_α and (``ends``) ε_γ, the radii of curvature at its ends ρ_p, specific
    sliding at the roots and m/ρ_red at the pitch point (ISO 21771:2007 §5.4)."""
    ca, cb, cbb = c[2], c[8], c[9]
    zs, t_w, sin_w, y = om[0], om[2], om[5], om[7]
    rb1, rw1, h1, ra1, rho_a1 = g1[3], g1[4], g1[5], g1[8], g1[13]
    rb2, rw2, h2, ra2, rho_a2 = g2[3], g2[4], g2[5], g2[8], g2[13]
    p_b = math.pi * m * ca / cb
    n1, n2 = rb1 * t_w, rb2 * t_w              # N1N2 = n1 + n2 = a_w sin α_w (a ring pair: n2 − n1)
    # e1 = ρ_a1 − r_b1 tan α_w = (r_a1² − r_w1²)/(ρ_a1 + r_b1 tan α_w) with r_a1 − r_w1 =
    # m(h_a* + x1 − k − y z1/z_Σ), and e2 the same for gear 2 (for a ring r_w2 − r_a2 =
    # m(h_a* − x2 − k + y z2/z_Σ), its part of the path runs inside): no cancellation
    e1 = m * (h1 - y * z1 / zs) * (ra1 + rw1) / (rho_a1 + n1)
    e2 = m * ((h2 + y * z2 / zs) if internal else (h2 - y * z2 / zs)) * (ra2 + rw2) / (rho_a2 + n2)
    g_alpha = e1 + e2
    eps_alpha = g_alpha / p_b
    if not ends:
        return {"p_b": p_b, "g_alpha": g_alpha, "eps_alpha": eps_alpha}
    # radii of curvature where the path of contact ends: the ring's grows with the pinion's
    rho_p1 = n1 - e2
    rho_p2 = n2 + e1 if internal else n2 - e1
    u = z2 / z1
    rho_w1, rho_w2 = rw1 * sin_w, rw2 * sin_w
    return {
        "p_b": p_b, "g_alpha": g_alpha, "eps_alpha": eps_alpha, "rho_p1": rho_p1, "rho_p2": rho_p2,
        # specific sliding ϑ1 = 1 − ρ2/(u ρ1), ϑ2 = 1 − u ρ1/ρ2 at both ends of the path of contact
        "sliding1_root": 1.0 - rho_a2 / (u * rho_p1), "sliding2_root": 1.0 - u * rho_a1 / rho_p2,
        # m/ρ_red in the normal section, where the radii of curvature are ρ_t/cos β_b; concave ring: 1/ρ1 − 1/ρ2
        "spec_pressure_pitch": m * ((rho_w2 - rho_w1) if internal else (rho_w1 + rho_w2)) / (rho_w1 * rho_w2) * cbb,
        "eps_gamma": eps_alpha + eps_beta,
    }


def _report_fields(mesh: Mesh, c, m, z1, z2, om, g1, g2, out: dict, ops) -> dict:
    """The fields only reports read: α_w, the thicknesses s and s_w, α_a, the diameters d_l and d_p,
    O2N1, O1N2, the sliding at the tips, the transverse and virtual sizes and the clearances."""
    rack, internal = mesh.rack, mesh.internal
    alpha, _, _, ta, inv_a, _, _, _, cb, cbb = c
    _, inv_aw, t_w, dt_w, _, _, _, _, _, dy, k = om
    zt1, d1, _, rb1, _, _, _, _, _, _, psi1, _, rho_l1, rho_a1, t_a1, _, _ = g1
    zt2, d2, _, rb2, _, _, _, _, _, _, psi2, _, rho_l2, rho_a2, t_a2, _, _ = g2
    dw1, dw2, rho_p1, rho_p2 = out["dw1"], out["dw2"], out["rho_p1"], out["rho_p2"]
    n1, n2 = rb1 * t_w, rb2 * t_w              # as in _contact_fields
    u = z2 / z1
    g = n2 - n1 if internal else n1 + n2
    # external: a_w − r_a1 − r_f2 = m(c* + k − Δy); internal: r_f2 − a_w − r_a1 = m(c* + k + Δy); both gears
    clearance = m * (rack.c + k + dy) if internal else m * (rack.c + k - dy)
    return {
        "alpha_w_deg": ops.degrees(alpha + ops.atan(dt_w / (1.0 + ta * t_w))),   # α_w = α + atan Δt/(1 + t t_w)
        "s1": d1 * (psi1 - inv_a), "s2": d2 * (psi2 + inv_a) if internal else d2 * (psi2 - inv_a),
        "sw1": dw1 * (psi1 - inv_aw), "sw2": dw2 * (psi2 + inv_aw) if internal else dw2 * (psi2 - inv_aw),
        "p_w": math.pi * dw1 / z1,
        "alpha_a1_deg": ops.degrees(ops.atan(t_a1)), "alpha_a2_deg": ops.degrees(ops.atan(t_a2)),
        "d_l1": 2.0 * ops.sqrt(rb1 * rb1 + ops.positive(rho_l1) ** 2),
        "d_l2": 2.0 * ops.sqrt(rb2 * rb2 + ops.positive(rho_l2) ** 2),
        "d_p1": 2.0 * ops.sqrt(rb1 * rb1 + rho_p1 * rho_p1),
        "d_p2": 2.0 * ops.sqrt(rb2 * rb2 + rho_p2 * rho_p2),
        "o2n1": ops.sqrt(rb2 * rb2 + g * g), "o1n2": ops.sqrt(rb1 * rb1 + g * g),
        "sliding1_tip": 1.0 - rho_p2 / (u * rho_a1), "sliding2_tip": 1.0 - u * rho_p1 / rho_a2,
        "alpha_t_deg": ops.degrees(alpha + 0.0 * m), "beta_b_deg": ops.degrees(mesh.section.beta_b + 0.0 * m),
        "m_t": m / cb, "z_n1": zt1 / (cbb * cbb), "z_n2": zt2 / (cbb * cbb),
        "clearance1": clearance, "clearance2": clearance,
    }


def _operating_mesh(mesh: Mesh, c, m, z1, z2, x1, x2, ops) -> tuple:
    """z_Σ, inv α_w, tan α_w, tan α_w − tan α, cos α_w, sin α_w, a, y, a_w, Δy and the tip shortening k
    (lengths in mm, y, Δy and k in modules): ISO 21771:2007 eq. (62), (63); the tip shortening
    after GOST 16532-70 Table 1, item 7."""
    _, _, ca, ta, inv_a, _, _, tn, cb, _ = c
    internal = mesh.internal
    # z1 + z2 and x1 + x2 of an external pair, z2 − z1 and x2 − x1 of an internal one (GOST 19274-73)
    zs = z2 - z1 if internal else z1 + z2
    xs = x2 - x1 if internal else x1 + x2
    inv_aw, t_w, dt_w = ops.per_distinct(lambda D: _operating_angle(D, ta, inv_a, ops),
                                         2.0 * xs * tn / zs)
    cos_w = 1.0 / ops.sqrt(1.0 + t_w * t_w)
    a = m * zs / cb / 2.0
    # y = a (cos α − cos α_w)/(m cos α_w), cos α − cos α_w = (cos²α − cos²α_w)/(cos α + cos α_w)
    # = Δt (tan α + tan α_w) cos²α cos²α_w/(cos α + cos α_w), Δt = tan α_w − tan α: no cancellation
    y = zs / (2.0 * cb) * dt_w * (ta + t_w) * (ca * ca) * cos_w / (ca + cos_w)
    dy = xs - y
    # GOST 16532-70 shortens both tips of an external pair by Δy·m; internal pairs keep their tips
    k = dy if mesh.tip_shortening and not internal else 0.0 * dy
    return zs, inv_aw, t_w, dt_w, cos_w, t_w * cos_w, a, y, a + y * m, dy, k


def _gear(rack: BasicRack, c, m, z, x, k, cos_w, ops, ring: bool = False, tips: bool = True) -> tuple:
    """One gear: z/cos β, d, d_b, r_b, r_w, tip height h (modules), d_a, d_f, r_a, r_a − r_b, ψ = s/d ± inv α,
    x_min, ρ_l, ρ_a, tan α_a, s_a, inv α_a. An external gear (ISO 21771:2007 §4–5), or with ``ring``
    the internal gear of an internal pair (tips inside the reference circle, roots outside, flanks
    concave; KHK Table 5-1 and GOST 19274-73, docs/references.md). ``tips=False``: None for tan α_a, s_a, inv α_a."""
    _, sa, ca, ta, inv_a, s2h, h_limit, tn, cb, _ = c
    zt = z / cb                                # d/m_n: the reference diameter in normal modules
    d = m * zt
    db = d * ca
    rb = db / 2.0
    m2 = 2.0 * m
    hf = rack.ha + rack.c
    s2a = sa * sa / 2.0
    if ring:
        h = rack.ha - x - k                    # the tip height inside the reference circle
        s_d = (math.pi / 2.0 - 2.0 * x * tn) / z   # a ring's tooth is its counter-rack's gap
        da = d - m2 * h
        df = d + m2 * (hf + x)
        gap = m * (zt * s2h - rack.ha + x + k)
        psi = s_d - inv_a   # s/d − inv α: s_y = d_y(ψ + inv α_y)
        x_min = math.nan * x                   # a ring is not undercut by its generating counter-rack
        rho_l = m * (zt * s2a + h_limit + x) / sa   # the form limit near the ring's root
    else:
        h = rack.ha + x - k                    # tip height over the reference circle in modules: h_a* + x − k
        s_d = (math.pi / 2.0 + 2.0 * x * tn) / z   # s/d = (π/2 + 2 x tan α_n)/z
        da = d + m2 * h
        df = d - m2 * (hf - x)
        # r_a − r_b = m (z sin²(α/2) + h_a* + x − k): exact when the tip is near the base circle
        # (summed left to right: at a tip near the base circle the terms cancel, and this order holds the
        # 50-digit extremes to 1e-12 where h_a* + x − k summed first does not)
        gap = m * (zt * s2h + rack.ha + x - k)
        psi = s_d + inv_a   # s/d + inv α
        x_min = h_limit - zt * s2a
        rho_l = m * (x - x_min) / sa
    ra = da / 2.0
    rho_a = ops.sqrt(gap * (gap + db))         # √(r_a² − r_b²) = r_b tan α_a
    if not tips:
        return zt, d, db, rb, rb / cos_w, h, da, df, ra, gap, psi, x_min, rho_l, rho_a, None, None, None
    # s_a = d_a (s/(m_t z) − (inv α_a − inv α_t)), the difference of involutes a step from
    # Δt = tan α_a − tan α_t = (r_a − r)(r_a + r)/(r_b (ρ_a + r_b tan α_t)): at large z the two
    # involutes agree to many digits, and α_t, a derived double, must not leak its rounding (z·ulp)
    # into s_a; the checks' gradients read inv α_a as inv α_t + step. A ring's tip lies below its
    # reference circle: Δt < 0.
    side = -1.0 if ring else 1.0
    step = _inv_step(ta, side * m * h * (ra + d / 2.0) / (rb * (rho_a + rb * ta)), ops)
    s_a = da * (s_d - side * step)
    return (zt, d, db, rb, rb / cos_w, h, da, df, ra, gap, psi, x_min, rho_l, rho_a, rho_a / rb, s_a,
            inv_a + step)


def _inv_step(t, dt, ops):
    """inv(atan(t + Δt)) − inv(atan t) without cancellation: Δt·t t₂/(1 + t t₂) + (u − atan u),
    u = Δt/(1 + t t₂), two terms of one sign (as in :func:`_operating_angle`). u − atan u is the plain
    difference: where it cancels (small u) it is the cubic term beside the linear one, so its error,
    ~ε|u|, is ~ε/(t t₂) of the step (t = tan α_t is never small); where the linear term vanishes
    (t₂ → 0) u is not small. The 50-digit extremes hold s_a to 1e-12 with it."""
    t2 = t + dt
    q = 1.0 + t * t2
    u = dt / q
    return dt * t * t2 / q + (u - ops.atan(u))


def _overlap_ratio(mesh: Mesh, m, ops):
    """ε_β = b sin β / (π m_n) (ISO 21771:2007 eq. (83)): 0 for a spur pair whatever b is, NaN for a
    helical pair without a face width."""
    if mesh.beta_deg == 0.0:
        return 0.0 * m
    if mesh.face_width_mm is None:
        return math.nan * m
    return mesh.face_width_mm * math.sin(math.radians(mesh.beta_deg)) / (math.pi * m)


def _normal_tip_thickness(sa, da, d, mesh: Mesh):
    """s_an = s_at cos β_a, tan β_a = tan β d_a/d (ISO 21771:2007 eq. (54), (55)): the tooth thickness
    on the tip cylinder across the helix; the transverse s_at for a spur pair."""
    if mesh.beta_deg == 0.0 or sa is None:
        return sa
    tb = math.tan(math.radians(mesh.beta_deg)) * da / d
    return sa / (1.0 + tb * tb) ** 0.5


# --- result object ----------------------------------------------------------------------


@dataclass(frozen=True)
class Geometry:
    """Geometry of one gear pair (floats) or of many (arrays), in mm and degrees.

    Field names, units and meanings are listed in :data:`GEOMETRY_FIELDS`.
    ``to_dict()`` gives plain values, ``to_frame()`` a DataFrame (one row per design for
    arrays; for one pair, rows ``quantity, value, unit, description``).
    """

    alpha_w_deg: object
    inv_alpha_w: object
    a: object
    a_w: object
    y: object
    dy: object
    d1: object
    d2: object
    db1: object
    db2: object
    dw1: object
    dw2: object
    da1: object
    da2: object
    df1: object
    df2: object
    s1: object
    s2: object
    sw1: object
    sw2: object
    sa1: object
    sa2: object
    p_b: object
    p_w: object
    g_alpha: object
    eps_alpha: object
    alpha_a1_deg: object
    alpha_a2_deg: object
    clearance1: object
    clearance2: object
    x_min1: object
    x_min2: object
    rho_l1: object
    rho_l2: object
    rho_p1: object
    rho_p2: object
    d_l1: object
    d_l2: object
    d_p1: object
    d_p2: object
    o2n1: object
    o1n2: object
    sliding1_root: object
    sliding1_tip: object
    sliding2_root: object
    sliding2_tip: object
    spec_pressure_pitch: object
    eps_beta: object
    eps_gamma: object
    san1: object
    san2: object
    alpha_t_deg: object
    beta_b_deg: object
    m_t: object
    z_n1: object
    z_n2: object

    @classmethod
    def _from_core(cls, geo: dict, scalar: bool, names=None) -> "Geometry":
        """From a geometry dict; fields not in ``names`` (when given) are None."""
        vals = {}
        shape = geo["a"].shape
        for f in fields(cls):
            if names is not None and f.name not in names:
                vals[f.name] = None
                continue
            v = geo[f.name]
            if scalar:
                vals[f.name] = float(v)
            else:
                vals[f.name] = v if np.shape(v) == shape else np.full(shape, v, dtype=float)
        return cls(**vals)

    @classmethod
    def from_float(cls, geo: dict) -> "Geometry":
        """One design from a float geometry dict (:func:`mesh_geometry_float`), without the
        dataclass's per-field setattr: the fields are plain floats already."""
        obj = object.__new__(cls)
        obj.__dict__.update(zip(_FIELD_NAMES, _GET_FIELDS(geo)))
        return obj

    @property
    def is_scalar(self) -> bool:
        return np.ndim(self.a) == 0

    @property
    def names(self) -> list:
        """The fields this object holds (all of :data:`GEOMETRY_FIELDS` unless some were asked for)."""
        return [k for k in GEOMETRY_FIELDS if getattr(self, k) is not None]

    def to_dict(self) -> dict:
        return {k: getattr(self, k) for k in self.names}

    def to_frame(self):
        import pandas as pd   # only when a table is asked for

        if self.is_scalar:
            return pd.DataFrame(
                [(k, getattr(self, k), *GEOMETRY_FIELDS[k]) for k in self.names],
                columns=["quantity", "value", "unit", "description"])
        return pd.DataFrame({k: np.ravel(getattr(self, k)) for k in self.names})

    def __getitem__(self, name: str):
        """``geo["eps_alpha"]``: the same as ``geo.eps_alpha`` (a field of :data:`GEOMETRY_FIELDS`)."""
        if name not in GEOMETRY_FIELDS or getattr(self, name) is None:
            raise KeyError(f"{name!r} is not a field of this Geometry; fields: {', '.join(self.names)}")
        return getattr(self, name)

    def keys(self) -> list:
        return self.names

    def to_table(self, helical: bool | None = None):
        """One pair's geometry in the handbook's layout: ``quantity, symbol, unit, gear 1, gear 2``
        (:func:`geardesign.gears.quantities.geometry_table`)."""
        from .quantities import geometry_table

        if not self.is_scalar:
            raise NotImplementedError("to_table() lays out one pair; for arrays use to_frame()")
        return geometry_table(self, helical)

    def __repr__(self) -> str:
        if not self.is_scalar:
            names = self.names
            return (f"Geometry(<{np.size(self.a)} designs, {len(names)} fields: {', '.join(names[:8])}"
                    f"{', ...' if len(names) > 8 else ''}>; g.to_frame() a row per design, g['a_w'] one field)")
        from .quantities import summary_lines

        return "\n".join([f"Geometry of one pair ({len(self.names)} fields: g.to_table() lays them out, "
                          "g['eps_alpha'] or g.eps_alpha reads one)", *summary_lines(self)])

    def _repr_html_(self) -> str:
        if not self.is_scalar:
            return f"<p>{repr(self)}</p>"
        return self.to_table().to_html(index=False, na_rep="", float_format="{:.7g}".format)


_FIELD_NAMES = tuple(GEOMETRY_FIELDS)
_GET_FIELDS = operator.itemgetter(*_FIELD_NAMES)


def pair_geometry(m, z1=None, z2=None, x1=0.0, x2=0.0, rack: BasicRack = BasicRack(), tip_shortening: bool = True,
                  fields=None, beta_deg: float = 0.0, internal: bool = False, face_width_mm=None, *,
                  mesh: Mesh | None = None) -> Geometry:
    """Geometry of spur and helical, external and internal pairs; m, z1, z2, x1, x2 broadcast.

    ``beta_deg``: reference helix angle (``m`` is then the normal module, x1/x2 normal shifts; the
    circles, angles, thicknesses and path of contact are transverse). ``internal``: gear 2 is a
    ring with z2 > z1 teeth (GOST 19274-73 sign convention, see :class:`~geardesign.gears.mesh.Mesh`).
    ``face_width_mm`` (mm): for the overlap ratio ε_β. ``mesh``: a :class:`~geardesign.gears.mesh.Mesh` instead
    of z1, z2 and those five keywords (giving both is refused); x1, x2 default to 0.

    ``fields`` (names of :data:`GEOMETRY_FIELDS`) keeps only those in the result (the others are
    None) and computes only what they need: the report-only fields (:data:`REPORT_FIELDS`) are
    skipped unless one of them is asked for, the path of contact (:data:`CONTACT_FIELDS`) unless it
    or a report field is, and only the fields asked for and those the validation reads are stored
    at full size (10⁶ designs: ~7× faster than every field).

    Returns a :class:`Geometry` of arrays (of floats when all inputs are scalars). Raises
    :class:`~geardesign.errors.GearDesignError` naming the first design whose geometry
    does not exist (x-sum too negative for α_w, tip inside the base circle, root diameter <= 0).
    Designs whose gears do not mesh are returned with g_alpha <= 0 and eps_alpha <= 0
    (:class:`~geardesign.GearPair` refuses them by name).

    >>> g = pair_geometry(3, 12, 24, 0.6, 0.36)      # KHK worked example
    >>> round(g.a_w, 4), round(g.alpha_w_deg, 4), round(g.da1, 3), round(g.eps_alpha, 3)
    (56.4999, 26.0886, 44.84, 1.202)
    >>> import numpy as np
    >>> pair_geometry(2, 17, 34, 0.0, np.array([0.0, 0.0])).a_w   # seed 001 task 2: a_w = 51 mm
    array([51., 51.])
    >>> pair_geometry(3, 12, 24, 0.6, 0.36, fields=["a_w", "eps_alpha"]).names
    ['a_w', 'eps_alpha']
    """
    if mesh is not None:   # one Mesh instead of the tooth counts and the mesh's five keywords
        mesh = mesh_of(mesh, z1, z2, rack, tip_shortening, beta_deg, internal, face_width_mm)
        z1, z2, rack, tip_shortening, beta_deg, internal, face_width_mm = (
            mesh.z1, mesh.z2, mesh.rack, mesh.tip_shortening, mesh.beta_deg, mesh.internal, mesh.face_width_mm)
    elif z1 is None or z2 is None:
        raise GearDesignError("give the tooth counts z1 and z2, or a mesh= (a geardesign.Mesh)")
    if not isinstance(rack, BasicRack):
        raise GearDesignError(f"rack must be a geardesign.BasicRack, got {type(rack).__name__}")
    if type(z1) is int and type(z2) is int and plain_inputs_ok(m, x1, x2):
        one = _one_design(m, z1, z2, x1, x2, rack, tip_shortening, fields, beta_deg, internal, face_width_mm)
        if one is not None:
            return one
    scalar = all(ndim(v) == 0 for v in (m, z1, z2, x1, x2))
    m, z1, z2, x1, x2 = validate_inputs(m, z1, z2, x1, x2)
    broadcast_inputs(m=m, z1=z1, z2=z2, x1=x1, x2=x2)
    n = int(np.prod(np.broadcast_shapes(*(np.shape(v) for v in (m, z1, z2, x1, x2)))))
    if n > DESIGNS_MAX:
        raise GearDesignError(f"pair_geometry takes at most {DESIGNS_MAX:,} designs in one call, got {n:,}")
    names = None if fields is None else _field_names(fields)
    full = names is None or not REPORT_FIELDS.isdisjoint(names)
    contact = full or not CONTACT_FIELDS.isdisjoint(names)
    tips = full or not TIP_FIELDS.isdisjoint(names)
    # with ``fields``, only those and what the validation reads are stored at full size
    keep = None if names is None else _VALIDATION_FIELDS.union(names, ("a",))
    with np.errstate(all="ignore"):   # designs that do not exist are refused by name just below
        mesh = Mesh(z1, z2, rack, require_bool("tip_shortening", tip_shortening), beta_deg, internal, face_width_mm)
        shape = np.broadcast_shapes(*(np.shape(v) for v in (m, z1, z2, x1, x2)))
        geo = mesh_geometry(mesh, m, x1, x2, full, then=None if keep is None else (
            lambda g: {k: np.full(shape, v) if np.ndim(v) == 0 else v for k, v in g.items() if k in keep}),
            contact=contact, tips=tips)
    validate_geometry(geo, mesh)
    return Geometry._from_core(geo, scalar, names)


def _one_design(m, z1, z2, x1, x2, rack, tip_shortening, fields, beta_deg, internal, face_width_mm):
    """One design of plain Python numbers on the float path (GearPair's: the same formulas, ~8× faster than
    one-element arrays, which made pair_geometry 7.6× ``GearPair(...).geometry()``, issue 36 §3), or None for
    a design whose geometry does not exist, left to the array path to refuse by name."""
    names = None if fields is None else _field_names(fields)
    mesh = Mesh(z1, z2, rack, require_bool("tip_shortening", tip_shortening), beta_deg, internal, face_width_mm)
    if mesh.is_batch:
        return None
    geo = mesh_geometry_float(mesh, m, x1, x2)
    # validate_geometry's conditions without the path of contact (pair_geometry returns non-meshing designs)
    if not (geo["inv_alpha_w"] > 0 and geo["_gap1"] > 0 and geo["_gap2"] > 0 and geo["df1"] > 0 and geo["df2"] > 0):
        return None
    out = Geometry.from_float(geo)
    if names is not None:
        for k in _FIELD_NAMES:
            if k not in names:
                out.__dict__[k] = None
    return out


def _field_names(fields) -> list:
    """Field names asked for, each one of :data:`GEOMETRY_FIELDS`."""
    names = [fields] if isinstance(fields, str) else list(fields) if hasattr(fields, "__iter__") else None
    if not names or any(not isinstance(f, str) or f not in GEOMETRY_FIELDS for f in names):
        bad = next((f for f in (names or [fields]) if not isinstance(f, str) or f not in GEOMETRY_FIELDS), fields)
        raise GearDesignError(f"fields must be names of GEOMETRY_FIELDS ({', '.join(GEOMETRY_FIELDS)}), got {bad!r}")
    return names
