"""Scene files: one design case in TOML, validated, run, and written up as a report.

A scene has the optional sections ``[gear]``, ``[teeth]``, ``[chain]``, ``[key]`` (or several
``[[key]]``), ``[study]`` and ``[drive]`` (stages linked from the motor to the output: scene/drive.py), plus top-level ``title`` and ``description``. Only the sections
present are modelled, and only the catalogs they need are loaded. The keys mirror the Python
arguments::

    title = "Seed 000 engine pair"
    [gear]
    module = 8
    z1 = 17
    z2 = 26
    objective = "max_x_sum"
    x1 = 0.898          # optional: also report this pair's geometry and checks
    x2 = 0.517
    [gear.checks]
    eps_alpha_min = 1.2
    [gear.rack]
    alpha_deg = 20

Every value is checked before anything runs: an unknown section or key, a wrong type, a
missing required value or a value out of range raises one :class:`GearDesignError` naming
the file, the key and what was expected. :func:`run_scene` computes everything in memory and
only then writes ``report.md``, the tables (CSV) and the plots (PNG), through a temporary
directory moved into place, so a failed run leaves nothing behind.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from ..errors import GearDesignError
from ..validate import _short
from .schema import SECTIONS, Where, section_schema, type_name, validate_table
from .toml_file import SCENE_BYTES_MAX, SCENE_DEPTH_MAX, SCENE_INT_MAX, read_scene_toml

__all__ = ["Scene", "load_scene", "SCENE_BYTES_MAX", "SCENE_DEPTH_MAX", "SCENE_INT_MAX"]


@dataclass
class Scene:
    """A validated scene: ``sections`` maps each present section to its checked keys."""

    path: str
    title: str
    description: str
    sections: dict = field(default_factory=dict)

    def __contains__(self, name):
        return name in self.sections


def _rack(where, section, spec):
    from ..gears.rack import BasicRack
    if not spec:
        return None
    try:
        return BasicRack(**spec)
    except GearDesignError as exc:
        where.fail(f"{section}.rack", None, str(exc))


def scene_kind(section: dict) -> dict:
    """The kind of pair of a validated [gear] or [teeth] section, as keyword arguments of the
    library (beta_deg, internal, face_width_mm)."""
    return dict(beta_deg=section["beta_deg"], internal=section["internal"], face_width_mm=section.get("face_width_mm"))


def _cross_checks(where: Where, s: dict):
    """Rules between keys, and the checks the libraries would make later, made up front: one step
    per section the scene has."""
    for name, check in _CROSS_CHECKS.items():
        if name in s:
            check(where, s[name], s)


def _cross_gear(where: Where, g: dict, s: dict):
    if ("x1" in g) != ("x2" in g):
        where.fail("gear", "x2" if "x1" in g else "x1", "missing; give both x1 and x2 or neither")
    lo, hi = g["bounds"]
    if not lo < hi:
        where.fail("gear", "bounds", f"expected [lo, hi] with lo < hi, got {_short(list(g['bounds']))}")
    g["_rack"] = _rack(where, "gear", g.get("rack"))
    kind = scene_kind(g)
    if kind["internal"] and not g["z2"] > g["z1"]:
        where.fail("gear", "z2", f"expected a ring with more teeth than the pinion (z2 > z1 = {g['z1']}), "
                                 f"got {_short(g['z2'])}")
    if "a_w" in g:
        from ..gears.geometry import min_center_distance
        from ..gears.rack import BasicRack
        a_cos = float(min_center_distance(g["module"], g["z1"], g["z2"], g["_rack"] or BasicRack(),
                                          kind["beta_deg"], kind["internal"]))
        if g["a_w"] <= a_cos:
            where.fail("gear", "a_w", f"expected a centre distance > a·cos(alpha_t) = {a_cos:.6g} mm, "
                                      f"got {_short(g['a_w'])}")
    if "x1" in g:
        from ..gears.pair import GearPair
        try:
            GearPair(g["module"], g["z1"], g["z2"], g["x1"], g["x2"], **({"rack": g["_rack"]} if g["_rack"] else {}),
                     tip_shortening=g["tip_shortening"], **kind)
        except GearDesignError as exc:
            where.fail("gear", "x1/x2", f"expected a pair that can be built: {exc}")


def _cross_teeth(where: Where, t: dict, s: dict):
    lo, hi = t["z1_range"]
    if lo > hi:
        where.fail("teeth", "z1_range", f"expected [min, max] with min <= max, got {_short(list(t['z1_range']))}")
    t["_rack"] = _rack(where, "teeth", t.get("rack"))


def _cross_planetary(where: Where, p: dict, s: dict):
    p["_rack"] = _rack(where, "planetary", p.get("rack"))
    if "ratio" not in p:
        for k in ("z_sun", "z_planet", "z_ring"):
            if k not in p:
                where.fail("planetary", k, "missing; give z_sun, z_planet and z_ring, or ratio to search them")
    if ("x_sun" in p) != ("x_planet" in p):
        where.fail("planetary", "x_planet" if "x_sun" in p else "x_sun", "missing; give both x_sun and x_planet "
                                                                         "or neither")


def _cross_chain(where: Where, c: dict, s: dict):
    if ("torque_nm" in c) == ("power_kw" in c):
        where.fail("chain", "torque_nm", "expected exactly one of torque_nm or power_kw")
    if "k_e" in c and c.get("conditions"):
        where.fail("chain", "k_e", "expected either k_e or [chain.conditions], not both")
    if c.get("conditions"):
        from ..drives.chain import Conditions
        try:
            Conditions.from_mapping(c["conditions"])
        except GearDesignError as exc:
            where.fail("chain.conditions", None, str(exc))


def _cross_keys(where: Where, keys: list, s: dict):
    from ..drives.key import section as key_section
    for k in keys:
        try:
            key_section(k["d_mm"])
        except GearDesignError as exc:
            where.fail("key", "d_mm", f"expected a shaft diameter in the key table: {exc}")


def _cross_study(where: Where, st: dict, s: dict):
    target = st["target"]
    if target not in s:
        where.fail("study", "target", f"expected a section that the scene models; [{target}] is missing")
    if ("parameter2" in st) != ("values2" in st):
        where.fail("study", "values2" if "parameter2" in st else "parameter2",
                   "missing; give parameter2 and values2 together")
    from ..sensitivity.sweeps import sweep_parameters
    allowed = sweep_parameters(target)
    for key in ("parameter", "parameter2"):
        if key in st and st[key] not in allowed:
            where.fail("study", key, f"expected one of {', '.join(allowed)} for target {_short(target)}, got {_short(st[key])}")
    ints = ("z1", "z2", "strands")
    for key, vals in (("values", "parameter"), ("values2", "parameter2")):
        if key in st and st.get(vals) in ints and any(not float(v).is_integer() for v in st[key]):
            where.fail("study", key, f"expected whole numbers for {_short(st[vals])}, got {_short(list(st[key]))}")
    if st.get("parameter") == st.get("parameter2"):
        where.fail("study", "parameter2", "expected a parameter other than parameter")


# section -> its cross-checks, in the order they run
_CROSS_CHECKS = {"gear": _cross_gear, "teeth": _cross_teeth, "planetary": _cross_planetary, "chain": _cross_chain,
                 "key": _cross_keys, "study": _cross_study}


def _spectrum(where, path: Path, gear: dict, engine) -> None:
    """[gear.spectrum]'s load read into ``spec["_spectrum"]``: its ``file`` (relative to the scene), or without one
    the scene's [engine] torque curve counted per tooth and flank for the section's pair; a bad file fails naming
    the key."""
    from ..gears.spectrum import LoadSpectrum

    spec = gear["spectrum"]
    if "file" not in spec:
        _engine_spectrum(where, gear, engine)
        return
    if "levels" in spec:
        where.fail("gear.spectrum", "levels", "not used with file (it counts the [engine]'s torque curve)")
    name = spec["file"]
    csv = (path.parent / name) if not Path(name).is_absolute() else Path(name)
    try:
        spec["_spectrum"] = LoadSpectrum.from_csv(csv, n_rpm=spec.get("n_rpm"), duration_h=spec.get("duration_h",
                                                  spec.get("life_h")), on_gear=spec["on_gear"])
    except GearDesignError as exc:
        where.fail("gear.spectrum", "file", str(exc))


def _planetary_spectrum(where, path: Path, spec: dict) -> None:
    """[planetary.spectrum]'s file (relative to the scene) read into ``spec["_spectrum"]``, the sun's bins; a bad
    file fails naming the key."""
    from ..gears.spectrum import LoadSpectrum

    name = spec["file"]
    csv = (path.parent / name) if not Path(name).is_absolute() else Path(name)
    try:
        spec["_spectrum"] = LoadSpectrum.from_csv(csv, n_rpm=spec.get("n_rpm"), duration_h=spec.get("duration_h",
                                                  spec.get("life_h")), on_gear=1)
    except GearDesignError as exc:
        where.fail("planetary.spectrum", "file", str(exc))


SPECTRUM_LEVELS = 48      # classes per sign of the engine's torque counted per tooth (as LoadSpectrum.from_curve)


def _engine_spectrum(where, gear: dict, engine) -> None:
    """[gear.spectrum] without a file: the [engine]'s torque curve (the crankshaft carries gear ``on_gear``)
    counted at the mesh instants of the section's pair, per tooth and flank, over one period of the cycle."""
    from ..gears.spectrum import LoadSpectrum

    spec = gear["spectrum"]
    if engine is None:
        where.fail("gear.spectrum", "file", "missing; give a spectrum file, or an [engine] section whose torque "
                                            "curve the gear carries")
    for key in ("n_rpm", "duration_h"):
        if key in spec:
            where.fail("gear.spectrum", key, "not used with the [engine]'s torque curve (its speed and cycle give "
                                             "them); give life_h, the required life")
    if "life_h" not in spec:
        where.fail("gear.spectrum", "life_h", "missing; the [engine]'s spectrum is one run of its cycle, so the "
                                             "required life (hours) is needed")
    angle, torque, n_rpm = engine.engine.analyse(engine.points).curve()
    try:
        spec["_spectrum"] = LoadSpectrum.from_curve(torque, angle_deg=angle, n_rpm=n_rpm,
                                                    teeth=(gear["z1"], gear["z2"]), on_gear=spec["on_gear"],
                                                    levels=spec.get("levels", SPECTRUM_LEVELS),
                                                    period_deg=engine.engine.cycle_deg)
    except GearDesignError as exc:
        where.fail("gear.spectrum", None, f"the [engine]'s torque curve cannot be counted on this pair: {exc}")
    spec["_engine"] = True


