"""The scene's ``[drive]`` section: an input (``power_kw`` or ``output_torque_nm`` at ``n_in_rpm``, or a
``[drive.motor]`` chosen from the catalog), ``[[drive.stage]]`` entries (``kind`` = a registered stage
kind: "given", "gear", "chain", "worm", with the keywords of gd.GivenStage / GearStage / ChainStage / WormStage, or one
added by :func:`geardesign.drives.stage_kinds.register`) and ``[[drive.shaft]]`` keyed hubs.
With ``total_ratio`` the drive is optimised; without it, analysed as given.

``[drive.shafting]`` (the keys of :class:`geardesign.drives.shafting.Shafting`; ``nu40`` with ``nu100`` give the
lubricant of the computed efficiencies) puts the gear stages on shafts with bearings; a ``[[drive.shaft]]`` with
``lengths_mm`` is a shaft as drawn (:class:`~geardesign.drives.shafting.DriveShaft`: ``at``, ``lengths_mm`` and
``diameters_mm`` of its sections from the left end, ``supports_mm``, its elements' places in a table
``[drive.shaft.positions]`` {stage name or "coupling": x_mm}, ``bearing_a``/``bearing_b``, ``material``,
``bearing_type``), and a ``[[drive.shaft]]`` with only ``at`` and ``bearing_type`` sets a default shaft's bearing
type; each switches the shafting on (docs/shafts_in_drive.md)::

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

import math
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
    head = validate_table(where, "drive", {k: v for k, v in raw.items() if k not in ("stage", "shaft", "shafting")},
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
    shafts, layout, types = [], [], []
    for i, t in enumerate(_tables(where, raw["shaft"], "shaft") if "shaft" in raw else []):
        label = f"drive.shaft #{i + 1}"
        if "lengths_mm" in t:
            layout.append(_layout_shaft(where, label, t))
        elif "bearing_type" in t:      # a default shaft's bearing type: at and bearing_type alone
            types.append(validate_table(where, label, t, drive_schema("shaft_bearings")))
        else:
            shafts.append(validate_table(where, label, t, drive_schema("shaft")))
    section = dict(head, stages=stages, shafts=shafts, layout=layout, bearing_types=types)
    if "spectrum" in section:      # its file relative to the scene; read (and refused by name) by build_drive
        name = section["spectrum"]["file"]
        where_file = Path(name) if Path(name).is_absolute() else Path(scene_path).parent / name
        section["spectrum"] = dict(section["spectrum"], file=str(where_file), _label="[drive.spectrum] file")
    if "shafting" in raw:
        if not isinstance(raw["shafting"], dict):
            where.fail("drive", "shafting", f"expected a table [drive.shafting], got {_short(raw['shafting'])}")
        section["shafting"] = validate_table(where, "drive.shafting", raw["shafting"], drive_schema("shafting"))
        if ("nu40" in section["shafting"]) != ("nu100" in section["shafting"]):
            where.fail("drive.shafting", "nu100" if "nu40" in section["shafting"] else "nu40",
                       "missing; nu40 and nu100 give the lubricant together")
    try:
        build_drive(section)
    except GearDesignError as exc:
        where.fail("drive", None, str(exc))
    return section


def _layout_shaft(where: Where, label: str, t: dict) -> dict:
    """A validated [[drive.shaft]] with lengths_mm (a shaft as drawn); its [drive.shaft.positions] by hand: its keys
    are the user's stage names."""
    pos = t.get("positions")
    if not isinstance(pos, dict) or not pos:
        where.fail(label, "positions", "missing; expected a table [drive.shaft.positions] {stage name or 'coupling' "
                                       "= x_mm}")
    for k, v in pos.items():
        if isinstance(v, bool) or not isinstance(v, (int, float)):
            where.fail(f"{label}.positions", k, f"expected a number (x in mm), got {_short(v)} ({type_name(v)})")
    spec = validate_table(where, label, {k: v for k, v in t.items() if k != "positions"}, drive_schema("shaft_layout"))
    if len(spec["lengths_mm"]) != len(spec["diameters_mm"]):
        where.fail(label, "diameters_mm", f"expected one diameter per length ({len(spec['lengths_mm'])}), got "
                                          f"{len(spec['diameters_mm'])}")
    if ("bearing_a" in spec) != ("bearing_b" in spec):
        where.fail(label, "bearing_b" if "bearing_a" in spec else "bearing_a", "missing; give both bearings or neither")
    return dict(spec, positions={str(k): float(v) for k, v in pos.items()})


