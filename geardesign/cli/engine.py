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
    p.add_argument("--overwrite", action="store_true", help="replace existing --csv and --plot files")
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
    scene = load_engine(args.scene)
    points = scene.points if args.points is None else args.points
    if args.points is not None:
        from ..mechanism.engine import POINTS_RANGE
        from ..validate import require_count
        require_count("--points", args.points, *POINTS_RANGE)
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
