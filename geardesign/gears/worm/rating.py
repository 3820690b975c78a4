"""Load capacity of a cylindrical worm gear pair: mesh forces, worm deflection, mean contact stress, the
wheel's root shear stress, the oil sump temperature, their safety factors S_H, S_F, S_δ, S_T (S_W: see below)
in one result with a factor table, and the wheel torque T2 the pair carries at the required safeties.

What each check rests on (docs/worm_rating.md says the same, per factor):

- forces: SDP/SI *Elements of Metric Gear Technology* §16.5, eq. (16-20) (worm driving), written with the
  friction angle ρ' (tan ρ' = μ/cos α_n): F_t1 = F_t2·tan(γ_m + ρ'), F_r = F_t2·tan α_n·cos ρ'/cos(γ_m + ρ');
- worm deflection: the worm as a shaft on two supports l_1 apart, loaded at mid-span by the resultant of its
  tangential and radial force, δ = F·l_1³/(48·E·I), I = π·d_f1⁴/64 (Roark, simply supported beam, centre load;
  Autodesk Inventor's worm check uses the same symmetric mounting); the limit δ_lim ≈ 0.004·m_x for a hardened
  worm, 0.01·m_x for a through-hardened one (Autodesk Inventor help, *Strength calculation of worm gears*);
- contact: the mean Hertzian stress σ_Hm = (4/π)·√(p_m*·T2·10³·E_red/a³) in the form ISO/TS 14521 / DIN 3996
  are known by (for a line contact the peak pressure is 4/π of the mean one). The standard's text could not be
  read, so this form is **not checked against it**; its formula for the mean Hertzian stress parameter p_m* and
  the permissible stress σ_HG (σ_Hlim with its life, speed, size, ratio and oil factors) are the caller's;
- root: the nominal shear stress of the wheel's teeth F_t2/(b_2·m_x) times the product of ISO/TS 14521's
  factors Y_ε·Y_F·Y_γ·Y_K (the structure as the standard is known by, not checked against its text), the
  product and τ_FG given by the caller (their formulas were not found either);
- temperature: :mod:`geardesign.gears.worm.temperature`;
- wear (S_W): not computed — ISO/TS 14521's wear intensity J_0T against the lubricant film parameter and
  its material/lubricant factors could not be read in a public text;
- the AGMA load (S_AGMA): ANSI/AGMA 6034-B92 as Shigley ch. 15 prints it (:mod:`geardesign.gears.worm.agma`),
  the allowable tangential load W_t,all = C_s·D_m^0.8·F_e·C_m·C_v over the design load K_A·F_t2/η_z, when
  the wheel's casting is given; with ``k_heat="agma"`` (``"agma_fan"``) the temperature takes Shigley's cooling
  coefficient, with ``A_housing="agma_min"`` AGMA's smallest case area.

Minimum safeties default to the ones Niemann-Winter III Beispiel 3 asks for (as the DSoftCon report of that
example prints them: S_T 1.0, S_H 1.0, S_W 1.0, S_F 1.4, S_δ 1.0); S_AGMA's 1.0 leaves the design factor n_d of
Shigley's examples to the caller (``minimums={"S_AGMA": 1.2}``).
"""
from __future__ import annotations

import html
import math
from dataclasses import dataclass, field

import numpy as np

from ...errors import GearDesignError
from ...results import Result, notes_text, plain
from ...validate import one_number, require_positive, require_range
from . import agma
from . import efficiency as eff
from . import temperature as temp

__all__ = ["MIN_SAFETY", "E_STEEL_MPA", "worm_reference_diameter", "wheel_reference_diameter",
           "mean_lead_angle_deg", "centre_distance", "worm_root_diameter", "mesh_forces", "reduced_modulus",
           "mean_contact_stress", "root_shear_stress", "worm_deflection", "deflection_limit", "WormRating",
           "worm_rating", "rate_geometry", "load_capacity"]

# Niemann-Winter III Beispiel 3's required safeties (DSoftCon report, tests/data/worm_efficiency_examples.md)
MIN_SAFETY = {"S_H": 1.0, "S_F": 1.4, "S_delta": 1.0, "S_T": 1.0, "S_W": 1.0, "S_AGMA": 1.0}
E_STEEL_MPA = 206000.0          # steel, as ISO 6336-2 takes it (Z_E = 189.8 √MPa)


