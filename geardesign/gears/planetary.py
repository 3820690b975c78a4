"""A simple planetary set: sun, N equal planets, ring — two meshes that share one centre distance.

The sun–planet mesh is external (gear 1 the sun, gear 2 the planet), the planet–ring mesh internal
(gear 1 the planet, gear 2 the ring; GOST 19274-73 sign of the ring's shift, see
:class:`~geardesign.gears.mesh.Mesh`). Their operating centre distances must be equal
(coaxiality): with x_Σ,sp = x_s + x_p fixing a_w = m_t z_Σ,sp cos α_t / (2 cos α_w,sp), the
planet–ring mesh runs at cos α_w,pr = (z_Σ,pr / z_Σ,sp) cos α_w,sp and its shift sum
x_Σ,pr = x_r − x_p = z_Σ,pr (inv α_w,pr − inv α_t) / (2 tan α_n) (ISO 21771:2007 eq. (62) applied
to each mesh). So (x_s, x_p) are the free shifts and x_r follows; dx_Σ,pr/dx_Σ,sp =
sin α_w,pr / sin α_w,sp (the two meshes' a_w differentiated).

Modelling choices (written down here, once):

* The planet is one gear with one tip circle in both meshes, so no tip is shortened in a set:
  d_a = d + 2m(h_a* + x) for sun and planet, d_a = d − 2m(h_a* − x) for the ring (the sun–planet
  clearance is then (c* − Δy)m, reported as ``clearance1`` of that mesh).
* Checks: every check of the external pair for sun and planet, every check of the internal pair
  for the ring and the ring's tip against the planet's root; the planet's undercut and tip
  thickness are the same condition in both meshes and are kept once (in the sun–planet mesh).
* ``neighbours``: adjacent planets' tip circles clear each other, 2 a_w sin(π/N) − d_a,p >=
  clearance (SDP/SI–KHK *Elements of Metric Gear Technology* D785 §13.3.1 eq. (13-9), (13-10) ask
  d_a,p < 2 a sin(π/N); the default clearance of 0.5·m is a shop rule, see
  docs/research/planetary.md §4).
* ``assembly``: N equally spaced planets can be put in when (z_s + z_r)/N is whole (D785 eq.
  (13-7)); planets at carrier angles θ_k (unequal spacing) when every (z_s + z_r)·θ_k/360° is
  whole (D785 eq. (13-8), written for the angle from planet 1: a planet sits wherever the sun
  and ring teeth are in the phase they have at planet 1).
* ``coaxiality`` (given shifts): |a_w,sp − a_w,pr| <= tol, 1e-3·m by default (the housing
  tolerance of :class:`~geardesign.gears.checks.CenterDistance`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

from ..errors import GearDesignError
from ..validate import _show, ndim, one_number, require_choice, require_count, require_positive, require_range
from . import checks as _checks
from .geometry import (X_ABS_MAX, Geometry, mesh_geometry, mesh_geometry_float, min_center_distance, require_module,
                       validate_geometry)
from .mesh import Z_MAX, Z_MIN, Mesh
from .rack import STANDARD_RACK, BasicRack

__all__ = ["PlanetarySet", "PlanetaryMeshes", "ARRANGEMENTS", "N_PLANETS_RANGE", "MeshCheck", "Neighbours",
           "Coaxiality", "Assembly", "set_geometry", "set_checks", "planetary_ratio", "assembly_value",
           "DEFAULT_NEIGHBOUR_CLEARANCE", "MESH_NAMES"]

N_PLANETS_RANGE = (1, 64)
# a_w >= a cos α of both meshes and the planets around the sun: beyond ~30 planets the teeth of
# the sun are the limit, 64 is a hard bound on the work of one set
DEFAULT_NEIGHBOUR_CLEARANCE = 0.5   # × m: adjacent planet tips at least half a module apart
NEIGHBOUR_CLEARANCE_RANGE = (0.0, 100.0)   # × m
COAXIALITY_TOL = 1e-3               # × m, as the housing check CenterDistance
# arrangement -> (fixed member, input, output) of the simple set
ARRANGEMENTS = {
    "ring_fixed": ("ring", "sun", "carrier"),
    "carrier_fixed": ("carrier", "sun", "ring"),
    "sun_fixed": ("sun", "ring", "carrier"),
}
MESH_NAMES = ("sun-planet", "planet-ring")
_GEARS = {"sun-planet": ("sun", "planet"), "planet-ring": ("planet", "ring")}


def planetary_ratio(z_sun, z_ring, arrangement: str = "ring_fixed"):
    """Speed ratio n_in/n_out of a simple planetary set (Willis: (n_s − n_c)/(n_r − n_c) = −z_r/z_s).

    ring fixed, sun in, carrier out: 1 + z_r/z_s; carrier fixed, sun in, ring out: −z_r/z_s
    (the ring turns the other way); sun fixed, ring in, carrier out: 1 + z_s/z_r.

    >>> round(planetary_ratio(21, 108), 5)       # LECAD's test run prints 6.14286
    6.14286
    >>> planetary_ratio(24, 72, "carrier_fixed"), round(planetary_ratio(24, 72, "sun_fixed"), 4)
    (-3.0, 1.3333)
    """
    arrangement = require_choice("arrangement", arrangement, tuple(ARRANGEMENTS))
    zs, zr = np.asarray(z_sun, dtype=float), np.asarray(z_ring, dtype=float)
    out = {"ring_fixed": 1.0 + zr / zs, "carrier_fixed": -zr / zs, "sun_fixed": 1.0 + zs / zr}[arrangement]
    return float(out) if out.ndim == 0 else out


def assembly_value(z_sun, z_ring, n_planets, planet_angles_deg=None) -> float:
    """Distance of the assembly condition from a whole number (0 when the planets can be put in):
    (z_s + z_r)/N for equal spacing, the largest over k of (z_s + z_r)·θ_k/360° for planets at
    carrier angles θ_k measured from planet 1.

    >>> assembly_value(21, 108, 3), round(assembly_value(20, 70, 4), 3)     # 129/3 = 43; 90/4 = 22.5
    (0.0, 0.5)
    """
    q = z_sun + z_ring
    if planet_angles_deg is None:
        vals = [q / n_planets]
    else:
        vals = [q * float(t) / 360.0 for t in planet_angles_deg]
    return max(abs(v - round(v)) for v in vals)


@dataclass(frozen=True)
class PlanetaryMeshes:
    """The two meshes of a set (tooth counts, rack, helix) and its planets: what stays fixed while
    the shifts move, as one object (like :class:`~geardesign.gears.mesh.Mesh` for a pair)."""

    z_sun: int
    z_planet: int
    z_ring: int
    n_planets: int
    rack: BasicRack = STANDARD_RACK
    beta_deg: float = 0.0
    planet_angles_deg: tuple | None = None

    def __post_init__(self):
        for name in ("z_sun", "z_planet", "z_ring"):
            object.__setattr__(self, name, require_count(name, getattr(self, name), Z_MIN, Z_MAX))
        object.__setattr__(self, "n_planets", require_count("n_planets", self.n_planets, *N_PLANETS_RANGE))
        if self.z_ring <= self.z_planet:
            raise GearDesignError(f"z_ring must exceed z_planet (the ring is internal): z_ring = {self.z_ring} "
                                  f"<= z_planet = {self.z_planet}")
        if self.planet_angles_deg is not None:
            if ndim(self.planet_angles_deg) != 1 or isinstance(self.planet_angles_deg, (str, bytes)):
                raise GearDesignError(f"planet_angles_deg must be a list of {self.n_planets} carrier angles in deg, "
                                      f"got {_show(self.planet_angles_deg)}")
            angles = tuple(float(one_number("planet_angles_deg", require_range("planet_angles_deg", t, 0.0, 360.0,
                                                                                  hi_open=True, unit="deg")))
                           for t in self.planet_angles_deg)
            if len(angles) != self.n_planets or angles[0] != 0.0 or any(b <= a for a, b in zip(angles, angles[1:])):
                raise GearDesignError(f"planet_angles_deg must be {self.n_planets} increasing carrier angles in "
                                      f"[0, 360) deg starting at 0 (planet 1), got {list(self.planet_angles_deg)}")
            object.__setattr__(self, "planet_angles_deg", angles)
        sp = Mesh(self.z_sun, self.z_planet, self.rack, False, self.beta_deg)
        pr = Mesh(self.z_planet, self.z_ring, self.rack, False, self.beta_deg, internal=True)
        object.__setattr__(self, "rack", sp.rack)
        object.__setattr__(self, "beta_deg", sp.beta_deg)
        object.__setattr__(self, "sun_planet", sp)
        object.__setattr__(self, "planet_ring", pr)

    @property
    def standard(self) -> bool:
        """z_r = z_s + 2 z_p: coaxial without shifts."""
        return self.z_ring == self.z_sun + 2 * self.z_planet

    @property
    def title(self) -> str:
        return f"z_s/z_p/z_r = {self.z_sun}/{self.z_planet}/{self.z_ring}, {self.n_planets} planets"


def _ring_shift(meshes: PlanetaryMeshes, geo_sp: dict):
    """x_r − x_p of the coaxial planet–ring mesh and dx_Σ,pr/dx_Σ,sp, from the sun–planet geometry."""
    sc = meshes.sun_planet.section
    ratio = (meshes.z_ring - meshes.z_planet) / (meshes.z_sun + meshes.z_planet)
    cos_w = ratio * geo_sp["_cos_w"]
    zs_pr = meshes.z_ring - meshes.z_planet
    inv_t = math.tan(sc.alpha_t) - sc.alpha_t
    if isinstance(cos_w, float):
        if not 0.0 < cos_w < 1.0:
            return math.nan, math.nan
        sin_w = math.sqrt((1.0 - cos_w) * (1.0 + cos_w))
        inv_w = sin_w / cos_w - math.atan2(sin_w, cos_w)
    else:
        with np.errstate(invalid="ignore", divide="ignore"):
            cos_w = np.where((cos_w > 0) & (cos_w < 1), cos_w, np.nan)
            sin_w = np.sqrt((1.0 - cos_w) * (1.0 + cos_w))
            inv_w = sin_w / cos_w - np.arctan2(sin_w, cos_w)
    return zs_pr * (inv_w - inv_t) / (2.0 * sc.tan_n), sin_w / geo_sp["_sin_w"]


def set_geometry(meshes: PlanetaryMeshes, m, x_sun, x_planet, x_ring=None, full: bool = True) -> dict:
    """Both meshes' geometry at shifts (x_s, x_p) and the ring's x_r: given, or (``x_ring=None``)
    the one that makes the set coaxial. Python floats give the float path, arrays the vectorised
    one. The dict holds ``"sun-planet"`` and ``"planet-ring"`` geometries, ``x_ring``, the common
    ``a_w`` (the sun–planet one) and what the set's checks and the region's isolines read."""
    floats = all(type(v) is float for v in (m, x_sun, x_planet))
    core = mesh_geometry_float if floats else mesh_geometry
    sp = core(meshes.sun_planet, m, x_sun, x_planet, full)
    if x_ring is None:
        xs_pr, r = _ring_shift(meshes, sp)
        x_ring = x_planet + xs_pr
    else:
        r = math.nan
    pr = core(meshes.planet_ring, m, x_planet, x_ring, full)
    eps = min(sp["eps_alpha"], pr["eps_alpha"]) if floats else np.fmin(sp["eps_alpha"], pr["eps_alpha"])
    return {"sun-planet": sp, "planet-ring": pr, "x_ring": x_ring, "_r": r, "_n": meshes.n_planets,
            "a": sp["a"], "a_w": sp["a_w"], "a_w_pr": pr["a_w"], "da_planet": sp["da2"],
            "eps_alpha": eps, "sa1": sp["sa1"], "sa2": sp["sa2"], "_m": sp["_m"], "_x1": sp["_x1"],
            "_x2": sp["_x2"], "_sa": sp["_sa"], "_sin_w": sp["_sin_w"]}


@dataclass(frozen=True)
class MeshCheck(_checks.Check):
    """A check of one mesh of a set, seen on the set's shifts (x_s, x_p): its name says the mesh
    and the gear ("planet-ring:interference_planet"); its gradient in the planet–ring mesh's
    (x_p, x_r) is carried to (x_s, x_p) through x_r(x_s, x_p): ∂x_r/∂x_s = r, ∂x_r/∂x_p = 1 + r,
    r = dx_Σ,pr/dx_Σ,sp."""

    inner: _checks.Check = None
    mesh: str = "sun-planet"

    def __post_init__(self):
        base = self.inner.name
        gears = _GEARS[self.mesh]
        if base[-1:] in "12" and base[:-1]:
            base = f"{base[:-1]}_{gears[int(base[-1]) - 1]}"
        object.__setattr__(self, "name", self.name or f"{self.mesh}:{base}")
        label = self.inner.label.replace("gear 1", gears[0]).replace("gear 2", gears[1])
        object.__setattr__(self, "label", self.label or f"{self.mesh}: {label}")
        object.__setattr__(self, "limit", self.inner.limit)

    @property
    def n_parts(self):
        return self.inner.n_parts

    @property
    def needs_report_fields(self):
        return self.inner.needs_report_fields

    @property
    def costly(self):
        return self.inner.costly

    def modelled_at(self, geo):
        return replace(self, inner=self.inner.modelled_at(geo[self.mesh])) if self.costly else self

    def value(self, geo):
        return self.inner.value(geo[self.mesh])

    def limit_value(self, geo):
        return self.inner.limit_value(geo[self.mesh])

    def margin(self, geo):
        return self.inner.margin(geo[self.mesh])

    def _carry(self, g, geo):
        if g is None or self.mesh == "sun-planet":
            return g
        r = geo["_r"]
        return g[1] * r, g[0] + g[1] * (1.0 + r)

    def gradient(self, geo):
        return self._carry(self.inner.gradient(geo[self.mesh]), geo)

    def part_margins(self, geo):
        return self.inner.part_margins(geo[self.mesh])

    def part_gradients(self, geo):
        return [self._carry(g, geo) for g in self.inner.part_gradients(geo[self.mesh])]


@dataclass(frozen=True)
class Neighbours(_checks.Check):
    """Adjacent planets' tip circles clear each other: 2 a_w sin(π/N) − d_a,p >= ``limit``·m
    (clearance in modules, 0.5 by default). Margin (2 a_w sin(π/N) − d_a,p)/m − limit."""

    colour, kind_name = "teal", "neighbours"

    n_planets: int = 3

    def __post_init__(self):
        object.__setattr__(self, "name", self.name or "set:neighbours")
        object.__setattr__(self, "label", self.label or
                           f"adjacent planet tips clear by >= {self.limit:g} m (2 a_w sin(pi/{self.n_planets}) - d_a,p)")

    def value(self, geo):
        return (2.0 * geo["a_w"] * math.sin(math.pi / self.n_planets) - geo["da_planet"]) / geo["_m"]

    def gradient(self, geo):
        # ∂a_w/∂x_Σ = m sin α_t / sin α_w; ∂d_a,p/∂x_p = 2m (no tip shortening in a set)
        g = 2.0 * math.sin(math.pi / self.n_planets) * geo["_sa"] / geo["_sin_w"]
        return g, g - 2.0


@dataclass(frozen=True)
class Coaxiality(_checks.Check):
    """The two meshes' operating centre distances agree: |a_w,sp − a_w,pr| <= tol (mm; 1e-3·m by
    default). Margin (tol − |Δa_w|)/m. A check of given shifts: the optimiser keeps it exactly."""

    tol_mm: float | None = None

    def __post_init__(self):
        object.__setattr__(self, "name", self.name or "set:coaxiality")
        object.__setattr__(self, "label", self.label or "sun-planet a_w = planet-ring a_w (coaxial set)")

    def _tol(self, geo):
        return COAXIALITY_TOL * geo["_m"] if self.tol_mm is None else self.tol_mm

    def value(self, geo):
        return geo["a_w_pr"]

    def limit_value(self, geo):
        return geo["a_w"]

    def margin(self, geo):
        return (self._tol(geo) - abs(geo["a_w"] - geo["a_w_pr"])) / geo["_m"]

    def gradient(self, geo):
        return None


@dataclass(frozen=True)
class Assembly(_checks.Check):
    """The planets can be put in (see :func:`assembly_value`): margin 0 when the condition's
    number is whole, minus its distance from the nearest whole number otherwise. Independent of
    the shifts."""

    meshes: PlanetaryMeshes = None

    def __post_init__(self):
        ms = self.meshes
        where = ("(z_s + z_r)/N whole" if ms.planet_angles_deg is None
                 else "(z_s + z_r) theta_k/360 whole for every planet")
        object.__setattr__(self, "name", self.name or "set:assembly")
        object.__setattr__(self, "label", self.label or f"planets can be assembled: {where}")

    def _q(self):
        ms = self.meshes
        return ((ms.z_sun + ms.z_ring) / ms.n_planets if ms.planet_angles_deg is None else
                max((ms.z_sun + ms.z_ring) * t / 360.0 for t in ms.planet_angles_deg))

    def value(self, geo):
        return self._q()

    def limit_value(self, geo):
        return float(round(self._q()))

    def margin(self, geo):
        d = assembly_value(self.meshes.z_sun, self.meshes.z_ring, self.meshes.n_planets,
                           self.meshes.planet_angles_deg)
        return 0.0 * geo["a"] - (d if d > 1e-9 else 0.0)

    def gradient(self, geo):
        return 0.0, 0.0


def set_checks(meshes: PlanetaryMeshes, checks=None, cutter=None, arrangement: str = "ring_fixed") -> tuple:
    """The checks of a set, each named by its mesh ("sun-planet:undercut_sun",
    "planet-ring:ring_tip", "set:neighbours"): ``checks`` None (the defaults of both meshes and
    ``neighbours`` at 0.5 m), or a dict of :func:`~geardesign.gears.checks.make_checks` options
    for both meshes plus ``neighbour_clearance`` (in modules; None drops the check); ``cutter``: the
    :class:`~geardesign.gears.ring.ShaperCutter` of the ring (None: the standard one for the module).

    With ``load`` (the sun's, a :class:`~geardesign.gears.strength.Load`) the strength checks of both meshes
    come in, each mesh loaded as :func:`~geardesign.gears.strength.planetary_strength` loads it (the torque
    shared over the planets, speeds relative to the carrier of ``arrangement``; ``strength={"K_gamma": ...}``
    the mesh load factor); ``material`` is all three gears' unless ``planet_material`` or ``ring_material``
    is given."""
    opts = {} if checks is None else dict(checks) if isinstance(checks, dict) else None
    if opts is None:
        raise GearDesignError(f"checks of a planetary set must be None or a dict of options, got {checks!r}")
    clearance = opts.pop("neighbour_clearance", DEFAULT_NEIGHBOUR_CLEARANCE)
    sp_opts, pr_opts = _mesh_options(opts, meshes, arrangement)
    sp = _checks.resolve_checks(sp_opts or None, internal=False)
    pr = _checks.resolve_checks({**pr_opts, "cutter": cutter} if cutter is not None else pr_opts or None,
                                internal=True)
    # the planet's undercut and tip thickness are one condition in both meshes: kept once
    out = [MeshCheck(inner=c, mesh="sun-planet") for c in sp]
    out += [MeshCheck(inner=c, mesh="planet-ring") for c in pr if c.name not in ("undercut1", "tip_thickness1")]
    given = sp_opts.get("spectrum")
    if given is not None and any(s.reverses for s in (given if isinstance(given, (list, tuple)) else [given])):
        # a reversed bin loads the planet's other flank from the other mesh: its damage sums run across both meshes
        from .planet_damage import is_planet_damage, planet_damage_checks

        out = [c for c in out if not is_planet_damage(c)]
        out += planet_damage_checks({"sun-planet": sp_opts, "planet-ring": pr_opts},
                                    lambda c, tag: MeshCheck(inner=c, mesh=tag))
    if clearance is not None and meshes.n_planets > 1:
        clearance = one_number("neighbour_clearance", require_range("neighbour_clearance", clearance,
                                                                    *NEIGHBOUR_CLEARANCE_RANGE, unit="m"))
        out.append(Neighbours(limit=clearance, n_planets=meshes.n_planets))
    return tuple(out)


# the materials of a set's gears besides ``material`` (the sun's, and every gear's not given)
SET_MATERIALS = ("planet_material", "ring_material")


def _mesh_options(opts: dict, meshes: PlanetaryMeshes, arrangement: str) -> tuple[dict, dict]:
    """The checks options of the sun-planet and the planet-ring mesh: with a load, each mesh's own load
    case (its torque, speed, load cycles and materials); without one, the same options for both."""
    if "material2" in opts:
        raise GearDesignError("material2 is a pair's; a planetary set takes material (every gear) and "
                              "planet_material, ring_material")
    own = {k: opts.pop(k) for k in SET_MATERIALS if k in opts}
    if "alternating" in opts:
        raise GearDesignError("alternating is the set's own: the planet's root bends both ways (it meets the sun on "
                              "one flank and the ring on the other), the sun's and the ring's one way")
    if opts.get("load") is None and opts.get("spectrum") is None:
        if any(v is not None for v in own.values()):
            raise GearDesignError(f"{', '.join(k for k, v in own.items() if v is not None)} given without a load: "
                                  f"the strength checks need load= (a geardesign Load on the sun)")
        return opts, opts
    # here: the strength package loads pandas and the materials catalog, which a set without a load never needs
    from .strength.planetary_meshes import mesh_loads, mesh_spectra

    z = (meshes.z_sun, meshes.z_planet, meshes.z_ring, meshes.n_planets, arrangement)
    cases = mesh_loads(*z, opts["load"]) if opts.get("load") is not None else None
    # a spectrum on the sun (the damage checks, ISO 6336-6): each mesh's bins as the load's case, its own cycles
    spectra = None
    if opts.get("spectrum") is not None:
        given = opts["spectrum"]
        spectra = [mesh_spectra(*z, s) for s in (given if isinstance(given, (list, tuple)) else [given])]
        cycles = {tag: spectra[0][tag][1] for tag in MESH_NAMES}
        if cases is not None and any(cases[tag][1] != cycles[tag] for tag in MESH_NAMES):
            raise GearDesignError("the load and the spectrum give the meshes different load cycles")
    else:
        cycles = {tag: cases[tag][1] for tag in MESH_NAMES}
    sun = opts.get("material")
    planet = own.get("planet_material") or sun
    materials = {"sun-planet": (sun, planet), "planet-ring": (planet, own.get("ring_material") or sun)}
    strength = opts.get("strength") or {}
    if not isinstance(strength, dict):
        raise GearDesignError(f"strength must be a dict of pair_strength options, got {type(strength).__name__}")
    out = []
    for tag in MESH_NAMES:
        mesh = {**opts, "material": materials[tag][0], "material2": materials[tag][1],
                "strength": {**strength, "cycles_per_rev": cycles[tag]}}
        if cases is not None:
            mesh["load"] = cases[tag][0]
        if spectra is not None:
            parts = [s[tag][0] for s in spectra]
            mesh["spectrum"] = parts if isinstance(opts["spectrum"], (list, tuple)) else parts[0]
            # the planet is an idler between sun and ring: its root bends both ways once per relative revolution,
            # so its limit is times Y_M (ISO 6336-3:2019's alternating bending) in both meshes' damage checks
            mesh["alternating"] = (False, True) if tag == "sun-planet" else (True, False)
        out.append(mesh)
    return tuple(out)


@dataclass(frozen=True)
class PlanetarySet:
    """A simple planetary set of given shifts: sun, ``n_planets`` planets, ring.

    Parameters
    ----------
    m : module, mm (normal module of a helical set).  z_sun, z_planet, z_ring : tooth counts (the
        ring's a positive count).  n_planets : planets, 1..64.  x_sun, x_planet, x_ring : shift
        coefficients (GOST 19274-73 sign for the ring: positive moves its flanks outward).
    rack, beta_deg : the basic rack and helix angle of all three gears.
    arrangement : "ring_fixed" (sun in, carrier out; default), "carrier_fixed" (sun in, ring out)
        or "sun_fixed" (ring in, carrier out).
    planet_angles_deg : carrier angles of the planets from planet 1 for unequal spacing (None:
        equally spaced).
    cutter : the ring's :class:`~geardesign.gears.ring.ShaperCutter` (None: the standard one).

    >>> s = PlanetarySet(1.75, 21, 43, 108, 3, 0.438, 0.0426, 0.0)     # LECAD's test run
    >>> round(s.ratio, 5), round(s.a_w, 3), round(s.a_w_planet_ring, 3)   # printed 6.14286, a = 56.8
    (6.14286, 56.8, 56.8)
    """

    m: float
    z_sun: int
    z_planet: int
    z_ring: int
    n_planets: int
    x_sun: float = 0.0
    x_planet: float = 0.0
    x_ring: float = 0.0
    rack: BasicRack = STANDARD_RACK
    beta_deg: float = 0.0
    arrangement: str = "ring_fixed"
    planet_angles_deg: tuple | None = None
    cutter: object = None
    meshes: PlanetaryMeshes = field(init=False, repr=False)

    def __post_init__(self):
        object.__setattr__(self, "m", float(one_number("m (module)", require_module(self.m))))
        for name in ("x_sun", "x_planet", "x_ring"):
            object.__setattr__(self, name, float(one_number(name, require_range(name, getattr(self, name),
                                                                                  -X_ABS_MAX, X_ABS_MAX))))
        require_choice("arrangement", self.arrangement, tuple(ARRANGEMENTS))
        meshes = PlanetaryMeshes(self.z_sun, self.z_planet, self.z_ring, self.n_planets, self.rack, self.beta_deg,
                                 self.planet_angles_deg)
        object.__setattr__(self, "meshes", meshes)
        for name in ("z_sun", "z_planet", "z_ring", "n_planets", "rack", "beta_deg", "planet_angles_deg"):
            object.__setattr__(self, name, getattr(meshes, name))
        geo = set_geometry(meshes, self.m, self.x_sun, self.x_planet, self.x_ring)
        for tag in MESH_NAMES:
            g = geo[tag]
            if not (g["inv_alpha_w"] > 0 and g["_gap1"] > 0 and g["_gap2"] > 0 and g["g_alpha"] > 0):
                mesh = meshes.sun_planet if tag == "sun-planet" else meshes.planet_ring
                x1, x2 = (self.x_sun, self.x_planet) if tag == "sun-planet" else (self.x_planet, self.x_ring)
                try:
                    validate_geometry(mesh_geometry(mesh, self.m, x1, x2), mesh, contact=True)
                except GearDesignError as exc:
                    raise GearDesignError(f"{tag} mesh: {exc}") from None
        object.__setattr__(self, "_geo", geo)

    @property
    def ratio(self) -> float:
        """n_in/n_out for :attr:`arrangement` (see :func:`planetary_ratio`)."""
        return planetary_ratio(self.z_sun, self.z_ring, self.arrangement)

    @property
    def a_w(self) -> float:
        """Operating centre distance of the sun–planet mesh, mm (the carrier's arm)."""
        return float(self._geo["a_w"])

    @property
    def a_w_planet_ring(self) -> float:
        """Operating centre distance of the planet–ring mesh, mm (equal to :attr:`a_w` in a coaxial set)."""
        return float(self._geo["a_w_pr"])

    def geometry(self) -> dict:
        """{"sun-planet": Geometry, "planet-ring": Geometry} of the two meshes."""
        return {tag: Geometry.from_float(self._geo[tag]) for tag in MESH_NAMES}

    @classmethod
    def coaxial(cls, m, z_sun, z_planet, z_ring, n_planets, x_sun=0.0, x_planet=0.0, **kw) -> "PlanetarySet":
        """The set whose ring shift makes both meshes' a_w equal, for given sun and planet shifts."""
        meshes = PlanetaryMeshes(z_sun, z_planet, z_ring, n_planets, kw.get("rack", STANDARD_RACK),
                                 kw.get("beta_deg", 0.0))
        m = float(one_number("m (module)", require_module(m)))
        x_sun, x_planet = (float(one_number(n, require_range(n, v, -X_ABS_MAX, X_ABS_MAX)))
                           for n, v in (("x_sun", x_sun), ("x_planet", x_planet)))
        geo = set_geometry(meshes, m, x_sun, x_planet)
        x_ring = geo["x_ring"]
        if not math.isfinite(x_ring):
            a_min = float(min_center_distance(m, z_planet, z_ring, meshes.rack, meshes.beta_deg, internal=True))
            raise GearDesignError(f"no ring shift makes z_s/z_p/z_r = {z_sun}/{z_planet}/{z_ring} coaxial at "
                                  f"x_sun = {x_sun:g}, x_planet = {x_planet:g}: a_w = {geo['a_w']:.6g} mm must be > "
                                  f"{a_min:.6g} mm for the planet-ring mesh")
        return cls(m, z_sun, z_planet, z_ring, n_planets, x_sun, x_planet, x_ring, **kw)

    def checks(self, checks=None, coaxiality_tol_mm: float | None = None):
        """Table of every check of both meshes and of the set (``mesh`` column:
        sun-planet, planet-ring or set): ``check, mesh, margin, ok, value, limit, label``.
        ``checks``: as :func:`set_checks`; the set's coaxiality and assembly are always there."""
        if coaxiality_tol_mm is not None:
            coaxiality_tol_mm = one_number("coaxiality_tol_mm", require_positive("coaxiality_tol_mm",
                                                                                 coaxiality_tol_mm, unit="mm"))
        cs = set_checks(self.meshes, checks, self.cutter, self.arrangement) + (Coaxiality(tol_mm=coaxiality_tol_mm), Assembly(meshes=self.meshes))
        table = _checks.evaluate(self._geo, cs)
        table.insert(1, "mesh", [c.split(":", 1)[0] for c in table["check"]])
        table["margin"] = table["margin"].where(table["margin"].abs() > _checks.FEASIBILITY_TOL, 0.0)
        return table[["check", "mesh", "margin", "ok", "value", "limit", "label"]]

    def ok(self, **kw) -> bool:
        """True when every check of :meth:`checks` holds."""
        return bool(self.checks(**kw)["ok"].all())

