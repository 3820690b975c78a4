"""``geardesign drive scene.toml``: the [drive] section of a scene, analysed or optimised.

Prints the power flow, every check of the drive, the keys and (optimised) the ranked alternatives;
``--plot FILE`` writes the drive's diagram, ``--json`` prints the result. Exit status 0 when every
check holds, 1 when the drive fails (the output names the stage and checks), 2 on bad input.

The load options of ``pair``/``shift``/``teeth`` (:func:`~geardesign.cli.options.add_load_args`) mean
here: ``--power``/``--torque`` and ``--speed`` the drive's input (instead of the scene's; the power
flow brings each gear stage its own torque and speed), ``--material``, ``--life-h``,
``--application-factor`` and ``--strength-width`` the load case of every gear stage that does not set
its own in the scene (a stage without ``module`` is then sized by its load), and the strength options
(``--accuracy-grade``, ``--factor``, ``--fma``, ``--nu40``, ``--rz-flank``, ``--rz-root``, ``--sh-min``,
``--sf-min``) those of every gear stage that does not set its own. ``--spectrum CSV`` (``--sn-curve``,
``--mean-stress-factor``) is the drive's load spectrum at its input shaft, as the scene's [drive.spectrum]: every
gear stage's duty cycle relative to its own nominal load, sizing it by its life too. ``--on-gear 2`` and
``--material2`` have no meaning for a drive and are refused.
"""
from __future__ import annotations

import math
import sys

from ..errors import GearDesignError
from ..files import check_output_path, write_file_atomic
from ..scene.drive import compute_drive
from ..scene.html import drive_report
from ..scene.load import load_scene
from .options import add_cluster_args, add_load_args, add_output_file, cluster_from_args, strength_from_args
from .output import Progress, add_json_flag, add_progress_flag, print_frame, print_json, print_verdict_line, print_wrapped


def add_parser(subparsers):
    p = subparsers.add_parser(
        "drive", help="a drive from a scene's [drive] section: power flow, checks, keys, the optimal ratio split",
        description="Link the stages of a scene's [drive] section (motor, given units, gear pairs, chains, keyed "
                    "shafts): analyse the power flow, or with total_ratio optimise the ratio split and every free "
                    "variable together (see docs/drive_train.md). Exit status 0 when every check of the drive holds, 1 "
                    "when one fails (the output names the stage and check), 2 on bad input.",
        epilog="Load options for a drive: --power or --torque with --speed replace the scene's input; --material, "
               "--life-h, --application-factor and --strength-width apply to every gear stage that does not set "
               "its own (a gear stage without module is then sized by its load); --spectrum CSV is the drive's load "
               "spectrum at its input shaft (torque_nm, n_rpm as pair --spectrum takes them), read relative to the "
               "nominal input torque P/ω as every gear stage's duty cycle: the stages are then sized and checked by "
               "their service life too (ISO 6336-6); --on-gear 2 and --material2 are refused (each stage carries its "
               "own shaft's load, in one material).")
    p.add_argument("scene", help="a scene file (.toml) with a [drive] section")
    add_output_file(p, "--plot", "PNG", "the drive's diagram")
    p.add_argument("--layout-plot", metavar="PNG", default=None,
                   help="with shafts: write the shafts, gears and bearings seen from above, to scale, to this PNG file")
    p.add_argument("--report", metavar="HTML", default=None,
                   help="write a one-page report (checks, power flow, stages, gear geometry, keys, diagram) to this HTML file")
    add_json_flag(p)
    add_progress_flag(p)
    add_load_args(p, limits=True)     # --spectrum: the drive's, at its input shaft (every gear stage's duty cycle)
    for action in p._actions:         # a pair's wording ("torque on gear 1 (--on-gear)") said as a drive means it
        action.help = _DRIVE_LOAD_HELP.get(action.dest, action.help)
    _add_shafting_args(p)
    add_cluster_args(p)
    return p


_DRIVE_LOAD_HELP = {
    "torque": "the drive's input torque (on its input shaft), N·m, instead of the scene's input",
    "power": "the drive's input power, kW (instead of --torque), instead of the scene's input",
    "speed": "the drive's input speed, rpm (alone: the scene's input at this speed)",
    "on_gear": "refused: a drive's load is at its input shaft, the pinion of its first stage (1)",
    "material": "material of the gear stages that set none (both gears of each), a name of the ISO 6336-5 catalog, "
                "e.g. 42CrMo4, 18CrNiMo7-6, C45",
    "material2": "refused: a drive's gear stages take one material for both gears (--material)",
    "spectrum": "the drive's load spectrum at its input shaft: a CSV with columns torque_nm, n_rpm (or none: the "
                "input speed) and one of time_h, cycles, share, read relative to the nominal input torque P/ω as "
                "every gear stage's duty cycle",
}


