"""The scene's ``[drive]`` section: an input (``power_kw`` or ``output_torque_nm`` at ``n_in_rpm``, or a
``[drive.motor]`` chosen from the catalog), ``[[drive.stage]]`` entries (``kind`` = "given", "gear" or
"chain", with the keywords of gd.GivenStage / GearStage / ChainStage) and ``[[drive.shaft]]`` keyed hubs.
With ``total_ratio`` the drive is optimised; without it, analysed as given::

    [drive]
    power_kw = 4
    n_in_rpm = 1500
    [[drive.stage]]
    kind = "given"
    name = "gear motor"
    ratio = 12.5
    efficiency = 0.87
    [[drive.stage]]
    kind = "chain"
    z1 = 13
    z2 = 13
    [[drive.shaft]]
    at = 1
    d_mm = 60
    hub_length_mm = 50
"""
from __future__ import annotations

from .schema import _F, _I, _Key, Where, section_schema, type_name, validate_table

__all__ = ["drive_schema", "load_drive", "build_drive", "run_drive", "STAGE_KINDS"]

STAGE_KINDS = ("given", "gear", "chain")


def drive_schema(part: str = "") -> dict:
    """The keys of ``[drive]`` (part ""), ``[drive.motor]``, each stage kind and ``[[drive.shaft]]``."""
    from ..drives import chain as c
    from ..drives import drive as d
    from ..drives import motor as mo
    from ..drives import stages as s

    eff = dict(lo=s.EFFICIENCY_RANGE[0], hi=s.EFFICIENCY_RANGE[1], lo_open=True)
    if part == "":
        return {"power_kw": _F(lo=d.POWER_RANGE_KW[0], hi=d.POWER_RANGE_KW[1]),
                "output_torque_nm": _F(lo=d.TORQUE_RANGE_NM[0], hi=d.TORQUE_RANGE_NM[1]),
                "n_in_rpm": _F(lo=d.SPEED_RANGE_RPM[0], hi=d.SPEED_RANGE_RPM[1]),
                "total_ratio": _F(lo=d.TOTAL_RATIO_RANGE[0], hi=d.TOTAL_RATIO_RANGE[1]),
                "ratio_tol": _F(default=0.03, lo=d.RATIO_TOL_RANGE[0], hi=d.RATIO_TOL_RANGE[1]),
                "objective": _Key("choice", default=d.OBJECTIVES[0], choices=d.OBJECTIVES),
                "top": _I(default=10, lo=1, hi=d.TOP_MAX),
                "motor": {"power_kw": _F(required=True, lo=mo.POWER_RANGE_KW[0], hi=mo.POWER_RANGE_KW[1]),
                          "speed_rpm": _F(required=True, lo=mo.SPEED_RANGE_RPM[0], hi=mo.SPEED_RANGE_RPM[1]),
                          "service_factor": _F(default=1.0, lo=mo.SERVICE_FACTOR_RANGE[0], hi=mo.SERVICE_FACTOR_RANGE[1]),
                          "catalog": _Key("choice", default=mo.MOTOR_CATALOGS[0], choices=mo.MOTOR_CATALOGS)}}
    if part == "given":
        return {"kind": _Key("choice", required=True, choices=STAGE_KINDS), "name": _Key("str"),
                "ratio": _F(required=True, lo=s.GIVEN_RATIO_RANGE[0], hi=s.GIVEN_RATIO_RANGE[1]),
                "efficiency": _F(required=True, **eff), "rated_output_torque_nm": _F(lo=0.0, lo_open=True)}
    if part == "gear":
        from ..gears.geometry import M_RANGE_MM, X_ABS_MAX
        from ..gears.mesh import BETA_RANGE_DEG, FACE_WIDTH_RANGE_MM, Z_MAX, Z_MIN
        from ..shifts.objectives import OBJECTIVES
        from .schema import _checks_schema

        return {"kind": _Key("choice", required=True, choices=STAGE_KINDS), "name": _Key("str"),
                "module": _F(required=True, lo=M_RANGE_MM[0], hi=M_RANGE_MM[1]),
                "z1": _I(lo=Z_MIN, hi=Z_MAX), "z2": _I(lo=Z_MIN, hi=Z_MAX),
                "x1": _F(lo=-X_ABS_MAX, hi=X_ABS_MAX), "x2": _F(lo=-X_ABS_MAX, hi=X_ABS_MAX),
                "efficiency": _F(default=0.98, **eff), "beta_deg": _F(default=0.0, lo=BETA_RANGE_DEG[0], hi=BETA_RANGE_DEG[1]),
                "face_width_mm": _F(lo=FACE_WIDTH_RANGE_MM[0], hi=FACE_WIDTH_RANGE_MM[1], lo_open=True),
                "z1_range": _Key("ints", lo=Z_MIN, hi=Z_MAX, length=2), "z2_max": _I(lo=Z_MIN, hi=Z_MAX),
                "ratio_range": _Key("floats", lo=1.0, hi=100.0, length=2),
                "shift_objective": _Key("choice", choices=tuple(OBJECTIVES)),
                "checks": {key: v for key, v in _checks_schema().items() if key != "jamming"}}
    if part == "chain":
        return {"kind": _Key("choice", required=True, choices=STAGE_KINDS), "name": _Key("str"),
                "catalog": _Key("str", default="gost13568"), "z1": _I(lo=c.Z1_RANGE[0], hi=c.Z1_RANGE[1]),
                "z2": _I(lo=c.Z1_RANGE[0], hi=c.Z2_MAX_LIMIT), "designation": _Key("str"),
                "strands": _Key("ints", lo=c.STRANDS_RANGE[0], hi=c.STRANDS_RANGE[1]),
                "efficiency": _F(default=0.96, **eff), "k_e": _F(lo=c.K_E_RANGE[0], hi=c.K_E_RANGE[1]),
                "allowable_pressure_mpa": _F(lo=0.0, lo_open=True),
                "allowable_safety_factor": _F(lo=c.SAFETY_FACTOR_RANGE[0], hi=c.SAFETY_FACTOR_RANGE[1]),
                "method": _Key("choice", default=c.METHODS[0], choices=c.METHODS),
                "center_distance_mm": _F(lo=0.0, hi=c.CENTER_DISTANCE_MAX_MM, lo_open=True),
                "sag_factor": _F(default=6.0, lo=c.SAG_FACTOR_RANGE[0], hi=c.SAG_FACTOR_RANGE[1]),
                "z2_max": _I(default=120, lo=9, hi=c.Z2_MAX_LIMIT),
                "ratio_range": _Key("floats", lo=c.RATIO_RANGE[0], hi=c.RATIO_RANGE[1], length=2),
                "objective": _Key("choice", default=c.OBJECTIVES[0], choices=c.OBJECTIVES),
                "conditions": {key: _Key("float_or_str", lo=c.FACTOR_RANGE[0], hi=c.FACTOR_RANGE[1], choices=())
                               for key in c.FACTOR_NAMES}}
    if part == "shaft":   # a [key] whose torque is the shaft's own, and the shaft it sits on
        keys = {name: spec for name, spec in section_schema("key").items() if name != "torque_nm"}
        return {"at": _I(required=True, lo=0, hi=d.STAGES_MAX), **keys}
    raise KeyError(part)


