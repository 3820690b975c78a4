"""Efficiency of a cylindrical worm gear pair: sliding speed, coefficient of friction, friction angle,
mesh efficiency worm-driving and wheel-driving, self-locking, and the gearbox efficiency from its losses.

One function per formula, each with its source; every one takes numpy arrays (broadcast together).
Units at the interface: lengths in mm, speeds in rpm and m/s, angles in degrees (``_deg``), powers in W.

Sources (docs/worm_rating.md):

- the sliding speed at the mean (reference) cylinder v_g = d_m1·n1·π/(60000·cos γ_m): DIN 3996:2012 /
  ISO/TS 14521:2020 clause 6.3 (the kinematics of a worm: the worm's circumferential speed over cos γ_m);
- the worm pair as a screw and nut: η = tan γ_m / tan(γ_m + ρ'), η' = tan(γ_m − ρ')/tan γ_m with
  tan ρ' = μ/cos α_n — SDP/SI *Elements of Metric Gear Technology* eq. (16-21), (16-23) (written there as
  (cos α_n − μ tan γ)/(cos α_n + μ cot γ), the same number); DIN 3996 and Niemann-Winter write the tooth
  friction number μ_zm straight into ρ_z = arctan μ_zm, which is ``alpha_n_deg=0`` here;
- the coefficient of friction from the sliding speed for a case-hardened steel worm against a phosphor-bronze
  wheel: ANSI/AGMA 6034-B92 as Budynas-Nisbett, *Shigley's Mechanical Engineering Design*, eq. (15-38) print it;
- the mean tooth friction number of ISO/TS 14521 method B, μ_zm = μ_0T·Y_S·Y_G·Y_W·Y_R, with the factors given:
  the standard's curves for μ_0T and its factor formulas could not be read in a public text (docs say so);
- the gearbox efficiency from its losses η = (P1 − P_V)/P1, P_V = P_VZ + P_VL + P_V0 + P_VD (DIN 3996 eq. (1)
  as quoted by Oehler/Sauer et al., Gear Solutions, *Investigations on the efficiency of worm gear drives*).
"""
from __future__ import annotations

import math

import numpy as np

from ...errors import GearDesignError
from ...validate import require_positive, require_range

__all__ = ["FT_MIN_PER_M_S", "sliding_speed", "friction_angle_deg", "efficiency_worm_driving",
           "efficiency_wheel_driving", "self_locking", "friction_coefficient_agma", "tooth_friction_iso",
           "mesh_power_loss", "total_efficiency", "efficiency_at_speed"]

FT_MIN_PER_M_S = 60.0 / 0.3048          # 1 m/s in ft/min (the AGMA formula's unit)
GAMMA_RANGE_DEG = (0.0, 45.0)           # a worm's mean lead angle: (0, 45] degrees
MU_MAX = 1.0


def _gamma(gamma_m_deg):
    return require_range("gamma_m_deg", gamma_m_deg, *GAMMA_RANGE_DEG, lo_open=True, unit="deg")


def _mu(mu):
    return require_range("mu", mu, 0.0, MU_MAX, unit="")


def _alpha(alpha_n_deg):
    return require_range("alpha_n_deg", alpha_n_deg, 0.0, 45.0, hi_open=True, unit="deg")


def sliding_speed(d_m1, n1, gamma_m_deg):
    """Sliding speed v_g (m/s) at the worm's mean (reference) cylinder:
    v_g = d_m1·n1·π / (60000·cos γ_m), d_m1 in mm, n1 in rpm (DIN 3996:2012 / ISO/TS 14521 clause 6.3).

    A worm of d_m1 = 50 mm at 1500 rpm and γ_m = 5.711° (z1 = 1, q = 10): the worm's circumferential
    speed is 3.927 m/s, the sliding speed 1/cos γ_m times that:

    >>> round(float(sliding_speed(50.0, 1500.0, math.degrees(math.atan(0.1)))), 4)
    3.9466
    """
    d = require_positive("d_m1", d_m1, unit="mm")
    n = require_positive("n1", n1, unit="rpm")
    g = np.radians(_gamma(gamma_m_deg))
    return d * n * math.pi / (60000.0 * np.cos(g))


