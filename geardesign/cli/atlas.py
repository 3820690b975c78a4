"""``geardesign atlas``: optimal shifts and region size for a table of tooth pairs."""
from __future__ import annotations

import re

from ..files import check_output_path, write_file_atomic
from ..errors import GearDesignError
from .options import add_cluster_args, add_output_file, add_solver_args, cluster_from_args, local_workers
from .output import (Progress, add_json_flag, add_progress_flag, frame_records, print_frame, print_json,
                     print_verdict_line)
from .options import add_rack_args, rack_from_args
from .pair import add_kind_args, kind_from_args
from .options import add_check_args, checks_from_args


def parse_range(text: str, name: str) -> list[int]:
    """'8:40' (inclusive), '17', or '17,20,26'."""
    m = re.fullmatch(r"\s*(\d+)\s*:\s*(\d+)\s*", text)
    if m:
        lo, hi = int(m.group(1)), int(m.group(2))
        if hi < lo:
            raise GearDesignError(f"{name} range {text!r} must be LO:HI with LO <= HI")
        return range(lo, hi + 1)      # a range, not a list: its size is checked before any work
    try:
        return [int(v) for v in text.split(",")]
    except ValueError:
        raise GearDesignError(f"{name} must be LO:HI or a comma list of whole numbers, got {text!r}") from None


def add_parser(sub):
    p = sub.add_parser("atlas", help="optimal shifts for a table of z1 x z2",
                       description="Optimal shifts, margins and region area for every z1/z2 (z2 >= z1). A table: "
                                   "a pair without feasible shifts is a row (feasible False), not a failure; exit "
                                   "status 0 when the table is written, 2 on bad input.")
    p.add_argument("--z1", required=True, help="LO:HI or a comma list, e.g. 8:40")
    p.add_argument("--z2", required=True, help="LO:HI or a comma list, e.g. 10:120")
    add_solver_args(p, "max_x_sum")
    add_output_file(p, "--out", "CSV", "the table")
    add_kind_args(p)
    add_rack_args(p)
    add_check_args(p)
    add_json_flag(p)
    add_progress_flag(p)
    add_cluster_args(p)
    return p


def run(args) -> int:
    from ..shifts.atlas import ATLAS_PAIRS_MAX, atlas_size, shift_atlas   # here: it loads pandas (not for --help)

    z1 = parse_range(args.z1, "--z1")
    z2 = parse_range(args.z2, "--z2")
    n = atlas_size(z1, z2, internal=args.internal)
    limit = ATLAS_PAIRS_MAX * local_workers(args)   # a --scheduler's workers are counted by shift_atlas
    if n > limit and args.scheduler is None:
        raise GearDesignError(f"--z1 {args.z1} --z2 {args.z2} make {n:,} pairs; an atlas takes at most "
                              f"{limit:,}" + (f" ({ATLAS_PAIRS_MAX:,} per worker)" if limit > ATLAS_PAIRS_MAX else ""))
    if args.out:
        check_output_path(args.out, overwrite=args.overwrite, suffixes=(".csv",), what="--out")
    bar = Progress(n, "atlas", show=True if args.progress else None)
    with cluster_from_args(args) as client:
        df = shift_atlas(z1, z2, objective=args.objective, checks=checks_from_args(args), method=args.method,
                         rack=rack_from_args(args), progress=lambda k: bar.to(k, n), **kind_from_args(args),
                         client=client)
    bar.close()
    if args.out:
        write_file_atomic(args.out, lambda tmp: df.to_csv(tmp, index=False))
    if args.json:
        print_json({"ok": True, "time_s": df.attrs.get("time_s"), "rows": frame_records(df)})
        return 0
    print_verdict_line(True, f"{len(df)} pairs tabulated, {int(df.feasible.sum())} with feasible shifts (a pair "
                             f"without is a row, not a failure)")
    cols = ["z1", "z2", "feasible", "x1", "x2", "objective", "eps_alpha", "area", "active", "conflict"]
    print_frame(df[cols].head(40), f"{len(df)} pairs in {df.attrs.get('time_s', 0):.2f} s "
                                   f"({int(df.feasible.sum())} feasible); first rows:")
    if args.out:
        print(f"\ntable written to {args.out}")
    return 0
