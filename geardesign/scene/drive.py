"""The scene's ``[drive]`` section: an input (``power_kw`` or ``output_torque_nm`` at ``n_in_rpm``, or a
``[drive.motor]`` chosen from the catalog), ``[[drive.stage]]`` entries (``kind`` = a registered stage
kind: "given", "gear", "chain", "worm", with the keywords of gd.GivenStage / GearStage / ChainStage / WormStage, or one
added by :func:`geardesign.drives.stage_kinds.register`) and ``[[drive.shaft]]`` keyed hubs.
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

from pathlib import Path

from ..errors import GearDesignError
from ..validate import _short
from .markdown import md_table, pyplot
from .schema import Where, drive_schema, stage_kinds, type_name, validate_table

__all__ = ["load_drive", "build_drive", "run_drive"]

def _tables(where: Where, v, what: str) -> list:
    tables = v if isinstance(v, list) else [v]
    if not tables or not all(isinstance(t, dict) for t in tables):
        where.fail(f"drive.{what}", None, f"expected tables [[drive.{what}]], got {_short(v)} ({type_name(v)})")
    return tables


def load_drive(where: Where, scene_path, raw) -> dict:
    """The validated [drive] section; the stages and shafts are built once here, so that every
    error of the library (a pair that cannot exist, an unknown chain) is reported before a run."""
    from ..drives.stage_kinds import kind_named

    if not isinstance(raw, dict):
        where.fail("drive", None, f"expected a table [drive], got {_short(raw)} ({type_name(raw)})")
    head = validate_table(where, "drive", {k: v for k, v in raw.items() if k not in ("stage", "shaft")},
                          drive_schema(""))
    if "stage" not in raw:
        where.fail("drive", "stage", "missing; expected one or more tables [[drive.stage]]")
    stages = []
    for i, t in enumerate(_tables(where, raw["stage"], "stage")):
        label = f"drive.stage #{i + 1}"
        kind = t.get("kind")
        if kind not in stage_kinds():
            where.fail(label, "kind", f"expected one of {', '.join(repr(k) for k in stage_kinds())}, got {_short(kind)}")
        spec = validate_table(where, label, t, drive_schema(kind))
        stages.append(kind_named(kind).scene_spec(spec, Path(scene_path).parent))
    shafts = [validate_table(where, f"drive.shaft #{i + 1}", t, drive_schema("shaft"))
              for i, t in enumerate(_tables(where, raw.get("shaft", []), "shaft"))] if "shaft" in raw else []
    section = dict(head, stages=stages, shafts=shafts)
    try:
        build_drive(section)
    except GearDesignError as exc:
        where.fail("drive", None, str(exc))
    return section


def _stage(spec: dict):
    """The stage of a validated [[drive.stage]] table, built by its kind."""
    from ..drives.stage_kinds import kind_named

    return kind_named(spec["kind"]).from_scene({k: v for k, v in spec.items() if k != "kind"})


def build_drive(section: dict):
    """(Drive, motor selection or None) of a validated [drive] section."""
    from ..drives.drive import Drive
    from ..drives.stages import Shaft

    motor = None
    if "motor" in section:
        from ..drives.motor import select
        m = section["motor"]
        motor = select(m["power_kw"], m["n_rpm"], m["service_factor"], m["catalog"])
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
                             progress=progress, client=section.get("_client"))
        return drive, motor, opt, opt.best
    return drive, motor, None, drive.analyse(section["objective"])


def run_drive(rep, section: dict) -> None:
    """The [drive] section into the report: the flow, the diagram, each stage (a gear stage with a material with
    its strength and factor table), the keys, the alternatives."""
    from ..gears.strength.result import case_text

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
            md += ["### Alternatives (best first; why each loses)", "", md_table(opt.table), ""]
        rep.summary.append("drive: " + opt.message)
    if an is None:
        return
    rep.tables["drive_flow"] = an.flow
    rep.tables["drive_checks"] = an.checks
    rep.tables["drive_keys"] = an.keys
    pyplot()     # the non-interactive backend before the diagram makes its figure
    rep.figures["drive_diagram"] = an.plot().figure       # at its default size: sized to its labels
    md += ["### Power flow", "", an.message + ".", "", md_table(an.flow), "",
           "![drive diagram](drive_diagram.png)", "", "### Stages", ""]
    for st in an.stages:
        s = st["summary"]
        md += ["- " + ", ".join(f"{k} = {v:.6g}" if isinstance(v, float) else f"{k} = {v}" for k, v in s.items())]
    for st in an.stages:          # a gear stage with a material: its strength at the flow into it
        r = st.get("strength")
        if r is None:
            continue
        name, (check, margin) = st["summary"]["name"], r.governing
        rep.tables["drive_strength_" + "".join(c if c.isalnum() else "_" for c in str(name))] = r.factors
        md += ["", f"### Strength of stage '{name}' (ISO 6336:2019)", "",
               f"{'; '.join(case_text(r.case)) if r.case else ''}. S_H = {r.S_H1:.4g} / {r.S_H2:.4g} "
               f"(S_Hmin {r.S_Hmin:g}), S_F = {r.S_F1:.4g} / {r.S_F2:.4g} (S_Fmin {r.S_Fmin:g}); σ_H = {r.sigma_H1:.4g} / "
               f"{r.sigma_H2:.4g} MPa, σ_F = {r.sigma_F1:.4g} / {r.sigma_F2:.4g} MPa; governing {check} "
               f"(margin {margin:+.4f}).", "", md_table(r.factors)]
    md += ["", "### Checks of the whole drive", "", md_table(an.checks), "", "### Keys", "",
           md_table(an.keys.drop(columns=["message"])), ""]
    md += [f"- {r['name']}: {r['message']}" for _, r in an.keys.iterrows()] + [""]
    if opt is None:
        rep.summary.append("drive: " + an.message)