# option -> Shafting keyword (docs/shafts_in_drive.md); any of them puts the drive's gears on shafts
_SHAFTING_OPTIONS = (("--shaft-material", "material", str, "STEEL",
                      "the shafts' steel (catalogs/shaft_materials_din743.csv; default 42CrMo4)"),
                     ("--shaft-safety", "S_min", float, "S", "least DIN 743 safety of the shafts (1.2)"),
                     ("--bearing-life", "life_h", float, "H", "required bearing life L10h, h (20000)"),
                     ("--bearing-series", "bearing_series", str, "SERIES",
                      "bearing series the bearings are chosen from: 62, 63, 72B, 73B, NU2, NU3, or several "
                      "joined by commas (62,63,NU2,NU3)"),
                     ("--bearing-type", "bearing_type", str, "TYPE",
                      "the shafts' bearings: auto (deep groove, else a tapered roller pair on the seat), deep_groove, "
                      "cylindrical_roller or tapered for every shaft, or SHAFT=TYPE pairs joined by commas "
                      "(1=tapered,2=tapered; the others auto)"),
                     ("--arrangement", "arrangement", str, "X|O",
                      "a tapered roller pair's mounting: X (face to face, default) or O (back to back)"),
                     ("--oil-temperature", "oil_temperature_c", float, "C",
                      "oil temperature for the computed efficiencies, °C (70; with --oil)"))


def _add_shafting_args(p) -> None:
    g = p.add_argument_group("shafts, bearings and efficiency (docs/shafts_in_drive.md)")
    g.add_argument("--shafts", action="store_true",
                   help="put the gear stages on shafts: bearing reactions, DIN 743 seat sizes, bearings for the life, "
                        "seat keys, K_Hβ from the shafts' deflection (also on with [drive.shafting] or any option here)")
    for flag, key, kind, metavar, text in _SHAFTING_OPTIONS:
        g.add_argument(flag, dest="shafting_" + key, type=kind, default=None, metavar=metavar, help=text)
    g.add_argument("--oil", default=None, metavar="NU40,NU100",
                   help="the oil's kinematic viscosities at 40 and 100 °C, mm²/s: the gear stages' efficiencies are "
                        "then computed (ISO/TR 14179-2, SKF bearing friction) where a stage gives none")


def _with_shafting(section: dict, args) -> dict:
    """The [drive] section with the shafting options (each checked by its option's name)."""
    from ..drives.shafting import Shafting

    given = {key: getattr(args, "shafting_" + key) for _, key, *_ in _SHAFTING_OPTIONS
             if getattr(args, "shafting_" + key) is not None}
    if "bearing_series" in given:
        given["bearing_series"] = tuple(v.strip() for v in given["bearing_series"].split(","))
    if "bearing_type" in given and "=" in given["bearing_type"]:
        given["bearing_type"] = _per_shaft(given["bearing_type"])
    for flag, key, *_ in _SHAFTING_OPTIONS:
        if key in given:
            try:
                Shafting(**{key: given[key]})
            except GearDesignError as exc:      # the keyword's message, said of the option
                text = str(exc)
                raise GearDesignError(f"{flag} must {text.split(' must ', 1)[1]}" if " must " in text
                                      else f"{flag}: {text}") from None
    if {"bearing_series", "bearing_type"} & set(given):   # the two together (a type none of the series holds)
        merged = {**(section.get("shafting") or {}), **given}
        try:
            Shafting(**{k: merged[k] for k in ("bearing_series", "bearing_type") if k in merged})
        except GearDesignError as exc:
            flags = [f for f, k, *_ in _SHAFTING_OPTIONS if k in ("bearing_series", "bearing_type") and k in given]
            raise GearDesignError(f"{' with '.join(flags)}: {exc}") from None
        types = given.get("bearing_type")
        beyond = sorted(k for k in types if k > len(section["stages"])) if isinstance(types, dict) else []
        if beyond:
            raise GearDesignError(f"--bearing-type: shaft {beyond[0]} is beyond the drive's shafts 0 … "
                                  f"{len(section['stages'])}")
    if args.oil is not None:
        try:
            nu40, nu100 = (float(v) for v in args.oil.split(","))
            from ..gears.efficiency import Lubricant

            Lubricant(nu40, nu100)
        except (ValueError, GearDesignError) as exc:
            why = str(exc) if isinstance(exc, GearDesignError) else f"expected two numbers NU40,NU100, got {args.oil!r}"
            raise GearDesignError(f"--oil: {why}") from None
        given.update(nu40=nu40, nu100=nu100)
    if not (given or args.shafts):
        return section
    return dict(section, shafting={**(section.get("shafting") or {}), **given})


