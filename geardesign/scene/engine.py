"""The ``[engine]`` table of a scene file: a piston engine whose crankshaft torque drives the gears (issue 38).

``geardesign engine scene.toml`` reads this table (and the top-level ``title``) and leaves the file's other
sections to ``geardesign run``. The keys mirror :class:`geardesign.mechanism.engine.Engine`,
:class:`~geardesign.mechanism.slider_crank.SliderCrank` and the indicator diagram::

    title = "seed 000 engine"
    [engine]
    n_rpm = 1700
    cylinders = 2
    phases_deg = [0, 540]        # or firing_order (+ throws_deg); default: even firing
    mechanical_efficiency = 0.8
    [engine.mechanism]
    crank_radius_mm = 70
    rod_length_mm = 250
    rod_cg_mm = 75
    cylinder_bore_mm = 100
    [engine.pressure]            # kind = "otto" (parametric), "table" (two lists) or "csv" (a file beside the scene)
    kind = "otto"
    compression_ratio = 6.0
    peak_pressure_mpa = 3.2

Every value is checked before anything runs, and a wrong one is one :class:`GearDesignError` naming the file,
the key and what was expected (the scene schema's language, :mod:`geardesign.scene.schema`).
"""
from __future__ import annotations

import tomllib
from pathlib import Path

from ..errors import GearDesignError
from ..validate import _short
from .schema import Where, _F, _I, _Key, type_name, validate_table

__all__ = ["engine_schema", "load_engine", "engine_section", "EngineScene", "EngineGear", "engine_gear"]


def engine_schema() -> dict:
    """The keys of ``[engine]``, ``[engine.mechanism]`` and ``[engine.pressure]``, from the library's ranges."""
    from ..mechanism.cylinders import CYLINDERS_MAX
    from ..mechanism.engine import POINTS_RANGE, SPEED_RANGE_RPM
    from ..mechanism.kinetostatics import GRAVITY_M_S2
    from ..mechanism.pressure import ATMOSPHERE_MPA, PRESSURE_RANGE_MPA
    from ..mechanism.slider_crank import INERTIA_MAX_KG_M2, MASS_MAX_KG

    p_lo, p_hi = PRESSURE_RANGE_MPA
    mass = dict(default=0.0, lo=0.0, hi=MASS_MAX_KG)
    pos = dict(lo=0.0, lo_open=True)
    return {
        "n_rpm": _F(required=True, lo=SPEED_RANGE_RPM[0], hi=SPEED_RANGE_RPM[1], lo_open=True),
        "cylinders": _I(default=1, lo=1, hi=CYLINDERS_MAX),
        "strokes": _I(default=4, lo=2, hi=4),
        "firing_order": _Key("ints", lo=1, hi=CYLINDERS_MAX), "throws_deg": _Key("floats", lo=-720.0, hi=720.0),
        "phases_deg": _Key("floats", lo=0.0, hi=720.0), "axis_tilts_deg": _Key("floats", lo=-180.0, hi=180.0),
        "mechanical_efficiency": _F(lo=0.0, hi=1.0, lo_open=True),
        "flywheel_inertia_kg_m2": _F(lo=0.0, hi=INERTIA_MAX_KG_M2, lo_open=True),
        "crankcase_pressure_mpa": _F(default=ATMOSPHERE_MPA, lo=p_lo, hi=p_hi),
        "gravity_m_s2": _F(default=GRAVITY_M_S2, lo=0.0, hi=100.0),
        "points": _I(default=720, lo=POINTS_RANGE[0], hi=POINTS_RANGE[1]),
        "name": _Key("str"),
        "mechanism": {
            "crank_radius_mm": _F(required=True, **pos), "rod_length_mm": _F(required=True, **pos),
            "rod_cg_mm": _F(default=0.0, lo=0.0), "offset_mm": _F(default=0.0),
            "piston_mass_kg": _F(**mass), "rod_mass_kg": _F(**mass),
            "rod_inertia_kg_m2": _F(default=0.0, lo=0.0, hi=INERTIA_MAX_KG_M2),
            "crank_mass_kg": _F(**mass), "crank_cg_mm": _F(default=0.0),
            "cylinder_bore_mm": _F(required=True, **pos)},
        "pressure": {
            "kind": _Key("choice", required=True, choices=("otto", "table", "csv")),
            # kind = "otto": the parametric cycle (mechanism.pressure.otto_pressure)
            "compression_ratio": _F(lo=1.0, hi=40.0, lo_open=True),
            "intake_pressure_mpa": _F(default=0.09, lo=p_lo, hi=p_hi, lo_open=True),
            "exhaust_pressure_mpa": _F(default=0.11, lo=p_lo, hi=p_hi, lo_open=True),
            "peak_pressure_mpa": _F(lo=p_lo, hi=p_hi, lo_open=True),
            "polytropic_compression": _F(default=1.37, lo=1.0, hi=1.7),
            "polytropic_expansion": _F(default=1.25, lo=1.0, hi=1.7),
            "table_points": _I(default=1440, lo=POINTS_RANGE[0], hi=POINTS_RANGE[1]),
            # kind = "table": absolute pressures at cycle angles
            "crank_angle_deg": _Key("floats", lo=0.0, hi=720.0), "pressure_mpa": _Key("floats", lo=p_lo, hi=p_hi),
            # kind = "csv": a file with the columns crank_angle_deg, pressure_mpa (relative to the scene)
            "csv": _Key("str")}}