# -- geometry the pair helper (branch wormgeo, geardesign/gears/worm/geometry.py) computes too: one line each,
#    DIN 3975; the lead replaces these with theirs at merge.
def worm_reference_diameter(m_x, q):
    """Worm reference (mean) diameter d_m1 = q·m_x (mm), DIN 3975."""
    return require_positive("q", q) * require_positive("m_x", m_x, unit="mm")


def wheel_reference_diameter(m_x, z2):
    """Wheel reference diameter d_2 = z2·m_x (mm), DIN 3975."""
    return require_positive("z2", z2) * require_positive("m_x", m_x, unit="mm")


def mean_lead_angle_deg(z1, q):
    """Mean lead angle γ_m = arctan(z1/q) (degrees), DIN 3975."""
    return np.degrees(np.arctan(require_positive("z1", z1) / require_positive("q", q)))


def centre_distance(m_x, q, z2, x2=0.0):
    """Centre distance a = m_x·(q + z2 + 2·x2)/2 (mm), DIN 3975."""
    return require_positive("m_x", m_x, unit="mm") * (q + z2 + 2.0 * require_range("x2", x2, -2.0, 3.0)) / 2.0


def worm_root_diameter(m_x, q, c_star=0.25):
    """Worm root diameter d_f1 = d_m1 − 2·(1 + c*)·m_x (mm), DIN 3975 with the worm's addendum m_x."""
    return worm_reference_diameter(m_x, q) - 2.0 * (1.0 + c_star) * m_x


# -- the checks -------------------------------------------------------------------------------------------
def mesh_forces(T2, d_2, gamma_m_deg, alpha_n_deg, rho_deg):
    """Mesh forces with the worm driving (N): wheel tangential F_t2 = 2000·T2/d_2 (= worm axial), worm
    tangential F_t1 = F_t2·tan(γ_m + ρ') (= wheel axial) and radial F_r = F_t2·tan α_n·cos ρ'/cos(γ_m + ρ')
    (SDP/SI eq. (16-20) with μ = cos α_n·tan ρ'). T2 in N·m, d_2 in mm. Returns (F_t2, F_t1, F_r).

    Without friction F_t1 = F_t2·tan γ_m and F_r = F_t2·tan α_n/cos γ_m (500 N·m on d_2 = 200 mm, γ_m = 5°):

    >>> [round(float(f), 1) for f in mesh_forces(500.0, 200.0, 5.0, 20.0, 0.0)]
    [5000.0, 437.4, 1826.8]
    """
    t2 = require_range("T2", T2, 0.0, 1e9, unit="N·m")
    d2 = require_positive("d_2", d_2, unit="mm")
    g = np.radians(require_range("gamma_m_deg", gamma_m_deg, 0.0, 45.0, lo_open=True, unit="deg"))
    a = np.radians(require_range("alpha_n_deg", alpha_n_deg, 0.0, 45.0, hi_open=True, unit="deg"))
    rho = np.radians(require_range("rho_deg", rho_deg, 0.0, 45.0, unit="deg"))
    F_t2 = 2000.0 * t2 / d2
    return F_t2, F_t2 * np.tan(g + rho), F_t2 * np.tan(a) * np.cos(rho) / np.cos(g + rho)


def reduced_modulus(E1, nu1, E2, nu2):
    """Reduced modulus of the contact E_red = 2/((1 − ν1²)/E1 + (1 − ν2²)/E2) (MPa), twice Hertz's contact modulus
    E* (the convention DIN 3996 is known by; not checked against its text). Steel on steel (206 GPa, 0.3):
    226 374 MPa.

    >>> round(float(reduced_modulus(206000.0, 0.3, 206000.0, 0.3)))
    226374
    """
    e1 = require_positive("E1", E1, unit="MPa")
    e2 = require_positive("E2", E2, unit="MPa")
    n1 = require_range("nu1", nu1, 0.0, 0.5, hi_open=True)
    n2 = require_range("nu2", nu2, 0.0, 0.5, hi_open=True)
    return 2.0 / ((1.0 - n1 ** 2) / e1 + (1.0 - n2 ** 2) / e2)


