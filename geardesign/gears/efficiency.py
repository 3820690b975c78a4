"""Load-dependent power loss of a gear mesh: the lubricant's viscosity at its temperature, the mean
coefficient of friction μ_mZ and the gear loss factor H_V, and P_VZP = P·μ_mZ·H_V.

One function per formula, each with its source; every one takes numpy arrays. Units at the interface:
viscosities in mm²/s (kinematic, ν) and mPa·s (dynamic, η), temperatures in °C, densities in kg/m³,
speeds in m/s, lengths in mm, forces in N, powers in W, roughness in µm.

Sources (docs/efficiency.md, docs/references.md):

- ASTM D341 (Ubbelohde-Walther): log log(ν + 0.7) = A − B log T (T in K), through two measured points; DIN
  51563 writes the same line with 0.8 in place of 0.7;
- ISO/TR 14179-2:2001 (and the FZG literature it rests on: Schlenk 1994, Ohlendorf 1958, as restated in
  Höhn, Michaelis, Hinterstoißer, *Optimization of gearbox efficiency*, Goriva i maziva 48 (2009) 441-480,
  and Fernandes et al., *Gearbox power loss. Part II: friction losses in gears*, Tribology International 88
  (2015) 309-316): the mean coefficient of friction
  μ_mZ = 0.048·(F_bt/b / (v_ΣC·ρ_redC))^0.2·η_oil^−0.05·R_a^0.25·X_L, the gear loss factor of Ohlendorf
  H_V = π(u + 1)/(z1·u·cos β_b)·(1 − ε_α + ε_1² + ε_2²) and P_VZP = P_in·μ_mZ·H_V;
- the gear loss factor by integration of the sliding power over the plane of action (Wimmer's numerical
  H_V, as Fernandes et al. 2015 use it): :func:`gear_loss_factor_integrated`.

Not here: the no-load (churning, squeezing, windage) gear losses — ISO/TR 14179-2's dip-lubrication
formulas could not be read in a public text, so they are not implemented (docs/efficiency.md says so);
bearings are in :mod:`geardesign.drives.bearing_friction`, a stage's efficiency in
:mod:`geardesign.drives.efficiency`.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import GearDesignError
from ..validate import hint_unknown_arguments, one_number, require_positive, require_range

__all__ = ["WALTHER_C_ASTM", "WALTHER_C_DIN", "ISO_VG_GRADES", "LUBRICANT_FACTORS", "Lubricant", "walther_constants",
           "kinematic_viscosity", "oil_density", "dynamic_viscosity", "mean_friction_coefficient",
           "tip_contact_ratios", "gear_loss_factor_ohlendorf", "gear_loss_factor_integrated",
           "mesh_power_loss", "MeshLoss", "mesh_loss"]

WALTHER_C_ASTM = 0.7     # ASTM D341: log log(ν + 0.7), ν in mm²/s, for ν >= 2 mm²/s
WALTHER_C_DIN = 0.8      # DIN 51563 writes the same line with 0.8
NU_MIN_MM2S = 2.0        # below 2 mm²/s ASTM D341 adds further terms that are not implemented here
TEMPERATURE_RANGE_C = (-40.0, 200.0)
# ISO 3448 viscosity grades: the mid-point kinematic viscosity at 40 °C in mm²/s (limits ±10 %)
ISO_VG_GRADES = (2, 3, 5, 7, 10, 15, 22, 32, 46, 68, 100, 150, 220, 320, 460, 680, 1000, 1500, 2200, 3200)

# Lubricant factor X_L of the friction formula by base oil (ISO/TR 14179-2 after Schlenk, as restated by
# Höhn et al. 2009 and Fernandes et al. 2015): 1.0 mineral oil; the others are the values of those papers'
# tested oils and vary with the formulation — give the oil maker's or a test's value where known.
LUBRICANT_FACTORS = {"mineral": 1.0}


def walther_constants(nu1_mm2s, t1_c, nu2_mm2s, t2_c, c=WALTHER_C_ASTM):
    """(A, B) of the Ubbelohde-Walther line log10 log10(ν + c) = A − B·log10(T/K) through two measured
    viscosities ν1 at t1 and ν2 at t2 (ASTM D341; c = 0.7, DIN 51563: 0.8).

    An ISO VG 320 mineral oil of the FZG tests (GEARpie's library constants A = 9.0658, B = 3.4730) recovered
    from its own two points:

    >>> nu = lambda t: 10 ** 10 ** (9.0658 - 3.4730 * math.log10(t + 273.15)) - 0.7
    >>> A, B = walther_constants(nu(40), 40, nu(100), 100)
    >>> round(float(A), 9), round(float(B), 9)
    (9.0658, 3.473)
    """
    w1 = np.log10(np.log10(np.asarray(nu1_mm2s, dtype=float) + c))
    w2 = np.log10(np.log10(np.asarray(nu2_mm2s, dtype=float) + c))
    x1 = np.log10(np.asarray(t1_c, dtype=float) + 273.15)
    x2 = np.log10(np.asarray(t2_c, dtype=float) + 273.15)
    B = (w1 - w2) / (x2 - x1)
    return w1 + B * x1, B


def kinematic_viscosity(nu40, nu100, temperature_c, c=WALTHER_C_ASTM):
    """Kinematic viscosity ν (mm²/s) at ``temperature_c`` from the viscosities at 40 and 100 °C, on the
    Ubbelohde-Walther line of ASTM D341 (c = 0.7; DIN 51563: 0.8).

    A gear oil's data sheet (SAE 75W, ν40 = 30.8, ν100 = 5.9 mm²/s) prints ν80 = 9.12 and ν90 = 7.25 mm²/s
    (as quoted in tests/data/efficiency_examples.md); the DIN line gives:

    >>> [round(float(kinematic_viscosity(30.8, 5.9, t, c=0.8)), 2) for t in (80, 90)]
    [9.12, 7.25]
    """
    nu40 = require_range("nu40", nu40, NU_MIN_MM2S, 1e6, unit="mm²/s")
    nu100 = require_range("nu100", nu100, NU_MIN_MM2S, 1e6, unit="mm²/s")
    if np.any(nu100 >= nu40):
        raise GearDesignError(f"nu100 must be below nu40 (an oil thins as it warms), got "
                              f"nu40={nu40!r}, nu100={nu100!r}")
    t = require_range("temperature_c", temperature_c, *TEMPERATURE_RANGE_C, unit="°C")
    A, B = walther_constants(nu40, 40.0, nu100, 100.0, c)
    return 10.0 ** 10.0 ** (A - B * np.log10(t + 273.15)) - c


def oil_density(density15_kg_m3, temperature_c, expansion_per_k=5.8e-4):
    """Oil density (kg/m³) at ``temperature_c`` from the density at 15 °C, ρ = ρ15·(1 − α·(t − 15)), with the
    thermal expansion α = 5.8e-4 1/K of the FZG tests' mineral oils (Fernandes et al., Tribology International
    2015, as in GEARpie's lubricant library: ρ15 = 902 kg/m³ gives 870.6 kg/m³ at 75 °C).

    >>> round(float(oil_density(902.0, 75.0)), 1)
    870.6
    """
    rho = np.asarray(density15_kg_m3, dtype=float)
    return rho * (1.0 - np.asarray(expansion_per_k, dtype=float) * (np.asarray(temperature_c, dtype=float) - 15.0))


def dynamic_viscosity(nu_mm2s, density_kg_m3):
    """Dynamic viscosity η = ν·ρ in mPa·s from ν in mm²/s and ρ in kg/m³ (1 mm²/s × 1 kg/m³ = 1e-3 mPa·s).

    GEARpie's M320 at 75 °C: ν = 53.10 mm²/s, ρ = 870.6 kg/m³, η = 46.23 mPa·s:

    >>> round(float(dynamic_viscosity(53.10, 870.6)), 2)
    46.23
    """
    return np.asarray(nu_mm2s, dtype=float) * np.asarray(density_kg_m3, dtype=float) / 1000.0


@dataclass(frozen=True)
class Lubricant:
    """A gear oil: kinematic viscosities at 40 and 100 °C (mm²/s; an ISO VG grade fixes only ν40 ±10 %,
    ISO 3448, so ν100 must come from the data sheet), density at 15 °C (kg/m³) and the lubricant factor
    X_L of the friction formula (1.0 for mineral oil, ISO/TR 14179-2).

    >>> oil = Lubricant(320.0, 24.0)
    >>> round(float(oil.viscosity_mm2s(40.0)), 9)
    320.0
    """

    nu40: float
    nu100: float
    density15_kg_m3: float = 900.0
    lubricant_factor: float = 1.0
    name: str = "oil"

    def __post_init__(self):
        for field, lo, hi in (("nu40", NU_MIN_MM2S, 1e6), ("nu100", NU_MIN_MM2S, 1e6),
                              ("density15_kg_m3", 500.0, 2000.0), ("lubricant_factor", 0.1, 3.0)):
            object.__setattr__(self, field, one_number(field, require_range(field, getattr(self, field), lo, hi)))
        if self.nu100 >= self.nu40:
            raise GearDesignError(f"nu100 must be below nu40, got nu40={self.nu40!r}, "
                                  f"nu100={self.nu100!r}")

    @classmethod
    def iso_vg(cls, grade, nu100, **kwargs):
        """An oil of ISO viscosity grade ``grade`` (ISO 3448: ν40 is the grade's number, the mid-point of its
        ±10 % band) with the data sheet's ``nu100``.

        >>> Lubricant.iso_vg(220, 19.0).nu40
        220.0
        """
        if isinstance(grade, bool) or grade not in ISO_VG_GRADES:
            raise GearDesignError(f"grade must be an ISO 3448 viscosity grade ({', '.join(map(str, ISO_VG_GRADES))}), "
                                  f"got {grade!r}")
        return cls(float(grade), nu100, **kwargs)

    def viscosity_mm2s(self, temperature_c):
        """Kinematic viscosity (mm²/s) at ``temperature_c`` (ASTM D341)."""
        return kinematic_viscosity(self.nu40, self.nu100, temperature_c)

    def dynamic_viscosity_mpas(self, temperature_c):
        """Dynamic viscosity (mPa·s) at ``temperature_c``."""
        return dynamic_viscosity(self.viscosity_mm2s(temperature_c), oil_density(self.density15_kg_m3, temperature_c))


# Lubricant() without its viscosities: what each one is and where it lies (not Python's "missing 2 required
# positional arguments")
hint_unknown_arguments(Lubricant, {
    "nu": "give the viscosities at 40 and 100 °C as nu40= and nu100= (mm²/s)",
    "viscosity": "give the viscosities at 40 and 100 °C as nu40= and nu100= (mm²/s)",
    "grade": "for an ISO VG grade use Lubricant.iso_vg({value!r}, nu100)",
    "density_kg_m3": "the density at 15 °C is density15_kg_m3={value!r}",
}, needs={
    "nu40": f"the kinematic viscosity at 40 °C, mm²/s, in [{NU_MIN_MM2S:g}, 1e6] (an ISO VG grade's number, "
            "ISO 3448; or Lubricant.iso_vg(grade, nu100))",
    "nu100": f"the kinematic viscosity at 100 °C from the oil's data sheet, mm²/s, in [{NU_MIN_MM2S:g}, 1e6] and "
             "below nu40",
})


def mean_friction_coefficient(F_bt_per_b_n_mm, v_sum_c_m_s, rho_red_c_mm, eta_mpas, Ra_um, lubricant_factor=1.0):
    """Mean coefficient of friction of the mesh (ISO/TR 14179-2:2001 after Schlenk):
    μ_mZ = 0.048·(F_bt/b / (v_ΣC·ρ_redC))^0.2·η_oil^−0.05·R_a^0.25·X_L, with F_bt/b the transverse force on
    the base circle per face width (N/mm), v_ΣC = 2·v_t·sin α_wt the sum velocity at the pitch point (m/s),
    ρ_redC the reduced (normal) radius of curvature at the pitch point (mm), η_oil the dynamic viscosity at
    the oil temperature (mPa·s), R_a = (R_a1 + R_a2)/2 (µm) and X_L the lubricant factor (1 mineral oil).

    >>> round(float(mean_friction_coefficient(1.0, 1.0, 1.0, 1.0, 1.0)), 9)
    0.048
    """
    load = np.asarray(F_bt_per_b_n_mm, dtype=float) / (np.asarray(v_sum_c_m_s, dtype=float)
                                                       * np.asarray(rho_red_c_mm, dtype=float))
    return (0.048 * load ** 0.2 * np.asarray(eta_mpas, dtype=float) ** -0.05
            * np.asarray(Ra_um, dtype=float) ** 0.25 * np.asarray(lubricant_factor, dtype=float))


def tip_contact_ratios(geometry, internal=False):
    """(ε_1, ε_2): the parts of the transverse contact ratio on the pinion's and the wheel's tip side of the
    pitch point, ε_1 = (√(r_a1² − r_b1²) − r_b1·tan α_wt)/p_bt and ε_2 = ε_α − ε_1 (ISO 21771 path of
    contact; ε_1 + ε_2 = ε_α also for an internal pair, whose ring tip ends the path on gear 2's side).

    FZG type C gears (z 16/24, m 4.5, x 0.1817/0.1715, a 91.5 mm): ε_α = 1.44 (GEARpie's report):

    >>> from geardesign.gears.pair import GearPair
    >>> e1, e2 = tip_contact_ratios(GearPair(4.5, 16, 24, 0.1817, 0.1715).geometry())
    >>> round(float(e1 + e2), 2)
    1.44
    """
    g = geometry
    rb1, ra1 = np.asarray(g.db1) / 2.0, np.asarray(g.da1) / 2.0
    tan_w = np.tan(np.radians(np.asarray(g.alpha_w_deg, dtype=float)))
    eps1 = (np.sqrt(ra1 ** 2 - rb1 ** 2) - rb1 * tan_w) / np.asarray(g.p_b)
    return eps1, np.asarray(g.eps_alpha) - eps1


def gear_loss_factor_ohlendorf(z1, u, beta_b_deg, eps1, eps2, internal=False):
    """Gear loss factor of Ohlendorf (ISO/TR 14179-2; Höhn et al. 2009 eq. for H_V):
    H_V = π(u ± 1)/(z1·u·cos β_b)·(1 − ε_α + ε_1² + ε_2²), ε_α = ε_1 + ε_2, u = z2/z1 >= 1, + external,
    − internal (the sliding speed at a distance x from the pitch point is x·ω1(u ± 1)/u). It assumes the
    full load in single and half in double contact (1 <= ε_α < 2, ε_1, ε_2 < 1).

    FZG type C gears: H_V = 0.195 (GEARpie's report C14, "Ohlendorf"):

    >>> round(float(gear_loss_factor_ohlendorf(16, 1.5, 0.0, 0.72236, 0.71529)), 4)
    0.195
    """
    u = np.asarray(u, dtype=float)
    e1, e2 = np.asarray(eps1, dtype=float), np.asarray(eps2, dtype=float)
    up = u - 1.0 if internal else u + 1.0
    return (math.pi * up / (np.asarray(z1, dtype=float) * u * np.cos(np.radians(np.asarray(beta_b_deg, dtype=float))))
            * (1.0 - (e1 + e2) + e1 ** 2 + e2 ** 2))


_GAUSS_X, _GAUSS_W = np.polynomial.legendre.leggauss(16)


def _contact_mean_abs(s0, x_a, x_e, p, width):
    """Mean |x| over the contact lines in the plane of action at phase s0 (lines at x = s0 + k·p, each
    spanning ``width`` = b·tan β_b along x over the face; width 0: spur, a point per line), for an array s0."""
    k = np.arange(math.floor((x_a - width - p) / p) - 1, math.ceil((x_e + p) / p) + 2)
    lo = s0[:, None] + k[None, :] * p
    if width == 0.0:
        inside = (lo >= x_a) & (lo <= x_e)
        return np.sum(np.where(inside, np.abs(lo), 0.0), axis=1) / np.sum(inside, axis=1)
    c_lo = np.clip(lo, x_a, x_e)
    c_hi = np.clip(lo + width, x_a, x_e)
    def prim(x):     # ∫|x| dx
        return x * np.abs(x) / 2.0

    return np.sum(prim(c_hi) - prim(c_lo), axis=1) / np.sum(c_hi - c_lo, axis=1)


def gear_loss_factor_integrated(z1, u, beta_b_deg, eps1, eps2, eps_beta=0.0, internal=False):
    """Gear loss factor by integrating the sliding power over the plane of action (the numerical H_V of
    Wimmer, used by Fernandes et al. 2015): H_V = P_VZP/(μ·P_in) with the load spread evenly over the
    length of the lines of contact in mesh (a rigid mesh), time-averaged over one base pitch:
    H_V = (u ± 1)/(u·r_b1·cos β_b)·⟨mean |x| over the lines of contact⟩, x measured from the pitch point
    along the path of contact. The phase integral is done exactly: Gauss-Legendre (16 points) between
    its break points (where a line's end meets an end of the path or the pitch point), on which the mean
    is smooth (a ratio of a quadratic to a linear function of the phase).

    For a spur pair it is Ohlendorf's closed form; with an overlap ε_β it departs from it. FZG type C:

    >>> round(float(gear_loss_factor_integrated(16, 1.5, 0.0, 0.72236, 0.71529)), 4)
    0.195
    """
    z1, u = float(z1), float(u)
    e1, e2, eb = float(eps1), float(eps2), float(eps_beta)
    if not (e1 + e2 > 0 and eb >= 0):
        raise GearDesignError(f"eps1 + eps2 must be > 0 and eps_beta >= 0, got {e1!r}, {e2!r}, {eb!r}")
    # lengths in base pitches: p = 1, r_b1 = z1/(2π); the lines span ε_β pitches along the path
    # an overlap below 1e-9 is a spur pair's (its H_V differs by less): a helix of β = 1e-300 gave 0/0 here (fuzz)
    x_a, x_e, p, width = -e2, e1, 1.0, (eb if eb >= 1e-9 else 0.0)
    k = np.arange(-math.ceil(e2 + eb) - 2, math.ceil(e1) + 3)
    events = np.concatenate([(x_a - k) % p, (x_e - k) % p, (-k) % p,
                             (x_a - width - k) % p, (x_e - width - k) % p, (-width - k) % p, [0.0, p]])
    edges = np.unique(np.clip(events, 0.0, p))
    a, b = edges[:-1], edges[1:]
    keep = b - a > 1e-15
    a, b = a[keep], b[keep]
    s = ((a + b) / 2.0)[:, None] + ((b - a) / 2.0)[:, None] * _GAUSS_X[None, :]
    f = _contact_mean_abs(s.ravel(), x_a, x_e, p, width).reshape(s.shape)
    mean_abs = float(np.sum(f * _GAUSS_W[None, :] * ((b - a) / 2.0)[:, None])) / p
    up = u - 1.0 if internal else u + 1.0
    rb1 = z1 / (2.0 * math.pi)
    return up / (u * rb1 * math.cos(math.radians(float(beta_b_deg)))) * mean_abs


def mesh_power_loss(power_w, mu_mz, H_V):
    """Load-dependent gear power loss P_VZP = P_in·μ_mZ·H_V (W) (ISO/TR 14179-2).

    GEARpie's report C14: 31 415.9 W, H_V 0.1945 (integrated), μ_mZ 0.0483: 295.17 W:

    >>> round(float(mesh_power_loss(31415.9, 0.0483, 0.1945)), 1)
    295.1
    """
    return np.asarray(power_w, dtype=float) * np.asarray(mu_mz, dtype=float) * np.asarray(H_V, dtype=float)


@dataclass(frozen=True)
class MeshLoss:
    """The load-dependent loss of one mesh (see :func:`mesh_loss`)."""

    power_w: float
    mu_mz: float
    H_V: float
    H_V_ohlendorf: float
    loss_w: float
    eps1: float
    eps2: float
    v_t_m_s: float
    v_sum_c_m_s: float
    rho_red_c_mm: float
    F_bt_n: float
    eta_mpas: float
    method: str

    @property
    def efficiency(self) -> float:
        return 1.0 - self.loss_w / self.power_w


H_V_METHODS = ("integrated", "ohlendorf")


def mesh_loss(pair, torque1_nm, n1_rpm, eta_mpas, Ra_um=0.5, lubricant_factor=1.0, face_width_mm=None,
              method="integrated") -> MeshLoss:
    """Load-dependent loss of ``pair`` (a :class:`~geardesign.gears.pair.GearPair`) carrying gear 1's torque
    ``torque1_nm`` (N·m) at ``n1_rpm``, with the oil's dynamic viscosity ``eta_mpas`` at its temperature, the
    mean roughness ``Ra_um`` = (R_a1 + R_a2)/2 and the lubricant factor X_L. ``method``: the gear loss
    factor integrated over the plane of action (default) or Ohlendorf's closed form (both are reported).

    FZG type C gears at 200 N·m on the pinion, 1500 rpm, b = 14 mm, M320 oil at 75 °C (η = 46.23 mPa·s,
    X_L = 0.846), R_a = 0.6 µm (GEARpie's report C14 prints H_V = 0.1950 by Ohlendorf; its μ_mZ = 0.0483 and
    P_VZP = 295 W rest on a roughness it does not print):

    >>> from geardesign.gears.pair import GearPair
    >>> loss = mesh_loss(GearPair(4.5, 16, 24, 0.1817, 0.1715, face_width_mm=14), 200, 1500, 46.23, 0.6, 0.846)
    >>> round(loss.H_V, 4), round(loss.mu_mz, 4), round(loss.loss_w)
    (0.195, 0.0481, 294)
    """
    from ..validate import require_choice

    method = require_choice("method", method, H_V_METHODS)
    b = face_width_mm if face_width_mm is not None else pair.face_width_mm
    if b is None:
        raise GearDesignError("face_width_mm is needed for the mesh loss (give it to the pair or here), got None")
    # at least a micrometre: a subnormal width made the line load F_bt/b infinite and μ NaN (fuzz)
    b = one_number("face_width_mm", require_range("face_width_mm", b, 1e-3, 1e5, unit="mm"))
    T1 = one_number("torque1_nm", require_positive("torque1_nm", torque1_nm, "N·m"))
    n1 = one_number("n1_rpm", require_positive("n1_rpm", n1_rpm, "rpm"))
    eta = one_number("eta_mpas", require_positive("eta_mpas", eta_mpas, "mPa·s"))
    Ra = one_number("Ra_um", require_range("Ra_um", Ra_um, 0.01, 10.0, unit="µm"))
    X_L = one_number("lubricant_factor", require_range("lubricant_factor", lubricant_factor, 0.1, 3.0))
    g = pair.geometry()
    internal = bool(pair.internal)
    u = pair.z2 / pair.z1
    alpha_w = math.radians(float(g.alpha_w_deg))
    beta_b_deg = float(g.beta_b_deg)
    cos_bb = math.cos(math.radians(beta_b_deg))
    e1, e2 = (float(v) for v in tip_contact_ratios(g, internal))
    eps_beta = b * math.sin(math.radians(pair.beta_deg)) / (math.pi * pair.m)
    omega1 = n1 * math.pi / 30.0
    power = T1 * omega1
    v_t = omega1 * float(g.dw1) / 2000.0
    v_sum = 2.0 * v_t * math.sin(alpha_w)
    rho_c = float(g.dw1) / 2.0 * math.sin(alpha_w) * u / ((u - 1.0) if internal else (u + 1.0)) / cos_bb
    F_bt = 2000.0 * T1 / float(g.db1)
    mu = float(mean_friction_coefficient(F_bt / b, v_sum, rho_c, eta, Ra, X_L))
    hv_o = float(gear_loss_factor_ohlendorf(pair.z1, u, beta_b_deg, e1, e2, internal))
    hv = (gear_loss_factor_integrated(pair.z1, u, beta_b_deg, e1, e2, eps_beta, internal)
          if method == "integrated" else hv_o)
    return MeshLoss(power_w=power, mu_mz=mu, H_V=hv, H_V_ohlendorf=hv_o, loss_w=power * mu * hv, eps1=e1, eps2=e2,
                    v_t_m_s=v_t, v_sum_c_m_s=v_sum, rho_red_c_mm=rho_c, F_bt_n=F_bt, eta_mpas=eta, method=method)