def _shafting(section: dict):
    """The Shafting of a validated [drive] section, or None (no [drive.shafting], no drawn shaft)."""
    if "shafting" not in section and not section.get("layout") and not section.get("bearing_types"):
        return None
    from ..drives.shafting import DriveShaft, Shafting
    from ..gears.efficiency import Lubricant

    kw = dict(section.get("shafting") or {})
    nu40, nu100 = kw.pop("nu40", None), kw.pop("nu100", None)
    layout = [DriveShaft(s["at"], tuple(zip(s["lengths_mm"], s["diameters_mm"])), tuple(s["supports_mm"]),
                         s["positions"], bearings=(s["bearing_a"], s["bearing_b"]) if "bearing_a" in s else None,
                         material=s.get("material")) for s in section.get("layout", ())]
    per_shaft = {s["at"]: s["bearing_type"] for s in [*section.get("layout", ()), *section.get("bearing_types", ())]
                 if "bearing_type" in s}
    if per_shaft:       # [[drive.shaft]] bearing types over [drive.shafting]'s, which holds for the other shafts
        every = kw.get("bearing_type", "auto")
        given = every if isinstance(every, dict) else {}        # the command line's SHAFT=TYPE pairs win
        every = "auto" if given else every
        kw["bearing_type"] = {**{k: every for k in range(len(section["stages"]) + 1)}, **per_shaft, **given}
    return Shafting(layout=tuple(layout), lubricant=None if nu40 is None else Lubricant(nu40, nu100), **kw)


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
    specs = section["stages"]
    if "spectrum" in section:      # each gear stage's duty cycle, relative to the drive's nominal input
        specs = _with_duty_cycle(section["spectrum"], specs, *_nominal_input(section, motor))
    drive = Drive(stages=[_stage(s) for s in specs], n_in_rpm=section.get("n_in_rpm"),
                  power_kw=section.get("power_kw"), output_torque_nm=section.get("output_torque_nm"),
                  shafts=shafts, motor=motor, shafting=_shafting(section))
    return drive, motor


def input_spectrum(path, n_in_rpm: float, life_h=None):
    """The LoadSpectrum of a drive's spectrum file: torques (N·m) and speeds (rpm) at the drive's input shaft; a file
    without an ``n_rpm`` column is taken at the input speed ``n_in_rpm``; ``life_h`` the hours a ``share`` column
    divides."""
    from ..files import read_text_bounded
    from ..gears.spectrum import SPECTRUM_BYTES_MAX, LoadSpectrum

    text = read_text_bounded(path, "spectrum file", SPECTRUM_BYTES_MAX)   # bounded: /dev/zero is one endless line
    header = next((line for line in text.splitlines() if line.strip() and not line.lstrip().startswith("#")), "")
    has_speed = "n_rpm" in (h.strip() for h in header.split(","))
    return LoadSpectrum.from_csv(path, n_rpm=None if has_speed else n_in_rpm, duration_h=life_h)


def _nominal_input(section: dict, motor) -> tuple:
    """(n_in_rpm, power_kw or None) of a [drive] section as gd.Drive resolves them: the section's, else the motor's
    rated speed and (with no load given) its rated power."""
    row = None if motor is None else motor.motor
    n_in = section.get("n_in_rpm") or (None if row is None else float(row["rated_speed_rpm"]))
    power = section.get("power_kw")
    if power is None and section.get("output_torque_nm") is None and row is not None:
        power = float(row["power_kw"])
    if n_in is None:
        raise GearDesignError("n_in_rpm is required (or a motor)")
    return float(n_in), power


