"""The strength of both meshes of a planetary set, the sun's torque shared over the planets with the mesh
load factor K_γ (ISO 6336-1:2019 clause 6.4)."""
from __future__ import annotations

import dataclasses
import math

import numpy as np

from ...errors import GearDesignError
from ...validate import one_number, require_range
from ..geometry import mesh_geometry_float
from ..mesh import Mesh
from .chain import CHAIN_GEOMETRY_FIELDS, check_options, pair_strength
from .load import Load
from .options import DEFAULT_OPTIONS, gathered
from .result import StrengthResult, from_chain

__all__ = ["planetary_strength", "planetary_life", "mesh_loads", "mesh_spectra", "set_tips", "TIPS"]

# the tips planetary_strength may take: the set's unshortened tips, or the sun and planet shortened by the sun-planet
# mesh's k·m (ISO 21771: tip alteration, as a pair's tips are); a dict of diameters gives them as made
TIPS = ("unshortened", "shortened")


# the pair_strength options a set fixes itself
_SET_OWN = ("beta_deg", "rack", "tip_shortening", "internal", "cycles_per_rev", "geometry")


def _carrier_speed(arrangement: str, z_sun: int, z_ring: int, n_sun: float) -> float:
    """Carrier speed (rpm) with the sun at ``n_sun``: ring fixed n_c = n_s z_s/(z_s + z_r); carrier fixed 0."""
    if arrangement == "ring_fixed":
        return n_sun * z_sun / (z_sun + z_ring)
    if arrangement == "carrier_fixed":
        return 0.0
    raise GearDesignError(f"the strength of a planetary set takes the load on the sun, so the sun must turn: "
                          f"arrangement must be 'ring_fixed' or 'carrier_fixed', got {arrangement!r}")


def mesh_loads(z_sun: int, z_planet: int, z_ring: int, n_planets: int, arrangement: str, load: Load) -> dict:
    """The load of each mesh of a planetary set whose sun carries ``load``: {"sun-planet": (Load on the sun,
    cycles_per_rev), "planet-ring": (Load on the planet, cycles_per_rev)}. Each mesh carries T_sun/N (the
    planets share the torque; K_γ of ISO 6336-1:2019 6.4 is the caller's), at the speeds relative to the
    carrier, n_s − n_c on the sun and (n_s − n_c) z_s/z_p on the planet; a sun tooth meets N planets per
    relative revolution, a ring tooth N, a planet tooth one of each.

    >>> sp, pr = mesh_loads(20, 31, 82, 3, "ring_fixed", Load(torque_nm=300, n_rpm=1020)).values()
    >>> sp[0].torque_nm, round(sp[0].n_rpm, 6), sp[1], round(pr[0].torque_nm, 6), pr[1]
    (100.0, 820.0, (3, 1), 155.0, (1, 3))
    """
    if not isinstance(load, Load) or load.on_gear != 1:
        raise GearDesignError("load must be a geardesign Load given on the sun (on_gear=1)")
    n_sun_rel = abs(load.n_rpm - _carrier_speed(arrangement, z_sun, z_ring, load.n_rpm))
    if n_sun_rel == 0.0:
        raise GearDesignError("the sun turns with the carrier: no mesh is loaded cyclically")
    t_mesh = load.torque_nm / n_planets
    kept = dict(on_gear=1, application_factor=load.application_factor, life_h=load.life_h)
    return {"sun-planet": (Load(torque_nm=t_mesh, n_rpm=n_sun_rel, **kept), (n_planets, 1)),
            "planet-ring": (Load(torque_nm=t_mesh * z_planet / z_sun, n_rpm=n_sun_rel * z_sun / z_planet, **kept),
                            (1, n_planets))}


