"""A shaft as a beam on two or more rigid supports: reactions, moment and torque diagrams, deflection, slope
and the first bending critical speed.

The shaft lies on the x axis from 0 to L; it is made of consecutive sections (length, outside diameter,
bore), so its bending stiffness EI steps along the axis. Elements act at axial positions x: forces F_y and
F_z across the axis in two perpendicular planes, an axial force F_x acting at a point (y, z) off the axis
(a gear's pitch radius: it bends the shaft by the couple −y·F_x in the x-y plane and −z·F_x in the x-z
plane), bending couples, torques about the axis and masses. Units: mm, N, N·m, rad, rpm; E in N/mm².

Model (Euler-Bernoulli beam; shear deformation neglected; supports rigid radially, one of them locating
axially): each plane is solved on its own. In a plane the internal moment at x is
M(x) = Σ_{x_i<x} F_i·(x − x_i) − Σ_{x_c<x} C_c (reactions among the forces), and the deflection w satisfies
E·I(x)·w'' = M(x) (the moment-area / double-integration method: Gere & Goodno, *Mechanics of Materials*,
§9.3; Budynas & Nisbett, *Shigley's Mechanical Engineering Design*, 10th ed., §4-6 and §7-5). Between the
nodes (every section end, support and load position) M is linear and I constant, so the curvature M/EI is
linear and the double integral is done exactly, segment by segment (cumulative sums). The reactions of
n >= 2 supports and the two integration constants come from one small linear system: the two equilibrium
equations and w = 0 at every support (for n > 2 the shaft is statically indeterminate: the compatibility
conditions are these w = 0 rows). Every plane and every load case is solved in one vectorised pass.

First critical speed (bending): Rayleigh's equation with the static deflection under the weights,
ω² = g·Σ m_i|y_i| / Σ m_i·y_i², an upper estimate, and Dunkerley's, 1/ω² = Σ m_i·a_ii with the influence
coefficients a_ii, a lower estimate (Shigley 10th ed. §7-6, eqs. (7-23), (7-31); the true first critical speed
lies between). The shaft's own mass is lumped onto the nodes (half of each segment's mass at either end).
"""
from __future__ import annotations

from typing import TYPE_CHECKING

import math
from dataclasses import dataclass, field, replace
from functools import cached_property

import numpy as np

from ..errors import GearDesignError
from ..results import Result
from ..validate import one_number, require_count, require_finite, require_range

if TYPE_CHECKING:       # pandas loads with the first table (the command's start-up stays light)
    import pandas as pd


def _pandas():
    import pandas

    return pandas


__all__ = ["ShaftLoad", "ShaftModel", "ShaftAnalysis", "analyse_shaft", "second_moment_mm4", "E_STEEL_MPA",
           "DENSITY_STEEL_KG_M3", "G_MM_S2"]

E_STEEL_MPA = 210_000.0          # Young's modulus of steel, N/mm²
DENSITY_STEEL_KG_M3 = 7850.0
G_MM_S2 = 9806.65                # standard gravity, mm/s²
LENGTH_MAX_MM = 1e5
FORCE_MAX_N = 1e9
SECTIONS_MAX = 200
SUPPORTS_MAX = 20
LOADS_MAX = 500
POINTS_DEFAULT = 400
CRITICAL_POINTS = 60         # interior nodes of the critical-speed grid
END_TOL = 1e-9               # a position this far (relative to the length) beyond an end is at the end


def second_moment_mm4(d_mm, bore_mm=0.0):
    """Second moment of area of a round (hollow) section, I = π(d⁴ − d_i⁴)/64 in mm⁴ (Gere & Goodno,
    Appendix E, case 9 and 10).

    >>> round(float(second_moment_mm4(40.0)), 3)
    125663.706
    """
    d, di = np.asarray(d_mm, dtype=float), np.asarray(bore_mm, dtype=float)
    return math.pi * (d ** 4 - di ** 4) / 64.0


