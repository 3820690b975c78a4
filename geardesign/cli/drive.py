"""``geardesign drive scene.toml``: the [drive] section of a scene, analysed or optimised.

Prints the power flow, every check of the drive, the keys and (optimised) the ranked alternatives;
``--plot FILE`` writes the drive's diagram, ``--json`` prints the result. Exit status 0 when every
check holds, 1 when the drive fails (the output names the stage and checks), 2 on bad input.
"""
from __future__ import annotations

import sys

from ..errors import GearDesignError
from ..files import check_output_path, write_file_atomic
from ..scene.drive import compute_drive
from ..scene.html import drive_report
from ..scene.load import load_scene
from .options import add_cluster_args, add_output_file, cluster_from_args
from .output import Progress, add_json_flag, print_frame, print_json, print_wrapped


def add_parser(subparsers):
    p = subparsers.add_parser(
        "drive", help="a drive from a scene's [drive] section: power flow, checks, keys, the optimal ratio split",
        description="Link the stages of a scene's [drive] section (motor, given units, gear pairs, chains, keyed "
                    "shafts): analyse the power flow, or with total_ratio optimise the ratio split and every free "
                    "variable together (see docs/drive_train.md). Exit status 0 when every check of the drive holds, 1 "
                    "when one fails (the output names the stage and check), 2 on bad input.")
    p.add_argument("scene", help="a scene file (.toml) with a [drive] section")
    add_output_file(p, "--plot", "PNG", "the drive's diagram")
    p.add_argument("--report", metavar="HTML", default=None,
                   help="write a one-page report (checks, power flow, stages, gear geometry, keys, diagram) to this HTML file")
    add_json_flag(p)
    add_cluster_args(p)
    return p


def run(args) -> int:
    scene = load_scene(args.scene)
    if "drive" not in scene:
        raise GearDesignError(f"{args.scene}: no [drive] section (this command runs only that section)")
    target = check_output_path(args.plot, overwrite=args.overwrite) if args.plot else None
    if args.report:
        check_output_path(args.report, overwrite=args.overwrite, suffixes=(".html", ".htm"), what="--report")
    bar = Progress(1, "drive: gear pairs")
    try:
        with cluster_from_args(args) as client:
            drive, motor, opt, an = compute_drive({**scene.sections["drive"], "_client": client}, bar.to)
    finally:
        if bar.done:
            bar.close()
    if target is not None and an is not None:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        ax = an.plot()
        try:
            write_file_atomic(target, lambda tmp: ax.figure.savefig(tmp, dpi=110, bbox_inches="tight", format="png"))
        finally:
            plt.close(ax.figure)
    if args.report and an is not None:
        drive_report(an, args.report, overwrite=args.overwrite)
        print(f"report written to {args.report}", file=sys.stderr)
    ok = (opt.success if opt is not None else an.success)
    if args.json:
        out = {"ok": bool(ok), "scene": str(args.scene), "motor": None if motor is None else motor.to_dict(),
               "optimum": None if opt is None else opt.to_dict(), "analysis": None if an is None else an.to_dict()}
        print_json(out)
        return 0 if ok else 1
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
        print_frame(an.checks, title="checks:")
        if len(an.keys):
            print()
            print_frame(an.keys.drop(columns=["message"]), title="keys:")
    return 0 if ok else 1
