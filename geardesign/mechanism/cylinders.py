"""Several cylinders on one crankshaft: firing phases, the journal and crank-pin torques of seed 004, the unevenness
of the torque and the flywheel's coefficient of fluctuation. Every function takes the torque curves as arrays over
one working cycle sampled at equal steps (the last sample one step before the cycle closes).

References: seed 004 (EW10J4 engine thesis, p. 11: M_zi, M_qi, μ); Kolchin & Demidov 1980 §11 (the summed torque
of a multi-cylinder engine, its unevenness, the flywheel); Artobolevsky 1988 §§18-19 (the excess work and the
coefficient of fluctuation δ = ΔE/(J·ω²)).
"""
from __future__ import annotations

import math

import numpy as np

from ..errors import GearDesignError
from ..validate import one_number, require_finite, require_positive
from .kinematics import crank_speed

__all__ = ["firing_phases", "even_phases", "journal_torques", "crank_pin_torques", "unevenness", "excess_work",
           "fluctuation_coefficient", "reversal_angles", "CYLINDERS_MAX"]

CYLINDERS_MAX = 24      # the largest common engines (W/V 24); beyond, a value is a typing slip


def even_phases(cylinders: int, cycle_deg: float, firing_order=None) -> np.ndarray:
    """Firing phases ψ (degrees, per cylinder 1..n) of an even-firing engine: the k-th cylinder of the firing order
    (cylinder order 1..n when none is given) fires k·cycle/n after the first.

    >>> even_phases(4, 720, (1, 3, 4, 2)).tolist()
    [0.0, 540.0, 180.0, 360.0]
    """
    order = _order(cylinders, firing_order)
    out = np.empty(cylinders)
    out[np.asarray(order) - 1] = np.arange(cylinders) * (cycle_deg / cylinders)
    return out


def _order(cylinders: int, firing_order) -> tuple:
    if firing_order is None:
        return tuple(range(1, cylinders + 1))
    try:
        order = tuple(int(c) for c in firing_order)
    except (TypeError, ValueError):
        raise GearDesignError(f"firing_order must list the cylinder numbers 1..{cylinders}, got {firing_order!r}") \
            from None
    if sorted(order) != list(range(1, cylinders + 1)):
        raise GearDesignError(f"firing_order must list each cylinder 1..{cylinders} once, got {list(order)}")
    return order


def firing_phases(throws_deg, firing_order, cycle_deg: float) -> np.ndarray:
    """Firing phases ψ_c (degrees, per cylinder 1..n) from the crank throws and the firing order: ``throws_deg[c]``
    is the crank angle of cylinder 1 at which cylinder c's piston is at top dead centre (cylinder 1: 0). A cylinder
    of a four-stroke engine reaches top dead centre at θ_c and θ_c + 360° of the 720° cycle (of a two-stroke, at
    θ_c only); going along the firing order from cylinder 1 (firing at 0), each cylinder fires at the first of its
    top dead centres after the previous firing, inside the cycle (Kolchin & Demidov 1980 §11: the firing diagram).

    >>> firing_phases((0, 180, 180, 0), (1, 3, 4, 2), 720).tolist()     # the in-line four, 1-3-4-2
    [0.0, 540.0, 180.0, 360.0]
    >>> firing_phases((0, 180), (1, 2), 720).tolist()                  # the 180° twin fires at 0 and 180
    [0.0, 180.0]
    >>> firing_phases((0, 120, 240), (1, 3, 2), 360)
    Traceback (most recent call last):
    ...
    geardesign.errors.GearDesignError: firing_order [1, 3, 2] does not fit throws_deg [0, 120, 240]: cylinder 2 has no top dead centre after 240 degrees inside the cycle of 360
    """
    theta = np.mod(require_finite("throws_deg", throws_deg).astype(float).ravel(), 360.0)
    n = theta.size
    order = _order(n, firing_order)
    k = order.index(1)
    order = order[k:] + order[:k]            # the cycle's angle is cylinder 1's: it fires first, at 0
    theta = np.mod(theta - theta[0], 360.0)
    tops = np.arange(0.0, cycle_deg - 1e-9, 360.0)          # the crank's turns per cycle
    fire = np.zeros(n)
    last = 0.0
    for c in order[1:]:
        candidates = theta[c - 1] + tops
        later = candidates[candidates > last + 1e-9]
        if later.size == 0:
            shown = ", ".join(f"{t:g}" for t in theta)
            raise GearDesignError(f"firing_order {list(order)} does not fit throws_deg [{shown}]: cylinder {c} has "
                                  f"no top dead centre after {last:g} degrees inside the cycle of {cycle_deg:g}")
        last = fire[c - 1] = float(later.min())
    return fire


def journal_torques(cylinder_torques_nm) -> np.ndarray:
    """Torques on the main journals (seed 004): journal 1 (the front end, driving the timing gears) carries 0, journal
    i + 1 the sum of the torques of cylinders 1..i ahead of it, M_z(i+1) = Σ_{k≤i} M_k; the last journal carries the
    resultant. ``cylinder_torques_nm`` is (cylinders × points), cylinder 1 at the front; returns (cylinders + 1 ×
    points).

    >>> journal_torques([[1.0, 2.0], [10.0, 20.0]]).tolist()
    [[0.0, 0.0], [1.0, 2.0], [11.0, 22.0]]
    """
    m = require_finite("cylinder_torques_nm", cylinder_torques_nm).astype(float)
    m = np.atleast_2d(m)
    return np.vstack([np.zeros_like(m[:1]), np.cumsum(m, axis=0)])


