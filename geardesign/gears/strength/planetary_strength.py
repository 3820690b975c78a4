"""The strength of both meshes of a planetary set, the sun's torque shared over the planets with the mesh
load factor K_γ (ISO 6336-1:2019 clause 6.4)."""
from __future__ import annotations

from ...errors import GearDesignError
from .chain import pair_strength
from .load import Load
from .result import StrengthResult, from_chain

__all__ = ["planetary_strength"]


def _carrier_speed(pset, n_sun: float) -> float:
    """Carrier speed (rpm) with the sun at ``n_sun``: ring fixed n_c = n_s z_s/(z_s + z_r); carrier fixed 0."""
    if pset.arrangement == "ring_fixed":
        return n_sun * pset.z_sun / (pset.z_sun + pset.z_ring)
    if pset.arrangement == "carrier_fixed":
        return 0.0
    raise GearDesignError(f"planetary_strength takes the load on the sun, so the sun must turn: arrangement must be "
                          f"'ring_fixed' or 'carrier_fixed', got {pset.arrangement!r}")


def planetary_strength(pset, load: Load, material=None, *, face_width_mm: float, K_gamma: float = 1.0,
                       planet_material=None, ring_material=None, **options) -> dict[str, StrengthResult]:
    """ISO 6336 strength of the sun-planet and planet-ring meshes of a
    :class:`~geardesign.gears.planetary.PlanetarySet`: ``load`` is the sun's torque (or power) and its speed
    (``on_gear`` 1); each mesh carries T_sun/N_planets (F_t = 2000 T_s/(N d_s)) times ``K_gamma``, the mesh
    load factor of ISO 6336-1:2019 6.4 (1.0 for ideal sharing). Speeds are relative to the carrier; a sun
    tooth meets N planets per relative revolution, a ring tooth N. Materials: ``material`` for all three
    gears unless ``planet_material`` or ``ring_material`` is given. Returns {"sun-planet": ..., "planet-ring":
    ...}. The planet's root is loaded in both directions (reversed bending); its root safety here is the
    one-directional value of ISO 6336-3 without the mean stress factor.

    >>> from geardesign.gears.planetary import PlanetarySet
    >>> s = PlanetarySet.coaxial(2, 20, 31, 82, 3)
    >>> r = planetary_strength(s, Load(torque_nm=100, n_rpm=1500, life_h=10000), "18CrNiMo7-6", face_width_mm=25)
    >>> sorted(r), r["sun-planet"].S_H1 > 1.0
    (['planet-ring', 'sun-planet'], True)
    """
    if not isinstance(load, Load) or load.on_gear != 1:
        raise GearDesignError("load must be a geardesign Load given on the sun (on_gear=1)")
    if material is None:
        raise GearDesignError("material is needed (a geardesign Material or a name such as '18CrNiMo7-6')")
    n_p = pset.n_planets
    n_c = _carrier_speed(pset, load.n_rpm)
    n_sun_rel = abs(load.n_rpm - n_c)
    if n_sun_rel == 0.0:
        raise GearDesignError("the sun turns with the carrier: no mesh is loaded cyclically")
    t_mesh = load.torque_nm / n_p
    common = dict(beta_deg=pset.beta_deg, rack=pset.rack, tip_shortening=False, face_width_mm=face_width_mm,
                  K_gamma=K_gamma, **options)
    planet = planet_material or material
    sp_load = Load(torque_nm=t_mesh, n_rpm=n_sun_rel, on_gear=1, application_factor=load.application_factor,
                   life_h=load.life_h)
    sp = pair_strength(pset.m, pset.z_sun, pset.z_planet, pset.x_sun, pset.x_planet, load=sp_load,
                       material1=material, material2=planet, cycles_per_rev=(n_p, 1), **common)
    n_planet_rel = n_sun_rel * pset.z_sun / pset.z_planet
    pr_load = Load(torque_nm=t_mesh * pset.z_planet / pset.z_sun, n_rpm=n_planet_rel, on_gear=1,
                   application_factor=load.application_factor, life_h=load.life_h)
    pr = pair_strength(pset.m, pset.z_planet, pset.z_ring, pset.x_planet, pset.x_ring, load=pr_load,
                       material1=planet, material2=ring_material or material, internal=True,
                       cycles_per_rev=(1, n_p), **common)
    return {"sun-planet": from_chain(sp, title=f"sun-planet {pset.z_sun}/{pset.z_planet}"),
            "planet-ring": from_chain(pr, title=f"planet-ring {pset.z_planet}/{pset.z_ring}")}
