"""``geardesign shift``: the feasible x1/x2 region and the optimal shifts of one tooth pair."""
from __future__ import annotations

from ..problem import OBJECTIVES
from ..region import feasible_region
from ..shift import METHODS, optimize_shifts
from .output import add_json_flag, frame_records, print_frame, print_json
from .pair import add_limit_args, add_rack_args, rack_from_args


def add_check_args(p) -> None:
    add_limit_args(p)
    p.add_argument("--allow-undercut", action="store_true", help="drop the undercut checks")
    p.add_argument("--allow-interference", action="store_true", help="drop the interference checks")


def checks_from_args(args) -> dict:
    return {"eps_alpha_min": args.eps_alpha_min, "sa_min": args.sa_min,
            "undercut": not args.allow_undercut, "interference": not args.allow_interference}


def add_parser(sub):
    p = sub.add_parser("shift", help="feasible x1/x2 region and optimal shifts of one tooth pair",
                       description="The blocking contour of z1/z2 and the best x1/x2 in it.")
    p.add_argument("--z1", type=float, required=True)
    p.add_argument("--z2", type=float, required=True)
    p.add_argument("--module", "-m", type=float, default=1.0, help="module, mm (scales a_w; 1)")
    p.add_argument("--objective", choices=sorted(OBJECTIVES), default="max_x_sum")
    p.add_argument("--method", choices=METHODS, default="exact")
    p.add_argument("--tol", type=float, default=None, help="tolerance in x (method default)")
    p.add_argument("--center-distance", type=float, default=None, metavar="A",
                   help="fixed operating centre distance a_w, mm: the objective picks the split")
    p.add_argument("--no-tip-shortening", action="store_true")
    p.add_argument("--plot", metavar="PNG", default=None, help="write the blocking contour to this PNG")
    add_rack_args(p)
    add_check_args(p)
    add_json_flag(p)
    return p


def run(args) -> int:
    rack = rack_from_args(args)
    checks = checks_from_args(args)
    shorten = not args.no_tip_shortening
    res = optimize_shifts(args.z1, args.z2, objective=args.objective, checks=checks, method=args.method,
                          tol=args.tol, a_w=args.center_distance, m=args.module, rack=rack,
                          tip_shortening=shorten)
    region = feasible_region(args.z1, args.z2, rack=rack, checks=checks, m=args.module, tip_shortening=shorten)
    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        ax = region.plot(optimum=res if res.success else None)
        ax.figure.savefig(args.plot, dpi=120, bbox_inches="tight")
        plt.close(ax.figure)
    if args.json:
        d = res.to_dict()
        d["region"] = {"feasible": region.feasible, "area": region.area, "conflict": region.conflict,
                       "limiting_checks": region.limiting_checks() if region.feasible else [],
                       "boundary": frame_records(region.boundary)}
        print_json(d)
        return 0 if res.success else 1
    print(repr(res))
    print()
    print(repr(region))
    if res.success:
        print_frame(res.to_frame(), "\nChecks at the optimum (margin >= 0 holds; sensitivity = d fun / d limit)")
    if args.plot:
        print(f"\nblocking contour written to {args.plot}")
    return 0 if res.success else 1