def _tables(where: Where, v, what: str) -> list:
    tables = v if isinstance(v, list) else [v]
    if not tables or not all(isinstance(t, dict) for t in tables):
        where.fail(f"drive.{what}", None, f"expected tables [[drive.{what}]], got {v!r} ({type_name(v)})")
    return tables


def load_drive(where: Where, scene_path, raw) -> dict:
    """The validated [drive] section; the stages and shafts are built once here, so that every
    error of the library (a pair that cannot exist, an unknown chain) is reported before a run."""
    from pathlib import Path

    from ..errors import GearDesignError

    if not isinstance(raw, dict):
        where.fail("drive", None, f"expected a table [drive], got {raw!r} ({type_name(raw)})")
    head = validate_table(where, "drive", {k: v for k, v in raw.items() if k not in ("stage", "shaft")},
                          drive_schema(""))
    if "stage" not in raw:
        where.fail("drive", "stage", "missing; expected one or more tables [[drive.stage]]")
    stages = []
    for i, t in enumerate(_tables(where, raw["stage"], "stage")):
        label = f"drive.stage #{i + 1}"
        kind = t.get("kind")
        if kind not in STAGE_KINDS:
            where.fail(label, "kind", f"expected one of {', '.join(repr(k) for k in STAGE_KINDS)}, got {kind!r}")
        spec = validate_table(where, label, t, drive_schema(kind))
        if kind == "chain" and spec["catalog"].lower().endswith(".csv"):
            csv = Path(scene_path).parent / spec["catalog"]
            spec["catalog"] = str(csv)
        stages.append(spec)
    shafts = [validate_table(where, f"drive.shaft #{i + 1}", t, drive_schema("shaft"))
              for i, t in enumerate(_tables(where, raw.get("shaft", []), "shaft"))] if "shaft" in raw else []
    section = dict(head, stages=stages, shafts=shafts)
    try:
        build_drive(section)
    except GearDesignError as exc:
        where.fail("drive", None, str(exc))
    return section


