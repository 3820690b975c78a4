"""Mesh forces of cylindrical gears: the tangential, radial and axial forces and where they act.

One function per formula, each vectorised over numpy arrays; :func:`pair_forces` (and
:meth:`GearPair.forces <geardesign.gears.pair.GearPair.forces>`) for one pair, :func:`planetary_forces` for
each mesh of a planetary set. Forces in N, torques in N·m, lengths in mm, angles in degrees at the interface.

Convention (stated in every result as ``circle``):

* ``"reference"`` — ISO 6336-1:2019 eq. (1): F_t = 2000·T1/d1 on the reference circle, F_r = F_t·tan α_t
  with the reference transverse pressure angle (tan α_t = tan α_n / cos β), F_a = F_t·tan β: the nominal
  forces of a rating (NTN CAT. No. 2203/E §4.1 eqs. (4.2)-(4.6));
* ``"operating"`` (the default for shaft and bearing loads) — the same torque on the operating pitch
  circle: F_t = 2000·T1/d_w1 and F_r = F_t·tan α_wt. The tooth force acts along the line of action,
  F_bt = 2000·T1/d_b1 in the transverse plane, so these two are its exact components along and across the
  line of centres of a profile-shifted pair; the axial force F_a = 2000·T1·tan β/d1 is the same in both
  conventions (F_bt·tan β_b). For a pair without shift (d_w = d) the conventions agree.

Point of application: the pitch point C on the line of centres, at r_w1 = d_w1/2 from gear 1's axis (r_w2
from gear 2's), in the middle of the face width. The radial force pushes the two axes apart in an external
pair and pulls them together in an internal one (each gear's radial force points from C toward its own
axis for an external pair; for a ring it points away from the ring's axis). The axial force on a gear acts
at its pitch radius and so bends its shaft with the moment F_a·d_w/2000 (N·m).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import GearDesignError
from ..results import Result
from ..validate import require_choice

__all__ = ["CIRCLES", "tangential_force_n", "radial_force_n", "axial_force_n", "normal_force_n", "mesh_forces",
           "MeshForces", "pair_forces", "planetary_forces"]

CIRCLES = ("operating", "reference")


def tangential_force_n(torque_nm, d_mm):
    """F_t = 2000·T/d (N) from the torque T (N·m) of the gear whose circle has diameter d (mm)
    (ISO 6336-1:2019 eq. (1); NTN CAT. No. 2203/E eq. (4.2)).

    NTN's Example 4 (CAT. 2203/E p. A-44): 150 kW at 2 000 min⁻¹ on a 150 mm pitch circle, K_t = 9.55 kN:

    >>> round(float(tangential_force_n(150e3 / (2000 * math.pi / 30), 150.0)) / 1000, 2)
    9.55
    """
    return 2000.0 * np.asarray(torque_nm, dtype=float) / np.asarray(d_mm, dtype=float)


def radial_force_n(F_t, alpha_t_deg):
    """F_r = F_t·tan α_t (N), α_t the transverse pressure angle of the circle F_t is taken on (NTN CAT.
    2203/E eqs. (4.4a), (4.4b): K_s = K_t·tan α_n/cos β for a helical gear, tan α_t = tan α_n/cos β).

    NTN's Example 4: K_s = 9.55 kN·tan 20° = 3.48 kN:

    >>> round(float(radial_force_n(9550.0, 20.0)) / 1000, 2)
    3.48
    """
    return np.asarray(F_t, dtype=float) * np.tan(np.radians(np.asarray(alpha_t_deg, dtype=float)))


def axial_force_n(F_t, beta_deg):
    """F_a = F_t·tan β (N) with F_t and β of the reference circle (NTN CAT. 2203/E eq. (4.6)); 0 for a spur
    pair.

    >>> round(float(axial_force_n(1000.0, 45.0)), 9)
    1000.0
    """
    return np.asarray(F_t, dtype=float) * np.tan(np.radians(np.asarray(beta_deg, dtype=float)))


def normal_force_n(F_t, alpha_n_deg, beta_deg):
    """F_n = F_t/(cos α_n·cos β) (N), the whole tooth force normal to the flank, with the reference F_t,
    α_n and β: the magnitude √(F_t² + F_r² + F_a²) of NTN CAT. 2203/E eqs. (4.2)-(4.6), since
    1 + tan²α_n/cos²β + tan²β = 1/(cos²α_n cos²β).

    >>> round(float(normal_force_n(9550.0, 20.0, 0.0)) / 1000, 2)   # NTN Example 4: K_r = 10.16 kN
    10.16
    """
    a = np.radians(np.asarray(alpha_n_deg, dtype=float))
    b = np.radians(np.asarray(beta_deg, dtype=float))
    return np.asarray(F_t, dtype=float) / (np.cos(a) * np.cos(b))


def mesh_forces(torque_nm, d_mm, alpha_t_deg, beta_deg=0.0, d_ref_mm=None) -> dict:
    """F_t, F_r, F_a and the resultant F (N) of a mesh, vectorised: the torque ``torque_nm`` of the gear whose
    circle of diameter ``d_mm`` carries F_t at the transverse pressure angle ``alpha_t_deg`` (the reference
    circle and α_t, or the operating pitch circle and α_wt); ``d_ref_mm`` that gear's reference diameter for
    the axial force (default ``d_mm``). F is √(F_t² + F_r² + F_a²), the magnitude of the tooth force.

    >>> f = mesh_forces(716.197, 150.0, 20.0)                 # NTN Example 4: 9.55, 3.48 kN
    >>> round(float(f["F_t_n"])), round(float(f["F_r_n"])), float(f["F_a_n"])
    (9549, 3476, 0.0)
    """
    F_t = tangential_force_n(torque_nm, d_mm)
    F_r = radial_force_n(F_t, alpha_t_deg)
    F_a = axial_force_n(tangential_force_n(torque_nm, d_mm if d_ref_mm is None else d_ref_mm), beta_deg)
    return {"F_t_n": F_t, "F_r_n": F_r, "F_a_n": F_a, "F_n": np.sqrt(F_t * F_t + F_r * F_r + F_a * F_a)}


@dataclass(frozen=True)
class MeshForces(Result):
    """The forces of one mesh on each of its gears (N) and where they act (mm), in one convention.

    ``F_t_n``, ``F_r_n``, ``F_a_n``: the magnitudes (equal and opposite on the two gears); ``F_n``: the
    resultant; ``r1_mm``, ``r2_mm``: the radius at which they act on gear 1 and gear 2 (operating pitch
    radii with ``circle="operating"``, reference radii otherwise); ``axial_moment1_nm``,
    ``axial_moment2_nm``: the bending moments F_a·r of the axial force on the two shafts; ``torque1_nm``,
    ``torque2_nm``: the torques the forces balance; ``circle``: the convention; ``internal``: the radial force
    pulls the axes together (True) or pushes them apart (False)."""

    mesh: str
    circle: str
    torque1_nm: float
    torque2_nm: float
    F_t_n: float
    F_r_n: float
    F_a_n: float
    F_n: float
    r1_mm: float
    r2_mm: float
    alpha_t_deg: float
    beta_deg: float
    axial_moment1_nm: float
    axial_moment2_nm: float
    internal: bool

    _success_field = "finite"

    @property
    def finite(self) -> bool:
        return all(math.isfinite(v) for v in (self.F_t_n, self.F_r_n, self.F_a_n))

    def __repr__(self) -> str:
        return (f"MeshForces({self.mesh}, {self.circle} circle: F_t = {self.F_t_n:.6g} N, F_r = {self.F_r_n:.6g} N, "
                f"F_a = {self.F_a_n:.6g} N, at r1 = {self.r1_mm:.6g} mm, r2 = {self.r2_mm:.6g} mm)")


def _circle(circle: str) -> str:
    return require_choice("circle", circle, CIRCLES)


def _one_mesh(name, geo: dict, torque1_nm: float, z1: int, z2: int, beta_deg: float, internal: bool,
              circle: str) -> MeshForces:
    """A mesh's forces from its geometry dict (d1, d2, dw1, dw2, alpha_w_deg, alpha_t_deg) and gear 1's torque."""
    if circle == "operating":
        d1, d2, alpha = geo["dw1"], geo["dw2"], geo["alpha_w_deg"]
    else:
        d1, d2, alpha = geo["d1"], geo["d2"], geo["alpha_t_deg"]
    f = mesh_forces(torque1_nm, d1, alpha, beta_deg, d_ref_mm=geo["d1"])
    F_a = float(f["F_a_n"])
    return MeshForces(mesh=name, circle=circle, torque1_nm=float(torque1_nm), torque2_nm=float(torque1_nm) * z2 / z1,
                      F_t_n=float(f["F_t_n"]), F_r_n=float(f["F_r_n"]), F_a_n=F_a, F_n=float(f["F_n"]),
                      r1_mm=float(d1) / 2.0, r2_mm=float(d2) / 2.0, alpha_t_deg=float(alpha), beta_deg=float(beta_deg),
                      axial_moment1_nm=F_a * float(d1) / 2000.0, axial_moment2_nm=F_a * float(d2) / 2000.0,
                      internal=bool(internal))


def _torque_on_gear1(load, z1: int, z2: int) -> float:
    """Gear 1's torque (N·m) from a Load, or a plain torque (N·m, taken on gear 1)."""
    from .strength.load import Load   # here: the load object only, not the strength chain

    if isinstance(load, Load):
        t = load.torque_nm
        return t if load.on_gear == 1 else t * z1 / z2
    if isinstance(load, bool) or not isinstance(load, (int, float, np.floating, np.integer)):
        raise GearDesignError(f"load must be a geardesign Load or gear 1's torque in N·m, got {load!r}")
    t = float(load)
    if not (math.isfinite(t) and t > 0):
        raise GearDesignError(f"load (gear 1's torque) must be a finite torque > 0 N·m, got {load!r}")
    return t


