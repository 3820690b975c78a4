"""``geardesign atlas``: optimal shifts and region size for a table of tooth pairs."""
from __future__ import annotations

import re

from ..atlas import shift_atlas
from ..errors import GearDesignError
from ..problem import OBJECTIVES
from ..shift import METHODS
from .output import Progress, add_json_flag, frame_records, print_frame, print_json
from .pair import add_rack_args, rack_from_args
from .shift import add_check_args, checks_from_args


def parse_range(text: str, name: str) -> list[int]:
    """'8:40' (inclusive), '17', or '17,20,26'."""
    m = re.fullmatch(r"\s*(\d+)\s*:\s*(\d+)\s*", text)
    if m:
        lo, hi = int(m.group(1)), int(m.group(2))
        if hi < lo:
            raise GearDesignError(f"{name} range {text!r} must be LO:HI with LO <= HI")
        return list(range(lo, hi + 1))
    try:
        return [int(v) for v in text.split(",")]
    except ValueError:
        raise GearDesignError(f"{name} must be LO:HI or a comma list of whole numbers, got {text!r}") from None


def add_parser(sub):
    p = sub.add_parser("atlas", help="optimal shifts for a table of z1 x z2",
                       description="Optimal shifts, margins and region area for every z1/z2 (z2 >= z1).")
    p.add_argument("--z1", required=True, help="LO:HI or a comma list, e.g. 8:40")
    p.add_argument("--z2", required=True, help="LO:HI or a comma list, e.g. 10:120")
    p.add_argument("--objective", choices=sorted(OBJECTIVES), default="max_x_sum")
    p.add_argument("--method", choices=METHODS, default="exact")
    p.add_argument("--out", metavar="CSV", default=None, help="write the table to this CSV")
    add_rack_args(p)
    add_check_args(p)
    add_json_flag(p)
    return p


def run(args) -> int:
    z1 = parse_range(args.z1, "--z1")
    z2 = parse_range(args.z2, "--z2")
    n = sum(1 for a in z1 for b in z2 if b >= a)
    bar = Progress(n, "atlas")
    df = shift_atlas(z1, z2, objective=args.objective, checks=checks_from_args(args), method=args.method,
                     rack=rack_from_args(args), progress=lambda k: bar.update(1))
    bar.close()
    if args.out:
        df.to_csv(args.out, index=False)
    if args.json:
        print_json({"time_s": df.attrs.get("time_s"), "rows": frame_records(df)})
        return 0
    cols = ["z1", "z2", "feasible", "x1", "x2", "objective", "eps_alpha", "area", "active", "conflict"]
    print_frame(df[cols].head(40), f"{len(df)} pairs in {df.attrs.get('time_s', 0):.2f} s "
                                   f"({int(df.feasible.sum())} feasible); first rows:")
    if args.out:
        print(f"\ntable written to {args.out}")
    return 0
