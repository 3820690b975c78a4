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

from pathlib import Path

from ..errors import GearDesignError
from ..validate import _short
from .schema import Where, engine_schema, type_name, validate_table
from .toml_file import read_scene_toml

__all__ = ["engine_schema", "load_engine", "engine_section", "EngineScene"]


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
    path = Path(path)
    where = Where(path)
    raw = read_scene_toml(path)
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