@dataclass(frozen=True)
class ShaftLoad:
    """One element's action on the shaft at ``x_mm``: forces ``fy_n``, ``fz_n`` across the axis, an axial
    force ``fx_n`` acting at the point (``y_mm``, ``z_mm``) off the axis (a gear's mesh point: its couple
    bends the shaft), bending couples ``my_nm`` (in the x-z plane, turning +x toward +z) and ``mz_nm`` (in
    the x-y plane, turning +x toward +y), the torque ``torque_nm`` put into the shaft about +x (a drive's
    input positive, its output negative: the torques on a shaft balance) and the element's ``mass_kg``
    (for the critical speed)."""

    x_mm: float
    fy_n: float = 0.0
    fz_n: float = 0.0
    fx_n: float = 0.0
    y_mm: float = 0.0
    z_mm: float = 0.0
    torque_nm: float = 0.0
    my_nm: float = 0.0
    mz_nm: float = 0.0
    mass_kg: float = 0.0
    name: str = ""


def _onto_shaft(x, L):
    """Positions within END_TOL of an end, outside the shaft, onto that end: a support or load given at the end
    of a shaft whose length, the sum of its sections, rounded a few ulp the other way (25.4·8.5 + 25.4·11.5 is not
    25.4·20) is at the end."""
    tol = END_TOL * L
    return np.where((x > L) & (x <= L + tol), L, np.where((x < 0.0) & (x >= -tol), 0.0, x))


def _as_load(item, i) -> ShaftLoad:
    if isinstance(item, ShaftLoad):
        return item
    if isinstance(item, dict):
        try:
            return ShaftLoad(**item)
        except TypeError as exc:
            raise GearDesignError(f"loads[{i}]: {exc}") from None
    raise GearDesignError(f"loads[{i}] must be a ShaftLoad or a dict of its fields, got {type(item).__name__}")


