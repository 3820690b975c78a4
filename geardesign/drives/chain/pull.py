"""The pull of a roller chain on its shafts: the working pull, the centrifugal and sag tensions, the branch
tensions and the load on each sprocket shaft with its direction from the layout.

Forces in N, torques in N·m, lengths in mm, the chain's mass per length in kg/m, speeds in m/s, angles in
degrees measured from the horizontal.

Sources (docs/references.md, docs/bearings.md): the working pull F_t = 2T/d on the sprocket's pitch circle
(as a gear's, NTN CAT. No. 2203/E eq. (4.2)); the centrifugal tension F_v = q·v² and the sag tension
F_f = 9.81·k_f·q·a (a in m; k_f = 6 horizontal, 1.5 at 40°, 1 vertical) of Chernavsky's course design of
machine parts (the same as :func:`geardesign.drives.chain.formulas.safety_factor`); the load on the shafts
F_B = F_t + 2·F_f, directed along the line of centres (Chernavsky; a worked course design applying it:
https://vunivere.ru/work4181/page2, "Сила, нагружающая валы передачи, Fb = Ft + 2Ff"). The centrifugal
tension is in both branches and the sprocket turns it back on itself: it stretches the chain, not the
shafts (as for a belt, whose branch tensions "except F_v" reach the shafts: http://3-net.ru/sign/sign-381333.php).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...results import Result
from ...validate import one_number, require_range
from ..sprocket import pitch_diameter_mm
from .formulas import G

__all__ = ["working_pull_n", "centrifugal_tension_n", "sag_tension_n", "shaft_load_n", "sag_factor",
           "ChainPull", "chain_pull"]

SAG_FACTOR_POINTS = ((0.0, 6.0), (40.0, 1.5), (90.0, 1.0))   # (incline from horizontal, k_f): Chernavsky


def working_pull_n(torque_nm, pitch_diameter_mm):
    """Working pull F_t = 2000·T/d (N) of a sprocket with torque T (N·m) and pitch diameter d (mm).

    Seed 002's drive (1.9.6): T1 = 380 N·m on z1 = 13 teeth of pitch 31.75 mm (d = 132.67 mm): 5 728.5 N.

    >>> round(float(working_pull_n(380, pitch_diameter_mm(31.75, 13))), 1)
    5728.5
    """
    return 2000.0 * np.asarray(torque_nm, dtype=float) / np.asarray(pitch_diameter_mm, dtype=float)


def centrifugal_tension_n(mass_kg_m, speed_m_s):
    """Centrifugal tension F_v = q·v² (N), q in kg/m, v in m/s (Chernavsky).

    >>> float(centrifugal_tension_n(3.8, 2.0))
    15.2
    """
    v = np.asarray(speed_m_s, dtype=float)
    return np.asarray(mass_kg_m, dtype=float) * v * v


def sag_tension_n(mass_kg_m, center_distance_mm, k_f=6.0):
    """Sag tension F_f = 9.81·k_f·q·a (N), a in m (×1/1000 inside), k_f = 6 for a horizontal drive,
    1.5 at 40°, 1 vertical (Chernavsky).

    >>> round(float(sag_tension_n(3.8, 1000.0)), 3)
    223.668
    """
    return G * np.asarray(k_f, dtype=float) * np.asarray(mass_kg_m, dtype=float) * np.asarray(
        center_distance_mm, dtype=float) / 1000.0


def sag_factor(incline_deg):
    """k_f for a line of centres inclined ``incline_deg`` from the horizontal: 6 at 0°, 1.5 at 40°, 1 at 90°
    (Chernavsky's three values), linear between them.

    >>> float(sag_factor(0)), float(sag_factor(40)), float(sag_factor(90))
    (6.0, 1.5, 1.0)
    """
    a = np.abs(np.asarray(incline_deg, dtype=float))
    xs, ys = zip(*SAG_FACTOR_POINTS)
    return np.interp(a, xs, ys)


def shaft_load_n(working_pull, sag_tension):
    """Load of the chain on each sprocket shaft F_B = F_t + 2·F_f (N), along the line of centres (Chernavsky;
    vunivere.ru/work4181/page2).

    >>> float(shaft_load_n(5000.0, 200.0))
    5400.0
    """
    return np.asarray(working_pull, dtype=float) + 2.0 * np.asarray(sag_tension, dtype=float)


@dataclass(frozen=True)
class ChainPull(Result):
    """The chain's tensions and its load on the two sprocket shafts (N). ``direction1`` is the unit vector
    (horizontal, vertical) from the driving sprocket's axis toward the driven one's: the load on shaft 1 acts
    along it, the load on shaft 2 against it (the chain pulls the shafts together)."""

    working_pull_n: float
    centrifugal_n: float
    sag_n: float
    tight_branch_n: float
    slack_branch_n: float
    shaft_load_n: float
    direction1: tuple
    incline_deg: float
    k_f: float
    speed_m_s: float

    _success_field = "finite"

    @property
    def finite(self) -> bool:
        return math.isfinite(self.shaft_load_n)

    def __repr__(self) -> str:
        return (f"ChainPull(working pull {self.working_pull_n:.6g} N, centrifugal {self.centrifugal_n:.4g} N, sag "
                f"{self.sag_n:.4g} N (k_f = {self.k_f:g}); load on each shaft {self.shaft_load_n:.6g} N along the line "
                f"of centres at {self.incline_deg:g} deg)")

    @property
    def shaft1_load_n(self) -> tuple:
        """The load on the driving sprocket's shaft as (horizontal, vertical) components, N."""
        return (self.shaft_load_n * self.direction1[0], self.shaft_load_n * self.direction1[1])

    @property
    def shaft2_load_n(self) -> tuple:
        """The load on the driven sprocket's shaft as (horizontal, vertical) components, N."""
        return (-self.shaft_load_n * self.direction1[0], -self.shaft_load_n * self.direction1[1])


def chain_pull(torque_nm, pitch_mm, z1, n1_rpm, mass_kg_m, center_distance_mm, incline_deg=0.0,
               k_f=None) -> ChainPull:
    """The pull of a roller chain with pitch ``pitch_mm`` whose driving sprocket (``z1`` teeth, ``n1_rpm``)
    carries ``torque_nm``, of mass ``mass_kg_m`` and centre distance ``center_distance_mm``, the line of centres
    rising ``incline_deg`` from the horizontal toward the driven sprocket (k_f from it unless given).

    Branch tensions: tight F_t + F_v + F_f, slack F_v + F_f (Chernavsky); the shaft load F_t + 2·F_f along
    the line of centres.

    >>> p = chain_pull(380, 31.75, 13, 120, 3.8, 1270.0)
    >>> round(p.working_pull_n, 1), round(p.shaft_load_n, 1), p.direction1
    (5728.5, 6296.6, (1.0, 0.0))
    """
    t = one_number("torque_nm", require_range("torque_nm", torque_nm, 0.0, 1e9, lo_open=True, unit="N·m"))
    p = one_number("pitch_mm", require_range("pitch_mm", pitch_mm, 0.0, 500.0, lo_open=True, unit="mm"))
    z = one_number("z1", require_range("z1", z1, 5, 200))
    n = one_number("n1_rpm", require_range("n1_rpm", n1_rpm, 0.0, 1e5, lo_open=True, unit="rpm"))
    q = one_number("mass_kg_m", require_range("mass_kg_m", mass_kg_m, 0.0, 1e3, unit="kg/m"))
    a = one_number("center_distance_mm", require_range("center_distance_mm", center_distance_mm, 0.0, 1e5,
                                                       lo_open=True, unit="mm"))
    inc = one_number("incline_deg", require_range("incline_deg", incline_deg, -90.0, 90.0, unit="deg"))
    kf = float(sag_factor(inc)) if k_f is None else one_number("k_f", require_range("k_f", k_f, 0.0, 10.0))
    d = float(pitch_diameter_mm(p, z))
    v = z * p * n / 60000.0                       # chain speed, m/s
    F_t = float(working_pull_n(t, d))
    F_v = float(centrifugal_tension_n(q, v))
    F_f = float(sag_tension_n(q, a, kf))
    rad = math.radians(inc)
    return ChainPull(working_pull_n=F_t, centrifugal_n=F_v, sag_n=F_f, tight_branch_n=F_t + F_v + F_f,
                     slack_branch_n=F_v + F_f, shaft_load_n=float(shaft_load_n(F_t, F_f)),
                     direction1=(round(math.cos(rad), 15), round(math.sin(rad), 15)), incline_deg=inc, k_f=kf,
                     speed_m_s=v)
