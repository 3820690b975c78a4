"""``geardesign shift``: the feasible x1/x2 region and the optimal shifts of one tooth pair."""
from __future__ import annotations

from ..errors import GearDesignError
from ..files import check_output_path, write_file_atomic
from ..gears.pair import GearPair
from ..shifts.objectives import OBJECTIVES
from ..shifts.optimize import DEFAULT_TOL, METHODS, optimize_shifts
from .options import add_check_args, add_output_file, checks_from_args
from .output import (add_json_flag, check_details, failing_margins, frame_records, print_frame, print_json,
                     print_verdict, print_verdict_line, print_wrapped)
from .options import add_rack_args, rack_from_args
from .pair import add_kind_args, kind_from_args

_METHOD_HELP = {
    "exact": "active-set Newton, x to ~1e-12 (default)",
    "convex": "SQP in cvxpy/Clarabel, x to ~tol, slower",
    "grid": "best node of a grid, fastest, x within the node spacing",
}


def add_parser(sub):
    p = sub.add_parser("shift", help="feasible x1/x2 region and optimal shifts of one tooth pair",
                       description="The blocking contour of z1/z2 and the best x1/x2 in it. Exit status 0 when "
                                   "an optimum exists (and a proposed --x1/--x2 passes every check), 1 when the "
                                   "region is empty or the proposed pair fails a check (the output names them), "
                                   "2 on bad input.")
    p.add_argument("--z1", type=float, required=True, help="number of teeth of gear 1 (the pinion), a whole number >= 3")
    p.add_argument("--z2", type=float, required=True,
                   help="number of teeth of gear 2 (the wheel; with --internal the ring, z2 > z1)")
    p.add_argument("--module", "-m", type=float, default=None,
                   help="module, mm: needed with --center-distance; otherwise it only scales a_w (default 1)")
    p.add_argument("--objective", choices=sorted(OBJECTIVES), default=None,
                   help="what the optimum maximises or minimises (default max_x_sum; balanced_sliding with "
                        "--center-distance): " + "; ".join(f"{k}: {o.description}" for k, o in OBJECTIVES.items()))
    p.add_argument("--method", choices=METHODS, default="exact",
                   help="; ".join(f"{k}: {v}" for k, v in _METHOD_HELP.items()))
    p.add_argument("--tol", type=float, default=None,
                   help="tolerance in x (" + ", ".join(f"{k} {v:g}" for k, v in DEFAULT_TOL.items()) + ")")
    p.add_argument("--center-distance", type=float, default=None, metavar="A",
                   help="the housing's operating centre distance a_w, mm (with --module): fixes x1 + x2, "
                        "the objective picks the split")
    p.add_argument("--x1", type=float, default=None, help="a proposed x1 to check and mark (with --x2)")
    p.add_argument("--x2", type=float, default=None, help="a proposed x2 to check and mark (with --x1)")
    p.add_argument("--no-tip-shortening", action="store_true",
                   help="keep d_a = d + 2(h_a* + x)m instead of shortening tips by dy*m")
    add_kind_args(p)
    add_output_file(p, "--plot", "PNG", "the blocking contour")
    p.add_argument("--html", metavar="HTML", default=None,
                   help="write the blocking contour as an interactive page (hover: every check's margin; "
                        "works offline) to this HTML file")
    add_rack_args(p)
    add_check_args(p)
    add_json_flag(p)
    return p