class EngineScene:
    """A loaded ``[engine]`` table: the :class:`~geardesign.mechanism.engine.Engine`, the points to sample and the
    scene's title."""

    def __init__(self, path: str, title: str, engine, points: int, has_gear: bool = False):
        self.path, self.title, self.engine, self.points = path, title, engine, points
        self.has_gear = has_gear      # the file has a [gear] section too: the engine's gear (engine_gear)

    def __repr__(self) -> str:
        return f"EngineScene({self.path!r}, {self.title!r}, {self.engine.cylinders} cylinders, {self.points} points)"


_NEEDS = {"otto": ("compression_ratio", "peak_pressure_mpa"), "table": ("crank_angle_deg", "pressure_mpa"),
          "csv": ("csv",)}


def _diagram(where: Where, path: Path, p: dict, mech: dict, strokes: int):
    from ..mechanism.pressure import IndicatorDiagram

    kind = p["kind"]
    for key in _NEEDS[kind]:
        if key not in p:
            where.fail("engine.pressure", key, f"missing; kind = {kind!r} needs {', '.join(_NEEDS[kind])}")
    others = {k for need in _NEEDS.values() for k in need} - set(_NEEDS[kind])
    for key in sorted(others & set(p)):
        where.fail("engine.pressure", key, f"not used by kind = {kind!r} (it needs {', '.join(_NEEDS[kind])})")
    if kind == "otto":
        keys = ("intake_pressure_mpa", "exhaust_pressure_mpa", "peak_pressure_mpa", "polytropic_compression",
                "polytropic_expansion")
        return IndicatorDiagram.otto(mech["crank_radius_mm"], mech["rod_length_mm"], p["compression_ratio"],
                                     offset_mm=mech["offset_mm"], points=p["table_points"], strokes=strokes,
                                     **{k: p[k] for k in keys})
    if kind == "table":
        return IndicatorDiagram(p["crank_angle_deg"], p["pressure_mpa"], strokes, source=f"{path.name} [engine.pressure]")
    csv = Path(p["csv"]) if Path(p["csv"]).is_absolute() else path.parent / p["csv"]
    if not csv.is_file():
        where.fail("engine.pressure", "csv", f"the indicator diagram {_short(str(csv))} does not exist")
    return IndicatorDiagram.from_csv(csv, strokes)