def mesh_spectra(z_sun: int, z_planet: int, z_ring: int, n_planets: int, arrangement: str, spectrum) -> dict:
    """The load spectrum of each mesh of a planetary set whose sun carries ``spectrum`` (a
    :class:`~geardesign.gears.spectrum.LoadSpectrum` of bins given on the sun, ``on_gear`` 1), bin by bin as
    :func:`mesh_loads` loads one case: {"sun-planet": (spectrum on the sun, cycles_per_rev), "planet-ring":
    (spectrum on the planet, cycles_per_rev)}, each mesh T_sun/N (signed: a reversed bin stays reversed) at the
    speeds relative to the carrier, the bins' hours kept. A spectrum counted per tooth is refused: its teeth are
    a pair's, and a set's sun meets N planets.

    >>> from geardesign.gears.spectrum import LoadSpectrum
    >>> s = LoadSpectrum.from_bins([300, -150], 1020, time_h=[10, 5])
    >>> sp, pr = mesh_spectra(20, 31, 82, 3, "ring_fixed", s).values()
    >>> sp[0].torque_nm.tolist(), sp[0].n_rpm.tolist(), sp[1], pr[0].torque_nm.tolist(), pr[1]
    ([100.0, -50.0], [820.0, 820.0], (3, 1), [155.0, -77.5], (1, 3))
    """
    from ..spectrum import LoadSpectrum

    if not isinstance(spectrum, LoadSpectrum) or spectrum.on_gear != 1:
        raise GearDesignError("a planetary set's spectrum must be a geardesign LoadSpectrum given on the sun "
                              "(on_gear=1)")
    if spectrum.per_tooth:
        raise GearDesignError("a spectrum counted per tooth belongs to the pair it was counted for: give a planetary "
                              "set a spectrum of bins (LoadSpectrum.from_bins or from_csv) on the sun")
    carrier = np.array([_carrier_speed(arrangement, z_sun, z_ring, float(n)) for n in spectrum.n_rpm])
    n_rel = np.abs(spectrum.n_rpm - carrier)
    if not np.all(n_rel > 0.0):
        raise GearDesignError("the sun turns with the carrier: no mesh is loaded cyclically")
    t_mesh = spectrum.torque_nm / n_planets
    return {"sun-planet": (LoadSpectrum(t_mesh, n_rel, spectrum.time_h, 1), (n_planets, 1)),
            "planet-ring": (LoadSpectrum(t_mesh * z_planet / z_sun, n_rel * z_sun / z_planet, spectrum.time_h, 1),
                            (1, n_planets))}


def _contact_ratio(g: dict, da1: float, da2: float, internal: bool) -> float:
    """ε_α = g_α/p_bt of a mesh's geometry ``g`` with tip diameters ``da1``, ``da2``: each gear's part of the path of
    contact √(r_a² − r_b²) − r_b tan α_wt, a ring's r_b tan α_wt − √(r_a² − r_b²) (ISO 21771:2007 5.4)."""
    tan_w = math.sqrt(g["dw1"] ** 2 - g["db1"] ** 2) / g["db1"]
    e1 = math.sqrt(da1 * da1 - g["db1"] ** 2) / 2.0 - g["db1"] / 2.0 * tan_w
    rho2 = math.sqrt(da2 * da2 - g["db2"] ** 2) / 2.0
    e2 = g["db2"] / 2.0 * tan_w - rho2 if internal else rho2 - g["db2"] / 2.0 * tan_w
    return (e1 + e2) / g["p_b"]