def _per_shaft(text: str) -> dict:
    """--bearing-type's SHAFT=TYPE pairs as {shaft: type} (refused by the option's name when not so)."""
    out = {}
    for part in text.split(","):
        k, sep, v = part.partition("=")
        if not sep or not k.strip().isdigit():
            raise GearDesignError(f"--bearing-type must be a type or SHAFT=TYPE pairs joined by commas "
                                  f"(e.g. 1=tapered,2=deep_groove), got {text!r}")
        out[int(k)] = v.strip()
    return out


_STAGE_LOAD = (("material", "material"), ("life_h", "life_h"), ("application_factor", "application_factor"),
               ("strength_width", "face_width_mm"))


def _flag(key: str) -> str:
    """The option that sets a gear stage's ``key``."""
    from ..gears.strength.user_options import FACTORS_FLAG, STRENGTH_OPTIONS

    flags = {"factors": FACTORS_FLAG, "face_width_mm": "--strength-width", **{o.keyword: o.flag for o in STRENGTH_OPTIONS}}
    return flags.get(key, "--" + key.replace("_", "-"))


def _input_from_args(section: dict, args) -> dict:
    """The [drive] head with --power/--torque/--speed as the drive's input."""
    if args.power is None and args.torque is None and args.speed is None:
        return section
    if "motor" in section:
        raise GearDesignError("--power/--torque/--speed: the scene's [drive.motor] sets the drive's input; "
                              "give either the motor or these options")
    from ..gears.strength import Load   # validates the options by their names and ranges

    if args.speed is not None:    # named by the option, not by the Drive's n_in_rpm it becomes
        from ..drives.drive import SPEED_RANGE_RPM
        from ..validate import require_range

        require_range("--speed", args.speed, *SPEED_RANGE_RPM, unit="rpm")
    speed = args.speed if args.speed is not None else section.get("n_in_rpm")
    if speed is None:
        raise GearDesignError("--speed: the drive's input speed is needed (the scene's [drive] gives no n_in_rpm)")
    out = dict(section, n_in_rpm=speed)
    if args.power is not None or args.torque is not None:
        load = Load(torque_nm=args.torque, power_kw=args.power, n_rpm=speed)
        out.pop("output_torque_nm", None)
        out["power_kw"] = load.torque_nm * speed * 2 * math.pi / 60_000 if args.power is None else args.power
    return out


def _spectrum_from_args(section: dict, args) -> dict:
    """The [drive] section with ``--spectrum`` as its [drive.spectrum] (the CSV's torques and speeds at the drive's
    input shaft, read relative to its nominal input: every gear stage's duty cycle; ``--life-h`` the required life
    and the hours a ``share`` column divides), or the scene's with ``--sn-curve``/``--mean-stress-factor``."""
    if args.spectrum is not None:
        sp = {"file": args.spectrum, "life_h": args.life_h, "sn_curve": args.sn_curve, "_label": "--spectrum",
              **({"mean_stress_factor": args.mean_stress_factor} if args.mean_stress_factor is not None else {})}
        return dict(section, spectrum=sp)
    if "spectrum" not in section:
        for flag, value, unset in (("--mean-stress-factor", args.mean_stress_factor, None),
                                   ("--sn-curve", args.sn_curve, "iso")):
            if value != unset:
                raise GearDesignError(f"{flag} needs --spectrum (or the scene's [drive.spectrum])")
        return section
    sp = dict(section["spectrum"])
    if args.mean_stress_factor is not None:
        sp["mean_stress_factor"] = args.mean_stress_factor
    if args.sn_curve != "iso":
        sp["sn_curve"] = args.sn_curve
    return dict(section, spectrum=sp)


