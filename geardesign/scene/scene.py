"""Scene files: one design case in TOML, validated, run, and written up as a report.

A scene has the optional sections ``[gear]``, ``[teeth]``, ``[chain]``, ``[key]`` (or several
``[[key]]``) and ``[study]``, plus top-level ``title`` and ``description``. Only the sections
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

import math
import time
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from ..catalogs.tables import CHAIN_CATALOGS
from ..files import check_output_dir, write_dir_atomic
from ..errors import GearDesignError

__all__ = ["load_scene", "run_scene", "Scene", "SceneReport", "SECTIONS"]

SECTIONS = ("gear", "teeth", "chain", "key", "study")
_OBJECTIVES = ("max_x_sum", "max_eps_alpha", "balanced_sliding", "min_specific_pressure", "max_margin")
_SHIFT_METHODS = ("grid", "convex", "exact")
_CHAIN_OBJECTIVES = ("min_mass", "min_width", "min_sprocket_diameter", "max_safety")
_CHAIN_METHODS = ("hinge_pressure", "power_rating")
_CHAIN_CATALOGS = CHAIN_CATALOGS
_FACTORS = ("k_d", "k_a", "k_n", "k_reg", "k_lub", "k_mode")


# --- a tiny schema language ------------------------------------------------------------------

@dataclass(frozen=True)
class _Key:
    """One scene key: its kind, whether it is required, its default and its range."""

    kind: str                   # "float", "int", "bool", "str", "choice", "floats", "ints", "float_or_str"
    required: bool = False
    default: object = None
    lo: float | None = None
    hi: float | None = None
    lo_open: bool = False
    choices: tuple = ()
    length: int | None = None   # for lists: exact length

    def expected(self) -> str:
        rng = ""
        if self.lo is not None or self.hi is not None:
            left = "(" if self.lo_open else "["
            lo = "-inf" if self.lo is None else f"{self.lo:g}"
            hi = "inf" if self.hi is None else f"{self.hi:g}"
            rng = f" in {left}{lo}, {hi}]"
        if self.kind == "float":
            return "a number" + rng
        if self.kind == "int":
            return "a whole number" + rng
        if self.kind == "bool":
            return "true or false"
        if self.kind == "str":
            return "a string"
        if self.kind == "choice":
            return "one of " + ", ".join(repr(c) for c in self.choices)
        if self.kind == "float_or_str":
            return "a number" + rng + " or one of " + ", ".join(repr(c) for c in self.choices)
        n = f"a list of {self.length} " if self.length else "a list of "
        what = "numbers" if self.kind == "floats" else "whole numbers"
        return f"{n}{what}{rng}"


def _F(**kw):
    return _Key("float", **kw)


def _I(**kw):
    return _Key("int", **kw)


_RACK = {"alpha_deg": _F(default=20.0, lo=0.0, hi=45.0, lo_open=True), "ha": _F(default=1.0, lo=0.0, hi=2.0, lo_open=True),
         "c": _F(default=0.25, lo=0.0, hi=1.0), "rho_f": _F(default=0.38, lo=0.0, hi=1.0)}
_CHECKS = {"eps_alpha_min": _F(lo=0.5, hi=3.0), "sa_min": _F(lo=0.0, hi=1.0), "undercut": _Key("bool"),
           "interference": _Key("bool"), "jamming": _Key("bool")}
_CHECK_SWITCHES = {"eps_alpha": "eps_alpha_min", "sa": "sa_min"}

SCHEMA = {
    "": {"title": _Key("str"), "description": _Key("str")},
    "gear": {
        "module": _F(required=True, lo=0.0, hi=100.0, lo_open=True),
        "z1": _I(required=True, lo=3, hi=10000), "z2": _I(required=True, lo=3, hi=10000),
        "objective": _Key("choice", choices=_OBJECTIVES),   # default: max_x_sum, or balanced_sliding with a_w
        "method": _Key("choice", default="exact", choices=_SHIFT_METHODS),
        "x1": _F(lo=-1.5, hi=3.0), "x2": _F(lo=-1.5, hi=3.0),
        "a_w": _F(lo=0.0, lo_open=True), "tip_shortening": _Key("bool", default=True),
        "bounds": _Key("floats", default=(-1.5, 3.0), lo=-5.0, hi=10.0, length=2),
        "checks": _CHECKS, "rack": _RACK,
    },
    "teeth": {
        "ratio": _F(required=True, lo=1.0, hi=20.0), "ratio_tol": _F(default=0.02, lo=0.0, hi=0.5),
        "module": _Key("float_or_str", lo=0.0, hi=100.0, lo_open=True, choices=("series",)),
        "a_w": _Key("float_or_str", lo=0.0, lo_open=True, choices=("series",)),
        "z1_range": _Key("ints", default=(8, 40), lo=3, hi=1000, length=2), "z_sum_max": _I(lo=6, hi=20000),
        "objective": _Key("choice", choices=_OBJECTIVES),
        "method": _Key("choice", default="exact", choices=_SHIFT_METHODS),
        "top": _I(default=10, lo=1, hi=1000), "checks": _CHECKS, "rack": _RACK,
    },
    "chain": {
        "torque_nm": _F(lo=0.0, lo_open=True), "power_kw": _F(lo=0.0, lo_open=True),
        "n1_rpm": _F(required=True, lo=0.0, hi=20000.0, lo_open=True), "ratio": _F(required=True, lo=1.0, hi=10.0),
        "catalog": _Key("str", default="gost13568"),   # a built-in chain table or a CSV beside the scene
        "k_e": _F(lo=0.1, hi=20.0), "allowable_pressure_mpa": _F(lo=0.0, hi=200.0, lo_open=True),
        "allowable_safety_factor": _F(lo=0.0, hi=100.0, lo_open=True),
        "strands": _Key("ints", default=(1, 2, 3), lo=1, hi=4), "z1": _I(lo=7, hi=120),
        "center_distance_mm": _F(lo=0.0, lo_open=True),
        "objective": _Key("choice", default="min_mass", choices=_CHAIN_OBJECTIVES),
        "method": _Key("choice", default="hinge_pressure", choices=_CHAIN_METHODS),
        "sag_factor": _F(default=6.0, lo=0.5, hi=10.0), "top": _I(default=10, lo=1, hi=1000),
        "conditions": {k: _Key("float_or_str", lo=0.1, hi=10.0, choices=()) for k in _FACTORS},
    },
    "key": {
        "name": _Key("str"), "d_mm": _F(required=True, lo=6.0, hi=500.0), "torque_nm": _F(required=True, lo=0.0, lo_open=True),
        "hub_length_mm": _F(required=True, lo=0.0, lo_open=True),
        "allowable_crush_mpa": _F(default=130.0, lo=0.0, hi=2000.0, lo_open=True),
        "allowable_shear_mpa": _F(default=85.0, lo=0.0, hi=2000.0, lo_open=True),
        "end": _Key("choice", default="rounded", choices=("rounded", "half", "flat")),
        "max_keys": _I(default=2, lo=1, hi=2),
    },
    "study": {
        "target": _Key("choice", default="gear", choices=("gear", "chain")),
        "parameter": _Key("str", required=True), "values": _Key("floats", required=True),
        "parameter2": _Key("str"), "values2": _Key("floats"),
        "tornado": _Key("bool", default=True), "step": _F(default=0.02, lo=0.0, hi=0.5, lo_open=True),
    },
}


class _Where:
    def __init__(self, path):
        self.path = str(path)

    def fail(self, section: str, key: str | None, text: str):
        where = f"[{section}]" if section else "top level"
        if key is not None:
            where += f" {key}"
        raise GearDesignError(f"{self.path}: {where}: {text}")


def _type_name(v) -> str:
    return {bool: "boolean", int: "integer", float: "float", str: "string", list: "array",
            dict: "table"}.get(type(v), type(v).__name__)


def _check_value(where: _Where, section: str, key: str, spec: _Key, v):
    def bad(extra=""):
        where.fail(section, key, f"expected {spec.expected()}, got {v!r} ({_type_name(v)}){extra}")

    def in_range(x):
        if spec.lo is not None and (x <= spec.lo if spec.lo_open else x < spec.lo):
            return False
        return not (spec.hi is not None and x > spec.hi)

    def number(x, whole):
        if isinstance(x, bool) or not isinstance(x, (int, float)):
            return None
        if isinstance(x, float) and not math.isfinite(x):
            return None
        if whole:
            if isinstance(x, float) and not x.is_integer():
                return None
            return int(x)
        return float(x)

    k = spec.kind
    if k == "bool":
        if not isinstance(v, bool):
            bad()
        return v
    if k == "str":
        if not isinstance(v, str):
            bad()
        return v
    if k == "choice":
        if not isinstance(v, str) or v not in spec.choices:
            bad()
        return v
    if k in ("float", "int", "float_or_str"):
        if k == "float_or_str" and isinstance(v, str):
            if spec.choices and v not in spec.choices:
                bad()
            return v
        x = number(v, k == "int")
        if x is None or not in_range(x):
            bad()
        return x
    # lists
    if not isinstance(v, list) or not v or (spec.length and len(v) != spec.length):
        bad()
    out = []
    for item in v:
        x = number(item, k == "ints")
        if x is None or not in_range(x):
            bad(f"; the element {item!r} is not")
        out.append(x)
    return tuple(out)


def _validate_table(where: _Where, section: str, table: dict, schema: dict) -> dict:
    out = {}
    for key, v in table.items():
        if key not in schema:
            allowed = ", ".join(schema)
            where.fail(section, key, f"unknown key; expected one of {allowed}")
        spec = schema[key]
        if isinstance(spec, dict):
            if not isinstance(v, dict):
                where.fail(section, key, f"expected a table [{section}.{key}], got {v!r} ({_type_name(v)})")
            out[key] = _validate_table(where, f"{section}.{key}", v, spec)
        else:
            out[key] = _check_value(where, section, key, spec, v)
    for key, spec in schema.items():
        if isinstance(spec, dict):
            continue
        if key not in out:
            if spec.required:
                where.fail(section, key, f"missing; expected {spec.expected()}")
            if spec.default is not None:
                out[key] = spec.default
    return out


# --- the parsed scene --------------------------------------------------------------------------

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
        return BasicRack(**{k: spec.get(k, SCHEMA["gear"]["rack"][k].default) for k in _RACK})
    except GearDesignError as exc:
        where.fail(f"{section}.rack", None, str(exc))


def _checks_dict(spec: dict | None) -> dict | None:
    return dict(spec) if spec else None


def _cross_checks(where: _Where, s: dict):
    """Rules between keys, and the checks the libraries would make later, made up front."""
    if "gear" in s:
        g = s["gear"]
        if ("x1" in g) != ("x2" in g):
            where.fail("gear", "x2" if "x1" in g else "x1", "missing; give both x1 and x2 or neither")
        lo, hi = g["bounds"]
        if not lo < hi:
            where.fail("gear", "bounds", f"expected [lo, hi] with lo < hi, got {list(g['bounds'])}")
        g["_rack"] = _rack(where, "gear", g.get("rack"))
        if "a_w" in g:
            alpha = math.radians(g.get("rack", {}).get("alpha_deg", 20.0))
            a = g["module"] * (g["z1"] + g["z2"]) / 2
            if g["a_w"] <= a * math.cos(alpha):
                where.fail("gear", "a_w", f"expected a centre distance > a·cos(alpha) = {a * math.cos(alpha):.6g} mm, "
                                          f"got {g['a_w']!r}")
        if "x1" in g:
            from ..gears.pair import GearPair
            try:
                GearPair(g["module"], g["z1"], g["z2"], g["x1"], g["x2"], **({"rack": g["_rack"]} if g["_rack"] else {}),
                         tip_shortening=g["tip_shortening"])
            except GearDesignError as exc:
                where.fail("gear", "x1/x2", f"expected a pair that can be built: {exc}")
    if "teeth" in s:
        t = s["teeth"]
        lo, hi = t["z1_range"]
        if lo > hi:
            where.fail("teeth", "z1_range", f"expected [min, max] with min <= max, got {list(t['z1_range'])}")
        t["_rack"] = _rack(where, "teeth", t.get("rack"))
    if "chain" in s:
        c = s["chain"]
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
    for i, k in enumerate(s.get("key", [])):
        from ..drives.key import section as key_section
        try:
            key_section(k["d_mm"])
        except GearDesignError as exc:
            where.fail("key", "d_mm", f"expected a shaft diameter in the key table: {exc}")
    if "study" in s:
        st = s["study"]
        target = st["target"]
        if target not in s:
            where.fail("study", "target", f"expected a section that the scene models; [{target}] is missing")
        if ("parameter2" in st) != ("values2" in st):
            where.fail("study", "values2" if "parameter2" in st else "parameter2",
                       "missing; give parameter2 and values2 together")
        from ..sensitivity.studies import sweep_parameters
        allowed = sweep_parameters(target)
        for key in ("parameter", "parameter2"):
            if key in st and st[key] not in allowed:
                where.fail("study", key, f"expected one of {', '.join(allowed)} for target {target!r}, got {st[key]!r}")
        ints = ("z1", "z2", "strands")
        for key, vals in (("values", "parameter"), ("values2", "parameter2")):
            if key in st and st.get(vals) in ints and any(not float(v).is_integer() for v in st[key]):
                where.fail("study", key, f"expected whole numbers for {st[vals]}, got {list(st[key])}")
        if st.get("parameter") == st.get("parameter2"):
            where.fail("study", "parameter2", "expected a parameter other than parameter")


def _chain_catalog(where, path: Path, name: str) -> str:
    """A built-in chain catalog's name, or a user's CSV (relative to the scene file) as a path."""
    if name in CHAIN_CATALOGS:
        return name
    if name.lower().endswith(".csv"):
        csv = (path.parent / name) if not Path(name).is_absolute() else Path(name)
        if not csv.is_file():
            where.fail("chain", "catalog", f"the chain catalog {str(csv)!r} does not exist")
        return str(csv)
    where.fail("chain", "catalog", f"expected one of {', '.join(CHAIN_CATALOGS)} or a .csv file of chains "
                                   f"(relative to the scene file), got {name!r}")


SCENE_BYTES_MAX = 1 << 20    # 1 MiB: a scene is a page of settings, not data
SCENE_DEPTH_MAX = 8          # sections, tables of tables, lists: a few levels at most
SCENE_INT_MAX = 10**15       # integers beyond this are typing slips (and overflow floats)


def _read_bounded(path: Path) -> bytes:
    """The scene file's bytes: a regular file of at most SCENE_BYTES_MAX (a device such as
    /dev/zero, a folder or a huge file is refused before it is read)."""
    try:
        if not path.exists():
            raise GearDesignError(f"{path}: cannot read the scene file (no such file)")
        if not path.is_file():
            raise GearDesignError(f"{path}: not a regular file (a scene is a .toml text file)")
        with open(path, "rb") as fh:
            text = fh.read(SCENE_BYTES_MAX + 1)
    except OSError as exc:
        raise GearDesignError(f"{path}: cannot read the scene file ({exc.strerror or exc})") from None
    if len(text) > SCENE_BYTES_MAX:
        raise GearDesignError(f"{path}: larger than {SCENE_BYTES_MAX // 1024} KiB; a scene file is a page of settings")
    return text


def _check_values(path: Path, value, key: str = "", depth: int = 0) -> None:
    """Refuse nesting deeper than SCENE_DEPTH_MAX and integers beyond SCENE_INT_MAX, by key."""
    if depth > SCENE_DEPTH_MAX:
        raise GearDesignError(f"{path}: {key or 'the file'} is nested deeper than {SCENE_DEPTH_MAX} levels")
    if isinstance(value, dict):
        for k, v in value.items():
            _check_values(path, v, f"{key}.{k}" if key else str(k), depth + 1)
    elif isinstance(value, list):
        for v in value:
            _check_values(path, v, key, depth + 1)
    elif isinstance(value, int) and not isinstance(value, bool) and abs(value) > SCENE_INT_MAX:
        raise GearDesignError(f"{path}: {key} = an integer of {len(str(abs(value)))} digits; "
                              f"whole numbers must be within ±{SCENE_INT_MAX:.0e}")


def load_scene(path) -> Scene:
    """Read and validate a scene file; raise one :class:`GearDesignError` on the first problem."""
    path = Path(path)
    where = _Where(path)
    text = _read_bounded(path)
    try:
        raw = tomllib.loads(text.decode("utf-8"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as exc:
        raise GearDesignError(f"{path}: not a valid TOML file: {' '.join(str(exc).split())}") from None
    except RecursionError:
        raise GearDesignError(f"{path}: nested deeper than a scene can be (at most {SCENE_DEPTH_MAX} levels)") from None
    _check_values(path, raw)
    top = {k: v for k, v in raw.items() if not isinstance(v, (dict, list)) or k not in SECTIONS}
    for k, v in top.items():
        if k not in SCHEMA[""]:
            where.fail("", k, f"unknown section or key; expected sections {', '.join(f'[{s}]' for s in SECTIONS)} "
                              f"and the keys title, description")
    head = _validate_table(where, "", top, SCHEMA[""])
    sections = {}
    for name in SECTIONS:
        if name not in raw:
            continue
        v = raw[name]
        if name == "key":
            tables = v if isinstance(v, list) else [v]
            if not tables or not all(isinstance(t, dict) for t in tables):
                where.fail("key", None, f"expected a table [key] or tables [[key]], got {v!r}")
            sections["key"] = [_validate_table(where, "key" if len(tables) == 1 else f"key #{i + 1}", t, SCHEMA["key"])
                               for i, t in enumerate(tables)]
            continue
        if not isinstance(v, dict):
            where.fail(name, None, f"expected a table [{name}], got {v!r} ({_type_name(v)})")
        sections[name] = _validate_table(where, name, v, SCHEMA[name])
    if not sections:
        where.fail("", None, f"expected at least one of the sections {', '.join(f'[{s}]' for s in SECTIONS)}")
    _cross_checks(where, sections)
    if "chain" in sections:
        sections["chain"]["catalog"] = _chain_catalog(where, path, sections["chain"]["catalog"])
    return Scene(str(path), head.get("title", path.stem), head.get("description", ""), sections)


# --- running --------------------------------------------------------------------------------------

@dataclass
class SceneReport:
    """Everything a scene produced, in memory: tables, figures, Markdown and a summary."""

    scene: Scene
    tables: dict = field(default_factory=dict)      # name -> DataFrame (written as name.csv)
    figures: dict = field(default_factory=dict)     # name -> matplotlib Figure (written as name.png)
    markdown: list = field(default_factory=list)
    summary: list = field(default_factory=list)
    results: dict = field(default_factory=dict)     # section -> result object(s)
    time_s: float = 0.0

    def to_dict(self) -> dict:
        return {"scene": self.scene.path, "title": self.scene.title, "summary": list(self.summary),
                "tables": sorted(f"{k}.csv" for k in self.tables), "figures": sorted(f"{k}.png" for k in self.figures),
                "time_s": self.time_s}


def _md_table(frame: pd.DataFrame, floatfmt="{:.6g}") -> str:
    def cell(v):
        if isinstance(v, (bool, np.bool_)):
            return "yes" if v else "no"
        if isinstance(v, (float, np.floating)):
            return "–" if not np.isfinite(v) else floatfmt.format(v)
        return str(v).replace("|", "\\|")
    cols = list(frame.columns)
    lines = ["| " + " | ".join(map(str, cols)) + " |", "|" + "---|" * len(cols)]
    for row in frame.itertuples(index=False):
        lines.append("| " + " | ".join(cell(v) for v in row) + " |")
    return "\n".join(lines)


def _run_gear(rep: SceneReport, g: dict):
    import matplotlib.pyplot as plt
    from ..gears.pair import GearPair
    from ..shifts.region import feasible_region
    from ..shifts.optimize import optimize_shifts

    rack = g["_rack"]
    checks = _checks_dict(g.get("checks"))
    kw = dict(checks=checks, rack=rack, tip_shortening=g["tip_shortening"], bounds=tuple(g["bounds"]))
    res = optimize_shifts(g["z1"], g["z2"], objective=g.get("objective"), method=g["method"], m=g["module"],
                          a_w=g.get("a_w"), **kw)
    reg = feasible_region(g["z1"], g["z2"], m=g["module"], **kw)
    rep.results["gear"] = {"optimum": res, "region": reg}
    md = rep.markdown
    md += [f"## Gear pair z1/z2 = {g['z1']}/{g['z2']}, m = {g['module']:g} mm", ""]
    limits = {k: v for k, v in (checks or {}).items()}
    md += [f"Checks: {', '.join(reg.checks)}" + (f" (limits: {', '.join(f'{k} = {v}' for k, v in limits.items())})"
                                                  if limits else " (default limits: ε_α >= 1.2, s_a >= 0.25 m)"), ""]
    if reg.feasible:
        md += [f"Feasible region of (x1, x2): area {reg.area:.4f}, bounded by {', '.join(reg.limiting_checks())}.", ""]
    else:
        md += [f"The feasible region is **empty**: checks {', '.join(reg.conflict)} conflict.", ""]
    opt = pd.DataFrame([{"objective": res.objective, "method": res.method, "x1": res.x1, "x2": res.x2,
                         "x_sum": res.x1 + res.x2, "fun": res.fun, "eps_alpha": res.eps_alpha,
                         "a_w_mm": res.a_w, "active": ", ".join(res.active) or "-", "success": res.success}])
    rep.tables["gear_optimum"] = opt
    rep.tables["gear_optimum_checks"] = res.to_frame()
    rep.tables["gear_region_boundary"] = reg.boundary
    md += ["### Optimum", "", f"{res.message}.", "", _md_table(opt), "",
           "Margins of every check at the optimum, and d(fun)/d(limit) of the active ones:", "",
           _md_table(res.to_frame()), ""]
    sm = (f"gear {g['z1']}/{g['z2']} m={g['module']:g}: optimum ({res.objective}) x1 = {res.x1:.4f}, "
          f"x2 = {res.x2:.4f}, eps_alpha = {res.eps_alpha:.4f}, a_w = {res.a_w:.4f} mm, "
          f"active {', '.join(res.active) or '-'}; region area {reg.area:.4f}")
    rep.summary.append(sm if res.success else f"gear {g['z1']}/{g['z2']}: no feasible shifts: {res.message}")
    geo_opt = GearPair(g["module"], g["z1"], g["z2"], res.x1, res.x2, **({"rack": rack} if rack else {}),
                       tip_shortening=g["tip_shortening"]).geometry().to_frame()
    rep.tables["gear_optimum_geometry"] = geo_opt
    given = None
    if "x1" in g:
        pair = GearPair(g["module"], g["z1"], g["z2"], g["x1"], g["x2"], **({"rack": rack} if rack else {}),
                        tip_shortening=g["tip_shortening"])
        lim = {k: v for k, v in (checks or {}).items()}
        # with a housing a_w as well, the given shifts are checked against it (center_distance)
        chk = pair.checks(**{k: lim[k] for k in ("eps_alpha_min", "sa_min", "undercut", "interference") if k in lim},
                          jamming=lim.get("jamming", True), housing_a_w=g.get("a_w"))
        geo = pair.geometry().to_frame()
        rep.tables["gear_given_geometry"] = geo
        rep.tables["gear_given_checks"] = chk
        failed = chk.loc[~chk["ok"], "check"].tolist()
        verdict = ("passes every check" if not failed else f"**fails** {', '.join(failed)}")
        ga = pair.geometry()
        md += [f"### Given shifts x1 = {g['x1']:g}, x2 = {g['x2']:g}", "",
               f"This pair {verdict}: α_w = {ga.alpha_w_deg:.4f}°, a_w = {ga.a_w:.4f} mm, "
               f"ε_α = {ga.eps_alpha:.4f}.", "", _md_table(chk.drop(columns=["label"])), "",
               "Geometry of the given pair (mm, degrees):", "", _md_table(geo[["quantity", "value", "unit"]]), ""]
        rep.summary.append(f"given x1/x2 = {g['x1']:g}/{g['x2']:g}: eps_alpha = {ga.eps_alpha:.4f}, "
                           + ("all checks pass" if not failed else f"FAILS {', '.join(failed)}"))
        given = (g["x1"], g["x2"])
    md += ["Geometry at the optimum (mm, degrees):", "", _md_table(geo_opt[["quantity", "value", "unit"]]), ""]
    fig, ax = plt.subplots(figsize=(8.6, 6.2))
    reg.plot(ax=ax, optimum=res if res.success else None, proposed=given, x_sum=res.x_sum_fixed)
    rep.figures["gear_region"] = fig
    md += ["![blocking contour](gear_region.png)", ""]


def _run_teeth(rep: SceneReport, t: dict):
    from ..shifts.teeth import select_teeth

    kw = dict(ratio=t["ratio"], ratio_tol=t["ratio_tol"], m=t.get("module"), a_w=t.get("a_w"),
              z1_range=tuple(t["z1_range"]), z_sum_max=t.get("z_sum_max"), objective=t.get("objective"),
              checks=_checks_dict(t.get("checks")), rack=t["_rack"], method=t["method"])
    sel = select_teeth(**kw)
    rep.results["teeth"] = sel
    rep.tables["teeth"] = sel.table
    cols = [c for c in ("rank", "z1", "z2", "ratio", "ratio_error", "module_mm", "a_w_mm", "x1", "x2", "eps_alpha",
                        "objective", "feasible", "reason") if c in sel.table.columns]
    rep.markdown += [f"## Tooth counts for u = {t['ratio']:g} (± {100 * t['ratio_tol']:g} %)", "", sel.choice, "",
                     _md_table(sel.table[cols].head(t["top"])), ""]
    b = sel.best
    rep.summary.append("teeth: " + (f"z1/z2 = {int(b['z1'])}/{int(b['z2'])}, x1 = {b['x1']:.4f}, x2 = {b['x2']:.4f}"
                                    if b is not None else "no feasible tooth counts"))


def _chain_kwargs(c: dict) -> dict:
    kw = {k: c[k] for k in ("torque_nm", "power_kw", "n1_rpm", "ratio", "catalog", "k_e", "allowable_pressure_mpa",
                            "allowable_safety_factor", "z1", "center_distance_mm", "objective", "method",
                            "sag_factor") if k in c}
    kw["strands"] = tuple(c["strands"])
    if c.get("conditions"):
        kw["conditions"] = dict(c["conditions"])
    return kw


def _run_chain(rep: SceneReport, c: dict):
    from ..drives.chain import design

    res = design(**_chain_kwargs(c))
    rep.results["chain"] = res
    rep.tables["chain_candidates"] = res.candidates
    rep.tables["chain_blocking"] = res.blocking
    load = f"T1 = {c['torque_nm']:g} N·m" if "torque_nm" in c else f"P = {c['power_kw']:g} kW"
    md = rep.markdown
    md += [f"## Roller chain: {load}, n1 = {c['n1_rpm']:g} rpm, u = {c['ratio']:g} ({res.catalog}, {res.method})", "",
           f"{res.message}. K_e = {res.k_e:.4g}.", ""]
    if res.pitch_estimate_mm:
        md += ["Classic pitch estimate: " + ", ".join(f"{k} strand(s) t >= {v:.2f} mm"
                                                      for k, v in res.pitch_estimate_mm.items()) + ".", ""]
    show = [col for col in ("designation", "pitch_mm", "strands", "z1", "z2", "links", "center_distance_mm",
                            "speed_m_s", "force_n", "pressure_mpa", "allowable_pressure_mpa", "safety_factor",
                            "sprocket1_pitch_diameter_mm", "sprocket2_tip_diameter_mm", "mass_kg_m", "margin_pressure", "margin_safety", "min_margin", "feasible")
            if col in res.candidates.columns]
    md += ["Best candidates:", "", _md_table(res.candidates[show].head(c["top"])), ""]
    for note in res.notes:
        md += [f"- {note}"]
    if res.notes:
        md += [""]
    b = res.best
    rep.summary.append("chain: " + (f"{b['designation']} x{int(b['strands'])}, z1/z2 = {int(b['z1'])}/{int(b['z2'])}, "
                                    f"{int(b['links'])} links, a = {b['center_distance_mm']:.2f} mm, "
                                    f"limiting {b['limiting_check']} (margin {b['min_margin']:+.3f})"
                                    if b is not None else f"no chain passes: {res.message}"))


def _run_keys(rep: SceneReport, keys: list):
    from ..drives.key import select

    rows, results = [], []
    for i, k in enumerate(keys):
        sel = select(k["d_mm"], k["torque_nm"], k["hub_length_mm"], k["allowable_crush_mpa"], k["allowable_shear_mpa"],
                     k["end"], k["max_keys"])
        results.append(sel)
        row = {"name": k.get("name", f"key {i + 1}")}
        row.update(sel.to_dict())
        rows.append(row)
        rep.summary.append(f"key '{row['name']}': {sel.message}"
                           + (f", crush {sel.crush_mpa:.1f}/{sel.allowable_crush_mpa:g} MPa" if sel.feasible else ""))
    rep.results["key"] = results
    frame = pd.DataFrame(rows)
    rep.tables["keys"] = frame
    show = ["name", "d_mm", "torque_nm", "hub_length_mm", "b_mm", "h_mm", "t1_mm", "length_mm", "working_length_mm",
            "n_keys", "crush_mpa", "allowable_crush_mpa", "shear_mpa", "allowable_shear_mpa", "margin_crush",
            "margin_shear", "feasible"]
    rep.markdown += ["## Parallel keys", "", *[f"- {r['name']}: {r['message']}" for r in rows], "",
                     _md_table(frame[show]), ""]


def _run_study(rep: SceneReport, st: dict, sections: dict):
    import matplotlib.pyplot as plt
    from ..sensitivity import studies

    target = st["target"]
    base = studies.base_from_scene(target, sections[target])
    frame = studies.sweep(st["parameter"], list(st["values"]), st.get("parameter2"),
                          None if "values2" not in st else list(st["values2"]), target=target, **base)
    rep.tables["study_sweep"] = frame
    rep.results["study"] = {"sweep": frame}
    md = rep.markdown
    what = st["parameter"] + (f" × {st['parameter2']}" if "parameter2" in st else "")
    md += [f"## Study: {target} sweep over {what}", "", _md_table(frame.drop(columns=[c for c in frame.columns
                                                                                   if c.startswith("sens_")])), ""]
    fig, ax = plt.subplots(figsize=(7, 4.5))
    studies.plot_margins(frame, st["parameter"], ax=ax, by=st.get("parameter2"))
    rep.figures["study_margins"] = fig
    md += ["![margins along the sweep](study_margins.png)", ""]
    if target == "gear" and st["parameter"] in studies.LIMIT_PARAMETERS and "parameter2" not in st:
        fig, ax = plt.subplots(figsize=(7, 6))
        studies.plot_region_motion(st["parameter"], list(st["values"]), ax=ax, **base)
        rep.figures["study_region_motion"] = fig
        md += ["![the region moving with the limit](study_region_motion.png)", ""]
    if target == "gear" and st["tornado"]:
        tor = studies.local_sensitivities(step=st["step"], **base)
        rep.tables["study_sensitivities"] = tor
        rep.results["study"]["sensitivities"] = tor
        fig, ax = plt.subplots(figsize=(7, 4.5))
        studies.plot_tornado(tor, ax=ax)
        rep.figures["study_tornado"] = fig
        md += ["### Local sensitivities of the optimum", "",
               f"Each input moved by ±{100 * st['step']:g} % (limits: the convex method's duals give the slope "
               "d fun/d limit; the bars re-solve):", "", _md_table(tor), "",
               "![tornado chart](study_tornado.png)", ""]
    rep.summary.append(f"study: {len(frame)} sweep points over {what}")


def compute_scene(scene: Scene, progress=None) -> SceneReport:
    """Run every section of a validated scene in memory (nothing is written).

    ``progress(done, total, section)`` is called before each section and at the end."""
    import matplotlib
    matplotlib.use("Agg")
    t0 = time.perf_counter()
    rep = SceneReport(scene)
    rep.markdown += [f"# {scene.title}", ""]
    if scene.description:
        rep.markdown += [scene.description.strip(), ""]
    rep.markdown += [f"Scene file: `{Path(scene.path).name}`; sections modelled: "
                     f"{', '.join(f'[{s}]' for s in scene.sections)}.", ""]
    s = scene.sections
    runners = (("gear", _run_gear), ("teeth", _run_teeth), ("chain", _run_chain), ("key", _run_keys))
    todo = [name for name, _ in runners if name in s] + (["study"] if "study" in s else [])
    step = progress or (lambda done, total, section: None)
    try:
        for name, fn in runners:
            if name in s:
                step(todo.index(name), len(todo), name)
                fn(rep, s[name])
        if "study" in s:
            step(len(todo) - 1, len(todo), "study")
            _run_study(rep, s["study"], s)
        step(len(todo), len(todo), "done")
    except GearDesignError as exc:
        for fig in rep.figures.values():
            import matplotlib.pyplot as plt
            plt.close(fig)
        raise GearDesignError(f"{scene.path}: {exc}") from None
    rep.markdown += ["## Files", "", *[f"- `{k}.csv`" for k in rep.tables], *[f"- `{k}.png`" for k in rep.figures], ""]
    rep.time_s = time.perf_counter() - t0
    return rep


def write_report(rep: SceneReport, out_dir, overwrite: bool = False) -> Path:
    """Write report.md, the CSV tables and the PNG plots into ``out_dir``: a new or empty
    folder (its contents replaced only with ``overwrite``). Everything is written into a
    temporary folder beside it first and moved into place whole; a failure leaves nothing."""
    import matplotlib.pyplot as plt

    out = check_output_dir(out_dir, overwrite=overwrite)

    def write(tmp: Path) -> None:
        for name, frame in rep.tables.items():
            frame.to_csv(tmp / f"{name}.csv", index=False)
        for name, fig in rep.figures.items():
            fig.savefig(tmp / f"{name}.png", dpi=110, bbox_inches="tight")
            plt.close(fig)
        (tmp / "report.md").write_text("\n".join(rep.markdown), encoding="utf-8")

    return write_dir_atomic(out, write)


def run_scene(path, out_dir, overwrite: bool = False, progress=None) -> SceneReport:
    """Load, validate and run a scene file, then write its report into ``out_dir``.

    The output folder is checked first; nothing is written when the scene is wrong or a
    section fails.
    """
    check_output_dir(out_dir, overwrite=overwrite)
    rep = compute_scene(load_scene(path), progress)
    write_report(rep, out_dir, overwrite=overwrite)
    return rep