def _with_duty_cycle(spectrum: dict, specs: list, n_in_rpm: float, power_kw) -> list:
    """The gear stages' tables with the drive's spectrum as their duty cycle (:class:`~geardesign.DutyCycle`: the
    file's bins over the drive's nominal input torque P/ω and speed), its required life, S-N curve and Y_M; a
    stage's own keys win. Errors name ``spectrum["_label"]`` (the scene's key or the command's option)."""
    from ..drives.duty_cycle import DutyCycle

    label = spectrum.get("_label", "[drive.spectrum] file")
    gears = [i for i, st in enumerate(specs) if st["kind"] == "gear"]
    if not gears:
        raise GearDesignError(f"{label}: the drive has no gear stage to rate under a spectrum")
    if power_kw is None:
        raise GearDesignError(f"{label}: a drive's spectrum is read relative to its nominal input torque, which needs "
                              f"the input power (power_kw, --power or a motor), not an output torque")
    torque = 1000.0 * power_kw / (2.0 * math.pi * n_in_rpm / 60.0)
    try:
        spec = input_spectrum(spectrum["file"], n_in_rpm, spectrum.get("life_h"))
        duty = DutyCycle.from_spectrum(spec, torque, n_in_rpm)
    except (GearDesignError, OSError, UnicodeDecodeError) as exc:
        why = str(exc) if isinstance(exc, GearDesignError) else (f"{spectrum['file']!r} cannot be read: "
                                                                 f"{getattr(exc, 'strerror', None) or exc}")
        raise GearDesignError(f"{label}: {why}") from None
    given = {"spectrum": duty, "life_h": spectrum.get("life_h") or spec.duration_h,
             **{k: spectrum[k] for k in ("sn_curve", "mean_stress_factor") if spectrum.get(k) is not None}}
    out = list(specs)
    for i in gears:
        out[i] = {**given, **specs[i]}
    return out


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
    for st in an.stages:          # a gear stage with a spectrum: its service life at the flow into it
        r = st.get("life")
        if r is None:
            continue
        name = st["summary"]["name"]
        rep.tables["drive_life_" + "".join(c if c.isalnum() else "_" for c in str(name))] = r.bins
        mode, D = r.governing
        md += ["", f"### Service life of stage '{name}' (ISO 6336-6:2019)", "",
               f"{r.life_h:.4g} h of {r.required_life_h:.6g} h required ({'holds' if r.ok else 'FAILS'}; governing "
               f"{mode}, D = {D:.4g}; S-N curve {r.sn_curve}).", "", md_table(r.damage_table())]
    md += ["", "### Checks of the whole drive", "", md_table(an.checks), "", "### Keys", "",
           md_table(an.keys.drop(columns=["message"])), ""]
    md += [f"- {r['name']}: {r['message']}" for _, r in an.keys.iterrows()] + [""]
    if an.shafting is not None:       # the shafts, bearings, sections, seat keys, efficiencies, K_Hβ
        from ..drives.drive_results import SHAFTING_TABLES

        rep.figures["drive_layout"] = an.plot_layout().figure
        md += ["### Shafts, bearings and efficiency", "", f"Overall efficiency {an.overall_efficiency:.5f}; heat to "
               f"dissipate {1000 * an.heat_kw:.5g} W.", "", "![shafts and bearings seen from above](drive_layout.png)",
               ""]
        for name in SHAFTING_TABLES:
            table = an.shafting.get(name)
            if table is not None and len(table):
                rep.tables[f"drive_{name}"] = table
                md += [f"#### {name.replace('_', ' ')}", "", md_table(table), ""]
    if opt is None:
        rep.summary.append("drive: " + an.message)