def mean_contact_stress(T2, a, p_m_star, E_red):
    """Mean Hertzian stress σ_Hm = (4/π)·√(p_m*·T2·10³·E_red/a³) (MPa) of ISO/TS 14521 / DIN 3996: T2 in N·m,
    a in mm, E_red in MPa, p_m* the mean Hertzian stress parameter of the geometry (given: the standard's
    formula for it was not found in a public text)."""
    t2 = require_range("T2", T2, 0.0, 1e9, unit="N·m")
    p = require_range("p_m_star", p_m_star, 0.05, 20.0)
    e = require_positive("E_red", E_red, unit="MPa")
    return 4.0 / math.pi * np.sqrt(p * t2 * 1e3 * e / require_positive("a", a, unit="mm") ** 3)


def root_shear_stress(F_t2, b_2, m_x, Y_root):
    """Root shear stress of the wheel τ_F = F_t2/(b_2·m_x)·Y (MPa), Y = Y_ε·Y_F·Y_γ·Y_K of ISO/TS 14521 given
    by the caller (their formulas were not found in a public text). F_t2 in N, b_2 and m_x in mm."""
    f = require_range("F_t2", F_t2, 0.0, 1e12, unit="N")
    return f / (require_positive("b_2", b_2, unit="mm") * require_positive("m_x", m_x, unit="mm")) * \
        require_range("Y_root", Y_root, 0.05, 20.0)


def worm_deflection(F_t1, F_r, l_1, d_f1, E_1=E_STEEL_MPA):
    """Deflection δ_m (mm) of the worm at the mesh: a shaft on supports l_1 apart loaded at mid-span by
    F = √(F_t1² + F_r²), δ = F·l_1³/(48·E·I), I = π·d_f1⁴/64 (the root cylinder carries the bending).

    >>> round(float(worm_deflection(3000.0, 4000.0, 300.0, 40.0)), 5)     # 5 kN, 300 mm, Ø40, steel
    0.10865
    """
    F = np.hypot(require_range("F_t1", F_t1, 0.0, 1e12, unit="N"), require_range("F_r", F_r, 0.0, 1e12, unit="N"))
    inertia = math.pi * require_positive("d_f1", d_f1, unit="mm") ** 4 / 64.0
    return F * require_positive("l_1", l_1, unit="mm") ** 3 / (48.0 * require_positive("E_1", E_1, unit="MPa") * inertia)


def deflection_limit(m_x, hardened=True):
    """Permissible worm deflection δ_lim ≈ 0.004·m_x for a (case-)hardened worm, 0.01·m_x for a
    through-hardened (heat-treated) one (Autodesk Inventor help, *Strength calculation of worm gears*)."""
    return (0.004 if hardened else 0.01) * require_positive("m_x", m_x, unit="mm")


# -- one pair's rating -----------------------------------------------------------------------------------
_CHECKS = ("S_H", "S_F", "S_delta", "S_T", "S_W", "S_AGMA")
_CHECK_NAMES = {"S_H": "pitting (mean contact stress)", "S_F": "tooth root of the wheel",
                "S_delta": "worm deflection", "S_T": "temperature (oil sump)", "S_W": "wear",
                "S_AGMA": "AGMA 6034 load (W_t,all/W_t)"}