def friction_angle_deg(mu, alpha_n_deg=0.0):
    """Friction angle ρ' (degrees) of the worm pair: tan ρ' = μ / cos α_n.

    ``alpha_n_deg=0`` (the default) gives ρ' = arctan μ, the form of DIN 3996 / ISO/TS 14521, whose mean tooth
    friction number μ_zm already holds the flank inclination; a measured sliding-friction coefficient of the
    materials takes the normal pressure angle α_n (SDP/SI eq. (16-21)).

    >>> round(float(friction_angle_deg(0.12)), 4)      # Niemann-Winter III Beispiel 3: μ_zA = 0.12, ρ = 6.8428°
    6.8428
    """
    m = _mu(mu)
    a = np.radians(_alpha(alpha_n_deg))
    return np.degrees(np.arctan(m / np.cos(a)))


def efficiency_worm_driving(gamma_m_deg, mu, alpha_n_deg=0.0):
    """Mesh efficiency with the worm driving, η = tan γ_m / tan(γ_m + ρ'), tan ρ' = μ/cos α_n
    (SDP/SI eq. (16-21); DIN 3996 clause 7 with ``alpha_n_deg=0``).

    Niemann-Winter III Beispiel 3 (z1 = 1, d_m1 = 83.2 mm, m_x = 10.42 mm: γ_m = 7.138°), μ_z = 0.0261 prints
    η_z = 0.82 (as the DSoftCon report quotes it, tests/data/worm_efficiency_examples.md):

    >>> round(float(efficiency_worm_driving(math.degrees(math.atan(10.42 / 83.2)), 0.0261)), 2)
    0.82
    """
    g = np.radians(_gamma(gamma_m_deg))
    rho = np.radians(friction_angle_deg(mu, alpha_n_deg))
    if np.any(g + rho >= math.pi / 2):
        raise GearDesignError("gamma_m_deg + the friction angle must stay below 90 deg, got "
                              f"gamma_m_deg={np.degrees(g).max():g}, rho={np.degrees(rho).max():g}")
    return np.tan(g) / np.tan(g + rho)


def efficiency_wheel_driving(gamma_m_deg, mu, alpha_n_deg=0.0):
    """Mesh efficiency with the wheel driving the worm, η' = tan(γ_m − ρ')/tan γ_m (SDP/SI eq. (16-23)).

    Zero or negative where γ_m <= ρ': the wheel cannot turn the worm (self-locking), and the value says
    by how much the friction exceeds what the lead lets through. Niemann-Winter III Beispiel 3 prints
    η'_z = 0.79:

    >>> round(float(efficiency_wheel_driving(math.degrees(math.atan(10.42 / 83.2)), 0.0261)), 2)
    0.79
    """
    g = np.radians(_gamma(gamma_m_deg))
    rho = np.radians(friction_angle_deg(mu, alpha_n_deg))
    return np.tan(g - rho) / np.tan(g)


def self_locking(gamma_m_deg, mu, alpha_n_deg=0.0):
    """True where the wheel cannot drive the worm: γ_m <= ρ' (η' <= 0). With the static (starting)
    coefficient of friction this is static self-locking (the pair holds at rest); with the running μ at the
    sliding speed it is dynamic self-locking (the pair stops once the drive stops)."""
    g = _gamma(gamma_m_deg)
    return np.asarray(g <= friction_angle_deg(mu, alpha_n_deg))


def friction_coefficient_agma(v_g):
    """Coefficient of friction of a case-hardened steel worm on a phosphor-bronze wheel from the sliding
    speed v_g (m/s): ANSI/AGMA 6034-B92 as Shigley eq. (15-38) prints it with V_s in ft/min,

        f = 0.15 at V_s = 0; 0.124·exp(−0.074·V_s^0.645) for V_s <= 10 ft/min;
        0.103·exp(−0.110·V_s^0.450) + 0.012 above.

    This is the friction of the material pair, to be used with ``alpha_n_deg`` = α_n. It is not ISO/TS 14521
    method B (whose μ_0T curves were not found in a public text).

    At rest the source prints f = 0.15:

    >>> float(friction_coefficient_agma(0.0))
    0.15
    """
    v = require_range("v_g", v_g, 0.0, 100.0, unit="m/s")
    vs = v * FT_MIN_PER_M_S
    low = 0.124 * np.exp(-0.074 * vs ** 0.645)
    high = 0.103 * np.exp(-0.110 * vs ** 0.450) + 0.012
    return np.where(vs == 0.0, 0.15, np.where(vs <= 10.0, low, high))