def set_tips(pset, tips="unshortened") -> dict:
    """The tip diameters (mm) planetary strength uses: {"sun": d_a, "planet": d_a, "ring": d_a}. ``"unshortened"``:
    the set's own (d ± 2(h_a* ± x)m, as its checks have them); ``"shortened"``: the sun's and planet's shortened by
    the sun-planet mesh's tip alteration k·m (ISO 21771:2007, as a pair's tips are; a ring is not shortened);
    a dict with any of "sun", "planet", "ring": those diameters as made (the others unshortened).

    >>> from geardesign.gears.planetary import PlanetarySet
    >>> s = PlanetarySet(45, 19, 17, 56, 3, 0.617, 0.8021, 0.5013)     # NREL 5 MW stage 1
    >>> {k: round(v, 3) for k, v in set_tips(s, "shortened").items()}
    {'sun': 978.809, 'planet': 905.468, 'ring': 2475.117}
    """
    sp, pr = pset._geo["sun-planet"], pset._geo["planet-ring"]
    out = {"sun": float(sp["da1"]), "planet": float(sp["da2"]), "ring": float(pr["da2"])}
    if isinstance(tips, str) and tips in TIPS:
        if tips == "shortened":
            mesh = Mesh(pset.z_sun, pset.z_planet, pset.rack, True, pset.beta_deg)
            short = mesh_geometry_float(mesh, pset.m, pset.x_sun, pset.x_planet, full=False, tips=False)
            out.update(sun=float(short["da1"]), planet=float(short["da2"]))
        return out
    if not isinstance(tips, dict) or not tips or not set(tips) <= set(out):
        raise GearDesignError(f"tips must be 'unshortened', 'shortened' or a dict of tip diameters in mm with keys "
                              f"'sun', 'planet', 'ring', got {tips!r}")
    for gear, d in tips.items():
        d = float(one_number(f"tips[{gear!r}]", require_range(f"tips[{gear!r}]", d, 0.0, 1e9, lo_open=True,
                                                              unit="mm")))
        base = (sp["db1"] if gear == "sun" else sp["db2"] if gear == "planet" else pr["db2"])
        root = (sp["df1"] if gear == "sun" else sp["df2"] if gear == "planet" else pr["df2"])
        if gear != "ring" and not base < d or gear == "ring" and not d < root:
            lo_hi = (f"above the base circle {base:.6g} mm" if gear != "ring" else
                     f"below the root circle {root:.6g} mm")
            raise GearDesignError(f"tips[{gear!r}] = {d:g} mm: an {'external' if gear != 'ring' else 'internal'} "
                                  f"gear's tip diameter must lie {lo_hi}")
        out[gear] = d
    return out


def _mesh_geometry(pset, tag: str, da1: float, da2: float) -> dict:
    """The chain's geometry fields of one mesh of the set with these tip diameters (ε_α recomputed)."""
    g = pset._geo[tag]
    internal = tag == "planet-ring"
    geo = {k: float(g[k]) for k in CHAIN_GEOMETRY_FIELDS}
    geo.update(da1=da1, da2=da2, eps_alpha=_contact_ratio(g, da1, da2, internal), _z1=float(g["_z1"]),
               _z2=float(g["_z2"]))
    if not geo["eps_alpha"] > 0.0:
        raise GearDesignError(f"{tag} mesh: no path of contact with these tips (eps_alpha = {geo['eps_alpha']:.4g})")
    return geo