@dataclass(frozen=True)
class WormRating(Result):
    """Efficiency and load capacity of one worm pair at one load. Speeds and friction: ``v_g`` (m/s), ``mu``
    and ``mu_static`` with the ``friction_method``, the friction angle ``rho_deg``; efficiencies ``eta_z``
    (worm driving), ``eta_z_reverse`` (wheel driving, <= 0 when self-locking), ``eta_total`` (with the given
    no-load, bearing and seal losses); ``self_locking_static`` (at rest, μ_static) and
    ``self_locking_dynamic`` (running, μ); forces ``F_t2, F_t1, F_r`` (N); stresses ``sigma_Hm``, ``tau_F``
    (MPa), deflection ``delta_m`` and its limit ``delta_lim`` (mm), oil temperature ``theta_S`` (°C), power
    loss ``P_V`` (W); safeties ``S_H, S_F, S_delta, S_T, S_W, S_AGMA`` (NaN: not computed, ``notes`` says why),
    ``W_t_all`` and ``W_t`` (N) the AGMA allowable and design tangential loads of the wheel;
    ``minimums`` the required ones; ``factors`` a table of every quantity with its method and source."""

    T2: float
    v_g: float
    mu: float
    mu_static: float
    friction_method: str
    rho_deg: float
    eta_z: float
    eta_z_reverse: float
    eta_total: float
    self_locking_static: bool
    self_locking_dynamic: bool
    F_t2: float
    F_t1: float
    F_r: float
    sigma_Hm: float
    tau_F: float
    delta_m: float
    delta_lim: float
    theta_S: float
    P_V: float
    S_H: float
    S_F: float
    S_delta: float
    S_T: float
    S_W: float
    S_AGMA: float
    W_t_all: float
    W_t: float
    minimums: dict
    _rows: tuple = field(repr=False, compare=False, default=())
    notes: tuple = ()
    _success_field = "ok"
    _table_fields = ("factors",)

    @property
    def factors(self):
        """Every quantity with its value, unit and method/source: columns ``symbol, value, unit, method``."""
        import pandas as pd
        return pd.DataFrame(list(self._rows), columns=["symbol", "value", "unit", "method"])

    @property
    def margins(self) -> dict:
        """S/S_min − 1 of every computed check (>= 0 holds); checks not computed are left out."""
        return {k: getattr(self, k) / self.minimums[k] - 1.0 for k in _CHECKS if math.isfinite(getattr(self, k))}

    @property
    def ok(self) -> bool:
        """True when every computed safety reaches its minimum (and at least one was computed)."""
        m = self.margins
        return bool(m) and all(v >= 0.0 for v in m.values())

    @property
    def governing(self) -> tuple[str, float]:
        """(check, margin) of the smallest margin among the computed checks."""
        m = self.margins
        if not m:
            return "", math.nan
        key = min(m, key=m.get)
        return key, m[key]

    def to_dict(self) -> dict:
        out = super().to_dict()
        out.pop("_rows", None)
        out.update(factors=plain(self.factors), ok=self.ok, margins=plain(self.margins),
                   governing=self.governing[0])
        return out

    def __repr__(self) -> str:
        check, margin = self.governing
        verdict = "OK" if self.ok else "FAILS"
        lines = [f"WormRating: {verdict} at T2 = {self.T2:g} N·m"
                 + (f" (governing: {_CHECK_NAMES[check]}, margin {margin:+.1%})" if check else ""),
                 f"  v_g {self.v_g:.3f} m/s, mu {self.mu:.4f} ({self.friction_method}), rho' {self.rho_deg:.3f} deg",
                 f"  eta_z {self.eta_z:.4f} (worm driving), eta_z' {self.eta_z_reverse:.4f} (wheel driving), "
                 f"eta_total {self.eta_total:.4f}",
                 f"  self-locking: static {'yes' if self.self_locking_static else 'no'}, "
                 f"dynamic {'yes' if self.self_locking_dynamic else 'no'}"]
        for k in _CHECKS:
            s = getattr(self, k)
            lines.append(f"  {k:8}{_shown(s):>14}   (min {self.minimums[k]:g})")
        lines.extend(notes_text(self.notes))
        return "\n".join(lines)

    def _repr_html_(self) -> str:
        rows = "".join(f"<tr><td>{html.escape(str(r[0]))}</td><td>{r[1]:.6g}</td><td>{html.escape(r[2])}</td>"
                       f"<td>{html.escape(r[3])}</td></tr>" for r in self._rows)
        safeties = "".join(f"<tr><td>{k}</td><td>{_shown(getattr(self, k))}</td><td>{self.minimums[k]:g}</td></tr>"
                           for k in _CHECKS)
        return (f"<div><b>WormRating: {'OK' if self.ok else 'FAILS'}</b><table><tr><th>safety</th><th>value</th>"
                f"<th>minimum</th></tr>{safeties}</table><details><summary>factors</summary><table>{rows}</table>"
                f"</details></div>")


def _shown(value: float) -> str:
    return f"{value:.3f}" if math.isfinite(value) else "not computed"


def _scalar(name, value):
    return one_number(name, np.asarray(value, dtype=float)) if value is not None else None