def _stage(spec: dict):
    from ..drives.stages import ChainStage, GearStage, GivenStage

    kw = {k: v for k, v in spec.items() if k != "kind"}
    if spec["kind"] == "given":
        return GivenStage(**kw)
    if spec["kind"] == "gear":
        kw["m"] = kw.pop("module")
        kw["checks"] = dict(kw["checks"]) if kw.get("checks") else None
        for k in ("z1_range", "ratio_range"):
            if k in kw:
                kw[k] = tuple(kw[k])
        return GearStage(**kw)
    if kw.get("conditions"):
        kw["conditions"] = dict(kw["conditions"])
    for k in ("strands", "ratio_range"):
        if k in kw:
            kw[k] = tuple(kw[k])
    return ChainStage(**kw)


def build_drive(section: dict):
    """(Drive, motor selection or None) of a validated [drive] section."""
    from ..drives.drive import Drive
    from ..drives.stages import Shaft
    from ..errors import GearDesignError

    motor = None
    if "motor" in section:
        from ..drives.motor import select
        m = section["motor"]
        motor = select(m["power_kw"], m["speed_rpm"], m["service_factor"], m["catalog"])
        if not motor.found:
            raise GearDesignError(f"[drive.motor]: {motor.message}")
    shafts = [Shaft(**{k: v for k, v in s.items()}) for s in section["shafts"]]
    drive = Drive(stages=[_stage(s) for s in section["stages"]], n_in_rpm=section.get("n_in_rpm"),
                  power_kw=section.get("power_kw"), output_torque_nm=section.get("output_torque_nm"),
                  shafts=shafts, motor=motor)
    return drive, motor


def compute_drive(section: dict, progress=None):
    """(Drive, motor selection, DriveOptimum or None, DriveAnalysis or None): optimised with
    ``total_ratio`` (``progress`` as for Drive.optimize), analysed otherwise."""
    drive, motor = build_drive(section)
    if "total_ratio" in section:
        opt = drive.optimize(section["total_ratio"], section["ratio_tol"], section["objective"], section["top"],
                             progress=progress)
        return drive, motor, opt, opt.best
    return drive, motor, None, drive.analyse(section["objective"])


def run_drive(rep, section: dict) -> None:
    """The [drive] section into the report: the flow, the diagram, each stage, the keys, the alternatives."""
    from .sections import _md_table, _pyplot

    drive, motor, opt, an = compute_drive(section)
    rep.results["drive"] = {"optimum": opt, "analysis": an, "motor": motor}
    md = rep.markdown
    md += ["## Drive", ""]
    if motor is not None:
        md += [f"Motor: {motor.message}.", ""]
    if opt is not None:
        md += [f"Optimised for {opt.objective}, u = {opt.total_ratio:g} ± {100 * opt.ratio_tol:g} %: {opt.message}.",
               "", f"{opt.n_combinations} ratio combinations, {opt.n_candidates} designs, {opt.n_shift_solves} shift "
               f"solves, {opt.time_s:.3f} s.", ""]
        rep.tables["drive_alternatives"] = opt.table
        if len(opt.table):
            md += ["### Alternatives (best first; why each loses)", "", _md_table(opt.table), ""]
        rep.summary.append("drive: " + opt.message)
    if an is None:
        return
    rep.tables["drive_flow"] = an.flow
    rep.tables["drive_checks"] = an.checks
    rep.tables["drive_keys"] = an.keys
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(2.2 + 2.4 * len(an.stages), 4.0))
    an.plot(ax=ax)
    rep.figures["drive_diagram"] = fig
    md += ["### Power flow", "", an.message + ".", "", _md_table(an.flow), "",
           "![drive diagram](drive_diagram.png)", "", "### Stages", ""]
    for st in an.stages:
        s = st["summary"]
        md += ["- " + ", ".join(f"{k} = {v:.6g}" if isinstance(v, float) else f"{k} = {v}" for k, v in s.items())]
    md += ["", "### Checks of the whole drive", "", _md_table(an.checks), "", "### Keys", "",
           _md_table(an.keys.drop(columns=["message"])), ""]
    md += [f"- {r['name']}: {r['message']}" for _, r in an.keys.iterrows()] + [""]
    if opt is None:
        rep.summary.append("drive: " + an.message)