@dataclass(frozen=True)
class ShaftModel:
    """A stepped shaft on its supports with the elements it carries.

    ``sections``: consecutive ``(length_mm, d_mm)`` or ``(length_mm, d_mm, bore_mm)`` from x = 0;
    ``supports_mm``: the support (bearing) positions, at least two; ``loads``: :class:`ShaftLoad` (or dicts
    of its fields); ``axial_support``: the index of the support that takes the axial force (the locating
    bearing); ``E_mpa`` and ``density_kg_m3`` of the material.

    >>> m = ShaftModel(sections=[(200.0, 40.0)], supports_mm=[0.0, 200.0], loads=[ShaftLoad(100.0, fy_n=-1000.0)])
    >>> m.length_mm
    200.0
    """

    sections: tuple
    supports_mm: tuple
    loads: tuple = ()
    axial_support: int = 0
    E_mpa: float = E_STEEL_MPA
    density_kg_m3: float = DENSITY_STEEL_KG_M3

    def __post_init__(self):
        if not isinstance(self.sections, (list, tuple)) and np.ndim(self.sections) == 0:
            raise GearDesignError(f"sections must be a list of (length_mm, d_mm[, bore_mm]), got {self.sections!r}")
        secs = list(self.sections)
        require_count("number of sections", len(secs), 1, SECTIONS_MAX)
        clean = []
        for i, s in enumerate(secs):
            s = tuple(s) if not isinstance(s, (int, float)) else (s,)
            if len(s) not in (2, 3):
                raise GearDesignError(f"sections[{i}] must be (length_mm, d_mm) or (length_mm, d_mm, bore_mm), "
                                      f"got {s!r}")
            length = float(one_number(f"sections[{i}] length_mm",
                                      require_range(f"sections[{i}] length_mm", s[0], 0.0, LENGTH_MAX_MM,
                                                    lo_open=True, unit="mm")))
            d = float(one_number(f"sections[{i}] d_mm", require_range(f"sections[{i}] d_mm", s[1], 0.0,
                                                                      LENGTH_MAX_MM, lo_open=True, unit="mm")))
            bore = 0.0 if len(s) == 2 else float(one_number(
                f"sections[{i}] bore_mm", require_range(f"sections[{i}] bore_mm", s[2], 0.0, d, hi_open=True,
                                                        unit="mm")))
            clean.append((length, d, bore))
        object.__setattr__(self, "sections", tuple(clean))
        L = self.length_mm
        sup = require_finite("supports_mm", self.supports_mm)
        if sup.ndim != 1 or not 2 <= sup.size <= SUPPORTS_MAX:
            raise GearDesignError(f"supports_mm must list 2 to {SUPPORTS_MAX} positions, got {sup.size}")
        if (sup < 0).any() or (sup > L).any():
            sup = _onto_shaft(sup, L)
        if (sup < 0).any() or (sup > L).any():
            raise GearDesignError(f"supports_mm must lie on the shaft, in [0, {L:g}] mm, got {sup.tolist()}")
        if np.unique(sup).size != sup.size:
            raise GearDesignError(f"supports_mm must be distinct, got {sup.tolist()}")
        object.__setattr__(self, "supports_mm", tuple(float(v) for v in sup))
        loads = [_as_load(item, i) for i, item in enumerate(self.loads)]
        require_count("number of loads", len(loads), 0, LOADS_MAX)
        for i, ld in enumerate(loads):
            if isinstance(ld.x_mm, (float, int, np.floating, np.integer)) and not 0.0 <= ld.x_mm <= L:
                x = float(_onto_shaft(np.asarray(float(ld.x_mm)), L))
                if x != ld.x_mm:
                    loads[i] = ld = replace(ld, x_mm=x)
            # one number each (a list, or an empty tuple, is refused by name, not met later as a ragged array)
            one_number(f"loads[{i}].x_mm", require_range(f"loads[{i}].x_mm", ld.x_mm, 0.0, L, unit="mm"))
            for name in ("fy_n", "fz_n", "fx_n"):
                one_number(f"loads[{i}].{name}", require_range(f"loads[{i}].{name}", getattr(ld, name), -FORCE_MAX_N,
                                                               FORCE_MAX_N, unit="N"))
            for name in ("y_mm", "z_mm"):
                one_number(f"loads[{i}].{name}", require_range(f"loads[{i}].{name}", getattr(ld, name),
                                                               -LENGTH_MAX_MM, LENGTH_MAX_MM, unit="mm"))
            for name in ("torque_nm", "my_nm", "mz_nm"):
                one_number(f"loads[{i}].{name}", require_range(f"loads[{i}].{name}", getattr(ld, name), -FORCE_MAX_N,
                                                               FORCE_MAX_N, unit="N·m"))
            one_number(f"loads[{i}].mass_kg", require_range(f"loads[{i}].mass_kg", ld.mass_kg, 0.0, 1e7, unit="kg"))
        loads = tuple(loads)
        object.__setattr__(self, "loads", loads)
        if not isinstance(self.axial_support, (int, np.integer)) or not 0 <= self.axial_support < sup.size:
            raise GearDesignError(f"axial_support must be a support index in [0, {sup.size - 1}], "
                                  f"got {self.axial_support!r}")
        require_range("E_mpa", self.E_mpa, 1e3, 1e7, unit="N/mm²")
        require_range("density_kg_m3", self.density_kg_m3, 0.0, 1e5, unit="kg/m³")
        torques = np.array([ld.torque_nm for ld in loads]) if loads else np.zeros(1)
        if abs(torques.sum()) > 1e-9 * max(np.abs(torques).max(), 1.0):
            raise GearDesignError(f"the torques on the shaft must balance (their sum is {torques.sum():.6g} N·m): "
                                  "give the output torque as a negative torque_nm")

    @property
    def length_mm(self) -> float:
        return float(sum(s[0] for s in self.sections))

    @cached_property
    def _section_arrays(self):
        """(section ends 0 … L, outside diameters, bores) as arrays, made once (the model is frozen)."""
        return (np.concatenate([[0.0], np.cumsum([s[0] for s in self.sections])]),
                np.array([s[1] for s in self.sections]), np.array([s[2] for s in self.sections]))

    @property
    def section_ends_mm(self) -> np.ndarray:
        """x of every section boundary, 0 … L."""
        return self._section_arrays[0].copy()

    def diameter_at(self, x_mm, side: str = "right"):
        """Outside diameter and bore (mm) at x; at a step, the section to the ``side`` of it."""
        ends, d, b = self._section_arrays
        x = np.asarray(x_mm, dtype=float)
        i = np.searchsorted(ends, x, side=side) - 1
        i = np.minimum(np.maximum(i, 0), len(self.sections) - 1)
        return d[i], b[i]

    def with_diameters(self, scale: float) -> "ShaftModel":
        """The same shaft with every diameter (and bore) times ``scale``."""
        return ShaftModel(tuple((s[0], s[1] * scale, s[2] * scale) for s in self.sections), self.supports_mm,
                          self.loads, self.axial_support, self.E_mpa, self.density_kg_m3)