def worm_rating(T2, n1, m_x, z1, z2, q, *, x2=0.0, alpha_n_deg=20.0, b_2=None, l_1=None, d_f1=None,
                **options) -> WormRating:
    """Efficiency and load capacity of one worm pair (worm driving) at the wheel torque T2 (N·m) and worm speed
    n1 (rpm): geometry from the axial module m_x (mm), starts z1, wheel teeth z2, diameter quotient q, the
    wheel's profile shift x2 and the normal pressure angle α_n.

    Friction: ``mu`` a measured coefficient (used with α_n, ``friction_method`` "given"); else the AGMA 6034
    curve at the sliding speed. ``mu_static`` the starting friction for static self-locking (default the AGMA
    value at rest, 0.15). Each check runs when its inputs are given, else its safety is NaN with a note:
    pitting needs ``p_m_star``, ``E_red``, ``sigma_HG``; the root needs ``b_2``, ``Y_root``, ``tau_FG``; the
    deflection ``l_1`` (bearing span, mm; ``d_f1`` defaults to the DIN 3975 root diameter with c* = 0.25);
    the temperature ``k_heat`` (W/(m²·K); ``"agma"``/``"agma_fan"``: Shigley's h̄_CR at n1 without/with a fan)
    and ``A_housing`` (m², e.g. :func:`~geardesign.gears.worm.temperature.housing_area_estimate`;
    ``"agma_min"``: AGMA's smallest case area); the AGMA load ``casting`` ("sand", "chill", "centrifugal":
    the bronze wheel's, :mod:`~geardesign.gears.worm.agma`) and ``b_2``, with the application factor
    ``application_factor`` (K_A);
    wear is never computed (not found).
    ``minimums`` overrides :data:`MIN_SAFETY` entries. The options are those of :func:`rate_geometry`.
    """
    m_x = one_number("m_x", require_positive("m_x", m_x, unit="mm"))
    z1 = one_number("z1", require_range("z1", z1, 1, 10))
    z2 = one_number("z2", require_range("z2", z2, 10, 1000))
    q = one_number("q", require_range("q", q, 2.0, 40.0))
    geo = {"m_x": m_x, "z1": z1, "z2": z2,
           "d_m1": (float(worm_reference_diameter(m_x, q)), "DIN 3975: q·m_x"),
           "d_2": (float(wheel_reference_diameter(m_x, z2)), "DIN 3975: z2·m_x"),
           "a": (float(centre_distance(m_x, q, z2, x2)), "DIN 3975: m_x(q + z2 + 2 x2)/2"),
           "gamma_m_deg": (float(mean_lead_angle_deg(z1, q)), "DIN 3975: arctan(z1/q)"),
           "alpha_n_deg": (one_number("alpha_n_deg", eff._alpha(alpha_n_deg)), "given by the caller")}
    if d_f1 is not None:
        geo["d_f1"] = (one_number("d_f1", require_positive("d_f1", d_f1, unit="mm")), "given by the caller")
    else:
        geo["d_f1"] = (float(worm_root_diameter(m_x, q)), "DIN 3975 (c* = 0.25)")
    if b_2 is not None:
        geo["b_2"] = (one_number("b_2", require_positive("b_2", b_2, unit="mm")), "given by the caller")
    return rate_geometry(T2, n1, geo, l_1=l_1, **check_options(options))


def check_options(options: dict) -> dict:
    """``options`` if every key is a keyword of :func:`rate_geometry`; else one GearDesignError naming the
    unknown keyword and the accepted ones (a misspelt option must not pass silently or as a TypeError)."""
    allowed = _RATE_OPTIONS
    bad = [k for k in options if k not in allowed]
    if bad:
        raise GearDesignError(f"unknown rating option {bad[0]!r}: the options are {', '.join(allowed)}")
    return options


