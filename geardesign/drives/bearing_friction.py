"""Frictional moment and power loss of rolling bearings after the SKF model (2004; as printed in SKF
*General Catalogue* 6000/I EN (2008) and *Rolling bearings* PUB BU/P1 10000/1 EN (2013), chapter
"Friction", "The SKF model for calculating the frictional moment", Tables 2a/2b and eqs. for φ_ish, φ_rs,
μ_sl).

M = M_rr + M_sl (+ M_seal + M_drag), in N·mm:

- rolling M_rr = φ_ish·φ_rs·G_rr·(ν·n)^0.6 with the inlet shear heating reduction
  φ_ish = 1/(1 + 1.84e-9·(n·d_m)^1.28·ν^0.64) and the kinematic replenishment/starvation reduction
  φ_rs = exp(−K_rs·ν·n·(d + D)·√(K_z/(2(D − d)))), K_rs = 3e-8 (low-level oil bath, oil jet) or 6e-8
  (grease, oil-air), K_z = 3.1 for deep groove ball bearings;
- sliding M_sl = G_sl·μ_sl, μ_sl = φ_bl·μ_bl + (1 − φ_bl)·μ_EHL, φ_bl = exp(−2.6e-8·(n·ν)^1.4·d_m);
- deep groove ball bearings (Table 2a): F_a = 0: G_rr = R1·d_m^1.96·F_r^0.54, G_sl = S1·d_m^−0.26·F_r^(5/3);
  F_a > 0: G_rr = R1·d_m^1.96·(F_r + R2/sin α_F·F_a)^0.54,
  G_sl = S1·d_m^−0.145·(F_r^5 + S2·d_m^1.5/sin α_F·F_a^4)^(1/3), α_F = 24.6·(F_a/C_0)^0.24 degrees.

The geometry constants R1, R2, S1, S2 of the series 62 and 63 (Table 2b) are in :data:`SKF_CONSTANTS`, read in a
public restatement of SKF's table (docs/efficiency.md says which sources were and were not read). Not
modelled: the seals' moment M_seal (the catalog rows are open bearings) and the drag loss M_drag of a
bearing dipping in an oil bath (it needs the oil level and SKF's drag diagram); other bearing types (angular
contact, cylindrical roller: their constants were not read in a public text). Units: n in rpm, ν in mm²/s
(at the operating temperature), d, D, d_m in mm, forces in N.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from ..errors import GearDesignError
from ..results import Result
from ..renamed import renamed_keywords
from ..validate import one_number, require_choice, require_range

__all__ = ["SKF_CONSTANTS", "K_RS", "K_Z_DEEP_GROOVE", "inlet_shear_heating_factor", "replenishment_factor",
           "load_angle_deg", "rolling_frictional_variable", "sliding_frictional_variable",
           "sliding_friction_coefficient", "rolling_frictional_moment", "frictional_power_w",
           "bearing_friction", "BearingFriction"]

# SKF Table 2b, deep groove ball bearings: series -> (R1, R2, S1, S2)
SKF_CONSTANTS = {"62": (3.9e-7, 1.7, 3.23e-3, 36.5), "63": (3.7e-7, 1.7, 2.84e-3, 92.8)}
K_RS = {"oil_jet": 3e-8, "oil_bath": 3e-8, "grease": 6e-8, "oil_air": 6e-8}
K_Z_DEEP_GROOVE = 3.1
# The boundary and full-film friction coefficients of μ_sl, as the restatement we read takes them: μ_bl = 0.12 and
# μ_EHL = 0.05 (it notes SKF's online calculator takes 0.05, and itself uses 0.04); both depend on the oil (its
# additives, mineral or synthetic base) and can be given
MU_BL = 0.12
MU_EHL = 0.05


def inlet_shear_heating_factor(n_rpm, dm_mm, nu_mm2s):
    """φ_ish = 1/(1 + 1.84e-9·(n·d_m)^1.28·ν^0.64) (SKF 10000/1 EN, "Inlet shear heating reduction factor").

    >>> round(float(inlet_shear_heating_factor(0.0, 50.0, 100.0)), 9)
    1.0
    """
    n, dm, nu = (np.asarray(v, dtype=float) for v in (n_rpm, dm_mm, nu_mm2s))
    return 1.0 / (1.0 + 1.84e-9 * (n * dm) ** 1.28 * nu ** 0.64)


def replenishment_factor(n_rpm, nu_mm2s, d_mm, D_mm, K_rs=3e-8, K_z=K_Z_DEEP_GROOVE):
    """φ_rs = exp(−K_rs·ν·n·(d + D)·√(K_z/(2(D − d)))) (SKF 10000/1 EN, "Kinematic replenishment/starvation
    reduction factor"), K_rs = 3e-8 oil bath/oil jet, 6e-8 grease/oil-air; K_z = 3.1 deep groove ball.

    >>> round(float(replenishment_factor(0.0, 100.0, 40.0, 80.0)), 9)
    1.0
    """
    n, nu, d, D = (np.asarray(v, dtype=float) for v in (n_rpm, nu_mm2s, d_mm, D_mm))
    return np.exp(-np.asarray(K_rs, dtype=float) * nu * n * (d + D) * np.sqrt(np.asarray(K_z) / (2.0 * (D - d))))


def load_angle_deg(F_a_n, C0_n):
    """α_F = 24.6·(F_a/C_0)^0.24 degrees, the load angle of a deep groove ball bearing under an axial load
    (SKF 10000/1 EN Table 2a).

    >>> round(float(load_angle_deg(1.0, 1.0)), 9)
    24.6
    """
    return 24.6 * (np.asarray(F_a_n, dtype=float) / np.asarray(C0_n, dtype=float)) ** 0.24


@renamed_keywords(fr_n="F_r_n", fa_n="F_a_n")
def rolling_frictional_variable(R1, R2, dm_mm, F_r_n, F_a_n=0.0, C0_n=None):
    """G_rr of a deep groove ball bearing (SKF 10000/1 EN Table 2a): R1·d_m^1.96·F_r^0.54 without axial load,
    R1·d_m^1.96·(F_r + R2/sin α_F·F_a)^0.54 with it.

    >>> round(float(rolling_frictional_variable(1.0, 1.7, 1.0, 1.0)), 9)
    1.0
    """
    dm, Fr, Fa = (np.asarray(v, dtype=float) for v in (dm_mm, F_r_n, F_a_n))
    with np.errstate(divide="ignore", invalid="ignore"):
        s = np.sin(np.radians(load_angle_deg(Fa, C0_n))) if C0_n is not None else np.ones_like(Fa)
        extra = np.where(Fa > 0, R2 / s * Fa, 0.0)
    return R1 * dm ** 1.96 * (Fr + extra) ** 0.54


@renamed_keywords(fr_n="F_r_n", fa_n="F_a_n")
def sliding_frictional_variable(S1, S2, dm_mm, F_r_n, F_a_n=0.0, C0_n=None):
    """G_sl of a deep groove ball bearing (SKF 10000/1 EN Table 2a): S1·d_m^−0.26·F_r^(5/3) without axial
    load, S1·d_m^−0.145·(F_r^5 + S2·d_m^1.5/sin α_F·F_a^4)^(1/3) with it.

    >>> round(float(sliding_frictional_variable(1.0, 36.5, 1.0, 8.0)), 9)
    32.0
    """
    dm, Fr, Fa = (np.asarray(v, dtype=float) for v in (dm_mm, F_r_n, F_a_n))
    with np.errstate(divide="ignore", invalid="ignore"):
        s = np.sin(np.radians(load_angle_deg(Fa, C0_n))) if C0_n is not None else np.ones_like(Fa)
        axial = S1 * dm ** -0.145 * (Fr ** 5 + S2 * dm ** 1.5 / s * Fa ** 4) ** (1.0 / 3.0)
    return np.where(Fa > 0, axial, S1 * dm ** -0.26 * Fr ** (5.0 / 3.0))


def sliding_friction_coefficient(n_rpm, nu_mm2s, dm_mm, mu_bl=MU_BL, mu_ehl=MU_EHL):
    """μ_sl = φ_bl·μ_bl + (1 − φ_bl)·μ_EHL with φ_bl = exp(−2.6e-8·(n·ν)^1.4·d_m) (SKF 10000/1 EN): boundary
    friction at standstill, full-film friction at speed.

    >>> round(float(sliding_friction_coefficient(0.0, 100.0, 50.0)), 9)
    0.12
    """
    n, nu, dm = (np.asarray(v, dtype=float) for v in (n_rpm, nu_mm2s, dm_mm))
    phi_bl = np.exp(-2.6e-8 * (n * nu) ** 1.4 * dm)
    return phi_bl * mu_bl + (1.0 - phi_bl) * mu_ehl


def rolling_frictional_moment(G_rr, n_rpm, nu_mm2s, phi_ish=1.0, phi_rs=1.0):
    """M_rr = φ_ish·φ_rs·G_rr·(ν·n)^0.6 in N·mm (SKF 10000/1 EN).

    >>> round(float(rolling_frictional_moment(2.0, 1000.0, 1000.0)), 6)
    7962.143411
    """
    return (np.asarray(phi_ish) * np.asarray(phi_rs) * np.asarray(G_rr, dtype=float)
            * (np.asarray(nu_mm2s, dtype=float) * np.asarray(n_rpm, dtype=float)) ** 0.6)


def frictional_power_w(M_nmm, n_rpm):
    """Power lost to a frictional moment, N_R = 1.047e-4·M·n in W with M in N·mm and n in rpm (SKF
    10000/1 EN, "Frictional power loss": M·2πn/60 / 1000).

    >>> round(float(frictional_power_w(1000.0, 1000.0)), 4)
    104.7198
    """
    return np.asarray(M_nmm, dtype=float) * np.asarray(n_rpm, dtype=float) * math.pi / 30.0 / 1000.0


@dataclass(frozen=True)
class BearingFriction(Result):
    """Frictional moments (N·mm) and power loss (W) of one bearing (see :func:`bearing_friction`)."""

    designation: str
    n_rpm: float
    F_r_n: float
    F_a_n: float
    nu_mm2s: float
    dm_mm: float
    M_rr_nmm: float
    M_sl_nmm: float
    M_nmm: float
    power_loss_w: float
    lubrication: str

    _success_field = "finite"

    @property
    def finite(self) -> bool:
        return math.isfinite(self.M_nmm)

    def __repr__(self) -> str:
        return (f"BearingFriction({self.designation} at {self.n_rpm:.6g} rpm, ν = {self.nu_mm2s:.4g} mm²/s: "
                f"M = {self.M_nmm:.4g} N·mm (rolling {self.M_rr_nmm:.4g}, sliding {self.M_sl_nmm:.4g}), "
                f"{self.power_loss_w:.4g} W)")


@lru_cache(maxsize=1)
def _catalog_rows() -> dict:
    """designation -> (series, d, D, C0 in N) of the bundled rows of the modelled series, read once: a drive
    search asks for the same few bearings many times, and a pandas lookup per call costs ~0.5 ms."""
    from .bearing import bearing_catalog

    rows = bearing_catalog(list(SKF_CONSTANTS))
    return {str(r.designation): (str(r.series), float(r.d_mm), float(r.D_mm), 1000.0 * float(r.C0_kn))
            for r in rows.itertuples()}


def _catalog_row(designation: str):
    rows = _catalog_rows()
    if str(designation) not in rows:
        have = list(rows)
        raise GearDesignError(f"bearing must be a deep groove ball bearing of series {', '.join(SKF_CONSTANTS)} "
                              f"({have[0]} ... {have[-1]}) for the friction model, got {designation!r}")
    return rows[str(designation)]


@renamed_keywords(fr_n="F_r_n", fa_n="F_a_n")
def bearing_friction(designation, F_r_n, F_a_n, n_rpm, nu_mm2s, lubrication="oil_jet", mu_bl=MU_BL,
                     mu_ehl=MU_EHL) -> BearingFriction:
    """Frictional moment and power loss of the catalog bearing ``designation`` (a deep groove ball bearing of
    series 62 or 63; d, D and C0 from its catalog row) under F_r and F_a (N) at ``n_rpm`` with the oil's
    kinematic viscosity ``nu_mm2s`` at the operating temperature, after the SKF model (module docstring).
    ``lubrication``: "oil_jet", "oil_bath" (low level; the drag loss of a deep bath is not modelled),
    "grease" (ν of the base oil), "oil_air".

    >>> f = bearing_friction("6208", 2000.0, 0.0, 1500.0, 68.0)
    >>> f.M_nmm > f.M_rr_nmm > f.M_sl_nmm > 0
    True
    """
    lubrication = require_choice("lubrication", lubrication, tuple(K_RS))
    Fr = one_number("F_r_n", require_range("F_r_n", F_r_n, 0.0, 1e8, unit="N"))
    Fa = one_number("F_a_n", require_range("F_a_n", F_a_n, 0.0, 1e8, unit="N"))
    if Fr == 0.0 and Fa == 0.0:
        raise GearDesignError("F_r_n and F_a_n must not both be 0 (the SKF model needs a load), got 0 and 0")
    n = one_number("n_rpm", require_range("n_rpm", n_rpm, 0.0, 1e6, lo_open=True, unit="rpm"))
    nu = one_number("nu_mm2s", require_range("nu_mm2s", nu_mm2s, 1.0, 1e5, unit="mm²/s"))
    for name, v in (("mu_bl", mu_bl), ("mu_ehl", mu_ehl)):
        require_range(name, v, 0.0, 1.0)
    series, d, D, C0 = _catalog_row(designation)
    R1, R2, S1, S2 = SKF_CONSTANTS[series]
    dm = (d + D) / 2.0
    G_rr = rolling_frictional_variable(R1, R2, dm, Fr, Fa, C0)
    G_sl = sliding_frictional_variable(S1, S2, dm, Fr, Fa, C0)
    M_rr = float(rolling_frictional_moment(G_rr, n, nu, inlet_shear_heating_factor(n, dm, nu),
                                           replenishment_factor(n, nu, d, D, K_RS[lubrication])))
    M_sl = float(G_sl * sliding_friction_coefficient(n, nu, dm, mu_bl, mu_ehl))
    M = M_rr + M_sl
    return BearingFriction(designation=str(designation), n_rpm=n, F_r_n=Fr, F_a_n=Fa, nu_mm2s=nu, dm_mm=dm,
                           M_rr_nmm=M_rr, M_sl_nmm=M_sl, M_nmm=M, power_loss_w=float(frictional_power_w(M, n)),
                           lubrication=lubrication)