def _with_load(section: dict, args) -> dict:
    """The [drive] section with the command's load options (see the module's docstring)."""
    if args.on_gear != 1:
        raise GearDesignError(f"--on-gear: a drive's load is at its input shaft, the pinion of its first stage "
                              f"(--on-gear 1); got {args.on_gear}")
    if args.material2 is not None:
        raise GearDesignError(f"--material2: a drive's gear stages take one material for both gears (--material); "
                              f"got {args.material2!r}")
    out = _spectrum_from_args(_input_from_args(section, args), args)
    if args.strength_width is not None:   # named by the option (the drive has no --face-width to name it by)
        from ..gears.mesh import FACE_WIDTH_RANGE_MM
        from ..validate import require_range

        require_range("--strength-width", args.strength_width, *FACE_WIDTH_RANGE_MM, lo_open=True, unit="mm")
    given = {key: getattr(args, opt) for opt, key in _STAGE_LOAD
             if getattr(args, opt) is not None and not (opt == "application_factor" and args.application_factor == 1.0)}
    given.update(strength_from_args(args))   # the strength options, keys of a gear stage as in a scene
    gears = [i for i, st in enumerate(out["stages"]) if st["kind"] == "gear"]
    if given and not gears:
        raise GearDesignError(f"{_flag(next(iter(given)))}: the scene's drive has no gear stage")
    stages = list(out["stages"])
    if given and gears:
        # checked here also where every gear stage sets its own (the option then fills nothing in): a bad value
        # is refused by name, never silently passed over
        from ..scene.drive import _stage

        _stage({"kind": "gear", "z1": 20, "z2": 60, "material": "42CrMo4", **given})
    for i in gears:
        stages[i] = {**given, **stages[i]}     # the stage's own keys win
    if args.spectrum is not None:      # the damage checks need each stage's S-N curves: said of the option
        bare = [st.get("name", "gear") for st in stages if st["kind"] == "gear" and st.get("material") is None]
        if bare:
            raise GearDesignError(f"--spectrum: gear stage '{bare[0]}' has no material to rate its life in (give "
                                  f"--material or the stage's material)")
    return dict(out, stages=stages)


def _verdict(opt, an) -> str:
    """The first line's text: the failing checks (stage:check with its margin), or what was found."""
    if an is None:
        return opt.message
    failing = an.checks.loc[~an.checks["ok"].astype(bool)]
    if len(failing):
        return "; ".join(f"{r['item']}:{r['check']} (margin {float(r['margin']) + 0.0:+.4g})"
                         for _, r in failing.iterrows())
    return an.message


def run(args) -> int:
    scene = load_scene(args.scene)
    if "drive" not in scene:
        raise GearDesignError(f"{args.scene}: no [drive] section (this command runs only that section)")
    target = check_output_path(args.plot, overwrite=args.overwrite) if args.plot else None
    layout_png = (check_output_path(args.layout_plot, overwrite=args.overwrite, what="--layout-plot")
                  if args.layout_plot else None)
    if args.report:
        check_output_path(args.report, overwrite=args.overwrite, suffixes=(".html", ".htm"), what="--report")
    bar = Progress(1, "drive: designs", show=True if args.progress else None)
    try:
        with cluster_from_args(args) as client:
            drive, motor, opt, an = compute_drive({**_with_shafting(_with_load(scene.sections["drive"], args), args),
                                                   "_client": client}, bar.to)
    finally:
        bar.close()
    if layout_png is not None and an is not None and an.shafting is None:
        raise GearDesignError("--layout-plot: the drive has no shafts (give --shafts, a shafting option or "
                              "[drive.shafting])")
    for path, draw in ((target, "plot"), (layout_png, "plot_layout")):
        if path is None or an is None:
            continue
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        ax = getattr(an, draw)()
        try:
            write_file_atomic(path, lambda tmp, fig=ax.figure: fig.savefig(tmp, dpi=110, bbox_inches="tight",
                                                                          format="png"))
        finally:
            plt.close(ax.figure)
        # said as the report is (stderr: --json keeps stdout pure)
        print(f"{'diagram' if draw == 'plot' else 'shaft layout'} written to {path}", file=sys.stderr)
    if args.report and an is not None:
        drive_report(an, args.report, overwrite=args.overwrite)
        print(f"report written to {args.report}", file=sys.stderr)
    unwritten = [flag for flag, asked in (("--plot", args.plot), ("--layout-plot", args.layout_plot),
                                          ("--report", args.report)) if asked]
    if an is None and unwritten:       # the search found no design to draw: said, not silently skipped
        print(f"no design to draw or report: {', '.join(unwritten)} not written", file=sys.stderr)
    ok = (opt.success if opt is not None else an.success)
    if args.json:
        out = {"ok": bool(ok), "scene": str(args.scene), "motor": None if motor is None else motor.to_dict(),
               "optimum": None if opt is None else opt.to_dict(), "analysis": None if an is None else an.to_dict()}
        print_json(out)
        return 0 if ok else 1
    print_verdict_line(bool(ok), _verdict(opt, an))
    if motor is not None:
        print_wrapped(f"motor: {motor.message}")
    if opt is not None:
        print_wrapped(f"optimum ({opt.objective}, u = {opt.total_ratio:g} ± {100 * opt.ratio_tol:g} %): {opt.message}")
        print(f"  {opt.n_combinations} ratio combinations, {opt.n_candidates} designs, {opt.n_shift_solves} shift "
              f"solves, {opt.time_s:.3f} s")
        if len(opt.table):
            print()
            print_frame(opt.table, title="alternatives (best first; reason: why each loses):")
    if an is not None:
        print()
        print_wrapped(f"analysis: {an.message}")
        print_frame(an.flow, title="power flow:")
        print()
        print("stages:")
        for st in an.stages:     # a gear stage sized by its load shows its module and face width here
            print_wrapped("  " + ", ".join(f"{k} = {v:.6g}" if isinstance(v, float) else f"{k} = {v}"
                                           for k, v in st["summary"].items()))
        _print_strength(an)
        _print_life(an)
        print()
        print_frame(an.checks, title="checks:")
        if len(an.keys):
            print()
            print_frame(an.keys.drop(columns=["message"]), title="keys:")
        _print_shafting(an)
    return 0 if ok else 1