def planetary_strength(pset, load: Load, material=None, *, face_width_mm: float, K_gamma: float = 1.0,
                       planet_material=None, ring_material=None, tips="unshortened",
                       **options) -> dict[str, StrengthResult]:
    """ISO 6336 strength of the sun-planet and planet-ring meshes of a
    :class:`~geardesign.gears.planetary.PlanetarySet`: ``load`` is the sun's torque (or power) and its speed
    (``on_gear`` 1); each mesh carries T_sun/N_planets (F_t = 2000 T_s/(N d_s)) times ``K_gamma``, the mesh
    load factor of ISO 6336-1:2019 6.4 (1.0 for ideal sharing). Speeds are relative to the carrier; a sun
    tooth meets N planets per relative revolution, a ring tooth N. Materials: ``material`` for all three
    gears unless ``planet_material`` or ``ring_material`` is given. Returns {"sun-planet": ..., "planet-ring":
    ...}. The planet's root is loaded in both directions (reversed bending); its root safety here is the
    one-directional value of ISO 6336-3 without the mean stress factor. ``tips``: the tip diameters the meshes
    have (ε_α, the root's load point, the tooth depth): ``"unshortened"`` (the default: the set's own tips, as its
    geometric checks have them), ``"shortened"`` (sun and planet shortened by the sun-planet mesh's k·m, as a pair's
    are) or a dict of the diameters as made (see :func:`set_tips`).

    >>> from geardesign.gears.planetary import PlanetarySet
    >>> s = PlanetarySet.coaxial(2, 20, 31, 82, 3)
    >>> r = planetary_strength(s, Load(torque_nm=100, n_rpm=1500, life_h=10000), "18CrNiMo7-6", face_width_mm=25)
    >>> sorted(r), r["sun-planet"].S_H1 > 1.0
    (['planet-ring', 'sun-planet'], True)
    """
    if material is None:
        raise GearDesignError("material is needed (a geardesign Material or a name such as '18CrNiMo7-6')")
    taken = sorted(set(options) & set(_SET_OWN))
    if taken:
        raise GearDesignError(f"{', '.join(taken)}: planetary_strength takes these from the set (its helix, rack and "
                              f"the planets' load cycles), not as options")
    check_options(options)
    (sp_load, sp_cycles), (pr_load, pr_cycles) = mesh_loads(pset.z_sun, pset.z_planet, pset.z_ring, pset.n_planets,
                                                             pset.arrangement, load).values()
    common = gathered(dict(beta_deg=pset.beta_deg, rack=pset.rack, tip_shortening=False, face_width_mm=face_width_mm,
                           **options))
    group = common.pop("options", None) or DEFAULT_OPTIONS
    if K_gamma != 1.0:    # the set's mesh load factor given: on the options of both meshes
        group = dataclasses.replace(group, K_gamma=K_gamma)
    d = set_tips(pset, tips)
    geo = ({} if isinstance(tips, str) and tips == "unshortened" else
           {"sun-planet": _mesh_geometry(pset, "sun-planet", d["sun"], d["planet"]),
            "planet-ring": _mesh_geometry(pset, "planet-ring", d["planet"], d["ring"])})
    planet = planet_material or material
    sp = pair_strength(pset.m, pset.z_sun, pset.z_planet, pset.x_sun, pset.x_planet, load=sp_load,
                       material1=material, material2=planet, geometry=geo.get("sun-planet"),
                       options=dataclasses.replace(group, cycles_per_rev=sp_cycles), **common)
    pr = pair_strength(pset.m, pset.z_planet, pset.z_ring, pset.x_planet, pset.x_ring, load=pr_load,
                       material1=planet, material2=ring_material or material, internal=True,
                       geometry=geo.get("planet-ring"), options=dataclasses.replace(group, cycles_per_rev=pr_cycles),
                       **common)
    return {"sun-planet": from_chain(sp, title=f"sun-planet {pset.z_sun}/{pset.z_planet}"),
            "planet-ring": from_chain(pr, title=f"planet-ring {pset.z_planet}/{pset.z_ring}")}