def _nodes(model: ShaftModel, points: int):
    """Node positions with every breakpoint twice (its left and right limit) and ``right`` flags."""
    L = model.length_mm
    brk = np.unique(np.concatenate([model.section_ends_mm, model.supports_mm,
                                    [ld.x_mm for ld in model.loads] or np.zeros(0)]))
    fill = np.linspace(0.0, L, points + 1)
    fill = fill[~np.isin(fill, brk)]
    x = np.concatenate([brk, brk, fill])
    right = np.concatenate([np.zeros(brk.size, bool), np.ones(brk.size, bool), np.ones(fill.size, bool)])
    order = np.lexsort((right, x))
    return x[order], right[order]


def _active(x, right, xs):
    """(nodes, points) mask: the point at xs acts on the part left of node x (strictly left, or at x on
    the node's right limit)."""
    xs = np.asarray(xs, dtype=float)
    return (xs[None, :] < x[:, None]) | ((xs[None, :] == x[:, None]) & right[:, None])


def _integrate(kappa, x):
    """Slope and deflection from the curvature (…, N), exact for curvature linear between nodes, with
    zero slope and deflection at x[0]."""
    h = np.diff(x)
    k0, k1 = kappa[..., :-1], kappa[..., 1:]
    theta = np.concatenate([np.zeros(kappa.shape[:-1] + (1,)), np.cumsum(h * (k0 + k1) / 2.0, axis=-1)], axis=-1)
    dw = theta[..., :-1] * h + h * h * (2.0 * k0 + k1) / 6.0
    w = np.concatenate([np.zeros(kappa.shape[:-1] + (1,)), np.cumsum(dw, axis=-1)], axis=-1)
    return theta, w


def _solve_plane(x, right, EI, supports, xf, F, xc, C):
    """Reactions, moment, curvature, slope and deflection of a batch of load cases in one plane.

    x, right, EI: nodes (N); supports (S); forces F (k, m) at xf (m); couples C (k, q) at xc (q).
    Returns R (k, S), M (k, N) in N·mm, kappa, theta (rad), w (mm)."""
    A = _active(x, right, xf) * (x[:, None] - np.asarray(xf)[None, :])          # (N, m)
    B = _active(x, right, xc).astype(float)                                       # (N, q)
    As = _active(x, right, supports) * (x[:, None] - supports[None, :])           # (N, S)
    M0 = F @ A.T - C @ B.T                                                        # (k, N)
    th0, w0 = _integrate(M0 / EI, x)
    ths, ws = _integrate(As.T / EI, x)                                            # (S, N)
    S = supports.size
    idx = np.searchsorted(x, supports, side="left")          # a support's left-limit node (w is continuous)
    L = x[-1]
    # unknowns: R_1..R_S, c0, c1 (w = w0 + R·ws + c0 + c1 x)
    K = np.zeros((S + 2, S + 2))
    K[0, :S] = 1.0
    K[1, :S] = L - supports
    K[2:, :S] = ws[:, idx].T
    K[2:, S] = 1.0
    K[2:, S + 1] = supports
    rhs = np.zeros((S + 2, F.shape[0]))
    rhs[0] = -F.sum(axis=1)
    rhs[1] = C.sum(axis=1) - F @ (L - np.asarray(xf))
    rhs[2:] = -w0[:, idx].T
    u = np.linalg.solve(K, rhs).T                                                 # (k, S+2)
    R, c0, c1 = u[:, :S], u[:, S:S + 1], u[:, S + 1:S + 2]
    M = M0 + R @ As.T
    theta = th0 + R @ ths + c1
    w = w0 + R @ ws + c0 + c1 * x[None, :]
    return R, M, M / EI, theta, w


@dataclass(frozen=True)
class _Plane:
    x: np.ndarray
    kappa: np.ndarray
    theta: np.ndarray
    w: np.ndarray

    def at(self, xq):
        """Slope and deflection at arbitrary x: the exact cubic of the segment holding it."""
        x = self.x
        xq = np.asarray(xq, dtype=float)
        i = np.clip(np.searchsorted(x, xq, side="right") - 1, 0, x.size - 2)
        h = x[i + 1] - x[i]
        s = xq - x[i]
        k0, k1 = self.kappa[i], self.kappa[i + 1]
        dk = np.where(h > 0, (k1 - k0) / np.where(h > 0, h, 1.0), 0.0)
        theta = self.theta[i] + k0 * s + dk * s * s / 2.0
        w = self.w[i] + self.theta[i] * s + k0 * s * s / 2.0 + dk * s ** 3 / 6.0
        return theta, w


