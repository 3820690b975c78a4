"""``geardesign run scene.toml --out DIR``: run a scene file and write its report.

Writes report.md (tables and pictures), the tables as CSV and the plots as PNG into DIR (its parent
folders are created, and removed again if the run fails) and prints a summary (``--json``: the summary and the file names as JSON). A
wrong scene stops with one line naming the file, the key and what was expected (exit 2), and writes
nothing. Exit status 1 when a design of the scene fails (:attr:`SceneReport.failures`: an empty shift
region, given shifts that fail a check, nothing feasible, a failing drive); the report is written
either way.
"""
from __future__ import annotations

from pathlib import Path

from ..files import parents_made
from ..scene import run_scene
from .options import add_cluster_args, cluster_from_args
from .output import Progress, add_json_flag, print_json


def add_parser(subparsers):
    p = subparsers.add_parser(
        "run", help="run a scene file (TOML) and write a report with tables and plots",
        description="Run one design case described in a TOML scene file ([gear], [teeth], [planetary], [chain], [key], [drive], "
                    "[study]; see docs/studies.md) and write report.md, CSV tables and PNG plots. Exit status 0 "
                    "when every design of the scene passes, 1 when one fails (an empty shift region, given shifts "
                    "that fail a check, nothing feasible, a failing drive; the report is written either way and "
                    "its last line names them), 2 on bad input.")
    p.add_argument("scene", help="the scene file (.toml)")
    p.add_argument("--out", required=True, metavar="DIR",
                   help="folder for report.md, CSV and PNG files: new (its parent folders are created), or empty "
                        "(written whole or not at all)")
    p.add_argument("--overwrite", action="store_true", help="replace the contents of a non-empty --out folder")
    add_json_flag(p)
    add_cluster_args(p)
    return p


def run(args) -> int:
    bar = Progress(1, "scene")
    try:
        # the parents are made for the report and removed again if the run fails (bad scene, Ctrl-C)
        with parents_made(args.out, "--out"), cluster_from_args(args) as client:
            rep = run_scene(args.scene, args.out, overwrite=args.overwrite, client=client,
                            progress=lambda done, total, section: bar.to(done, total, f"scene [{section}]"))
    finally:
        if bar.done:
            bar.close()
    out = Path(args.out)
    if args.json:
        d = rep.to_dict()
        d["out"] = str(out)
        print_json(d)
        return 1 if rep.failures else 0
    print("OK: every design of the scene passes." if not rep.failures else "FAILS: " + "; ".join(rep.failures))
    print(f"{rep.scene.title} ({Path(rep.scene.path).name}, {rep.time_s:.2f} s)")
    for line in rep.summary:
        print(f"  {line}")
    print(f"wrote {out / 'report.md'}, {len(rep.tables)} CSV table(s), {len(rep.figures)} plot(s)")
    return 1 if rep.failures else 0