def run(args) -> int:
    from ..shifts.region import feasible_region   # here: it loads pandas (not for --help)

    if (args.x1 is None) != (args.x2 is None):
        raise GearDesignError("--x1 and --x2 go together: give both to check a proposed pair")
    if args.plot:
        check_output_path(args.plot, overwrite=args.overwrite, suffixes=(".png",), what="--plot")
    if args.html:
        check_output_path(args.html, overwrite=args.overwrite, suffixes=(".html", ".htm"), what="--html")
    rack = rack_from_args(args)
    checks = checks_from_args(args)
    shorten = not args.no_tip_shortening
    kind = kind_from_args(args)
    res = optimize_shifts(args.z1, args.z2, objective=args.objective, checks=checks, method=args.method,
                          tol=args.tol, a_w=args.center_distance, m=args.module, rack=rack,
                          tip_shortening=shorten, **kind)
    m = 1.0 if args.module is None else args.module
    proposed = None
    if args.x1 is not None:
        pair = GearPair(m, args.z1, args.z2, args.x1, args.x2, rack, shorten, **kind)
        proposed = pair.checks(**{"jamming": False, **checks}, housing_a_w=args.center_distance)
    region = feasible_region(args.z1, args.z2, rack=rack, checks=checks, m=m, tip_shortening=shorten, **kind)
    if args.plot:
        _write_plot(region, res, proposed, args, write_file_atomic)
    if args.html:
        region.to_html(args.html, optimum=res if res.success else None,
                       proposed=None if proposed is None else (args.x1, args.x2), x_sum=res.x_sum_fixed,
                       overwrite=args.overwrite)
    failed = [] if proposed is None else proposed.loc[~proposed["ok"], "check"].tolist()
    ok = bool(res.success) and not failed
    if args.json:
        d = {"ok": ok, **res.to_dict()}
        d["region"] = {"feasible": region.feasible, "area": region.area, "conflict": region.conflict,
                       "limiting_checks": region.limiting_checks() if region.feasible else [],
                       "boundary": frame_records(region.boundary)}
        if proposed is not None:
            d["proposed"] = {"x1": args.x1, "x2": args.x2, "ok": not failed, "failing_checks": failed,
                             "checks": frame_records(proposed[["check", "value", "limit", "margin", "ok"]])}
        print_json(d)
        return 0 if ok else 1
    _verdict(res, proposed, failed, args)
    for line in repr(res).splitlines():
        print_wrapped(line, indent=" " * 14)
    print()
    print_wrapped(repr(region))
    if res.success:
        print_frame(res.to_frame(), "\nChecks at the optimum (margin >= 0 holds; sensitivity = d fun / d limit)")
    if proposed is not None:
        print_frame(proposed[["check", "value", "limit", "margin", "ok"]],
                    f"\nThe proposed pair x1 = {args.x1:g}, x2 = {args.x2:g}")
        print_verdict(failed, check_details(proposed))
    if args.plot:
        print(f"\nblocking contour written to {args.plot}")
    if args.html:
        print(f"interactive blocking contour written to {args.html}")
    return 0 if ok else 1


def _verdict(res, proposed, failed, args) -> None:
    """The first line: the proposed pair's failing checks, or the region's conflict, or the optimum."""
    if failed:
        details = check_details(proposed)
        print_verdict_line(False, "; ".join(f"{k} ({details[k]})" if details.get(k) else k for k in failed)
                           + f" at the proposed x1 = {args.x1:g}, x2 = {args.x2:g}")
    elif not res.success:
        print_verdict_line(False, f"{failing_margins(res.margins, res.conflict or None)}: no feasible shifts "
                                  f"({res.message})")
    else:
        print_verdict_line(True, f"optimum x1 = {res.x1:.6g}, x2 = {res.x2:.6g} ({res.objective}), every check holds"
                           + (f"; the proposed x1 = {args.x1:g}, x2 = {args.x2:g} too" if proposed is not None else ""))


def _write_plot(region, res, proposed, args, write_file_atomic) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ax = region.plot(optimum=res if res.success else None,
                     proposed=None if proposed is None else (args.x1, args.x2),
                     x_sum=res.x_sum_fixed)
    try:
        write_file_atomic(args.plot, lambda tmp: ax.figure.savefig(tmp, dpi=120, bbox_inches="tight", format="png"))
    finally:
        plt.close(ax.figure)