@dataclass(repr=False)
class ShaftAnalysis(Result):
    """Reactions, diagrams, deflections and critical speeds of a :class:`ShaftModel` (see
    :func:`analyse_shaft`). ``diagrams``: one row per node (x_mm, the moments My_nm (x-z plane), Mz_nm
    (x-y plane) and M_nm = √(My² + Mz²), torque T_nm, axial force N_n (tension +), deflections wy_mm,
    wz_mm, w_mm, slopes thy_rad, thz_rad, th_rad, diameter d_mm); at a step or a load a position shows
    twice (left and right limit). ``reactions``: per support, Ry_n, Rz_n, Rx_n, R_n (the radial resultant).
    ``elements``: per load, its deflection and slope (resultant and per plane).
    ``critical_speed_rpm`` is Rayleigh's (upper) estimate, ``critical_speed_dunkerley_rpm`` Dunkerley's
    (lower).

    The tables are made from the solution's arrays when first asked for, and the critical speeds (a solve of
    their own) computed then too: a drive that needs only the reactions and moments does not pay for them."""

    model: ShaftModel
    max_deflection_mm: float
    success: bool = True
    message: str = "analysed"
    _planes: tuple = field(default=(), repr=False)
    _arrays: dict = field(default_factory=dict, repr=False)     # the solution: diagram, reaction, element columns
    _shaft_mass: bool = True
    _cache: dict = field(default_factory=dict, repr=False)
    _table_fields = ("diagrams", "reactions", "elements")

    def _table(self, name):
        if name not in self._cache:
            self._cache[name] = _pandas().DataFrame(self._arrays[name])
        return self._cache[name]

    @property
    def diagrams(self) -> pd.DataFrame:
        return self._table("diagrams")

    @property
    def reactions(self) -> pd.DataFrame:
        return self._table("reactions")

    @property
    def elements(self) -> pd.DataFrame:
        if "elements" not in self._cache and not self.model.loads:
            self._cache["elements"] = _pandas().DataFrame(
                columns=["name", "x_mm", "wy_mm", "wz_mm", "w_mm", "thy_rad", "thz_rad", "th_rad"])
        return self._table("elements")

    def _critical(self):
        if "critical" not in self._cache:
            n_r, n_d, shaft_kg = _critical_speeds(self.model, self._shaft_mass)
            self._cache["critical"] = (n_r, n_d, shaft_kg + sum(ld.mass_kg for ld in self.model.loads))
        return self._cache["critical"]

    @property
    def critical_speed_rpm(self) -> float:
        return self._critical()[0]

    @property
    def critical_speed_dunkerley_rpm(self) -> float:
        return self._critical()[1]

    @property
    def mass_kg(self) -> float:
        return self._critical()[2]

    def deflection_at(self, x_mm) -> pd.DataFrame:
        """Deflection (mm) and slope (rad) at any positions x, per plane and resultant."""
        xq = require_range("x_mm", x_mm, 0.0, self.model.length_mm, unit="mm")
        (thy, wy), (thz, wz) = (p.at(np.atleast_1d(xq)) for p in self._planes)
        return _pandas().DataFrame({"x_mm": np.atleast_1d(xq), "wy_mm": wy, "wz_mm": wz, "w_mm": np.hypot(wy, wz),
                             "thy_rad": thy, "thz_rad": thz, "th_rad": np.hypot(thy, thz)})

    def to_dict(self) -> dict:
        # the diagrams (hundreds of rows) are left out: to_frame() has them
        from ..results import plain

        return {"reactions": plain(self.reactions), "elements": plain(self.elements),
                "max_deflection_mm": plain(self.max_deflection_mm), "critical_speed_rpm": plain(self.critical_speed_rpm),
                "critical_speed_dunkerley_rpm": plain(self.critical_speed_dunkerley_rpm),
                "mass_kg": plain(self.mass_kg), "success": self.success, "message": self.message,
                "status": self.status}

    def __repr__(self) -> str:
        r = self.reactions
        lines = [f"ShaftAnalysis: L = {self.model.length_mm:g} mm on {len(r)} supports, "
                 f"max deflection {self.max_deflection_mm:.4g} mm, "
                 f"first critical speed {self.critical_speed_rpm:.5g} rpm (Rayleigh; Dunkerley "
                 f"{self.critical_speed_dunkerley_rpm:.5g})"]
        for _, row in r.iterrows():
            lines.append(f"  support at {row['x_mm']:g} mm: Ry {row['Ry_n']:.6g} N, Rz {row['Rz_n']:.6g} N, "
                         f"Rx {row['Rx_n']:.6g} N")
        d = self.diagrams
        i = int(np.argmax(d["M_nm"].to_numpy()))
        lines.append(f"  max bending moment {d['M_nm'].iloc[i]:.6g} N·m at {d['x_mm'].iloc[i]:g} mm, "
                     f"max torque {np.abs(d['T_nm']).max():.6g} N·m")
        return "\n".join(lines)