def pair_forces(pair, load, circle: str = "operating") -> MeshForces:
    """The mesh forces of a :class:`~geardesign.gears.pair.GearPair` under ``load`` (a
    :class:`~geardesign.gears.strength.Load`, whose torque is taken on the gear it names, or gear 1's torque
    in N·m) in the convention ``circle`` (see the module docstring).

    >>> from geardesign.gears.pair import GearPair
    >>> f = pair_forces(GearPair(5, 30, 60), 716.197)           # d1 = 150 mm, α = 20°: NTN Example 4
    >>> round(f.F_t_n / 1000, 2), round(f.F_r_n / 1000, 2)
    (9.55, 3.48)
    """
    circle = _circle(circle)
    geo = pair.geometry()
    g = {k: getattr(geo, k) for k in ("d1", "d2", "dw1", "dw2", "alpha_w_deg", "alpha_t_deg")}
    t1 = _torque_on_gear1(load, pair.z1, pair.z2)
    return _one_mesh("pair", g, t1, pair.z1, pair.z2, pair.beta_deg, pair.internal, circle)


def planetary_forces(pset, load, circle: str = "operating") -> dict:
    """The forces of both meshes of a :class:`~geardesign.gears.planetary.PlanetarySet` whose sun carries
    ``load`` (a Load on the sun, ``on_gear`` 1, or the sun's torque in N·m), shared equally by the planets
    (each sun-planet mesh carries T_sun/N; the planet passes T_sun·z_p/(N·z_s) to the ring): {"sun-planet":
    MeshForces, "planet-ring": MeshForces, "planet_bearing_n": the force on each planet's bearing (N), the
    vector sum of the two meshes' forces on the planet}. The planets' load sharing factor K_γ (ISO 6336-1
    6.4) is the caller's to apply.

    In a set without shifts the radial forces on a planet cancel and its bearing carries 2·F_t:

    >>> from geardesign.gears.planetary import PlanetarySet
    >>> s = PlanetarySet(2, 20, 31, 82, 3)
    >>> f = planetary_forces(s, 300.0)                       # F_t = 2000·100/40 = 5000 N per mesh
    >>> round(f["sun-planet"].F_t_n, 9), round(f["planet-ring"].F_t_n, 9), round(f["planet_bearing_n"], 9)
    (5000.0, 5000.0, 10000.0)
    """
    circle = _circle(circle)
    from .strength.load import Load

    if isinstance(load, Load) and load.on_gear != 1:
        raise GearDesignError("load must be given on the sun (on_gear=1) for a planetary set")
    t_sun = _torque_on_gear1(load, pset.z_sun, pset.z_planet)
    geos = pset.geometry()
    t_mesh = t_sun / pset.n_planets
    out = {}
    for tag, t1, z1, z2, internal in (("sun-planet", t_mesh, pset.z_sun, pset.z_planet, False),
                                      ("planet-ring", t_mesh * pset.z_planet / pset.z_sun, pset.z_planet,
                                       pset.z_ring, True)):
        geo = geos[tag]
        g = {k: getattr(geo, k) for k in ("d1", "d2", "dw1", "dw2", "alpha_w_deg", "alpha_t_deg")}
        out[tag] = _one_mesh(tag, g, t1, z1, z2, pset.beta_deg, internal, circle)
    sp, pr = out["sun-planet"], out["planet-ring"]
    # on the planet: both tangential forces point the same way (the sun drives, the ring holds back); the
    # sun pushes it outward (F_r,sp) and the ring, meshing on the far side, pushes it inward (F_r,pr)
    tangential = sp.F_t_n + pr.F_t_n
    radial = sp.F_r_n - pr.F_r_n
    out["planet_bearing_n"] = math.hypot(tangential, radial)
    return out