def rate_geometry(T2, n1, geo: dict, *, l_1=None, mu=None, mu_static=None, E_1=E_STEEL_MPA, worm_hardened=True,
                  p_m_star=None, E_red=None, sigma_HG=None, Y_root=None, tau_FG=None, k_heat=None, A_housing=None,
                  theta_0=20.0, theta_lim=90.0, P_V0=0.0, P_VL=0.0, P_VD=0.0, casting=None, application_factor=1.0,
                  minimums=None) -> WormRating:
    """:func:`worm_rating` on a pair's geometry ``geo``: ``m_x``, ``z1``, ``z2`` as numbers and ``d_m1``, ``d_2``,
    ``a``, ``gamma_m_deg``, ``alpha_n_deg``, ``d_f1`` and (optionally) ``b_2`` as ``(value, source)`` pairs (the
    factor table names each source), as a :class:`~geardesign.gears.worm.pair.WormPair` gives them."""
    T2 = one_number("T2", require_range("T2", T2, 0.0, 1e9, lo_open=True, unit="N·m"))
    n1 = one_number("n1", require_positive("n1", n1, unit="rpm"))
    m_x, z1, z2 = float(geo["m_x"]), float(geo["z1"]), float(geo["z2"])
    alpha_n_deg = geo["alpha_n_deg"][0]
    mins = dict(MIN_SAFETY)
    if minimums:
        for k, v in minimums.items():
            if k not in mins:
                raise GearDesignError(f"minimums keys must be among {list(mins)}, got {k!r}")
            mins[k] = one_number(f"minimums[{k!r}]", require_positive(f"minimums[{k!r}]", v))
    rows, notes = [], []

    def row(symbol, value, unit, method):
        rows.append((symbol, float(value), unit, method))
        return float(value)

    d_m1 = row("d_m1", geo["d_m1"][0], "mm", geo["d_m1"][1])
    d_2 = row("d_2", geo["d_2"][0], "mm", geo["d_2"][1])
    a = row("a", geo["a"][0], "mm", geo["a"][1])
    gamma = row("gamma_m", geo["gamma_m_deg"][0], "deg", geo["gamma_m_deg"][1])
    row("alpha_n", alpha_n_deg, "deg", geo["alpha_n_deg"][1])
    u = z2 / z1
    v_g = row("v_g", eff.sliding_speed(d_m1, n1, gamma), "m/s", "ISO/TS 14521 6.3: d_m1 n1 π/(60000 cos γ_m)")
    if mu is None:
        mu_v = float(eff.friction_coefficient_agma(v_g))
        method = "AGMA 6034-B92 (Shigley eq. 15-38)"
    else:
        mu_v = float(eff._mu(_scalar("mu", mu)))
        method = "given"
    row("mu", mu_v, "", f"coefficient of friction: {method}")
    mu_s = float(eff.friction_coefficient_agma(0.0)) if mu_static is None else float(eff._mu(_scalar("mu_static", mu_static)))
    row("mu_static", mu_s, "", "starting friction: " + ("AGMA 6034-B92 at rest (0.15)" if mu_static is None else "given"))
    rho = row("rho'", eff.friction_angle_deg(mu_v, alpha_n_deg), "deg", "arctan(mu/cos α_n) (SDP/SI eq. 16-21)")
    eta = row("eta_z", eff.efficiency_worm_driving(gamma, mu_v, alpha_n_deg), "", "tan γ_m/tan(γ_m + ρ')")
    eta_r = row("eta_z'", eff.efficiency_wheel_driving(gamma, mu_v, alpha_n_deg), "", "tan(γ_m − ρ')/tan γ_m")
    lock_s = bool(eff.self_locking(gamma, mu_s, alpha_n_deg))
    lock_d = bool(eff.self_locking(gamma, mu_v, alpha_n_deg))
    n2 = n1 / u
    P2 = T2 * n2 * math.pi / 30.0
    P_VZ = float(eff.mesh_power_loss(P2, eta))
    P_V = row("P_V", P_VZ + P_V0 + P_VL + P_VD, "W", "P_VZ + P_V0 + P_VL + P_VD (DIN 3996 eq. 1); P_V0, P_VL, P_VD given")
    eta_t = row("eta_total", eff.total_efficiency(P2, eta, P_V0, P_VL, P_VD), "", "P2/(P2 + P_V)")
    F_t2, F_t1, F_r = (float(f) for f in mesh_forces(T2, d_2, gamma, alpha_n_deg, rho))
    row("F_t2", F_t2, "N", "2000 T2/d_2")
    row("F_t1", F_t1, "N", "F_t2 tan(γ_m + ρ') (SDP/SI eq. 16-20)")
    row("F_r", F_r, "N", "F_t2 tan α_n cos ρ'/cos(γ_m + ρ') (SDP/SI eq. 16-20)")

    nan = math.nan
    sigma_Hm = tau_F = delta = delta_lim = theta_S = W_all = W_t = nan
    S_H = S_F = S_d = S_T = S_A = nan
    if p_m_star is not None and E_red is not None and sigma_HG is not None:
        sigma_Hm = row("sigma_Hm", mean_contact_stress(T2, a, p_m_star, E_red), "MPa",
                       "(4/π)√(p_m* T2 E_red/a³) (ISO/TS 14521 form, not checked against its text); p_m*, E_red given")
        S_H = row("S_H", require_positive("sigma_HG", sigma_HG, unit="MPa") / sigma_Hm, "", "sigma_HG (given)/sigma_Hm")
    else:
        notes.append("S_H not computed: give p_m_star, E_red and sigma_HG (ISO/TS 14521's p_m* formula and "
                     "sigma_Hlim table were not found in a public text)")
    if "b_2" in geo and Y_root is not None and tau_FG is not None:
        b_2 = row("b_2", geo["b_2"][0], "mm", geo["b_2"][1])
        tau_F = row("tau_F", root_shear_stress(F_t2, b_2, m_x, Y_root), "MPa", "F_t2/(b_2 m_x)·Y_root (ISO/TS 14521 structure, not checked; Y given)")
        S_F = row("S_F", require_positive("tau_FG", tau_FG, unit="MPa") / tau_F, "", "tau_FG (given)/tau_F")
    else:
        notes.append("S_F not computed: give b_2, Y_root (= Y_eps Y_F Y_gamma Y_K) and tau_FG")
    if l_1 is not None:
        df1 = row("d_f1", geo["d_f1"][0], "mm", geo["d_f1"][1])
        delta = row("delta_m", worm_deflection(F_t1, F_r, l_1, df1, E_1), "mm", "F l_1³/(48 E I), I = π d_f1⁴/64")
        delta_lim = row("delta_lim", deflection_limit(m_x, worm_hardened), "mm",
                        "Autodesk/CSN: 0.004 m_x hardened, 0.01 m_x heat-treated worm")
        S_d = row("S_delta", delta_lim / delta if delta > 0 else math.inf, "", "delta_lim/delta_m")
    else:
        notes.append("S_delta not computed: give l_1, the worm's bearing span")
    if isinstance(k_heat, str):
        fan = {"agma": False, "agma_fan": True}.get(k_heat)
        if fan is None:
            raise GearDesignError(f"k_heat must be a number (W/(m²·K)), 'agma' or 'agma_fan', got {k_heat!r}")
        k_heat = row("k_heat", agma.heat_transfer_coefficient_agma(n1, fan), "W/(m²·K)",
                     f"Shigley's h_CR = n1/{3939 if fan else 6494} + 0.13 ft·lbf/(min·in²·°F) (Eq. 15-50), "
                     f"{'a fan' if fan else 'no fan'} on the worm shaft")
    if isinstance(A_housing, str):
        if A_housing != "agma_min":
            raise GearDesignError(f"A_housing must be a number (m²) or 'agma_min', got {A_housing!r}")
        A_housing = row("A_housing", agma.housing_area_min_agma(a), "m²", "AGMA's A_min = 43.2 C^1.7 in² (Shigley Eq. 15-52)")
    if k_heat is not None and A_housing is not None:
        theta_S = row("theta_S", temp.oil_sump_temperature(P_V, k_heat, A_housing, theta_0), "°C",
                      "theta_0 + P_V/(k A) (heat balance)")
        S_T = row("S_T", temp.thermal_safety(P_V, k_heat, A_housing, theta_0, theta_lim), "",
                  "k A (theta_lim − theta_0)/P_V (Autodesk/CSN form)")
    else:
        notes.append("S_T not computed: give k_heat and A_housing")
    if casting is not None and "b_2" in geo:
        b_2 = float(geo["b_2"][0])
        src = "ANSI/AGMA 6034-B92 as Shigley ch. 15 prints it"
        load = agma.agma_load_float(a, d_2, d_m1, b_2, u, v_g, gamma, alpha_n_deg, mu_v, T2, eta, casting,
                                    application_factor)
        row("C_s", load["C_s"], "", f"materials factor, {casting}-cast bronze wheel (lbf/in^1.8; {src}, "
            "Eqs. 15-32…15-35)")
        row("C_m", load["C_m"], "", f"ratio correction factor ({src}, Eq. 15-36)")
        row("C_v", load["C_v"], "", f"velocity factor at v_g ({src}, Eq. 15-37)")
        row("F_e", load["F_e"], "mm", "min(b_2, 0.67 d_m1) (Shigley §15-6)")
        W_all = row("W_t_all", load["W_t_all"], "N", f"C_s D_m^0.8 F_e C_m C_v ({src}, Eq. 15-28)")
        W_t = row("W_t", load["W_t"], "N",
                  "K_A F_t2/eta_z (Shigley Eq. 15-58 without its design factor; K_A = application_factor given)")
        row("W_f", load["W_f"], "N", "mu W_t2/(cos α_n cos γ_m − mu sin γ_m) (Shigley §15-6)")
        row("P_f", load["P_f"], "W", "|W_f| v_g (Shigley §15-6)")
        S_A = row("S_AGMA", W_all / W_t, "", "W_t_all/W_t (AGMA 6034-B92 load; lives over 25 000 h, Shigley §15-8)")
    elif casting is not None:
        notes.append("S_AGMA not computed: give the wheel's face width b_2 with the casting")
    else:
        notes.append("S_AGMA not computed: give the wheel's casting ('sand', 'chill' or 'centrifugal'; AGMA 6034-B92)")
    notes.append("S_W (wear) not computed: ISO/TS 14521's wear intensity curves were not found in a public text")
    if lock_d:
        notes.append("dynamically self-locking: the wheel cannot drive the worm even while it runs")
    return WormRating(T2=T2, v_g=v_g, mu=mu_v, mu_static=mu_s, friction_method=method, rho_deg=rho, eta_z=eta,
                      eta_z_reverse=eta_r, eta_total=eta_t, self_locking_static=lock_s, self_locking_dynamic=lock_d,
                      F_t2=F_t2, F_t1=F_t1, F_r=F_r, sigma_Hm=sigma_Hm, tau_F=tau_F, delta_m=delta,
                      delta_lim=delta_lim, theta_S=theta_S, P_V=P_V, S_H=S_H, S_F=S_F, S_delta=S_d, S_T=S_T,
                      S_W=nan, S_AGMA=S_A, W_t_all=W_all, W_t=W_t, minimums=mins, _rows=tuple(rows), notes=tuple(notes))