def _print_life(an) -> None:
    """Per gear stage with a spectrum: its ISO 6336-6 service life (damage sums, lives and safety factors for the
    required life per gear and mode) under the spectrum at the flow into it."""
    for st in an.stages:
        r = st.get("life")
        if r is None:
            continue
        print()
        print_wrapped(f"service life of stage '{st['summary']['name']}' under its spectrum (ISO 6336-6; "
                      f"{r.bins.shape[0]} bins, the bins: --json, --report):")
        print(repr(r))
        for note in r.notes:
            print_wrapped(f"  note: {note}")


def _print_shafting(an) -> None:
    """The shafts, bearings, checked sections, seat keys, efficiencies and K_Hβ of a drive with shafting."""
    if an.shafting is None:
        return
    print()
    print_wrapped(f"overall efficiency {an.overall_efficiency:.5f}; heat to dissipate {1000 * an.heat_kw:.5g} W")
    for name, title in (("shafts", "shafts (DIN 743; d at the ends, bearing seats, gear seats):"),
                        ("bearings", "bearings (ISO 281):"), ("sections", "checked sections (DIN 743):"),
                        ("seat_keys", "keys at the seats:"),
                        ("gear_deflections", "deflection and slope of the shafts at each gear:"),
                        ("efficiency", "efficiency of each stage:"),
                        ("mesh_misalignment", "K_Hβ from the shafts (ISO 6336-1 method C with the shafts' f_sh):")):
        table = an.shafting.get(name)
        if table is not None and len(table):
            print()
            print_frame(table, title=title)


def factor_columns(result):
    """A StrengthResult's factor table one row per symbol: ``symbol, pair, gear 1, gear 2, clause`` (the value of a
    pair factor under ``pair``, a per-gear factor under its gear), in the order of the factor chain."""
    import pandas as pd

    f = result.factors
    rows = {}
    for sym, gear, value, clause in f.itertuples(index=False, name=None):
        row = rows.setdefault(sym, {"symbol": sym, "pair": None, "gear 1": None, "gear 2": None, "clause": clause})
        row[("pair", "gear 1", "gear 2")[int(gear)]] = value
    return pd.DataFrame(list(rows.values()))


def _print_strength(an) -> None:
    """Per gear stage with a material: its ISO 6336 result at the flow into it (material with σ_Hlim and σ_Flim,
    S_H, S_F, σ_H, σ_F, the governing check) and its factor table (issue 35 §6)."""
    for st in an.stages:
        r = st.get("strength")
        if r is None:
            continue
        flow = st["flow"]
        print()
        name = st["summary"]["name"]
        print_wrapped(f"strength of stage '{name}' (ISO 6336 at {flow.torque_in_nm:.6g} N·m, {flow.n_in_rpm:.6g} "
                      f"rpm on its pinion):")
        print(repr(r))
        print_frame(factor_columns(r).drop(columns="clause"),
                    title=f"factors of stage '{name}' (each with its clause: --json, --report):")
