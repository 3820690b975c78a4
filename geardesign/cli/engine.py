"""``geardesign engine scene.toml``: the crankshaft torque of the scene's ``[engine]`` over one working cycle.

Prints the torque summary (mean, max, min, unevenness μ, the angles where the torque reverses, the flywheel's
fluctuation), writes the torque curve as CSV (``--csv``) and its plot (``--plot``), never over an existing file
unless ``--overwrite``, all or nothing. Exit status 0 when the engine does work over the cycle (a positive mean
torque), 1 when it does not, 2 on bad input (one line naming the file and key, or the option).
"""
from __future__ import annotations

from ..files import all_or_nothing, check_output_path, write_file_atomic
from ..scene.engine import load_engine
from .output import add_json_flag, print_json, print_verdict_line, print_wrapped


def add_parser(subparsers):
    p = subparsers.add_parser(
        "engine", help="the crankshaft torque of a piston engine over its cycle (slider-crank kinetostatics)",
        description="Compute the torque a piston engine puts on its crankshaft over one working cycle from the "
                    "scene file's [engine] table (the slider-crank's dimensions and masses, the indicator diagram, "
                    "the cylinders and their firing phases; see docs/engine.md): every cylinder's torque by "
                    "kinetostatics, their sum with the firing phases, the journal and crank-pin torques, the mean, "
                    "the unevenness and the reversals. Exit status 0 when the engine does work over the cycle, 1 "
                    "when its mean torque is not positive, 2 on bad input.")
    p.add_argument("scene", help="the scene file (.toml) with an [engine] table")
    p.add_argument("--points", type=int, default=None, metavar="N",
                   help="crank angles over the cycle (default: the scene's points, else 720)")
    p.add_argument("--csv", default=None, metavar="CSV",
                   help="write the torque curves (resultant, gas, inertia, each cylinder, journal and crank pin; N·m) "
                        "to this CSV file")
    p.add_argument("--plot", default=None, metavar="PNG", help="write the torque curves' plot to this PNG file")
    p.add_argument("--journals", action="store_true",
                   help="plot the journal torques M_z1 ... (seed 004) instead of the cylinders' torques")
    p.add_argument("--html", default=None, metavar="HTML",
                   help="with a [gear] in the scene: write the engine's gear report (torque, spectrum, life, S-N "
                        "diagrams, damage tables, optimal shifts) to this self-contained HTML page")
    p.add_argument("--overwrite", action="store_true", help="replace existing --csv, --plot and --html files")
    add_json_flag(p)
    return p


def run(args) -> int:
    targets = {}
    if args.csv:
        targets["csv"] = check_output_path(args.csv, overwrite=args.overwrite, suffixes=(".csv",), what="--csv")
    if args.plot:
        targets["plot"] = check_output_path(args.plot, overwrite=args.overwrite, suffixes=(".png",), what="--plot")
    if args.plot and args.csv and targets["plot"].resolve() == targets["csv"].resolve():
        from ..errors import GearDesignError
        raise GearDesignError("--csv and --plot name the same file")
    if args.html:
        targets["html"] = check_output_path(args.html, overwrite=args.overwrite, suffixes=(".html", ".htm"),
                                            what="--html")
    if len({t.resolve() for t in targets.values()}) < len(targets):
        from ..errors import GearDesignError
        raise GearDesignError("--csv, --plot and --html name the same file")
    scene = load_engine(args.scene)
    if args.html and not scene.has_gear:
        from ..errors import GearDesignError
        raise GearDesignError("--html is the report of the engine's gear: the scene has no [gear] (--plot draws the "
                              "torque)")
    points = scene.points if args.points is None else args.points
    if args.points is not None:
        from ..mechanism.engine import POINTS_RANGE
        from ..validate import require_count
        require_count("--points", args.points, *POINTS_RANGE)
    gear = None
    if scene.has_gear:        # the engine's gear: its spectrum, life and best shifts (the whole scene checked first)
        from ..scene.engine_gear import engine_gear
        from ..scene.load import load_scene

        gear = engine_gear(load_scene(args.scene), points)
    res = scene.engine.analyse(points)
    with all_or_nothing():      # every file of the command, or none
        if "csv" in targets:
            table = res.table()
            write_file_atomic(targets["csv"], lambda tmp: table.to_csv(tmp, index=False, float_format="%.10g"))
        if "plot" in targets:
            import matplotlib

            matplotlib.use("Agg", force=False)
            import matplotlib.pyplot as plt

            ax = res.plot(journals=args.journals)
            try:
                write_file_atomic(targets["plot"],
                                  lambda tmp: ax.figure.savefig(tmp, dpi=110, bbox_inches="tight", format="png"))
            finally:
                plt.close(ax.figure)
        if "html" in targets:
            import matplotlib

            matplotlib.use("Agg", force=False)
            from ..scene.engine_gear import engine_gear_report

            engine_gear_report(gear, targets["html"], overwrite=args.overwrite)
    if gear is not None:
        return _report_gear(args, gear, res, targets)
    if args.json:
        print_json({"ok": res.success, "title": scene.title, **res.to_dict(),
                    "files": {k: str(v) for k, v in targets.items()}})
        return 0 if res.success else 1
    verdict = (f"the engine does work: mean torque M_i = {res.mean_torque_nm:.6g} N·m"
               if res.success else f"the engine does no work over the cycle (mean torque {res.mean_torque_nm:.6g} N·m)")
    print_verdict_line(res.success, f"{scene.title}: {verdict}")
    for line in res.summary():
        print_wrapped(line)
    for what, path in targets.items():
        print(f"wrote {path} ({'the torque curves' if what == 'csv' else 'the plot'})")
    return 0 if res.success else 1