_RATE_OPTIONS = ("l_1", "mu", "mu_static", "E_1", "worm_hardened", "p_m_star", "E_red", "sigma_HG", "Y_root",
                 "tau_FG", "k_heat", "A_housing", "theta_0", "theta_lim", "P_V0", "P_VL", "P_VD", "casting",
                 "application_factor",
                 "minimums")


def load_capacity(rating: WormRating, P_const=0.0) -> dict:
    """The wheel torque T2 (N·m) at which each computed check just reaches its minimum safety, from a rating
    at any load: friction depends on the sliding speed only, so the forces, τ_F and δ_m grow as T2, σ_Hm as
    √T2 and the mesh loss as T2 — every limit is closed-form (no root finding needed):

        T2_H = T2·(S_H/S_Hmin)², T2_F = T2·S_F/S_Fmin, T2_δ = T2·S_δ/S_δmin, T2_AGMA = T2·S_AGMA/S_AGMAmin,
        T2_T from S_T = Q/(P_VZ(T2) + P_const) = S_Tmin, P_const the load-independent losses (W) in P_V.

    Returns ``{"S_H": …, "S_F": …, "S_delta": …, "S_T": …, "S_AGMA": …, "T2_max": …, "governing": …}`` (checks not
    computed left out). Load-dependent bearing losses given as a constant are taken as load-independent.
    """
    r = rating
    out = {}
    if math.isfinite(r.S_H):
        out["S_H"] = r.T2 * (r.S_H / r.minimums["S_H"]) ** 2
    if math.isfinite(r.S_F):
        out["S_F"] = r.T2 * r.S_F / r.minimums["S_F"]
    if math.isfinite(r.S_delta):
        out["S_delta"] = r.T2 * r.S_delta / r.minimums["S_delta"]
    if math.isfinite(r.S_AGMA):
        out["S_AGMA"] = r.T2 * r.S_AGMA / r.minimums["S_AGMA"]
    if math.isfinite(r.S_T):
        pc = one_number("P_const", require_range("P_const", P_const, 0.0, 1e9, unit="W"))
        q_heat = r.S_T * r.P_V                       # the heat the housing sheds at theta_lim
        p_vz = r.P_V - pc                            # the load-dependent part, ∝ T2
        if p_vz <= 0:
            raise GearDesignError(f"P_const must be below the rating's power loss P_V = {r.P_V:g} W, got {pc:g}")
        out["S_T"] = r.T2 * (q_heat / r.minimums["S_T"] - pc) / p_vz
    if not out:
        raise GearDesignError("the rating has no computed check: give the inputs of at least one check")
    gov = min(out, key=out.get)
    out["T2_max"] = out[gov]
    out["governing"] = gov
    return out