def crank_pin_torques(cylinder_torques_nm) -> np.ndarray:
    """Torques on the crank pins (seed 004): the pin of throw i carries the journal torque ahead of it plus half its
    own cylinder's, M_qi = M_zi + 0.5·M_i (one cylinder: M_q = 0.5·M).

    >>> crank_pin_torques([[1.0, 2.0], [10.0, 20.0]]).tolist()
    [[0.5, 1.0], [6.0, 12.0]]
    """
    m = np.atleast_2d(require_finite("cylinder_torques_nm", cylinder_torques_nm).astype(float))
    return journal_torques(m)[:-1] + 0.5 * m


def unevenness(torque_nm) -> float:
    """μ = (M_max − M_min)/M_mean of a torque curve sampled evenly over the cycle (seed 004; Kolchin & Demidov 1980
    §11): the smaller, the smoother the engine. A mean that is not positive (a curve that does no work) has no μ.

    >>> unevenness([0.0, 100.0, 200.0, 100.0])
    2.0
    """
    m = require_finite("torque_nm", torque_nm).astype(float)
    mean = float(m.mean())
    if not mean > 0:
        raise GearDesignError(f"torque_nm must have a positive mean for its unevenness, got a mean of {mean:.6g} N·m")
    return float((m.max() - m.min()) / mean)


def excess_work(torque_nm, cycle_deg: float) -> tuple[np.ndarray, float]:
    """The running excess work E(φ) = ∫₀^φ (M − M_mean) dφ (J) of a torque curve against a constant load equal to
    its mean (trapezoids over the even samples, closing on the cycle), and its swing ΔE = E_max − E_min, the energy
    the flywheel stores and gives back (Artobolevsky 1988 §19).

    >>> e, swing = excess_work([2.0, 2.0, 0.0, 0.0], 360)    # ±1 N·m about the mean: ΔE = 1 N·m × π/2
    >>> round(swing, 6)
    1.570796
    """
    m = require_finite("torque_nm", torque_nm).astype(float)
    step = np.radians(cycle_deg) / m.size
    d = m - m.mean()
    e = np.concatenate([[0.0], np.cumsum(0.5 * (d + np.roll(d, -1)) * step)])
    return e[:-1], float(e.max() - e.min())


def fluctuation_coefficient(excess_work_j, inertia_kg_m2, n_rpm) -> float:
    """Coefficient of fluctuation of the crank speed δ = (ω_max − ω_min)/ω_mean = ΔE/(J·ω_mean²) for the swing of
    the excess work ΔE (J) and the moment of inertia J (kg·m²) of everything turning with the crankshaft
    (Artobolevsky 1988 §19, eq. of the energy method; exact to first order in δ).

    >>> round(fluctuation_coefficient(1000.0, 1.0, 3000 / 3.141592653589793), 12)    # ω = 100 rad/s
    0.1
    """
    de = one_number("excess_work_j", require_finite("excess_work_j", excess_work_j))
    j = one_number("inertia_kg_m2", require_positive("inertia_kg_m2", inertia_kg_m2, "kg·m²"))
    w = float(crank_speed(n_rpm))
    den = j * w * w
    delta = de / den if den > 0 else math.inf
    if not math.isfinite(delta):    # ω² underflowed (n = 5e-324 rpm was a ZeroDivisionError, fuzz)
        raise GearDesignError(f"n_rpm = {one_number('n_rpm', n_rpm):g} rpm is too slow for a fluctuation coefficient "
                              f"with inertia_kg_m2 = {j:g}: ΔE/(J·ω²) overflows (no flywheel carries such a cycle)")
    return delta


def reversal_angles(crank_angle_deg, torque_nm, cycle_deg: float | None = None) -> np.ndarray:
    """Crank angles (degrees, in the cycle) where the torque changes sign, interpolated linearly between samples,
    the curve closing on the cycle (``cycle_deg``; by default one step after the last sample): where a gear driven
    by it changes flank. Samples within 1e-9 of the largest |M| count as zero; a run of zeros between opposite signs
    is one reversal at its middle, a touch of zero none.

    >>> reversal_angles([0, 90, 180, 270], [1.0, -1.0, -1.0, 1.0]).tolist()
    [45.0, 225.0]
    >>> reversal_angles([0, 90, 180, 270], [0.0, 1.0, 0.0, -1.0]).tolist()    # through zero at 0 and at 180
    [0.0, 180.0]
    """
    phi = require_finite("crank_angle_deg", crank_angle_deg).astype(float).ravel()
    m = require_finite("torque_nm", torque_nm).astype(float).ravel()
    n = m.size
    if cycle_deg is None:
        cycle_deg = phi[-1] + (phi[1] - phi[0] if n > 1 else 360.0) - phi[0]
    sign = np.where(np.abs(m) <= 1e-9 * np.abs(m).max(initial=0.0), 0, np.sign(m)).astype(int)
    nonzero = np.flatnonzero(sign)
    if nonzero.size < 2:
        return np.empty(0)
    i = nonzero
    j = np.roll(nonzero, -1)                     # the next nonzero sample, round the cycle
    flip = sign[i] != sign[j]
    i, j = i[flip], j[flip]
    gap = (j - i) % n                            # samples from i to j (j after i round the cycle)
    adjacent = gap == 1
    t = m[i] / (m[i] - m[(i + 1) % n])
    a_adj = _angle(phi, cycle_deg, i) + t * (_angle(phi, cycle_deg, i + 1) - _angle(phi, cycle_deg, i))
    a_zero = 0.5 * (_angle(phi, cycle_deg, i + 1) + _angle(phi, cycle_deg, i + gap - 1))   # the zero run's middle
    out = np.where(adjacent, a_adj, a_zero)
    return np.sort(phi[0] + np.mod(out - phi[0], cycle_deg))


def _angle(phi, cycle_deg, k):
    """The angle of sample k, counting on past the last sample into the next cycle."""
    n = phi.size
    return phi[k % n] + cycle_deg * (k // n)
