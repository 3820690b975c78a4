"""Exact kinematics of the slider-crank (central or offset) at constant crank speed, vectorised over the crank angle.

The frame: the crank turns about O; the y axis runs along the cylinder from O towards the cylinder head, the
x axis so that the crank turns counter-clockwise (a moment about z is positive in the sense of rotation). The
crank angle φ is measured from the cylinder axis in the sense of rotation (top dead centre of a central
mechanism); the crank pin A is at r·(−sin φ, cos φ). The piston pin B runs on the line x = −e (the offset e is
positive towards the side the crank pin moves into during the first half-turn). The rod angle β is the rod's
angle from the cylinder axis, B − A = l·(sin β, cos β), so that

    sin β = (r·sin φ − e) / l                                                 (Artobolevsky 1988, §4; Kolchin & Demidov 1980, §9.1)

and every other quantity follows by differentiating the closed loop r·cos φ + l·cos β = y_B at dφ/dt = ω. Units at
the interface: lengths mm, speeds m/s, accelerations m/s², angular speeds rad/s, angular accelerations rad/s²,
angles in degrees. The seeds' course work checks these against its velocity plan (seed 000 §5.3.3).

References: I. I. Artobolevsky, *Теория механизмов и машин*, Nauka 1988, §4 (kinematics of the crank-slider);
A. I. Kolchin, V. P. Demidov, *Расчёт автомобильных и тракторных двигателей*, Vysshaya shkola 1980, §9.1 (the
exact and the approximate piston kinematics); J. B. Heywood, *Internal Combustion Engine Fundamentals*, McGraw-Hill
1988, §2.2 (piston position and speed).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import GearDesignError
from ..validate import one_number, require_finite, require_positive, require_range

__all__ = ["crank_speed", "rod_angle_deg", "piston_position", "piston_displacement", "piston_velocity",
           "piston_acceleration", "rod_angular_velocity", "rod_angular_acceleration", "crank_pin_acceleration",
           "rod_cg_acceleration", "check_lengths", "State", "state", "cg_acceleration"]

MM = 1e-3   # mm -> m: lengths come in mm, speeds go out in m/s
LENGTH_RANGE_MM = (1e-3, 1e5)    # a crank's and a rod's length, mm: 1 µm to 100 m (a rod of 1e38 mm is as long as
# the crank's stroke is lost in its last bit: s(φ) = r + l − x rounds to 0 and the cycle's volumes to 0/0)
SPEED_RANGE_RPM = (0.0, 1e5)     # a crankshaft's speed, rpm (above, ω² overflows nothing but is no engine)


def check_lengths(crank_radius_mm, rod_length_mm, offset_mm=0.0) -> tuple[float, float, float]:
    """(r, l, e) as floats, checked: r > 0 and l > r + |e| (else the rod cannot follow the crank all round:
    the mechanism locks where |r·sin φ − e| reaches l).

    >>> check_lengths(70, 60)
    Traceback (most recent call last):
    ...
    geardesign.errors.GearDesignError: rod_length_mm must exceed crank_radius_mm + |offset_mm| = 70 mm (l/r > 1), got 60
    """
    r = one_number("crank_radius_mm", require_range("crank_radius_mm", crank_radius_mm, *LENGTH_RANGE_MM, unit="mm"))
    l_ = one_number("rod_length_mm", require_range("rod_length_mm", rod_length_mm, *LENGTH_RANGE_MM, unit="mm"))
    e = one_number("offset_mm", require_range("offset_mm", offset_mm, -LENGTH_RANGE_MM[1], LENGTH_RANGE_MM[1],
                                              unit="mm"))
    if not l_ > r + abs(e):
        raise GearDesignError(f"rod_length_mm must exceed crank_radius_mm + |offset_mm| = {r + abs(e):g} mm "
                              f"(l/r > 1), got {l_:g}")
    return r, l_, e


def crank_speed(n_rpm) -> np.ndarray:
    """Angular speed of the crank, ω = π·n/30 (rad/s) for n in rpm.

    >>> round(float(crank_speed(1700)), 3)       # seed 000 §5.3.3 prints 177.9 (with π = 3.14)
    178.024
    """
    return math.pi * require_range("n_rpm", n_rpm, *SPEED_RANGE_RPM, lo_open=True, unit="rpm") / 30.0


@dataclass(frozen=True, slots=True)
class State:
    """Every kinematic quantity of the slider-crank at the crank angles, from one pass (SI units: m, m/s, m/s²,
    rad/s, rad/s²)."""

    sin_phi: np.ndarray
    cos_phi: np.ndarray
    sin_beta: np.ndarray
    cos_beta: np.ndarray
    y_b: np.ndarray          # piston pin from the crank axis, m
    v: np.ndarray            # ds/dt, m/s (away from the head)
    a: np.ndarray            # d²s/dt², m/s²
    beta_dot: np.ndarray     # dβ/dt, rad/s
    beta_ddot: np.ndarray    # d²β/dt², rad/s²
    omega: float             # the crank's ω, rad/s


def state(phi, r, l_, e, omega) -> State:
    """The kinematics at crank angles ``phi`` (radians) for r, l, e in mm and ω in rad/s, unchecked: the formulas
    of the functions below, computed once (Artobolevsky 1988 §4; Kolchin & Demidov 1980 §9.1)."""
    sp, cp = np.sin(phi), np.cos(phi)
    y = r * sp - e
    sb = y / l_                                  # sin β = (r·sin φ − e)/l
    # cos² β = (1 − s)(1 + s) = (l − y)(l + y)/l²: the differences of lengths, not 1 − s after s was rounded
    # (near the dead point of l/r → 1, 1 − r/l loses the digits its rounding had: 1e-4 relative at l/r = 1 + 1e-12)
    cb = np.sqrt((l_ - y) * (l_ + y)) / l_
    lam = r / l_
    rm = r * MM
    y_b = rm * cp + l_ * MM * cb                 # y_B = r·cos φ + l·cos β
    v = omega * rm * (sp * cb + cp * sb) / cb    # ω·r·sin(φ + β)/cos β
    cb3 = cb * cb * cb
    a = omega * omega * rm * (cp - sp * sb / cb + lam * cp * cp / cb3)
    beta_dot = omega * lam * cp / cb             # ω·r·cos φ/(l·cos β)
    beta_ddot = omega * omega * (-lam * sp / cb + lam * lam * cp * cp * sb / cb3)
    return State(sp, cp, sb, cb, y_b, v, a, beta_dot, beta_ddot, omega)


def _state(crank_angle_deg, crank_radius_mm, rod_length_mm, offset_mm, n_rpm=30.0 / math.pi) -> State:
    r, l_, e = check_lengths(crank_radius_mm, rod_length_mm, offset_mm)
    return state(np.radians(require_finite("crank_angle_deg", crank_angle_deg)), r, l_, e, crank_speed(n_rpm))


def rod_angle_deg(crank_angle_deg, crank_radius_mm, rod_length_mm, offset_mm=0.0) -> np.ndarray:
    """Rod angle β from the cylinder axis, sin β = (r·sin φ − e)/l (degrees; positive while the crank pin is on
    the −x side of the pin line, i.e. while it goes down in the first half-turn).

    >>> round(float(rod_angle_deg(90, 70, 250)), 4)     # λ = r/l = 0.28: β_max = arcsin 0.28
    16.2602
    """
    st = _state(crank_angle_deg, crank_radius_mm, rod_length_mm, offset_mm)
    return np.degrees(np.arctan2(st.sin_beta, st.cos_beta))


def piston_position(crank_angle_deg, crank_radius_mm, rod_length_mm, offset_mm=0.0) -> np.ndarray:
    """Distance of the piston pin from the crank axis along the cylinder, y_B = r·cos φ + l·cos β (mm)."""
    return _state(crank_angle_deg, crank_radius_mm, rod_length_mm, offset_mm).y_b / MM


def piston_displacement(crank_angle_deg, crank_radius_mm, rod_length_mm, offset_mm=0.0) -> np.ndarray:
    """Piston travel from top dead centre, s = √((l + r)² − e²) − y_B (mm; 0 at TDC, the stroke at BDC).

    Heywood 1988 eq. (2.5) for e = 0: s = r + l − (r·cos φ + √(l² − r²·sin² φ)).

    >>> round(float(piston_displacement(180, 70, 250)), 9)     # the stroke of a central mechanism is 2r
    140.0
    """
    r, l_, e = check_lengths(crank_radius_mm, rod_length_mm, offset_mm)
    return math.sqrt((l_ + r) ** 2 - e * e) - piston_position(crank_angle_deg, r, l_, e)


def piston_velocity(crank_angle_deg, crank_radius_mm, rod_length_mm, n_rpm, offset_mm=0.0) -> np.ndarray:
    """Piston speed ds/dt = ω·r·sin(φ + β)/cos β (m/s; positive moving away from the head).

    Artobolevsky 1988 §4: v_B = ω·r·sin(φ + β)/cos β (from the velocity plan v_B = v_A + v_BA).

    >>> round(float(piston_velocity(300, 70, 250, 1700)), 3)    # seed 000 §5.3.3 reads -11.5 off its plan
    -12.349
    """
    return _state(crank_angle_deg, crank_radius_mm, rod_length_mm, offset_mm, n_rpm).v


def piston_acceleration(crank_angle_deg, crank_radius_mm, rod_length_mm, n_rpm, offset_mm=0.0) -> np.ndarray:
    """Piston acceleration d²s/dt² = ω²·r·(cos φ − sin φ·tan β + (r/l)·cos² φ / cos³ β) (m/s²; positive away from
    the head: ω²·r·(1 + r/l) at the top dead centre of a central mechanism).

    Kolchin & Demidov 1980 §9.1: the exact form, of which ω²r(cos φ + λ cos 2φ) is the first two harmonics.

    >>> w = float(crank_speed(1700)); round(float(piston_acceleration(0, 70, 250, 1700)) / (w * w * 0.07), 12)
    1.28
    """
    return _state(crank_angle_deg, crank_radius_mm, rod_length_mm, offset_mm, n_rpm).a


def rod_angular_velocity(crank_angle_deg, crank_radius_mm, rod_length_mm, n_rpm, offset_mm=0.0) -> np.ndarray:
    """dβ/dt = ω·r·cos φ / (l·cos β) (rad/s). The rod's angular velocity about z (counter-clockwise, the sense
    of rotation) is its negative, −dβ/dt.

    >>> round(float(rod_angular_velocity(300, 70, 250, 1700)) * 0.25, 2)  # v_BA; seed 000 §5.3.3: 36 mm x 0.1779
    6.42
    """
    return _state(crank_angle_deg, crank_radius_mm, rod_length_mm, offset_mm, n_rpm).beta_dot


def rod_angular_acceleration(crank_angle_deg, crank_radius_mm, rod_length_mm, n_rpm, offset_mm=0.0) -> np.ndarray:
    """d²β/dt² = ω²·(−r·sin φ/(l·cos β) + r²·cos² φ·sin β/(l²·cos³ β)) (rad/s²); the rod's angular acceleration
    about z is its negative.

    >>> w = float(crank_speed(1700))   # at φ = 90°: −λ/√(1 − λ²) = −0.28/0.96 = −7/24
    >>> round(float(rod_angular_acceleration(90, 70, 250, 1700)) / (w * w) * 24, 12)
    -7.0
    """
    return _state(crank_angle_deg, crank_radius_mm, rod_length_mm, offset_mm, n_rpm).beta_ddot


def crank_pin_acceleration(crank_angle_deg, crank_radius_mm, n_rpm) -> tuple[np.ndarray, np.ndarray]:
    """(x, y) acceleration of a point of the crank at radius r, −ω²·r·(−sin φ, cos φ) (m/s²; centripetal at
    constant ω)."""
    r = one_number("crank_radius_mm", require_positive("crank_radius_mm", crank_radius_mm, "mm"))
    phi = np.radians(require_finite("crank_angle_deg", crank_angle_deg))
    w = crank_speed(n_rpm)
    return w * w * r * MM * np.sin(phi), -w * w * r * MM * np.cos(phi)


def rod_cg_acceleration(crank_angle_deg, crank_radius_mm, rod_length_mm, rod_cg_mm, n_rpm,
                        offset_mm=0.0) -> tuple[np.ndarray, np.ndarray]:
    """(x, y) acceleration of the rod's centre of gravity S at ``rod_cg_mm`` = |AS| from the crank pin along the
    rod (m/s²): S = A + (|AS|/l)·(B − A) with constant weights, so a_S = a_A + (|AS|/l)·(a_B − a_A), a_B = (0, −s̈)
    (Artobolevsky 1988 §4: the similarity theorem of the acceleration plan).

    >>> ax, ay = rod_cg_acceleration(0, 70, 250, 0, 1700); w = float(crank_speed(1700))
    >>> round(float(ay) / (w * w * 0.07), 12)       # S at the crank pin: the pin's centripetal acceleration
    -1.0
    """
    r, l_, e = check_lengths(crank_radius_mm, rod_length_mm, offset_mm)
    k = one_number("rod_cg_mm", require_range("rod_cg_mm", rod_cg_mm, 0.0, l_, unit="mm")) / l_
    st = _state(crank_angle_deg, r, l_, e, n_rpm)
    return cg_acceleration(st, r, k)


def cg_acceleration(st: State, crank_radius_mm, k) -> tuple[np.ndarray, np.ndarray]:
    """(x, y) acceleration (m/s²) of the point at the fraction k of the rod from A to B, from a :class:`State`."""
    w2r = st.omega * st.omega * crank_radius_mm * MM
    ax_a, ay_a = w2r * st.sin_phi, -w2r * st.cos_phi     # centripetal: −ω²·A
    return (1.0 - k) * ax_a, ay_a + k * (-st.a - ay_a)

