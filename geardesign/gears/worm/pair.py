"""One cylindrical worm pair as an object: inputs validated, geometry, checks, the measuring sizes for the
drawing, the wheel's shift for a centre distance and the best shift for the checks (exact: a 1-D problem).

>>> import geardesign as gd
>>> p = gd.WormPair(3, 2, 30, 44 / 3)          # SDP/SI-KHK axial-module example (d_m1 = 44 mm)
>>> g = p.geometry()
>>> g.a, g.d_2, g.d_a1, g.d_a2, round(g.gamma_m_deg, 5)
(67.0, 90.0, 50.0, 96.0, 7.76517)
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

from ...errors import GearDesignError
from ...results import Result
from ...validate import (_show, hint_unknown_arguments, ndim, one_number, require_choice, require_int,
                         require_positive, require_range)
from .. import checks as _checks
from ..inputs import M_RANGE_MM, X_ABS_MAX
from ..mesh import Z_MAX, Z_MIN
from ..rack import STANDARD_RACK, BasicRack, require_rack
from .geometry import (FIELD_INFO, FLANK_FORMS, LENGTH_RANGE_MM, Q_MAX, WORM_FIELDS, Z1_RANGE,
                       worm_geometry_float, x2_from_center_distance)

__all__ = ["WormPair", "WormGeometry", "WormShiftResult", "X2_OBJECTIVES"]

# The objectives of WormPair.optimize_x2: the smallest |x2| the checks allow (the designer's first wish: a
# wheel cut by the worm's own hob at its nominal setting) or the largest smallest margin (the robust point).
X2_OBJECTIVES = {"min_abs_x2": "the x2 nearest to 0 that every check allows",
                 "max_margin": "the x2 whose smallest margin (of the checks that move with x2) is largest"}


@dataclass(frozen=True)
class WormPair:
    """A cylindrical worm (flank form ZA, ZN, ZI or ZK) with its wheel, shafts crossed at 90° (DIN 3975).

    Parameters
    ----------
    m_x : axial module of the worm, mm.  z1 : number of threads (starts), 1 … 10.  z2 : wheel teeth.
    q : diameter quotient d_m1/m_x (> 2(h_a* + c*), so the worm has a root).  x2 : the wheel's profile shift.
    flank_form : "ZA" (straight axial profile), "ZN" (straight normal profile), "ZI" (involute helicoid) or
        "ZK" (ground by a conical wheel); the rack's ``alpha_deg`` is axial for ZA and normal otherwise.
    rack : the :class:`~geardesign.gears.rack.BasicRack` (α, h_a*, c*, ρ_f*; the standard one by default).
    worm_length_mm, face_width_mm : the worm's threaded length b_1 and the wheel's width b_2, mm (None: what the
        mesh needs, :func:`~geardesign.gears.worm.geometry.worm_length_min` and the working width b_2H).

    >>> WormPair(3, 2, 30, 44 / 3).ok()
    True
    """

    m_x: float
    z1: int
    z2: int
    q: float
    x2: float = 0.0
    flank_form: str = "ZA"
    rack: BasicRack = STANDARD_RACK
    worm_length_mm: float | None = None
    face_width_mm: float | None = None

    def __post_init__(self):
        for name in ("m_x", "z1", "z2", "q", "x2"):
            if ndim(getattr(self, name)) != 0:
                raise GearDesignError(f"{name} must be a single number for WormPair (use worm_geometry for arrays), "
                                      f"got {_show(getattr(self, name))}")
        rack = require_rack(self.rack)
        require_choice("flank_form", self.flank_form, FLANK_FORMS)
        m_x = one_number("m_x", require_range("m_x", require_positive("m_x", self.m_x, unit="mm"), *M_RANGE_MM,
                                              unit="mm"))
        z1 = int(require_int("z1", self.z1, *Z1_RANGE))
        z2 = int(require_int("z2", self.z2, Z_MIN, Z_MAX))
        q_min = 2.0 * (rack.ha + rack.c)
        q = one_number("q", require_range("q", self.q, q_min, Q_MAX, lo_open=True))
        x2 = one_number("x2", require_range("x2", self.x2, -X_ABS_MAX, X_ABS_MAX))
        lengths = {}
        for name in ("worm_length_mm", "face_width_mm"):
            v = getattr(self, name)
            lengths[name] = None if v is None else one_number(name, require_range(name, v, *LENGTH_RANGE_MM,
                                                                                  unit="mm"))
        for name, value in (("m_x", m_x), ("z1", z1), ("z2", z2), ("q", q), ("x2", x2), ("rack", rack), *lengths.items()):
            object.__setattr__(self, name, value)
        geo = worm_geometry_float(m_x, z1, z2, q, x2, self.flank_form, rack, lengths["worm_length_mm"],
                                  lengths["face_width_mm"])
        _require_exists(geo)
        object.__setattr__(self, "_geo", geo)

    @classmethod
    def from_center_distance(cls, a, m_x, z1, z2, q, flank_form: str = "ZA", rack: BasicRack | None = None,
                             worm_length_mm: float | None = None, face_width_mm: float | None = None) -> "WormPair":
        """The pair whose wheel shift x2 = a/m_x − (q + z2)/2 gives the centre distance ``a`` (mm) exactly
        (GOST 19650-97 Table 2; DIN 3975). The shift's usual range is a check (``x2_abs_max``), not a refusal.

        >>> p = WormPair.from_center_distance(160, 8, 2, 31, 8)     # x2 = 20 − 19.5
        >>> p.x2, p.geometry().a
        (0.5, 160.0)
        """
        a = one_number("a (center distance)", require_positive("a (center distance)", a, unit="mm"))
        m = one_number("m_x", require_range("m_x", require_positive("m_x", m_x, unit="mm"), *M_RANGE_MM, unit="mm"))
        qv = one_number("q", require_positive("q", q))
        z2v = int(one_number("z2", require_int("z2", z2, Z_MIN, Z_MAX)))
        x2 = x2_from_center_distance(a, m, z2v, qv)
        if not abs(x2) <= X_ABS_MAX:
            lo, hi = (m * (qv + z2v - 2 * X_ABS_MAX) / 2, m * (qv + z2v + 2 * X_ABS_MAX) / 2)
            raise GearDesignError(f"a (center distance) must be in [{max(lo, 0):.6g}, {hi:.6g}] mm for m_x = {m:g}, "
                                  f"q = {qv:g}, z2 = {z2v} (|x2| <= {X_ABS_MAX:g}), got {a:g}")
        return cls(m, z1, z2v, qv, x2, flank_form, require_rack(rack), worm_length_mm, face_width_mm)

    def geometry(self) -> "WormGeometry":
        """Every dimension of the pair (mm, degrees): :data:`~geardesign.gears.worm.geometry.WORM_FIELDS`."""
        return WormGeometry(dict(self._geo), self.flank_form)

    def checks(self, **limits):
        """Table of checks ``check, margin, ok, value, limit, label`` (margins dimensionless, >= 0 holds):
        ``limits`` are the worm's options of :func:`~geardesign.gears.checks.make_checks` (``undercut``,
        ``sa_min``, ``eps_alpha_min``, ``x2_abs_max``, ``worm_length_min``, ``wheel_width_max``).

        >>> t = WormPair(3, 2, 30, 44 / 3, x2=1.5).checks()
        >>> bool(t.set_index("check").loc["x2_range", "ok"])
        False
        """
        table = _checks.evaluate(self._geo, _worm_checks(limits))[["check", "margin", "ok", "value", "limit", "label"]]
        table["margin"] = table["margin"].where(table["margin"].abs() > _checks.FEASIBILITY_TOL, 0.0)
        return table

    def ok(self, **limits) -> bool:
        """True when every check of :meth:`checks` holds."""
        return bool(self.checks(**limits)["ok"].all())

    def measurements(self):
        """The sizes the drawing gives for measuring the thread and the teeth (zero backlash; mm): the worm's
        axial and normal thickness at d_m1, its normal chordal thickness and height, the wheel's normal chordal
        thickness and height (on its virtual spur gear), as a table ``quantity, symbol, value, unit``."""
        import pandas as pd   # only when a table is asked for

        rows = [(FIELD_INFO[k][2], FIELD_INFO[k][0], self._geo[k], FIELD_INFO[k][1])
                for k in ("s_x1", "s_n1", "s_chord1", "h_chord1", "z_v2", "s_chord2", "h_chord2")]
        return pd.DataFrame(rows, columns=["quantity", "symbol", "value", "unit"])

    def x2_limits(self, **limits) -> tuple[float, float]:
        """The interval of x2 (this pair's m_x, z1, z2, q) where every check that depends on x2 holds, exact
        (each margin is monotone in x2: undercut rises, the wheel's tip thickness and the contact ratio fall;
        their roots by Brent's method to 1e-14), searched over x2 >= −h_a* (the throat at or above the reference
        circle: below it the contact ratio is not monotone). (nan, nan) when no x2 satisfies them all."""
        lo, hi, _ = _x2_interval(self, _worm_checks(limits))
        return lo, hi

    def optimize_x2(self, objective: str = "min_abs_x2", **limits) -> "WormShiftResult":
        """The best wheel shift x2 for this worm and wheel under the checks (``limits`` as :meth:`checks`),
        exactly: ``"min_abs_x2"`` (the x2 nearest 0 in the feasible interval) or ``"max_margin"`` (the x2 where
        the smallest margin is largest). The result is a :class:`WormShiftResult`, in the manner of the spur
        pair's :class:`~geardesign.shifts.result.ShiftResult`.

        >>> r = WormPair(3, 2, 30, 44 / 3).optimize_x2()
        >>> r.success, r.x2
        (True, 0.0)
        """
        require_choice("objective", objective, X2_OBJECTIVES)
        t0 = time.perf_counter()
        checks = _worm_checks(limits)
        lo, hi, nit = _x2_interval(self, checks)
        if not (math.isfinite(lo) and math.isfinite(hi)):
            x2 = _least_bad(self, checks)
            pair = self.with_x2(x2)
            margins = _margins(pair, checks)
            conflict = sorted(k for k, v in margins.items() if v < -_checks.FEASIBILITY_TOL)
            return WormShiftResult(x2=x2, fun=min(margins.values()), objective=objective, success=False,
                                   message="no x2 satisfies every check: " + ", ".join(conflict) + " fail at the "
                                           "x2 where the smallest margin is largest",
                                   nit=nit, time_s=time.perf_counter() - t0, margins=margins, active=[],
                                   conflict=conflict, **self._identity(pair))
        if objective == "min_abs_x2":
            x2 = min(max(0.0, lo), hi)
        else:
            x2 = _max_min_margin(self, checks, lo, hi)
        pair = self.with_x2(x2)
        margins = _margins(pair, checks)
        active = [k for k, v in margins.items() if k in _X2_SENSE and abs(v) <= 1e-9]   # the ones that fix x2
        # the checks that do not move with x2 cannot change the choice: max_margin is over those that do
        fun = abs(x2) if objective == "min_abs_x2" else min(v for k, v in margins.items() if k in _X2_SENSE)
        return WormShiftResult(x2=x2, fun=fun, objective=objective, success=True,
                               message=f"x2 in [{lo:.10g}, {hi:.10g}] satisfies every check; "
                                       + X2_OBJECTIVES[objective],
                               nit=nit, time_s=time.perf_counter() - t0, margins=margins, active=active,
                               conflict=[], **self._identity(pair))

    def rating(self, T2, n1, **options):
        """Efficiency and load capacity of this pair (worm driving) at the wheel torque ``T2`` (N·m) and worm speed
        ``n1`` (rpm), on its own DIN 3975 geometry (d_m1, d_2, a, γ_m, α_n, d_f1, b_2): a
        :class:`~geardesign.gears.worm.rating.WormRating`. ``options`` are those of
        :func:`~geardesign.gears.worm.rating.rate_geometry` (``l_1``, ``mu``, ``k_heat``, ``A_housing``, ...;
        docs/worm_rating.md).

        >>> r = WormPair(8, 2, 25, 10).rating(842.0, 1500.0, l_1=250.0)
        >>> r.factors.set_index("symbol").loc["d_f1", "method"]
        'WormPair geometry (DIN 3975)'
        """
        from .rating import check_options, rate_geometry
        return rate_geometry(T2, n1, self._rating_geometry(), **check_options(options))

    def efficiency(self, n1, mu=None, mu_static=None) -> dict:
        """The worm-driving and wheel-driving mesh efficiency at the worm speed ``n1`` (rpm): ``v_g`` (m/s),
        ``mu`` (given, else the AGMA 6034 curve at v_g) and ``mu_static`` (at rest), the friction angle
        ``rho_deg``, ``eta_z``, ``eta_z_reverse`` and the static and dynamic self-locking (docs/worm_rating.md).
        The mesh efficiency does not depend on the load."""
        r = self.rating(1.0, n1, mu=mu, mu_static=mu_static)
        return {k: getattr(r, k) for k in ("v_g", "mu", "mu_static", "friction_method", "rho_deg", "eta_z",
                                           "eta_z_reverse", "self_locking_static", "self_locking_dynamic")}

    def allowable_torque(self, n1, casting="sand", application_factor=1.0) -> float:
        """The wheel (output) torque T2 (N·m) this pair carries at the worm speed ``n1`` (rpm) by ANSI/AGMA
        6034-B92 as Shigley ch. 15 prints it, for a bronze wheel cast ``casting`` ("sand", "chill",
        "centrifugal"): W_t,all·η_z·d_2/(2000·K_A) (:func:`~geardesign.gears.worm.agma.agma_capacity`;
        docs/worm_rating.md). Seed 002's worm of a = 125 mm at 1500 rpm, sand-cast wheel:

        >>> round(WormPair(4, 4, 50, 12.5).allowable_torque(1500.0, "sand"))
        431
        """
        from .agma import agma_capacity
        return float(agma_capacity(self._geo, n1, casting, application_factor)["T2_all"])

    def _rating_geometry(self) -> dict:
        g, src = self._geo, "WormPair geometry (DIN 3975)"
        out = {"m_x": self.m_x, "z1": self.z1, "z2": self.z2}
        out.update({k: (float(g[k]), src) for k in ("d_m1", "d_2", "a", "gamma_m_deg", "alpha_n_deg", "d_f1", "b_2")})
        return out

    def with_x2(self, x2: float) -> "WormPair":
        """The same worm and wheel with the wheel's shift ``x2``."""
        return WormPair(self.m_x, self.z1, self.z2, self.q, x2, self.flank_form, self.rack, self.worm_length_mm,
                        self.face_width_mm)

    @staticmethod
    def _identity(pair) -> dict:
        g = pair._geo
        return dict(m_x=pair.m_x, z1=pair.z1, z2=pair.z2, q=pair.q, a=g["a"], eps_alpha=g["eps_alpha"])

    def __repr__(self) -> str:
        g = self._geo
        return (f"WormPair({self.flank_form}, m_x = {self.m_x:g} mm, z1/z2 = {self.z1}/{self.z2}, q = {self.q:.6g}, "
                f"x2 = {self.x2:.6g}: a = {g['a']:.6g} mm, u = {g['u']:.6g}, γ_m = {g['gamma_m_deg']:.4f}°)")


def _require_exists(geo: dict) -> None:
    """The wheel has a root and a throat above its base circle, and the worm meshes with it: else refused by the
    input that moves it (x2)."""
    if not geo["d_f2"] > 0:
        raise GearDesignError(f"x2 = {geo['x2']:g} is too small for z2 = {geo['z2']:g}: the wheel's root diameter "
                              f"d_f2 = {geo['d_f2']:.6g} mm is not positive")
    if not (math.isfinite(geo["sa2"]) and math.isfinite(geo["eps_alpha"])):
        raise GearDesignError(f"x2 = {geo['x2']:g} is too small for z2 = {geo['z2']:g}: the wheel's throat circle "
                              "lies inside its base circle (no involute to mesh with)")
    if not geo["eps_alpha"] > 0:
        raise GearDesignError(f"x2 = {geo['x2']:g} is too large for z2 = {geo['z2']:g}: the worm's tip line is "
                              "above the wheel's throat, the pair does not mesh (contact ratio <= 0)")


def _worm_checks(limits: dict) -> tuple:
    return _checks.make_checks(kind="worm", **limits)


def _margins(pair: WormPair, checks) -> dict:
    return {c.name: float(c.margin(pair._geo)) for c in checks}


# the checks whose margin depends on x2, and how: +1 rises with x2, -1 falls, 0 both (|x2|)
_X2_SENSE = {"undercut2": 1, "tip_thickness2": -1, "contact_ratio": -1, "x2_range": 0}


def _geo_at(pair: WormPair, x2: float) -> dict:
    return worm_geometry_float(pair.m_x, pair.z1, pair.z2, pair.q, x2, pair.flank_form, pair.rack,
                               pair.worm_length_mm, pair.face_width_mm)


def _root(f, lo, hi) -> float:
    from scipy.optimize import brentq   # here: importing scipy.optimize costs more than a pair

    return float(brentq(f, lo, hi, xtol=1e-14, rtol=1e-15, maxiter=200))


def _x2_window(pair: WormPair) -> tuple[float, float]:
    """The x2 where the wheel exists (a root), its throat circle is at or above its reference circle (x2 >= −h_a*)
    and it meshes with the worm (ε_α > 0), within |x2| <= X_ABS_MAX: the window every search of x2 stays in.
    Below x2 = −h_a* the throat angle α_a2 falls under α_x and the contact ratio no longer falls with x2 (its
    slope m_x(1/sin α_a2 − 1/sin α_x)/p_bx changes sign); no wheel is made so."""
    ha, c, z2 = pair.rack.ha, pair.rack.c, pair.z2
    lo = max(-X_ABS_MAX, -ha, -(z2 / 2.0 - ha - c) + 1e-9)
    hi = X_ABS_MAX
    if not _geo_at(pair, hi)["eps_alpha"] > 0:
        hi = _root(lambda x2: _geo_at(pair, x2)["eps_alpha"] - 1e-9, lo, hi)
    return lo, hi


def _x2_interval(pair: WormPair, checks) -> tuple[float, float, int]:
    """(lo, hi, roots found) of x2 where every check holds; (nan, nan) when the checks that do not depend on x2
    fail or the monotone ones leave no room."""
    nan = math.nan
    lo, hi = _x2_window(pair)
    nit = 0
    for c in checks:
        sense = _X2_SENSE.get(c.name)
        if sense is None:
            if not float(c.margin(pair._geo)) >= -_checks.FEASIBILITY_TOL:
                return nan, nan, nit
            continue
        if sense == 0:
            lo, hi = max(lo, -c.limit), min(hi, c.limit)
        else:
            def f(x2, c=c):
                return float(c.margin(_geo_at(pair, x2)))

            edge, inner = (hi, lo) if sense > 0 else (lo, hi)
            if f(edge) < 0:        # fails over the whole window
                return nan, nan, nit
            if f(inner) < 0:
                x = _root(f, lo, hi)
                nit += 1
                lo, hi = (max(lo, x), hi) if sense > 0 else (lo, min(hi, x))
        if lo > hi:
            return nan, nan, nit
    return lo, hi, nit


def _max_min_margin(pair: WormPair, checks, lo: float, hi: float) -> float:
    """The x2 in [lo, hi] where the smallest margin is largest: the smallest margin is the minimum of rising,
    falling and constant margins, so it peaks where the lowest rising one meets the lowest falling one (a root
    of their difference, which rises with x2), or at an end of the interval."""
    def f(x2):
        g = _geo_at(pair, x2)
        up, down = math.inf, math.inf
        for c in checks:
            sense = _X2_SENSE.get(c.name)
            if sense == 1:
                up = min(up, float(c.margin(g)))
            elif sense == -1:
                down = min(down, float(c.margin(g)))
            elif sense == 0:       # |x2| <= limit: limit + x2 rises, limit − x2 falls
                up, down = min(up, c.limit + x2), min(down, c.limit - x2)
        if math.isinf(up) or math.isinf(down):   # nothing to balance: every margin moves one way
            return up if math.isinf(down) else -down
        return up - down

    if f(lo) >= 0:
        return lo
    if f(hi) <= 0:
        return hi
    return _root(f, lo, hi)


def _least_bad(pair: WormPair, checks) -> float:
    """Where no x2 satisfies the checks: the x2 of the largest smallest margin over the geometry's window."""
    lo, hi = _x2_window(pair)
    return _max_min_margin(pair, checks, lo, hi)


class WormGeometry(Result):
    """The geometry of one worm pair: every field of :data:`~geardesign.gears.worm.geometry.WORM_FIELDS` as an
    attribute (mm, degrees), ``to_dict()``/``to_json()`` with those keys, ``table()`` the handbook's layout
    (quantity, symbol, value, unit) and ``summary()`` a few lines of text."""

    _success_field = "exists"

    def __init__(self, values: dict, flank_form: str):
        self._values = {k: float(values[k]) for k in WORM_FIELDS}
        self.flank_form = flank_form
        self.exists = True

    def __getattr__(self, name):
        values = self.__dict__.get("_values", {})
        if name in values:
            return values[name]
        raise AttributeError(f"WormGeometry has no field {name!r}")

    def to_dict(self) -> dict:
        from ...results import plain

        return {"flank_form": self.flank_form, **plain(self._values), "status": self.status}

    def table(self):
        """One row per quantity: ``quantity, symbol, value, unit, field``."""
        import pandas as pd

        rows = [(FIELD_INFO[k][2], FIELD_INFO[k][0], v, FIELD_INFO[k][1], k) for k, v in self._values.items()]
        return pd.DataFrame(rows, columns=["quantity", "symbol", "value", "unit", "field"])

    to_frame = table

    def summary(self) -> str:
        v = self._values
        return "\n".join([
            f"worm pair {self.flank_form}: m_x = {v['m_x']:g} mm, z1/z2 = {v['z1']:g}/{v['z2']:g} (u = {v['u']:.6g}), "
            f"q = {v['q']:.6g}, x2 = {v['x2']:.6g}",
            f"  a = {v['a']:.6g} mm, γ_m = {v['gamma_m_deg']:.5f}°, α_x = {v['alpha_x_deg']:.5f}°, "
            f"α_n = {v['alpha_n_deg']:.5f}°, ε_α = {v['eps_alpha']:.4f}",
            f"  worm: d_m1 = {v['d_m1']:.6g}, d_a1 = {v['d_a1']:.6g}, d_f1 = {v['d_f1']:.6g}, b_1 = {v['b_1']:.6g} mm",
            f"  wheel: d_2 = {v['d_2']:.6g}, d_a2 = {v['d_a2']:.6g}, d_e2 = {v['d_e2']:.6g}, d_f2 = {v['d_f2']:.6g}, "
            f"b_2 = {v['b_2']:.6g} mm",
        ])

    def __repr__(self) -> str:
        return self.summary()


@dataclass
class WormShiftResult(Result):
    """The best wheel shift of :meth:`WormPair.optimize_x2`, in the manner of
    :class:`~geardesign.shifts.result.ShiftResult` (``x2``, ``fun``, ``success``, ``message``, ``margins``,
    ``active``, ``conflict``, ``method``, ``tol``, ``nit``, ``time_s``; ``to_frame()`` one row per check)."""

    x2: float
    fun: float
    objective: str
    success: bool
    message: str
    nit: int
    time_s: float
    margins: dict = field(default_factory=dict)
    active: list = field(default_factory=list)
    conflict: list = field(default_factory=list)
    m_x: float = 1.0
    z1: int = 1
    z2: int = 0
    q: float = math.nan
    a: float = math.nan
    eps_alpha: float = math.nan
    method: str = "exact"
    tol: float = 1e-14

    def pair(self, **kw) -> WormPair:
        """The pair at the optimum (``kw``: flank_form, rack, worm_length_mm, face_width_mm)."""
        return WormPair(self.m_x, self.z1, self.z2, self.q, self.x2, **kw)

    def to_frame(self):
        """One row per check: margin and whether it is active at the optimum."""
        import pandas as pd

        return pd.DataFrame({"check": list(self.margins), "margin": list(self.margins.values()),
                             "active": [k in self.active for k in self.margins]})

    def __repr__(self) -> str:
        lines = [
            f"     message: {self.message}",
            f"     success: {self.success}",
            f"        worm: m_x = {self.m_x:g} mm, z1/z2 = {self.z1}/{self.z2}, q = {self.q:.6g}",
            f"          x2: {self.x2:.10g}",
            f"         fun: {self.fun:.10g}  ({self.objective})",
            f"   eps_alpha: {self.eps_alpha:.6g}   a: {self.a:.6g} mm",
            f"      active: {', '.join(self.active) if self.active else '-'}",
            "     margins: " + ", ".join(f"{k} {v:+.4g}" for k, v in self.margins.items()),
            f"      method: {self.method}, tol {self.tol:g}, nit {self.nit}, {self.time_s * 1e3:.2f} ms",
        ]
        if self.conflict:
            lines.insert(2, "    conflict: " + ", ".join(self.conflict))
        return "\n".join(lines)


_ARGUMENT_HINTS = {
    "m": "the worm's axial module is m_x={value!r}",
    "module": "the worm's axial module is m_x={value!r}",
    "alpha_deg": "the pressure angle belongs to the basic rack: rack=BasicRack(alpha_deg={value!r})",
    "ha": "the addendum belongs to the basic rack: rack=BasicRack(ha={value!r})",
    "c": "the clearance belongs to the basic rack: rack=BasicRack(c={value!r})",
    "a": "for a centre distance use WormPair.from_center_distance(a, m_x, z1, z2, q)",
    "a_w": "for a centre distance use WormPair.from_center_distance(a, m_x, z1, z2, q)",
    "d_m1": "give the diameter quotient q = d_m1 / m_x (q={value!r} / m_x)",
    "b_1": "the worm length is worm_length_mm={value!r} (mm)",
    "b_2": "the wheel width is face_width_mm={value!r} (mm)",
}
hint_unknown_arguments(WormPair, _ARGUMENT_HINTS)