def load_engine(path) -> EngineScene:
    """Read a scene file's ``[engine]`` table (and its ``title``) and build the engine; one GearDesignError naming
    the file and the key on the first problem."""
    from .load import _check_values, _read_bounded

    path = Path(path)
    where = Where(path)
    text = _read_bounded(path)
    try:
        raw = tomllib.loads(text.decode("utf-8"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as exc:
        raise GearDesignError(f"{path}: not a valid TOML file: {' '.join(str(exc).split())}") from None
    except RecursionError:
        raise GearDesignError(f"{path}: nested too deep for a scene file") from None
    _check_values(path, raw)
    if "engine" not in raw:
        where.fail("", None, "expected an [engine] section (the engine whose torque the command computes)")
    if not isinstance(raw["engine"], dict):
        where.fail("engine", None, f"expected a table [engine], got {_short(raw['engine'])} "
                                   f"({type_name(raw['engine'])})")
    title = raw.get("title", path.stem)
    if not isinstance(title, str):
        where.fail("", "title", f"expected a string, got {_short(title)} ({type_name(title)})")
    out = engine_section(where, path, raw["engine"], title)
    out.has_gear = "gear" in raw
    return out


def engine_section(where: Where, path: Path, table: dict, title: str) -> EngineScene:
    """The scene's ``[engine]`` table (``table``, as read from the file at ``path``) validated and built; the
    engine's name defaults to the scene's ``title``. Shared by ``geardesign engine`` and ``geardesign run``."""
    from ..mechanism.engine import Engine
    from ..mechanism.slider_crank import SliderCrank

    path = Path(path)
    e = validate_table(where, "engine", table, engine_schema())
    for sub in ("mechanism", "pressure"):
        if sub not in e:
            where.fail("engine", sub, f"missing; expected a table [engine.{sub}]")
    if e["strokes"] not in (2, 4):
        where.fail("engine", "strokes", f"expected 2 or 4, got {e['strokes']}")
    try:
        mech = SliderCrank(**e["mechanism"])
    except GearDesignError as exc:
        where.fail("engine.mechanism", None, str(exc))
    try:
        diagram = _diagram(where, path, e["pressure"], e["mechanism"], e["strokes"])
    except GearDesignError as exc:
        if str(exc).startswith(str(path)):
            raise
        where.fail("engine.pressure", None, str(exc))
    kw = {k: e[k] for k in ("cylinders", "mechanical_efficiency", "flywheel_inertia_kg_m2", "crankcase_pressure_mpa",
                            "gravity_m_s2") if k in e}
    kw["name"] = e.get("name", title)
    for k in ("firing_order", "throws_deg", "phases_deg", "axis_tilts_deg"):
        if k in e:
            kw[k] = tuple(e[k])
    try:
        engine = Engine(mech, diagram, e["n_rpm"], **kw)
    except GearDesignError as exc:
        where.fail("engine", None, str(exc))
    return EngineScene(str(path), title, engine, e["points"])


class EngineGear:
    """The engine's gear end to end (:func:`engine_gear`): ``torque`` (the
    :class:`~geardesign.mechanism.engine.EngineTorque`), ``spectrum`` (its curve counted on the pair), ``optimum``
    (the :class:`~geardesign.shifts.result.ShiftResult` of the section's objective, ``max_life`` by default),
    ``life`` ({"given": ..., "optimum": ...}: :class:`~geardesign.gears.strength.life_result.LifeResult` at the
    scene's shifts and at the optimum), ``given_failed`` (the checks the scene's shifts fail) and ``failures``
    (what fails, one phrase each; empty: the engine does work and its gear reaches the required life at the
    optimal shifts, the given ones holding every check)."""

    def __init__(self, scene, torque, spectrum, optimum, life: dict, given_failed: list):
        self.scene, self.torque, self.spectrum, self.optimum = scene, torque, spectrum, optimum
        self.life, self.given_failed = life, given_failed

    @property
    def failures(self) -> list:
        out = [] if self.torque.success else ["the engine does no work over the cycle"]
        if not self.optimum.success:
            out.append("no shifts hold every check")
        best = self.life.get("optimum")
        if best is not None and not best.ok:
            mode = best.governing[0]
            out.append(f"at the best shifts the gear's life is {best.life_h:.4g} h < {best.required_life_h:.6g} h "
                       f"({'pitting' if mode[0] == 'H' else 'root'}, gear {mode[1]})")
        if self.given_failed:
            out.append("the given shifts fail " + ", ".join(self.given_failed))
        return out

    def to_dict(self) -> dict:
        from ..results import plain

        o = self.optimum
        return {"ok": not self.failures, "failures": self.failures, "title": self.scene.title,
                "engine": self.torque.to_dict(),
                "spectrum": {"bins": int(self.spectrum.torque_nm.size), "on_gear": self.spectrum.on_gear,
                             "per_tooth": self.spectrum.per_tooth, "reverses": self.spectrum.reverses,
                             "max_torque_nm": float(self.spectrum.torque_nm.max()),
                             "min_torque_nm": float(self.spectrum.torque_nm.min()),
                             "histogram": self.spectrum.histogram().to_dict(orient="records")},
                "optimum": {"objective": o.objective, "x1": o.x1, "x2": o.x2, "fun": o.fun, "success": o.success,
                            "active": list(o.active), "message": o.message},
                "life": {tag: {"x1": x[0], "x2": x[1], "ok": r.ok, "life_h": r.life_h,
                               "required_life_h": r.required_life_h,
                               "damage": plain(r.damage_table().to_dict(orient="records"))}
                         for tag, (x, r) in self._lives().items()},
                "given_failed": list(self.given_failed)}

    def _lives(self) -> dict:
        g = self.scene.sections["gear"]
        at = {"given": (g.get("x1"), g.get("x2")), "optimum": (self.optimum.x1, self.optimum.x2)}
        return {tag: (at[tag], r) for tag, r in self.life.items()}


def engine_gear(scene) -> EngineGear:
    """A loaded scene (:func:`geardesign.scene.load.load_scene`) with ``[engine]`` and ``[gear]`` whose
    ``[gear.spectrum]`` counts the engine's torque: the torque over the cycle, the spectrum on the pair, the shifts
    of the section's objective (``max_life``, the longest life, unless it names another) under its checks and the
    damage checks, and the life at the scene's shifts and at the optimum (ISO 6336-6)."""
    from ..gears.pair import GearPair
    from ..shifts.optimize import optimize_shifts
    from .load import scene_kind
    from .sections import _checks_dict

    where = Where(scene.path)
    g = scene.sections["gear"]
    if "spectrum" not in g:
        where.fail("gear", "spectrum", "missing; the engine's gear needs [gear.spectrum] (material, life_h, "
                                       "mean_stress_factor) to count the engine's torque on it")
    sp = g["spectrum"]
    if not sp.get("_engine"):
        where.fail("gear.spectrum", "file", "the engine command counts the [engine]'s torque on the gear: drop the "
                                            "file (geardesign run rates a file's spectrum)")
    e = scene.sections["engine"]
    torque = e.engine.analyse(e.points)
    checks = _checks_dict(g.get("checks"), g)
    kind = scene_kind(g)
    pair_kw = dict(**({"rack": g["_rack"]} if g["_rack"] else {}), tip_shortening=g["tip_shortening"], **kind)
    opt = optimize_shifts(g["z1"], g["z2"], objective=g.get("objective") or "max_life", method=g["method"],
                          m=g["module"], a_w=g.get("a_w"), checks=checks, bounds=tuple(g["bounds"]),
                          rack=g["_rack"], tip_shortening=g["tip_shortening"], **kind)
    spectrum = checks["spectrum"]
    at = ([("given", g["x1"], g["x2"])] if "x1" in g else []) + ([("optimum", opt.x1, opt.x2)] if opt.success else [])
    life, given_failed = {}, []
    for tag, x1, x2 in at:
        pair = GearPair(g["module"], g["z1"], g["z2"], x1, x2, **pair_kw)
        life[tag] = pair.life(spectrum, sp["material"], material2=sp.get("material2"),
                              face_width_mm=checks["face_width_mm"], life_h=sp.get("life_h"), sn_curve=sp["sn_curve"],
                              mean_stress_factor=sp.get("mean_stress_factor"), **checks.get("strength", {}))
        if tag == "given":
            table = pair.checks(**checks, housing_a_w=g.get("a_w"))
            given_failed = table.loc[~table["ok"], "check"].tolist()
    return EngineGear(scene, torque, spectrum, opt, life, given_failed)
