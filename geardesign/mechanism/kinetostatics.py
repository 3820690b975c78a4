"""Kinetostatics of one slider-crank at constant crank speed: the force in every joint and the balancing torque, by
the force plans of the Assur group (rod + piston) and the crank (d'Alembert's principle), and the same torque by
virtual power — the analytic form of Zhukovsky's lever.

The frame and signs are those of :mod:`geardesign.mechanism.kinematics` (y along the cylinder towards the head,
moments positive in the sense of rotation). Forces on the piston: the gas force F_g (towards the crank), its weight
and its inertia force −m_p·a_B; on the rod: its weight and inertia force −m_r·a_S at S and its inertia couple
−J_S·ε_r; on the crank: its weight and inertia force at its centre of gravity. Joints (seed 000 §5 numbers the
links frame 0, crank 1, rod 2, piston 3; the seeds write R_ij for the force of link i on link j):

- R03: the cylinder wall on the piston (normal, along x; no friction);
- R23: the rod on the piston, at the piston pin B;
- R12: the crank on the rod, at the crank pin A;
- R01: the main bearing on the crank, at O (the balancing load taken as a couple, no gear force).

The driving torque M (the crankshaft's torque, positive in the power stroke: the torque the mechanism puts on the
shaft in the sense of rotation) is the moment of −R12 and of the crank's weight about O; the seeds' balancing
torque is T_y = −M. The virtual-power balance (Zhukovsky's lever, seed 003 §2.7) gives the same torque without any
joint force: M·ω = Σ F_k·v_k + Σ M_k·ω_k over every force and couple on the moving links.

References: Artobolevsky 1988 §§13-15 (kinetostatics of Assur groups, Zhukovsky's lever); Kolchin & Demidov 1980
§10 (forces in the crank mechanism of an engine).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import GearDesignError
from ..results import Result, short_value
from ..validate import broadcast_inputs, one_number, require_finite, require_range
from .kinematics import MM, State, cg_acceleration, crank_speed, piston_velocity, state
from .slider_crank import SliderCrank

__all__ = ["JointForces", "joint_forces", "forces_from_state", "virtual_power_torque", "piston_force_torque",
           "GRAVITY_M_S2"]

GRAVITY_M_S2 = 9.80665     # standard gravity (ISO 80000-3)
# |F_g| at most 10 GN: a 1 m bore at 30 MPa (the largest two-stroke diesels) is 24 MN, the largest mechanical press
# 0.2 GN. Near the dead point (l/r → 1) the joint forces grow as F_g/cos β_max: an unbounded F_g (1e308 N)
# overflowed them to inf − inf = NaN (fuzz)
GAS_FORCE_MAX_N = 1e10


def _gravity(gravity_m_s2, axis_tilt_deg):
    """The gravity vector (x, y) in the cylinder's frame: the cylinder axis tilted ``axis_tilt_deg`` from the
    upward vertical in the sense of rotation (0: an upright cylinder, weights along −y)."""
    g = one_number("gravity_m_s2", require_range("gravity_m_s2", gravity_m_s2, 0.0, 100.0, unit="m/s²"))
    tau = np.radians(one_number("axis_tilt_deg", require_range("axis_tilt_deg", axis_tilt_deg, -360.0, 360.0)))
    return -g * np.sin(tau), -g * np.cos(tau)


@dataclass(frozen=True, repr=False)
class JointForces(Result):
    """The forces of :func:`joint_forces` at each crank angle (arrays, N and N·m; x, y in the cylinder's frame).

    ``torque_nm`` is the driving torque M on the crankshaft, ``balancing_torque_nm`` the seeds' T_y = −M."""

    crank_angle_deg: np.ndarray
    gas_force_n: np.ndarray
    piston_inertia_n: np.ndarray         # −m_p·a_B along y
    rod_inertia_x_n: np.ndarray          # −m_r·a_S
    rod_inertia_y_n: np.ndarray
    rod_inertia_moment_nm: np.ndarray    # −J_S·ε_r about z
    wall_n: np.ndarray                   # R03 (x)
    piston_pin_x_n: np.ndarray           # R23: the rod on the piston
    piston_pin_y_n: np.ndarray
    crank_pin_x_n: np.ndarray            # R12: the crank on the rod
    crank_pin_y_n: np.ndarray
    main_bearing_x_n: np.ndarray         # R01: the frame on the crank
    main_bearing_y_n: np.ndarray
    torque_nm: np.ndarray                # M, driving
    success: bool = True

    @property
    def balancing_torque_nm(self) -> np.ndarray:
        """T_y = −M: the torque the load (the gear) puts on the crank (seed 000 §5.2.3)."""
        return -self.torque_nm

    def table(self):
        """One row per crank angle, a column per force (N) and torque (N·m)."""
        import pandas as pd

        names = [f for f in self.__dataclass_fields__ if f != "success"]
        out = pd.DataFrame({f: np.atleast_1d(getattr(self, f)) for f in names})
        out["balancing_torque_nm"] = -out["torque_nm"]
        return out

    def to_frame(self):
        return self.table()

    def __repr__(self) -> str:
        t = np.atleast_1d(self.torque_nm)
        return (f"JointForces({t.size} crank angles; torque {t.min():.6g} … {t.max():.6g} N·m; crank pin force up to "
                f"{np.hypot(self.crank_pin_x_n, self.crank_pin_y_n).max():.6g} N; "
                f"phi {short_value(np.atleast_1d(self.crank_angle_deg))})")


def joint_forces(mechanism: SliderCrank, crank_angle_deg, n_rpm, gas_force_n=0.0, *, gravity_m_s2=GRAVITY_M_S2,
                 axis_tilt_deg=0.0) -> JointForces:
    """The force in every joint and the driving torque of one slider-crank by kinetostatics (the force plans of
    seed 000 §5.2 and seed 003 §2.6, as equations): first the Assur group rod + piston (5 equations: the piston's
    forces along x and y, the rod's forces, the rod's moments about the crank pin A), then the crank.

    With d = B − A and Q the moment about A of the rod's weight, inertia force and inertia couple:

        R23_y = F_g − G_py − Φ_p (the piston along y),   d × R23 = Q (the rod about A),   R03 = −R23_x − G_px,
        R12 = R23 − G_r − Φ_r,   M = A × (−R12) + S_c × G_c,   R01 = R12 − G_c − Φ_c.

    ``gas_force_n`` (N, towards the crank; :func:`~geardesign.mechanism.pressure.gas_force`) broadcasts against the
    crank angles (degrees).

    >>> mech = SliderCrank(70, 250, rod_cg_mm=75, piston_mass_kg=2.0, rod_mass_kg=4.7, rod_inertia_kg_m2=0.03)
    >>> f = joint_forces(mech, [90.0], 1700, 10000.0, gravity_m_s2=0)
    >>> round(float(f.torque_nm[0]), 6) == round(float(virtual_power_torque(mech, [90.0], 1700, 10000.0,
    ...                                                                        gravity_m_s2=0)[0]), 6)
    True
    """
    phi_deg, fg, st, gx, gy = _inputs(mechanism, crank_angle_deg, n_rpm, gas_force_n, gravity_m_s2, axis_tilt_deg)
    return forces_from_state(mechanism, phi_deg, st, fg, gx, gy)


def _inputs(mech, crank_angle_deg, n_rpm, gas_force_n, gravity_m_s2, axis_tilt_deg):
    if not isinstance(mech, SliderCrank):
        raise GearDesignError(f"mechanism must be a SliderCrank, got {type(mech).__name__}")
    phi_deg = require_finite("crank_angle_deg", crank_angle_deg).astype(float)
    fg = require_range("gas_force_n", gas_force_n, -GAS_FORCE_MAX_N, GAS_FORCE_MAX_N, unit="N")
    phi_deg, fg = (a.astype(float) for a in broadcast_inputs(crank_angle_deg=phi_deg, gas_force_n=fg))
    gx, gy = _gravity(gravity_m_s2, axis_tilt_deg)
    # one speed for the whole cycle (an array would broadcast against the angles, or not at all)
    omega = crank_speed(one_number("n_rpm", require_finite("n_rpm", n_rpm)))
    st = state(np.radians(phi_deg), mech.crank_radius_mm, mech.rod_length_mm, mech.offset_mm, omega)
    return phi_deg, fg, st, gx, gy


def forces_from_state(mech: SliderCrank, phi_deg, st: State, fg, gx: float, gy: float) -> JointForces:
    """:func:`joint_forces` from a kinematic :class:`~geardesign.mechanism.kinematics.State` (unchecked inputs)."""
    r, l_ = mech.crank_radius_mm * MM, mech.rod_length_mm * MM
    mp, mr, mc, js = mech.piston_mass_kg, mech.rod_mass_kg, mech.crank_mass_kg, mech.rod_inertia_kg_m2
    k = mech.rod_cg_mm / mech.rod_length_mm
    ax, ay = -r * st.sin_phi, r * st.cos_phi                    # the crank pin A
    dx, dy = l_ * st.sin_beta, l_ * st.cos_beta                 # B − A
    asx, asy = cg_acceleration(st, mech.crank_radius_mm, k)
    phi_p = mp * st.a                                           # −m_p·a_B along y (a_B = (0, −s̈))
    rix, riy = -mr * asx, -mr * asy
    rim = js * st.beta_ddot                                     # −J_S·ε_r, ε_r = −β̈ about z
    # the piston: R23 + R03·x̂ + (0, −F_g) + m_p·g + Φ_p = 0
    r23y = fg - mp * gy - phi_p
    # the rod about A: (B − A) × (−R23) + (S − A) × (G_r + Φ_r) + M_Φ = 0
    frx, fry = mr * gx + rix, mr * gy + riy
    q = k * (dx * fry - dy * frx) + rim
    r23x = (dx * r23y - q) / dy
    r03 = -r23x - mp * gx
    # the rod's forces: R12 − R23 + G_r + Φ_r = 0
    r12x, r12y = r23x - frx, r23y - fry
    # the crank about O: A × (−R12) + S_c × G_c (its inertia force is centripetal: no moment)
    kc = mech.crank_cg_mm / mech.crank_radius_mm
    torque = -(ax * r12y - ay * r12x) + mc * kc * (ax * gy - ay * gx)
    w2 = st.omega * st.omega
    r01x = r12x - mc * gx - mc * kc * w2 * ax                   # − G_c − Φ_c, Φ_c = m_c·ω²·S_c outward
    r01y = r12y - mc * gy - mc * kc * w2 * ay
    return JointForces(phi_deg, fg, phi_p, rix, riy, rim, r03, r23x, r23y, r12x, r12y, r01x, r01y, torque)


def virtual_power_torque(mechanism: SliderCrank, crank_angle_deg, n_rpm, gas_force_n=0.0, *, gravity_m_s2=GRAVITY_M_S2,
                         axis_tilt_deg=0.0) -> np.ndarray:
    """The driving torque M (N·m) by virtual power, the analytic form of Zhukovsky's lever (seed 003 §2.7;
    Artobolevsky 1988 §15): M·ω + T_y·ω = 0 and

        M·ω = F_gas·v_B + Σ (G_k + Φ_k)·v_k + M_Φ·ω_r,

    summed over the piston (at B), the rod (at S, and its inertia couple at the rod's angular velocity ω_r) and the
    crank's weight at its centre of gravity — no joint force appears. Vectorised over the crank angles (degrees).
    """
    mech = mechanism
    phi_deg, fg, st, gx, gy = _inputs(mech, crank_angle_deg, n_rpm, gas_force_n, gravity_m_s2, axis_tilt_deg)
    r = mech.crank_radius_mm * MM
    mp, mr, mc, js = mech.piston_mass_kg, mech.rod_mass_kg, mech.crank_mass_kg, mech.rod_inertia_kg_m2
    k = mech.rod_cg_mm / mech.rod_length_mm
    # the velocities per unit crank speed (v/ω, m): M = Σ F·v/ω without dividing by an ω that may underflow to 0
    # (n = 5e-324 rpm gave 0/0) or multiplying by one that is large
    vax, vay = -r * st.cos_phi, -r * st.sin_phi              # ẑ × A, A = r·(−sin φ, cos φ)
    vby = -r * (st.sin_phi * st.cos_beta + st.cos_phi * st.sin_beta) / st.cos_beta   # v_B/ω = (0, −ṡ/ω)
    vsx, vsy = (1.0 - k) * vax, (1.0 - k) * vay + k * vby
    asx, asy = cg_acceleration(st, mech.crank_radius_mm, k)
    # the piston (gas force (0, −F_g), weight, inertia (0, m_p·s̈)): it moves along y only
    torque = (-fg + mp * gy + mp * st.a) * vby
    # the rod: weight and inertia force at S; inertia couple −J_S·ε_r at ω_r = −β̇ (ε_r = −β̈)
    lam = mech.crank_radius_mm / mech.rod_length_mm
    torque = torque + (mr * gx - mr * asx) * vsx + (mr * gy - mr * asy) * vsy + (js * st.beta_ddot) * (
        -lam * st.cos_phi / st.cos_beta)                    # ω_r/ω = −β̇/ω
    # the crank: its weight at S_c = (ρ_c/r)·A (its inertia force is normal to the path)
    kc = mech.crank_cg_mm / mech.crank_radius_mm
    return torque + mc * kc * (gx * vax + gy * vay)          # Σ F·v/ω = M


def piston_force_torque(force_n, crank_angle_deg, crank_radius_mm, rod_length_mm, offset_mm=0.0) -> np.ndarray:
    """Torque on the crank of a force F along the cylinder axis on the piston (towards the crank), in the sense of
    rotation: M = F·r·sin(φ + β)/cos β (N·m; r in mm). Kolchin & Demidov 1980 §10.1, eq. for the tangential force
    T = F·sin(φ + β)/cos β; the classic engine torque of the gas and the reciprocating masses.

    >>> round(float(piston_force_torque(10000.0, 90, 70, 250)), 6)   # at φ = 90°: F·r
    700.0
    """
    f = require_finite("force_n", force_n)
    # M = F·v_B/ω: the piston's speed at ω = 1 rad/s (n = 30/π rpm) is the lever arm in m
    return f * piston_velocity(crank_angle_deg, crank_radius_mm, rod_length_mm, 30.0 / np.pi, offset_mm)