def planetary_life(pset, spectrum, material=None, *, face_width_mm: float, mean_stress_factor, planet_material=None,
                   ring_material=None, life_h=None, sn_curve: str = "iso", **options) -> dict:
    """ISO 6336-6 service life of a :class:`~geardesign.gears.planetary.PlanetarySet` whose sun carries ``spectrum``
    (bins on the sun, as :func:`mesh_spectra` shares them over the meshes), with the planet rated over **both** its
    meshes. Returns ``D_<mode>_<gear>`` (Miner's sums over the required life), ``life_h_<mode>_<gear>`` for mode H
    (pitting) and F (root) of the sun, the planet and the ring, ``planet_flanks`` ({"H": (flank A, flank B), "F":
    (fillet A, fillet B)}: the planet's sums per flank) and ``required_life_h``.

    The planet is an idler between sun and ring: with the sun's torque positive the sun loads one flank of a planet
    tooth (A) and the ring the other (B); a reversed bin swaps them. ISO 6336-6 sums damage per flank, so flank A's
    pitting sum is the sun mesh's positive bins with the ring mesh's negative ones (B the others), each bin on its
    mesh's σ_H/σ_HG. Its root bends both ways once per relative revolution: the alternating bending the repo rates
    a reversing tooth with (:func:`~geardesign.gears.strength.service_life.pair_life`: the root's limit times Y_M,
    ``mean_stress_factor``, ISO 6336-3:2019's mean stress influence, 0.7 in older texts for an idler; each fillet
    summing the bins that put it in tension, the same pairing as the flanks). D of each is the larger of its two
    sums. The sun and the ring are each one mesh's gear (:func:`pair_life` of that mesh). ``options``: the chain's
    (accuracy grade, lubricant, ...), as :func:`planetary_strength` takes them.

    >>> from geardesign.gears.planetary import PlanetarySet
    >>> from geardesign.gears.spectrum import LoadSpectrum
    >>> s = PlanetarySet.coaxial(2, 20, 31, 82, 3)
    >>> r = planetary_life(s, LoadSpectrum.from_bins([400, 250], 1500, time_h=[2000, 8000]), "18CrNiMo7-6",
    ...                    face_width_mm=25, mean_stress_factor=0.7)
    >>> r["D_F_planet"] == max(r["planet_flanks"]["F"])
    True
    """
    from .service_life import pair_life

    if material is None:
        raise GearDesignError("material is needed (a geardesign Material or a name such as '18CrNiMo7-6')")
    taken = sorted(set(options) & set(_SET_OWN + ("alternating", "bins", "mesh")))
    if taken:
        raise GearDesignError(f"{', '.join(taken)}: planetary_life takes these from the set, not as options")
    meshes = mesh_spectra(pset.z_sun, pset.z_planet, pset.z_ring, pset.n_planets, pset.arrangement, spectrum)
    planet = planet_material or material
    common = dict(beta_deg=pset.beta_deg, rack=pset.rack, tip_shortening=False, face_width_mm=face_width_mm,
                  life_h=life_h, sn_curve=sn_curve, mean_stress_factor=mean_stress_factor, bins=True, **options)
    (sp_spec, sp_cycles), (pr_spec, pr_cycles) = meshes.values()
    sp = pair_life(pset.m, pset.z_sun, pset.z_planet, pset.x_sun, pset.x_planet, spectrum=sp_spec,
                   material1=material, material2=planet, alternating=(False, True), cycles_per_rev=sp_cycles,
                   **common)
    pr = pair_life(pset.m, pset.z_planet, pset.z_ring, pset.x_planet, pset.x_ring, spectrum=pr_spec,
                   material1=planet, material2=ring_material or material, internal=True, alternating=(True, False),
                   cycles_per_rev=pr_cycles, **common)
    required = sp["required_life_h"]
    out = {"required_life_h": required, "D_H_sun": sp["D_H1"], "D_F_sun": sp["D_F1"], "D_H_ring": pr["D_H2"],
           "D_F_ring": pr["D_F2"], "planet_flanks": {}}
    # flank A: the sun mesh's positive bins and the ring mesh's negative ones; flank B the others
    sp_pos = sp_spec.torque_nm[sp["bin_index"]] > 0
    pr_pos = pr_spec.torque_nm[pr["bin_index"]] > 0
    for mode in ("H", "F"):
        with np.errstate(divide="ignore"):
            d_sp = np.where(sp["n2"] > 0, sp["n2"] / sp[f"N_{mode}2"], 0.0)
            d_pr = np.where(pr["n1"] > 0, pr["n1"] / pr[f"N_{mode}1"], 0.0)
        flanks = (float(d_sp[sp_pos].sum() + d_pr[~pr_pos].sum()), float(d_sp[~sp_pos].sum() + d_pr[pr_pos].sum()))
        out["planet_flanks"][mode] = flanks
        out[f"D_{mode}_planet"] = max(flanks)
    for key in [k for k in out if k.startswith("D_")]:
        out["life_h_" + key[2:]] = required / out[key] if out[key] > 0 else math.inf
    return out