def _critical_speeds(model, shaft_mass: bool):
    """Rayleigh and Dunkerley first bending critical speeds (rpm) and the shaft's own mass (kg), on a grid of
    its own (:data:`CRITICAL_POINTS` interior nodes: the lumping error is below 1e-4 there, and the Dunkerley
    sum needs one load case per mass)."""
    x, right = _nodes(model, CRITICAL_POINTS)
    d, bore = _diameters(model, x, right)
    EI = model.E_mpa * second_moment_mm4(d, bore)
    supports = np.asarray(model.supports_mm)
    # masses: the elements' at their nodes, the shaft's own lumped half-and-half onto each segment's ends
    lumped = np.zeros(x.size)
    for ld in model.loads:
        if ld.mass_kg > 0:
            lumped[np.searchsorted(x, ld.x_mm, side="right") - 1] += ld.mass_kg   # its right-limit node
    shaft_kg = 0.0
    if shaft_mass and model.density_kg_m3 > 0:
        h = np.diff(x)
        area = math.pi * (d[:-1] ** 2 - bore[:-1] ** 2) / 4.0          # the segment's (right-limit) section
        seg = model.density_kg_m3 * 1e-9 * area * h
        shaft_kg = float(seg.sum())
        lumped[:-1] += seg / 2.0
        lumped[1:] += seg / 2.0
    # a lumped mass belongs on the node's right limit (where the lookups below find it)
    lumped = _to_right(x, right, lumped)
    heavy = lumped > 0
    if not heavy.any():
        return math.nan, math.nan, shaft_kg
    xm, m = x[heavy], lumped[heavy]
    none = np.zeros((1, 0))
    # weights m·g (N with m in kg, g in m/s²), all in one direction
    F = (m * G_MM_S2 / 1000.0)[None, :]
    _, _, _, _, w = _solve_plane(x, right, EI, supports, xm, F, np.zeros(0), none)
    cols = np.searchsorted(x, xm, side="right") - 1             # the masses' (right-limit) nodes
    y = w[0][cols]
    num, den = (m * np.abs(y)).sum(), (m * y * y).sum()
    omega_r = math.sqrt(G_MM_S2 * num / den) if den > 0 else math.inf
    # Dunkerley: unit loads at every mass, the deflection at that mass (influence coefficient a_ii in mm/N)
    eye = np.eye(xm.size)
    _, _, _, _, wu = _solve_plane(x, right, EI, supports, xm, eye, np.zeros(0), np.zeros((xm.size, 0)))
    a_ii = np.abs(wu[np.arange(xm.size), cols])               # mm/N
    inv = (m * a_ii / 1000.0).sum()                           # s²: kg·mm/N = 1e-3 s²
    omega_d = math.sqrt(1.0 / inv) if inv > 0 else math.inf
    to_rpm = 30.0 / math.pi
    return omega_r * to_rpm, omega_d * to_rpm, shaft_kg


def _diameters(model, x, right):
    """Outside diameter and bore at each node, the left-limit nodes taking the section to their left."""
    d, bore = model.diameter_at(x, side="right")
    dl, bl = model.diameter_at(x, side="left")
    return np.where(right, d, dl), np.where(right, bore, bl)


