"""The sizes a shop measures on one gear: span W_k over k teeth, the dimension over balls or pins M_d, the
normal and chordal tooth thickness, each with the sizes its tooth-thickness allowances give.

:func:`tooth_measurements` broadcasts m, z, x (and k, the ball and pin sizes, the allowances) like
:func:`~geardesign.gears.geometry.pair_geometry`; the formulas are in
:mod:`geardesign.gears.measurement_formulas`. How k and the ball are chosen: both aim at the circle
d_y = d + 2 x m_n, where the generating rack's datum line rolls (about mid-height of the working flank); k is
the nearest whole number whose anvils touch inside the involute (between the form circle d_Ff and the tip
d_a; for a ring between its bore d_a and its form circle near the root), and the ball is the stocked size (ISO
3290 metric and inch balls, ``catalogs/measuring_balls_iso3290.csv``) nearest the one that touches on d_y exactly
(``ball_exact_mm``; ``ball_mm="exact"`` takes that one) that still touches inside the involute. A span whose contact falls outside the involute, a ball that does not, or a helical gear
narrower than W_k sin β_b plus a margin, is flagged (``span_ok``, ``ball_ok``), not hidden.

Internal gears (the project's GOST 19274-73 sign, see :mod:`~geardesign.gears.measurement_formulas`): M_d is
the dimension between balls, d_M − D_M; W_k is the span over k spaces, which needs an inside span gauge whose
anvils fit the spaces and is rarely measured: it is given, with ``span_ok`` False and the reason in
``notes`` (use M_d).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, fields
from types import SimpleNamespace

import numpy as np

from ..errors import GearDesignError
from ..results import Result, plain
from ..validate import broadcast_inputs, require_bool, require_int, require_range
from . import measurement_formulas as f
from .geometry import DESIGNS_MAX, X_ABS_MAX, require_module
from .involute import inv, inv_from_tan
from .mesh import BETA_RANGE_DEG, FACE_WIDTH_RANGE_MM, Z_MAX, Z_MIN, section_constants
from .rack import STANDARD_RACK, BasicRack

__all__ = ["ToothMeasurements", "tooth_measurements", "pair_measurements", "SPAN_FACE_MARGIN_MODULES", "ALLOWANCE_MAX_MODULES"]

# b must exceed W_k sin β_b by this many normal modules for the anvils' contact patches (a judgement: the
# standards ask only for b > W_k sin β_b; override with span_face_margin_mm)
SPAN_FACE_MARGIN_MODULES = 2.0
# |A_sn| larger than this many modules is no allowance but another gear
ALLOWANCE_MAX_MODULES = 1.0
# a ball or pin beyond this many modules cannot rest in a tooth space (the default is ~1.7 m)
BALL_MAX_MODULES = 10.0


@dataclass(frozen=True, eq=False)
class ToothMeasurements(Result):
    """The measuring sizes of one gear (floats) or of many (arrays), mm.

    ``k`` teeth spanned (spaces for a ring), ``w_k`` the span and ``w_k_max``/``w_k_min`` the sizes the
    allowances give, ``d_wk`` the diameter the anvils touch on, ``span_ok`` (inside the involute, and for a
    helical gear b >= ``face_width_min_mm``); ``ball_mm`` the ball (or pin) diameter (by default the stocked size
    nearest ``ball_exact_mm``, the one that touches on d_y exactly, that can measure the gear), ``d_m`` the circle through
    the ball centres, ``m_d`` the dimension over (ring: between) balls, ``m_d_max``/``m_d_min``, ``d_ball`` where
    the ball touches, ``ball_ok``; ``pin_mm``, ``m_d_pin`` (``m_d_pin_max``/``_min``) over pins, exact for a spur
    gear, approximate on a helical one (``pin_exact``); ``s_n`` the normal tooth thickness, ``s_chord`` the
    chordal thickness and ``h_chord`` the chordal height (``_max``/``_min``); ``x_e_sne``/``x_e_sni`` the
    generating shifts of the allowances ``a_sne``/``a_sni``; ``d_ff``, ``d_a`` the ends of the involute used
    for the flags, ``d_y`` the aim circle; ``notes`` what the flags mean here.
    """

    m_n: object
    z: object
    x: object
    beta_deg: float
    internal: bool
    k: object
    w_k: object
    w_k_max: object
    w_k_min: object
    d_wk: object
    span_ok: object
    face_width_min_mm: object
    ball_mm: object
    ball_exact_mm: object
    d_m: object
    m_d: object
    m_d_max: object
    m_d_min: object
    d_ball: object
    ball_ok: object
    pin_mm: object
    m_d_pin: object
    m_d_pin_max: object
    m_d_pin_min: object
    pin_exact: bool
    s_n: object
    s_n_max: object
    s_n_min: object
    s_chord: object
    s_chord_max: object
    s_chord_min: object
    h_chord: object
    x_e_sne: object
    x_e_sni: object
    a_sne: object
    a_sni: object
    d_ff: object
    d_a: object
    d_y: object
    notes: tuple = ()

    _success_field = "ok"

    @property
    def ok(self) -> bool:
        """True when every ball, and every span but a ring's (not measured), touches inside the involute (and a
        helical span fits the face)."""
        return bool(np.all(self.ball_ok) and (self.internal or np.all(self.span_ok)))

    @property
    def is_scalar(self) -> bool:
        return np.ndim(self.w_k) == 0

    def _columns(self) -> list:
        return [fl.name for fl in fields(self) if fl.name not in ("notes", "beta_deg", "internal", "pin_exact")]

    def to_frame(self):
        """One row per gear, one column per size (mm)."""
        import pandas as pd

        cols = {c: np.ravel(np.broadcast_to(getattr(self, c), np.shape(self.w_k))) for c in self._columns()}
        frame = pd.DataFrame(cols)
        frame.insert(3, "beta_deg", self.beta_deg)
        frame.insert(4, "internal", self.internal)
        return frame

    def to_dict(self) -> dict:
        out = {c: plain(getattr(self, c)) for c in self._columns()}
        out.update(beta_deg=self.beta_deg, internal=self.internal, pin_exact=self.pin_exact,
                   notes=list(self.notes), status=self.status)
        return out

    def __repr__(self) -> str:
        if not self.is_scalar:
            return f"ToothMeasurements(<{np.size(self.w_k)} gears; to_frame() for the table>)"
        kind = ("ring, " if self.internal else "") + (f"beta {self.beta_deg:g} deg, " if self.beta_deg else "")
        over = "between" if self.internal else "over"
        return "\n".join([
            f"ToothMeasurements({kind}m_n {self.m_n:g} mm, z {int(self.z)}, x {self.x:.6g}",
            f"  span      k = {int(self.k)}  W_k = {self.w_k:.4f} mm  ({self.w_k_min:.4f} .. {self.w_k_max:.4f}),"
            f" touches on d {self.d_wk:.4f}  ok {bool(self.span_ok)}",
            f"  balls     D_M = {self.ball_mm:.4f} mm (exact {self.ball_exact_mm:.4f})  M_d {over} = {self.m_d:.4f} mm  ({self.m_d_min:.4f} .. "
            f"{self.m_d_max:.4f}), touches on d {self.d_ball:.4f}  ok {bool(self.ball_ok)}",
            f"  pins      D = {self.pin_mm:.4f} mm  M_d = {self.m_d_pin:.4f} mm"
            + ("" if self.pin_exact else " (approximate: helical)"),
            f"  thickness s_n = {self.s_n:.4f} mm  chordal {self.s_chord:.4f} mm at height {self.h_chord:.4f} mm",
            f"  allowances A_sne {self.a_sne:.4g} / A_sni {self.a_sni:.4g} mm: x_E {self.x_e_sne:.5f} / {self.x_e_sni:.5f})",
        ])


# the sign convention of a tooth-thickness allowance, for the messages that refuse the other sign
THICKNESS_SIGN = ("tooth-thickness allowances thin the tooth: A_sni <= A_sne <= 0 (ISO 21771:2007 §5.4, DIN 3967: "
                  "negative = thinner than nominal; 0 = the nominal tooth)")


def refuse_thickening(name: str, upper) -> None:
    """Refuse an upper allowance A_sne > 0, which would make the tooth thicker than nominal (the mesh would jam
    at the nominal centre distance): by ``name`` (an argument or a command-line option) with the convention."""
    bad = np.asarray(upper) > 0
    if bad.any():
        raise GearDesignError(f"{name}: A_sne = {float(np.max(upper)):g} mm would make the tooth thicker than nominal; "
                              f"{THICKNESS_SIGN}")


def _allowances(thickness_allowance_mm):
    """(A_sne, A_sni) from one number (both) or a pair (upper, lower)."""
    value = thickness_allowance_mm
    if isinstance(value, (tuple, list)) and len(value) == 2:
        upper, lower = value
    elif isinstance(value, (tuple, list)):
        raise GearDesignError(f"thickness_allowance_mm must be one number or a pair (A_sne, A_sni), got {len(value)} values")
    else:
        upper = lower = value
    upper = require_range("thickness_allowance_mm (A_sne)", upper, -1e4, 1e4, unit="mm")
    lower = require_range("thickness_allowance_mm (A_sni)", lower, -1e4, 1e4, unit="mm")
    bad = np.asarray(lower > upper)
    if bad.any():
        raise GearDesignError(f"thickness_allowance_mm: the lower allowance A_sni must not exceed the upper A_sne, got "
                              f"A_sne = {float(np.max(upper)):g} mm, A_sni = {float(np.min(lower)):g} mm")
    refuse_thickening("thickness_allowance_mm", upper)
    return upper, lower


def _validated(m, z, x, beta_deg, internal, rack, k, ball_mm, pin_mm, face_width_mm, tip_diameter_mm):
    m = require_module(m)
    z = require_int("z", z, Z_MIN, Z_MAX)
    x = require_range("x", x, -X_ABS_MAX, X_ABS_MAX)
    beta = float(require_range("beta_deg", beta_deg, *BETA_RANGE_DEG, unit="deg")) if np.ndim(beta_deg) == 0 else None
    if beta is None:
        raise GearDesignError("beta_deg must be one number for tooth_measurements (one helix angle a call)")
    internal = require_bool("internal", internal)
    rack = STANDARD_RACK if rack is None else rack
    if not isinstance(rack, BasicRack):
        raise GearDesignError(f"rack must be a geardesign.BasicRack, got {type(rack).__name__}")
    k = None if k is None else require_int("k (teeth spanned)", k, 1, Z_MAX)
    if isinstance(ball_mm, str):
        if ball_mm != "exact":
            raise GearDesignError(f"ball_mm must be a diameter in mm, 'exact' or None (a stocked size), got {ball_mm!r}")
        ball = ball_mm
    else:
        ball = None if ball_mm is None else require_range("ball_mm", ball_mm, 0.0, 1e9, lo_open=True, unit="mm")
    pin = None if pin_mm is None else require_range("pin_mm", pin_mm, 0.0, 1e9, lo_open=True, unit="mm")
    for name, v in (("ball_mm", ball), ("pin_mm", pin)):
        if v is not None and not isinstance(v, str) and np.any(v > BALL_MAX_MODULES * m):
            raise GearDesignError(f"{name} must be at most {BALL_MAX_MODULES:g} modules ({float(np.min(BALL_MAX_MODULES * m)):g} mm "
                                  f"here), got {float(np.max(v)):g} mm")
    b = None if face_width_mm is None else require_range("face_width_mm", face_width_mm, *FACE_WIDTH_RANGE_MM,
                                                         lo_open=True, unit="mm")
    d_a = None if tip_diameter_mm is None else require_range("tip_diameter_mm", tip_diameter_mm, 0.0, 1e9, lo_open=True,
                                                             unit="mm")
    return m, z, x, beta, internal, rack, k, ball, pin, b, d_a


def _size_guard(*arrays) -> None:
    try:
        n = int(np.prod(np.broadcast_shapes(*(np.shape(a) for a in arrays if a is not None))))
    except ValueError:
        raise GearDesignError("input shapes do not broadcast together: "
                              + ", ".join(str(np.shape(a)) for a in arrays if a is not None)) from None
    if n > DESIGNS_MAX:
        raise GearDesignError(f"tooth_measurements: {n} gears in one call; at most {DESIGNS_MAX}")


def tooth_measurements(m, z, x=0.0, *, beta_deg=0.0, internal=False, rack: BasicRack | None = None, k=None,
                       ball_mm=None, pin_mm=None, thickness_allowance_mm=0.0, face_width_mm=None,
                       tip_diameter_mm=None, span_face_margin_mm=None) -> ToothMeasurements:
    """The measuring sizes of a gear (see the module docstring); m (normal module, mm), z, x broadcast.

    ``thickness_allowance_mm``: the normal tooth-thickness allowance A_sn (mm, negative thins the tooth), one
    number or the pair (A_sne, A_sni) (upper, lower; ISO 21771:2007 §5.4, DIN 3967); A_sni <= A_sne <= 0 (a
    positive one, a tooth thicker than nominal, is refused). ``k``, ``ball_mm``,
    ``pin_mm`` override the choices; ``tip_diameter_mm`` the tip (default d ± 2(h_a* ± x)m_n, no tip shortening;
    :meth:`GearPair.measurements` passes the pair's); ``face_width_mm`` b checks a helical span.

    >>> t = tooth_measurements(2, 20)                # MachineCalcs: k = 3, W = 15.321 mm, contact on d 40.59 mm
    >>> int(t.k), round(t.w_k, 3), round(t.d_wk, 2)
    (3, 15.321, 40.59)
    """
    m, z, x, beta, internal, rack, k, ball, pin, b, d_a_in = _validated(
        m, z, x, beta_deg, internal, rack, k, ball_mm, pin_mm, face_width_mm, tip_diameter_mm)
    a_sne, a_sni = _allowances(thickness_allowance_mm)
    given_ball = None if isinstance(ball, str) else ball
    _size_guard(m, z, x, k, given_ball, pin, a_sne, a_sni, d_a_in, b)
    shape = np.broadcast_shapes(*(np.shape(v) for v in (m, z, x, k, given_ball, pin, a_sne, a_sni, d_a_in, b)
                                  if v is not None))
    m, z, x, a_sne, a_sni = broadcast_inputs(m=m, z=z, x=x, a_sne=a_sne, a_sni=a_sni, shape=np.zeros(shape))[:5]
    if np.any(np.abs(a_sne) > ALLOWANCE_MAX_MODULES * m) or np.any(np.abs(a_sni) > ALLOWANCE_MAX_MODULES * m):
        raise GearDesignError(f"thickness_allowance_mm must be within ±{ALLOWANCE_MAX_MODULES:g}·m_n, got "
                              f"A_sne = {float(np.max(np.abs(a_sne))):g}, A_sni = {float(np.max(np.abs(a_sni))):g} mm")
    g = _gear(m, z, x, beta, internal, rack, d_a_in)
    g.x_e = (f.generating_shift(x, a_sne, m, g.an, internal), f.generating_shift(x, a_sni, m, g.an, internal))
    notes = []
    out = dict(m_n=m, z=z, x=x, **_span(g, k, b, span_face_margin_mm, notes), **_balls(g, ball, pin, b, notes),
               **_thickness(g, a_sne, a_sni), x_e_sne=g.x_e[0], x_e_sni=g.x_e[1], a_sne=a_sne, a_sni=a_sni,
               d_ff=g.d_ff, d_a=g.d_a, d_y=g.d_y)
    fl = _floats if z.ndim == 0 else (lambda v: v)
    return ToothMeasurements(beta_deg=beta, internal=internal, pin_exact=beta == 0.0, notes=tuple(notes),
                             **{key: fl(v) for key, v in out.items()})


def _largest_smallest(values):
    return np.maximum(*values), np.minimum(*values)


def _gear(m, z, x, beta: float, internal: bool, rack: BasicRack, d_a_in) -> SimpleNamespace:
    """The gear's circles and angles (mm, rad), its involute's ends (lo, hi) and the aim circle d_y: the rack's
    datum circle, kept within the middle half of the involute (a short or undercut flank)."""
    sc = section_constants(rack.alpha, math.radians(beta))
    zf = z.astype(float)
    d = m * zf / sc.cos_beta
    d_b = d * sc.cos_t
    sgn = -1.0 if internal else 1.0
    d_a = (d + sgn * 2.0 * (rack.ha + sgn * x) * m) if d_a_in is None else np.broadcast_to(d_a_in, d.shape)
    _require_tooth(m, zf, x, d, d_b, d_a, sc, internal)
    d_ff = _form_diameter(m, zf, x, rack, sc, d_b, internal)
    lo, hi = (d_a, d_ff) if internal else (d_ff, d_a)
    quarter = np.maximum(hi - lo, 0.0) / 4.0
    d_y = np.minimum(np.maximum(d + 2.0 * x * m, lo + quarter), hi - quarter)
    return SimpleNamespace(m=m, z=z, zf=zf, x=x, beta=beta, internal=internal, sc=sc, an=rack.alpha, at=sc.alpha_t,
                           cbb=sc.cos_beta_b, d=d, d_b=d_b, d_a=d_a, d_ff=d_ff, lo=lo, hi=hi, d_y=d_y, sgn=sgn)


def _span(g, k, b, span_face_margin_mm, notes: list) -> dict:
    """k, W_k and its sizes from the allowances, where the anvils touch, and whether the span is usable."""
    if k is None:
        k = _choose_k(g.m, g.zf, g.x, g.d_y, g.d_b, g.an, g.at, g.cbb, g.lo, g.hi)
    k = np.broadcast_to(k, g.d.shape)
    if np.any(k >= g.z):
        raise GearDesignError(f"k (teeth spanned) must be below z, got k = {int(np.max(k))} for "
                              f"z = {int(g.z.flat[np.argmax(k)])}")
    w = f.base_tangent_length(g.m, g.zf, g.x, k, g.an, g.at)
    d_wk = f.span_contact_diameter(w, g.d_b, g.cbb)
    span_ok = (d_wk > g.lo) & (d_wk < g.hi)
    face_min = np.zeros_like(w)
    if g.beta > 0.0:
        margin = SPAN_FACE_MARGIN_MODULES * g.m if span_face_margin_mm is None else float(
            require_range("span_face_margin_mm", span_face_margin_mm, 0.0, 1e4, unit="mm"))
        face_min = w * math.sin(g.sc.beta_b) + margin
        if b is None:
            notes.append("helical span: give face_width_mm to check b > W_k sin beta_b + margin")
        else:
            span_ok = span_ok & (b > face_min)
    if g.internal:
        span_ok = span_ok & False
        notes.append("ring: W_k is over k spaces (an inside span gauge); rarely measurable, use M_d between balls")
    w_max, w_min = _largest_smallest([f.base_tangent_length(g.m, g.zf, xe, k, g.an, g.at) for xe in g.x_e])
    return dict(k=k, w_k=w, w_k_max=w_max, w_k_min=w_min, d_wk=d_wk, span_ok=span_ok, face_width_min_mm=face_min)


def _balls(g, ball, pin, b, notes: list) -> dict:
    """The ball (default: touching on d_y), M_d and its sizes from the allowances, where it touches, whether it is
    usable; the pins."""
    exact = np.broadcast_to(f.ball_for_contact(g.m, g.zf, g.x, g.d_y, g.d_b, g.an, g.at, g.cbb, g.internal),
                            g.d.shape)
    if ball is None:
        ball = _stocked_ball(g, exact, notes)
    elif isinstance(ball, str):   # "exact"
        ball = exact
    ball = np.broadcast_to(ball, g.d.shape)
    pin = ball if pin is None else np.broadcast_to(pin, g.d.shape)
    inv_m, d_m, d_ball, ball_ok = _ball_fit(g, ball)
    sizes = [f.dimension_over_balls(f.ball_center_diameter(g.d_b, f.ball_center_inv(
        g.m, g.zf, xe, ball, g.an, g.at, g.internal)), ball, g.z, g.internal) for xe in g.x_e]
    pins = _pins(g.m, g.z, g.zf, g.x, g.x_e, pin, g.d_b, g.an, g.at, g.beta, b, g.internal, notes)
    return dict(ball_mm=ball, ball_exact_mm=exact, d_m=d_m, m_d=f.dimension_over_balls(d_m, ball, g.z, g.internal),
                m_d_max=_largest_smallest(sizes)[0], m_d_min=_largest_smallest(sizes)[1], d_ball=d_ball,
                ball_ok=ball_ok, pin_mm=pin, m_d_pin=pins[0], m_d_pin_max=_largest_smallest(pins[1:])[0],
                m_d_pin_min=_largest_smallest(pins[1:])[1])


def _ball_fit(g, ball):
    """(inv α of the ball centre, d_M, the diameter the ball touches on, whether it can measure the gear): the
    contact must lie on the involute (tan α_c > 0: past the base circle) between its ends, and an external gear's
    ball must stand out of the tips (a ring's inside its bore)."""
    inv_m = f.ball_center_inv(g.m, g.zf, g.x, ball, g.an, g.at, g.internal)
    d_m = f.ball_center_diameter(g.d_b, inv_m)
    d_ball = f.ball_contact_diameter(g.d_b, inv_m, ball, g.cbb, g.internal)
    t_c = f.tan_from_inv(inv_m, validate=False) - g.sgn * ball * g.cbb / g.d_b
    stands_out = (d_m - ball < g.d_a) if g.internal else (d_m + ball > g.d_a)
    return inv_m, d_m, d_ball, (t_c > 0) & (d_ball > g.lo) & (d_ball < g.hi) & stands_out


def _stocked_ball(g, exact, notes: list):
    """The stocked ball (:func:`~geardesign.catalogs.tables.measuring_ball_series`) nearest the exact one that
    can measure the gear: the two sizes on either side of it, nearest first; where none of the four can (or the
    exact size is outside the series), the exact size, with a note."""
    from ..catalogs.tables import measuring_ball_series   # here: the catalog module's import (~20 modules) is needed only for a stocked ball

    series = measuring_ball_series()
    i = np.searchsorted(series, exact)
    lower = [series[np.clip(i - j, 0, series.size - 1)] for j in (1, 2)]
    upper = [series[np.clip(i + j, 0, series.size - 1)] for j in (0, 1)]
    cands = []
    for lo, hi in zip(lower, upper):   # the nearer of each pair first
        near_lo = np.abs(exact - lo) <= np.abs(hi - exact)
        cands += [np.where(near_lo, lo, hi), np.where(near_lo, hi, lo)]
    chosen = np.full(exact.shape, np.nan)
    for c in cands:
        fits = np.isnan(chosen) & (np.abs(c - exact) <= 0.25 * exact) & _ball_fit(g, c)[3]
        chosen = np.where(fits, c, chosen)
    missing = np.isnan(chosen)
    if missing.any():
        notes.append("no stocked ball (ISO 3290 sizes, catalogs/measuring_balls_iso3290.csv) near the exact one can "
                     "measure " + ("this gear" if exact.ndim == 0 else f"{int(missing.sum())} of the gears")
                     + ": the exact size is given")
    return np.where(missing, exact, chosen)


def _thickness(g, a_sne, a_sni) -> dict:
    """Normal and chordal tooth thickness (on the virtual gear) with their sizes from the allowances, and the
    chordal height."""
    s_n = f.normal_tooth_thickness(g.m, g.x, g.an, g.internal)
    d_n = f.virtual_diameter(g.m, g.zf, g.sc.cos_beta, g.cbb)
    s_e = [s_n + a for a in (a_sne, a_sni)]
    chords = [f.chordal_thickness(d_n, s) for s in s_e]
    return dict(s_n=s_n, s_n_max=_largest_smallest(s_e)[0], s_n_min=_largest_smallest(s_e)[1],
                s_chord=f.chordal_thickness(d_n, s_n), s_chord_max=_largest_smallest(chords)[0],
                s_chord_min=_largest_smallest(chords)[1],
                h_chord=f.chordal_height(d_n, s_n, g.sgn * (g.d_a - g.d) / 2.0, g.internal, g.d_a, _tip_half_angle(g)))


def _tip_half_angle(g):
    """Half the tooth's angle on its tip circle (transverse), for the ring's chordal height."""
    return _tip_half(g.zf, g.x, g.d_b, g.d_a, g.sc, g.internal)


def _tip_half(zf, x, d_b, d_a, sc, internal: bool):
    """s_a/d_a: s_t/d + inv α_t − inv α_a for an external tooth, s_t/d − inv α_t + inv α_a for a ring's."""
    t_a = np.sqrt((d_a - d_b) * (d_a + d_b)) / d_b
    s_d = (math.pi / 2.0 + (-2.0 if internal else 2.0) * x * sc.tan_n) / zf      # s_t / d
    inv_t = float(inv(sc.alpha_t))
    return s_d - inv_t + inv_from_tan(t_a) if internal else s_d + inv_t - inv_from_tan(t_a)


def _require_tooth(m, zf, x, d, d_b, d_a, sc, internal: bool) -> None:
    """Refuse, by the first gear at fault, a tip circle inside the base circle (a ring's bore too) and a tooth
    pointed before its tip: s_a = d_a (s_t/d ± inv α_t ∓ inv α_a) <= 0 (external +, −; a ring's tooth −, +)."""
    def first(mask):
        i = int(np.flatnonzero(np.ravel(mask))[0])
        where = f" (gear at index {i})" if np.size(mask) > 1 else ""
        vals = [float(np.ravel(np.broadcast_to(v, np.shape(mask)))[i]) for v in (zf, x, d_a, d_b)]
        return where, vals
    low = ~(d_a > d_b)
    if np.any(low):
        where, (z, xx, da, db) = first(low)
        raise GearDesignError(f"the tip circle d_a = {da:.6g} mm lies inside the base circle d_b = {db:.6g} mm "
                              f"(z = {z:g}, x = {xx:g}){where}: no involute to measure; raise x or give tip_diameter_mm")
    pointed = ~(_tip_half(zf, x, d_b, d_a, sc, internal) > 0.0)
    if np.any(pointed):
        where, (z, xx, da, _) = first(pointed)
        raise GearDesignError(f"the tooth is pointed before its tip circle d_a = {da:.6g} mm (z = {z:g}, x = {xx:g})"
                              f"{where}: lower x (a ring: raise it) or give a smaller tip_diameter_mm")


def _floats(v):
    v = np.asarray(v)
    if v.dtype == bool:
        return bool(v)
    if v.dtype.kind in "iu":
        return int(v)
    return float(v)


def _form_diameter(m, zf, x, rack: BasicRack, sc, d_b, internal: bool):
    """The involute's inner end for an external gear (the form circle d_Ff, where the rack's straight flank ends:
    ρ_Ff = m_n (x − x_min)/sin α_t, x_min = h_l* − z sin² α_t/(2 cos β)); for a ring its outer end near the root
    (ρ = m_n (z sin² α_t/(2 cos β) + h_l* + x)/sin α_t, the counter-rack's flank end; the shaper cutter the ring
    is really cut with reaches about as deep). Undercut: the base circle."""
    half = zf / sc.cos_beta * sc.sin_t ** 2 / 2.0
    rho = m * ((half + rack.h_limit + x) if internal else (x - (rack.h_limit - half))) / sc.sin_t
    return np.hypot(d_b, 2.0 * np.maximum(rho, 0.0))


def _choose_k(m, zf, x, d_y, d_b, an, at, cbb, lo, hi):
    """The whole k nearest the aim circle whose contact lies inside the involute (of k* − 1, k*, k* + 1 rounded),
    else the rounded one (then flagged)."""
    k_star = f.span_teeth_for_diameter(m, zf, x, d_y, d_b, an, at, cbb)
    k0 = np.clip(np.rint(k_star), 1, np.maximum(zf - 1, 1))
    cand = np.stack([k0, np.clip(k0 - 1, 1, None), np.minimum(k0 + 1, np.maximum(zf - 1, 1))])
    d_c = f.span_contact_diameter(f.base_tangent_length(m, zf, x, cand, an, at), d_b, cbb)
    inside = (d_c > lo) & (d_c < hi)
    score = np.where(inside, np.abs(d_c - d_y), np.inf)
    best = np.take_along_axis(cand, np.argmin(score, axis=0)[None], axis=0)[0]
    return np.where(inside.any(axis=0), best, k0).astype(np.int64)


def _pins(m, z, zf, x, x_e, pin, d_b, an, at, beta: float, b, internal: bool, notes: list):
    """M_d over pins (nominal, from A_sne, from A_sni). A spur gear's pin is its ball (exact).
    On a helical gear the ball formula stands in for the pin (approximate: a cylinder parallel to the axis does
    not touch the helicoid as a ball does); for an odd z the pins sit diametrically opposite when the face is
    at least half an axial pitch wide, p_x/2 = π m_n/(2 sin β) (the helix correction), else cos(π/(2z))."""
    exact = beta == 0.0
    z_eff = z
    if not exact:
        notes.append("helical: M_d over pins is approximate (the ball formula); balls are exact")
        if b is not None:
            half_axial = math.pi * m / (2.0 * math.sin(math.radians(beta)))
            z_eff = np.where((z % 2 == 1) & (b >= half_axial), z + 1, z)   # diametral: the even formula
    out = []
    for xx in (x,) + tuple(x_e):
        d_mp = f.ball_center_diameter(d_b, f.ball_center_inv(m, zf, xx, pin, an, at, internal))
        out.append(f.dimension_over_balls(d_mp, pin, z_eff, internal))
    return out


def pair_measurements(pair, gear: int | None = None, **options):
    """:meth:`GearPair.measurements`: the sizes of gear 1, 2 or both (a tuple), with the pair's tips."""
    if gear is not None and not (type(gear) is int and gear in (1, 2)):
        raise GearDesignError(f"gear must be 1, 2 or None (both), got {gear!r}")
    for name in ("beta_deg", "internal", "rack", "tip_diameter_mm"):
        if name in options:
            raise GearDesignError(f"{name} comes from the pair; it is not an option of GearPair.measurements")
    geo = pair._geo
    if pair.face_width_mm is not None:
        options.setdefault("face_width_mm", pair.face_width_mm)

    def one(i):
        return tooth_measurements(pair.m, pair.z1 if i == 1 else pair.z2, pair.x1 if i == 1 else pair.x2,
                                  beta_deg=pair.beta_deg, internal=pair.internal and i == 2, rack=pair.rack,
                                  tip_diameter_mm=float(geo[f"da{i}"]), **options)
    return one(gear) if gear is not None else (one(1), one(2))