def _chain_catalog(where, path: Path, name: str) -> str:
    """A built-in chain catalog's name, or a user's CSV (relative to the scene file) as a path."""
    from ..catalogs.tables import CHAIN_CATALOGS

    if name in CHAIN_CATALOGS:
        return name
    if name.lower().endswith(".csv"):
        csv = (path.parent / name) if not Path(name).is_absolute() else Path(name)
        if not csv.is_file():
            where.fail("chain", "catalog", f"the chain catalog {_short(str(csv))} does not exist")
        return str(csv)
    where.fail("chain", "catalog", f"expected one of {', '.join(CHAIN_CATALOGS)} or a .csv file of chains "
                                   f"(relative to the scene file), got {_short(name)}")

def load_scene(path) -> Scene:
    """Read and validate a scene file; raise one :class:`GearDesignError` on the first problem."""
    path = Path(path)
    where = Where(path)
    raw = read_scene_toml(path)
    top = {k: v for k, v in raw.items() if not isinstance(v, (dict, list)) or k not in SECTIONS}
    for k in top:
        if k not in section_schema(""):
            where.fail("", k, f"unknown section or key; expected sections {', '.join(f'[{s}]' for s in SECTIONS)} "
                              f"and the keys title, description")
    head = validate_table(where, "", top, section_schema(""))
    sections = {}
    for name in SECTIONS:
        if name not in raw:
            continue
        v = raw[name]
        if name == "engine":
            from .engine import engine_section
            if not isinstance(v, dict):
                where.fail(name, None, f"expected a table [{name}], got {_short(v)} ({type_name(v)})")
            sections["engine"] = engine_section(where, path, v, head.get("title", path.stem))
            continue
        if name == "drive":
            from .drive import load_drive
            sections["drive"] = load_drive(where, path, v)
            continue
        if name == "key":
            tables = v if isinstance(v, list) else [v]
            if not tables or not all(isinstance(t, dict) for t in tables):
                where.fail("key", None, f"expected a table [key] or tables [[key]], got {_short(v)}")
            sections["key"] = [validate_table(where, "key" if len(tables) == 1 else f"key #{i + 1}", t, section_schema("key"))
                               for i, t in enumerate(tables)]
            continue
        if not isinstance(v, dict):
            where.fail(name, None, f"expected a table [{name}], got {_short(v)} ({type_name(v)})")
        sections[name] = validate_table(where, name, v, section_schema(name))
    if not sections:
        where.fail("", None, f"expected at least one of the sections {', '.join(f'[{s}]' for s in SECTIONS)}")
    _cross_checks(where, sections)
    if "chain" in sections:
        sections["chain"]["catalog"] = _chain_catalog(where, path, sections["chain"]["catalog"])
    if "spectrum" in sections.get("gear", {}):
        _spectrum(where, path, sections["gear"], sections.get("engine"))
    if "spectrum" in sections.get("planetary", {}):
        _planetary_spectrum(where, path, sections["planetary"]["spectrum"])
    return Scene(str(path), head.get("title", path.stem), head.get("description", ""), sections)