def _report_gear(args, gear, res, targets) -> int:
    """The engine's gear end to end: the verdict, the torque summary, the spectrum, the life at the given and the
    optimal shifts per gear and mode, the optimal shifts."""
    failures = gear.failures
    if args.json:
        print_json({**gear.to_dict(), "files": {k: str(v) for k, v in targets.items()}})
        return 1 if failures else 0
    o, best = gear.optimum, gear.life.get("optimum")
    head = (f"the gear's best shifts ({o.objective}) x1 = {o.x1:.4f}, x2 = {o.x2:.4f} give {best.life_h:.4g} h"
            f" >= {best.required_life_h:.6g} h required" if best is not None else "no shifts hold every check")
    print_verdict_line(not failures, f"{gear.scene.title}: " + ("; ".join(failures) if failures else head))
    print("engine:")
    for line in res.summary():
        print_wrapped("  " + line, indent="    ")
    s = gear.spectrum
    h = s.histogram()
    print_wrapped(f"spectrum: {s!r}: the torque counted at the mesh instants of gear {s.on_gear}, per tooth and "
                  f"flank, {len(h)} torque classes ({int((h['flank'] == 'coast').sum())} on the coast flank)",
                  indent="  ")
    for row in h.itertuples(index=False):
        print(f"  {row.torque_nm:10.4g} N·m  {100 * row.share:6.2f} %  {row.flank} flank")
    g = gear.scene.sections["gear"]
    for tag, (x, r) in gear._lives().items():
        what = "the given shifts" if tag == "given" else f"the optimal shifts ({o.objective})"
        fails = f" (they fail {', '.join(gear.given_failed)})" if tag == "given" and gear.given_failed else ""
        print_wrapped(f"life at {what} x1 = {x[0]:.4f}, x2 = {x[1]:.4f}{fails}: {r.life_h:.4g} h of "
                      f"{r.required_life_h:.6g} h required ({'ok' if r.ok else 'FAILS'}), Y_M = "
                      f"{'/'.join(f'{v:g}' for v in r.mean_stress_factor)}", indent="  ")
        for row in r.damage_table().itertuples(index=False):
            print(f"  {row.mode:8s} gear {row.gear}  D = {row.D:<10.4g} life {row.life_h:<10.4g} h  S = {row.S:.4g}")
    print_wrapped(f"optimal shifts: x1 = {o.x1:.6f}, x2 = {o.x2:.6f} ({o.objective}, fun = {o.fun:.6g}; "
                  f"{g['z1']}/{g['z2']} m = {g['module']:g}, a_w = {o.a_w:.4f} mm, eps_alpha = {o.eps_alpha:.4f}, "
                  f"active {', '.join(o.active) or '-'}): {o.message}", indent="  ")
    for what, path in targets.items():
        print(f"wrote {path} ({_WHAT[what]})")
    return 1 if failures else 0


_WHAT = {"csv": "the torque curves", "plot": "the plot", "html": "the engine's gear report"}