def analyse_shaft(model: ShaftModel, points: int = POINTS_DEFAULT, shaft_mass: bool = True) -> ShaftAnalysis:
    """Reactions, moment, torque and axial-force diagrams, deflection and slope along the shaft and at each
    element, and the first bending critical speed (method: module docstring). ``points``: interior nodes
    for the diagrams (the breakpoints are always nodes; the results at them do not depend on it);
    ``shaft_mass``: count the shaft's own mass in the critical speed.

    A uniform shaft, simply supported over 200 mm, 1000 N at mid-span: reactions 500 N, moment 50 N·m,
    deflection F·L³/(48·E·I) (Gere & Goodno Table H-2 case 4; Shigley Table A-9-5):

    >>> a = analyse_shaft(ShaftModel([(200.0, 40.0)], [0.0, 200.0], [ShaftLoad(100.0, fy_n=-1000.0)]))
    >>> a.reactions["Ry_n"].round(6).tolist()
    [500.0, 500.0]
    >>> round(a.max_deflection_mm / (1000 * 200**3 / (48 * 210000 * float(second_moment_mm4(40)))), 12)
    1.0
    """
    if not isinstance(model, ShaftModel):
        raise GearDesignError(f"model must be a ShaftModel, got {type(model).__name__}")
    points = require_count("points", points, 10, 100_000)
    x, right = _nodes(model, points)
    d, bore = _diameters(model, x, right)
    EI = model.E_mpa * second_moment_mm4(d, bore)
    supports = np.asarray(model.supports_mm)
    loads = model.loads
    xf = np.array([ld.x_mm for ld in loads], dtype=float)
    fy = np.array([ld.fy_n for ld in loads], dtype=float)
    fz = np.array([ld.fz_n for ld in loads], dtype=float)
    fx = np.array([ld.fx_n for ld in loads], dtype=float)
    # couples in N·mm: the axial force's −y·Fx (x-y plane), −z·Fx (x-z plane), plus the given couples
    cy_xy = np.array([-ld.y_mm * ld.fx_n + 1000.0 * ld.mz_nm for ld in loads], dtype=float)
    cz_xz = np.array([-ld.z_mm * ld.fx_n + 1000.0 * ld.my_nm for ld in loads], dtype=float)
    F = np.vstack([fy, fz]) if loads else np.zeros((2, 0))
    C = np.vstack([cy_xy, cz_xz]) if loads else np.zeros((2, 0))
    R, M, kappa, theta, w = _solve_plane(x, right, EI, supports, xf, F, xf, C)
    planes = tuple(_Plane(x, kappa[k], theta[k], w[k]) for k in range(2))
    act = _active(x, right, xf) if loads else np.zeros((x.size, 0), bool)
    T = act @ np.array([ld.torque_nm for ld in loads], dtype=float) if loads else np.zeros(x.size)
    Rx = -fx.sum() + 0.0     # + 0.0: no negative zero in the output
    N = -(act @ fx if loads else np.zeros(x.size)) - Rx * _active(x, right, [supports[model.axial_support]])[:, 0]
    Mz, My = M[0] / 1000.0, M[1] / 1000.0
    diagrams = {
        "x_mm": x, "My_nm": My, "Mz_nm": Mz, "M_nm": np.hypot(My, Mz), "T_nm": T, "N_n": N,
        "wy_mm": w[0], "wz_mm": w[1], "w_mm": np.hypot(w[0], w[1]),
        "thy_rad": theta[0], "thz_rad": theta[1], "th_rad": np.hypot(theta[0], theta[1]), "d_mm": d}
    rx = np.zeros(supports.size)
    rx[model.axial_support] = Rx
    reactions = {"x_mm": supports, "Ry_n": R[0], "Rz_n": R[1], "Rx_n": rx, "R_n": np.hypot(R[0], R[1])}
    arrays = {"diagrams": diagrams, "reactions": reactions}
    if loads:
        (thy, wy), (thz, wz) = (p.at(xf) for p in planes)
        arrays["elements"] = {"name": [ld.name or f"load {i}" for i, ld in enumerate(loads)], "x_mm": xf,
                              "wy_mm": wy, "wz_mm": wz, "w_mm": np.hypot(wy, wz), "thy_rad": thy,
                              "thz_rad": thz, "th_rad": np.hypot(thy, thz)}
    return ShaftAnalysis(model, float(diagrams["w_mm"].max()), _planes=planes, _arrays=arrays,
                         _shaft_mass=shaft_mass)


def _to_right(x, right, values):
    """Move values that sit on a breakpoint's left-limit node onto its right-limit node."""
    out = values.copy()
    left_dup = np.flatnonzero(~right)
    out[left_dup + 1] += out[left_dup]     # a left-limit node is always followed by its right twin
    out[left_dup] = 0.0
    return out