def tooth_friction_iso(mu_0T, Y_S=1.0, Y_G=1.0, Y_W=1.0, Y_R=1.0):
    """Mean tooth friction number of ISO/TS 14521 method B, μ_zm = μ_0T·Y_S·Y_G·Y_W·Y_R: the friction number
    of the standard reference gear μ_0T times the size, geometry, material and roughness factors (each 1 for
    the reference gear). All five are taken as given: the standard's curves and factor formulas could not be
    read in a public text (docs/worm_rating.md)."""
    out = require_range("mu_0T", mu_0T, 0.0, MU_MAX, lo_open=True)
    for name, value in (("Y_S", Y_S), ("Y_G", Y_G), ("Y_W", Y_W), ("Y_R", Y_R)):
        out = out * require_range(name, value, 0.1, 10.0)
    return out


def mesh_power_loss(P2, eta_z):
    """Load-dependent mesh loss P_VZ (W) of a pair delivering P2 (W) at mesh efficiency η_z:
    P_VZ = P2·(1/η_z − 1) (the mesh takes P2/η_z in)."""
    p2 = require_range("P2", P2, 0.0, 1e9, unit="W")
    e = require_range("eta_z", eta_z, 0.0, 1.0, lo_open=True)
    return p2 * (1.0 / e - 1.0)


def total_efficiency(P2, eta_z, P_V0=0.0, P_VL=0.0, P_VD=0.0):
    """Gearbox efficiency η = P2/(P2 + P_V), P_V = P_VZ + P_VL + P_V0 + P_VD (DIN 3996 eq. (1)): the mesh
    loss from η_z and the given no-load (churning, P_V0), load-dependent bearing (P_VL) and seal (P_VD)
    losses in W. ISO/TS 14521's formulas for P_V0 and P_VL could not be read in a public text; give them
    from a measurement or a bearing calculation (geardesign.drives.bearing_friction).

    >>> round(float(total_efficiency(1000.0, 0.9, P_V0=20.0, P_VL=10.0)), 4)
    0.8763
    """
    p2 = require_range("P2", P2, 0.0, 1e9, lo_open=True, unit="W")
    losses = mesh_power_loss(p2, eta_z)
    for name, value in (("P_V0", P_V0), ("P_VL", P_VL), ("P_VD", P_VD)):
        losses = losses + require_range(name, value, 0.0, 1e9, unit="W")
    return p2 / (p2 + losses)


def efficiency_at_speed(d_m1, n1, gamma_m_deg, alpha_n_deg=20.0, mu=None):
    """The worm-driving mesh efficiency at a worm speed, over arrays (for a drive's power flow or a sweep):
    v_g from :func:`sliding_speed`, μ given or from :func:`friction_coefficient_agma` at v_g, η_z from
    :func:`efficiency_worm_driving` with α_n. Returns ``(v_g, mu, eta_z)``, each broadcast over the inputs.

    With a given μ it is :func:`efficiency_worm_driving` (Niemann-Winter III Beispiel 3's tooth friction with
    α_n = 0 prints η_z = 0.82):

    >>> round(float(efficiency_at_speed(83.2, 1500.0, math.degrees(math.atan(10.42 / 83.2)), 0.0, 0.0261)[2]), 2)
    0.82
    """
    v = sliding_speed(d_m1, n1, gamma_m_deg)
    m = friction_coefficient_agma(v) if mu is None else np.broadcast_to(_mu(mu), np.shape(v)) * 1.0
    return v, m, efficiency_worm_driving(gamma_m_deg, m, alpha_n_deg)
