"""``geardesign teeth``: tooth counts for a ratio, with the best shifts for each, ranked.

Exit status 0 when some candidate passes every check, 1 when none does (the reason column
says which checks conflict for each pair), 2 on bad input.
"""
from __future__ import annotations


from ..errors import GearDesignError
from ..files import check_output_path, write_file_atomic
from .options import (add_check_args, add_cluster_args, add_output_file, add_solver_args, checks_from_args,
                      cluster_from_args)
from .output import (Progress, add_json_flag, add_progress_flag, frame_records, print_frame, print_json,
                     print_verdict_line, print_wrapped)
from .options import add_rack_args, rack_from_args
from .pair import add_kind_args, kind_from_args

SHOW = ["rank", "z1", "z2", "ratio", "ratio_error", "module_mm", "a_mm", "a_w_mm", "x1", "x2", "eps_alpha",
        "objective", "feasible", "reason"]


def _number_or_series(text: str, what: str):
    if text == "series":
        return "series"
    try:
        return float(text)
    except ValueError:
        raise GearDesignError(f"{what} must be a number in mm or 'series', got {text!r}") from None


def _no_feasible(sel) -> str:
    """The verdict of a search without a feasible pair: the first candidate's conflicting checks."""
    if not len(sel.table):
        return f"no tooth pair within the ratio tolerance ({len(sel.skipped)} skipped before solving)"
    row = sel.table.iloc[0]
    return (f"{str(row['reason']).removeprefix('conflict: ') or 'a check'} of the best candidate "
            f"{int(row['z1'])}/{int(row['z2'])}: no feasible tooth pair")


def add_parser(subparsers):
    p = subparsers.add_parser(
        "teeth", help="tooth counts for a ratio, with the best profile shifts for each, ranked",
        description="Enumerate every z1/z2 within the ratio tolerance, solve the profile shifts of each for the "
                    "objective (with the centre distance fixed, the x-sum follows from it), and rank: feasible "
                    "first, then ratio error, first-series module, objective, smaller tooth sum. Exit status 0 "
                    "when a feasible pair exists, 1 when no row is feasible, 2 on bad input.")
    p.add_argument("--ratio", type=float, required=True, help="gear ratio u = z2/z1 (>= 1)")
    p.add_argument("--module", "-m", default=None, metavar="MM",
                   help="module in mm, or 'series' for the ISO 54 / GOST 9563 modules (m = 1 when omitted "
                        "without a centre distance)")
    p.add_argument("--center-distance", default=None, metavar="A",
                   help="operating centre distance a_w in mm, or 'series': the smallest GOST 2185 value >= a")
    p.add_argument("--ratio-tol", type=float, default=0.02, help="relative ratio tolerance (0.02 = 2 %%)")
    p.add_argument("--z1-min", type=int, default=8, help="fewest pinion teeth (8)")
    p.add_argument("--z1-max", type=int, default=40, help="most pinion teeth (40)")
    p.add_argument("--z-sum-max", type=int, default=None, help="largest z1 + z2")
    p.add_argument("--m-min", type=float, default=None, help="smallest module with --module series, mm (1)")
    p.add_argument("--m-max", type=float, default=None, help="largest module with --module series, mm (50)")
    add_solver_args(p, None, "what the shifts optimise (max_x_sum; balanced_sliding with a centre distance)")
    p.add_argument("--top", type=int, default=20, help="rows to print (0: all; default 20)")
    add_output_file(p, "--out", "CSV", "the whole ranked table")
    add_kind_args(p)
    add_rack_args(p)
    add_check_args(p)
    add_json_flag(p)
    add_progress_flag(p)
    add_cluster_args(p)
    return p


def run(args) -> int:
    from ..shifts.teeth import select_teeth   # here: it loads pandas (not for --help)

    m = None if args.module is None else _number_or_series(args.module, "--module")
    a_w = None if args.center_distance is None else _number_or_series(args.center_distance, "--center-distance")
    if args.top < 0:
        raise GearDesignError(f"--top must be >= 0, got {args.top}")
    m_range = None
    if args.m_min is not None or args.m_max is not None:
        m_range = (args.m_min if args.m_min is not None else 1.0, args.m_max if args.m_max is not None else 50.0)
    if args.out:
        check_output_path(args.out, overwrite=args.overwrite, suffixes=(".csv",), what="--out")
    bar = Progress(0, "solving shifts", show=True if args.progress else None)
    try:
        with cluster_from_args(args) as client:
            sel = select_teeth(args.ratio, ratio_tol=args.ratio_tol, m=m, a_w=a_w,
                               z1_range=(args.z1_min, args.z1_max), z_sum_max=args.z_sum_max, objective=args.objective,
                               checks=checks_from_args(args), rack=rack_from_args(args), method=args.method,
                               m_range=m_range, progress=bar.to, **kind_from_args(args), client=client)
    finally:
        if bar.done:
            bar.close()
    if args.out:
        try:
            write_file_atomic(args.out, lambda tmp: sel.table.to_csv(tmp, index=False))
        except OSError as exc:
            raise GearDesignError(f"--out {args.out!r}: cannot write ({exc.strerror})") from None
    top = sel.table if args.top == 0 else sel.table.head(args.top)
    if args.json:
        out = {"ok": sel.best is not None, **sel.to_dict()}
        out["table"] = frame_records(top)
        out["skipped"] = frame_records(sel.skipped)
        print_json(out)
    else:
        b = sel.best
        print_verdict_line(b is not None, (
            f"z1/z2 = {int(b['z1'])}/{int(b['z2'])}, x1 = {b['x1']:.4f}, x2 = {b['x2']:.4f}, every check holds"
            if b is not None else _no_feasible(sel)))
        print_wrapped(f"Ratio {sel.ratio:g} ± {100 * sel.ratio_tol:g} %, objective {sel.objective}, "
              f"m = {sel.m}, a_w = {sel.a_w if sel.a_w is not None else 'free'}, method {sel.method}: "
              f"{len(sel.table)} candidates solved, {len(sel.skipped)} skipped, {sel.time_s:.2f} s")
        print_wrapped(f"choice: {sel.choice}")
        print()
        print_frame(top[SHOW], title=f"candidates ({len(top)} of {len(sel.table)}, best first):")
        if len(sel.skipped):
            print(f"\n{len(sel.skipped)} pairs skipped before solving, e.g. "
                  f"{sel.skipped['z1'].iloc[0]}/{sel.skipped['z2'].iloc[0]}: {sel.skipped['reason'].iloc[0]}")
        if args.out:
            print(f"\nwrote {len(sel.table)} rows to {args.out}")
    return 0 if sel.best is not None else 1
