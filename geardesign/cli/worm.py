"""``geardesign worm``: a cylindrical worm pair's geometry and checks (DIN 3975), the wheel's shift for a centre
distance, its best shift, the measuring sizes for the drawing, with --speed its efficiency and with --torque its
rating (docs/worm_rating.md), or (without --module) the ranked choice of module,
q and starts for a ratio and centre distance from the standard series.

Exit status 0 when every check holds (or a feasible candidate exists), 1 when one fails (the first line names it),
2 on bad input (one line naming the option).
"""
from __future__ import annotations

import argparse
import re

from ..errors import GearDesignError
from ..gears.worm.checks import worm_options
from ..gears.worm.geometry import FLANK_FORMS
from ..gears.worm.pair import X2_OBJECTIVES
from .options import _limit, add_rack_args, rack_from_args
from .output import (add_json_flag, check_details, frame_records, print_frame, print_json, print_verdict,
                     print_verdict_line, print_wrapped)

# the library's keywords in an error message, by the option that sets them here
_FLAGS = {"m_x": "--module", "z1": "--z1", "z2": "--z2", "q": "--q", "x2": "--x2", "flank_form": "--flank-form",
          "worm_length_mm": "--worm-length", "face_width_mm": "--face-width", "a (center distance)": "--center-distance",
          "ratio": "--ratio", "objective": "--optimize-x2", "alpha_deg": "--alpha-deg", "rho_f": "--rho-f",
          "ha": "--ha", "c": "--c", "n1": "--speed", "T2": "--torque", "mu": "--mu", "mu_static": "--mu-static",
          "l_1": "--bearing-span", "k_heat": "--heat-transfer", "A_housing": "--housing-area", "theta_0": "--ambient",
          "theta_lim": "--oil-limit", "P_V0": "--no-load-loss", "casting": "--casting",
          "application_factor": "--application-factor"}
# the rating's options by the flag that sets them (a flag left out leaves its check out of the rating)
_RATING_FLAGS = (("mu", "mu"), ("mu_static", "mu_static"), ("bearing_span", "l_1"), ("heat_transfer", "k_heat"),
                 ("housing_area", "A_housing"), ("ambient", "theta_0"), ("oil_limit", "theta_lim"),
                 ("no_load_loss", "P_V0"), ("casting", "casting"), ("application_factor", "application_factor"))
# the shared options' meaning for a worm pair (their spur-pair help speaks of two gears)
_WORM_HELP = {"undercut": "no undercut of the wheel by its hob (x2 >= x_min2)",
              "sa_min": "minimum tip thickness / m_x of the worm's thread and the wheel's teeth",
              "eps_alpha_min": "minimum contact ratio of the mid-plane mesh"}
_SELECT_SHOW = ["m_x", "q", "z1", "z2", "u", "x2", "a", "gamma_m_deg", "eps_alpha", "min_margin", "limiting_check",
                "feasible"]


def add_parser(sub):
    p = sub.add_parser(
        "worm", help="geometry and checks of a cylindrical worm pair (DIN 3975), or the choice of one",
        description="A cylindrical worm pair (flank forms ZA, ZN, ZI, ZK; DIN 3975 / ISO/TR 10828, GOST 19650): "
                    "the verdict first, then the checks (margins >= 0 hold), then the geometry. With "
                    "--center-distance the wheel's shift x2 is the one that gives it; --optimize-x2 picks the best x2 "
                    "for the checks; without --module, --ratio (and --center-distance) rank the standard modules "
                    "(GOST 19672), q and starts. The rack's --alpha-deg is axial for ZA, normal for ZN, ZI, ZK. Exit status 0 "
                    "when every check holds, 1 when one fails, 2 on bad input.")
    g = p.add_argument_group("the worm pair")
    g.add_argument("--module", type=float, default=None, metavar="MM", help="axial module m_x of the worm, mm")
    g.add_argument("--z1", type=float, default=None, help="worm starts z1 (1 … 10)")
    g.add_argument("--z2", type=float, default=None, help="wheel teeth z2")
    g.add_argument("--q", type=float, default=None, help="diameter quotient q = d_m1/m_x")
    g.add_argument("--x2", type=float, default=None, help="the wheel's profile shift (0)")
    g.add_argument("--center-distance", type=float, default=None, metavar="MM",
                   help="centre distance a, mm: x2 = a/m_x - (q + z2)/2 (or, without --module, the a to select for)")
    g.add_argument("--flank-form", default="ZA", help=f"flank form: {', '.join(FLANK_FORMS)} (ZA)")
    g.add_argument("--worm-length", type=float, default=None, metavar="MM",
                   help="threaded worm length b_1, mm (default: what the mesh needs)")
    g.add_argument("--face-width", type=float, default=None, metavar="MM",
                   help="wheel face width b_2, mm (default: the working width 2 m_x sqrt(h_a*(q + h_a*)))")
    g.add_argument("--optimize-x2", default=None, metavar="OBJECTIVE",
                   help="choose x2 for the checks: " + "; ".join(f"{k}: {v}" for k, v in X2_OBJECTIVES.items()))
    g.add_argument("--measurements", action="store_true", help="also the measuring sizes for the drawing")
    s = p.add_argument_group("choice from the series (without --module)")
    s.add_argument("--ratio", type=float, default=None, help="gear ratio u = z2/z1 to select for")
    s.add_argument("--top", type=int, default=10, help="rows of the ranking shown (10)")
    r = p.add_argument_group("efficiency and load capacity (docs/worm_rating.md; with --module)")
    r.add_argument("--speed", type=float, default=None, metavar="RPM",
                   help="worm speed n1, rpm: adds the efficiency (sliding speed, friction, worm- and wheel-driving "
                        "efficiency, self-locking)")
    r.add_argument("--torque", type=float, default=None, metavar="NM",
                   help="wheel torque T2, N·m (with --speed): adds the rating and the torque the pair carries")
    r.add_argument("--mu", type=float, default=None, help="measured coefficient of friction (default: AGMA 6034 at "
                                                             "the sliding speed)")
    r.add_argument("--mu-static", type=float, default=None, help="starting friction for static self-locking (0.15)")
    r.add_argument("--bearing-span", type=float, default=None, metavar="MM",
                   help="the worm's bearing span l_1, mm: adds the deflection check")
    r.add_argument("--heat-transfer", type=float, default=None, metavar="W/M2K",
                   help="housing heat transfer coefficient k, W/(m²·K): adds the temperature check")
    r.add_argument("--casting", default=None, metavar="METHOD",
                   help="the bronze wheel's casting, sand, chill or centrifugal: adds the AGMA 6034 load check "
                        "(allowable tangential load, Shigley ch. 15)")
    r.add_argument("--application-factor", type=float, default=None, metavar="K_A",
                   help="application factor K_A of the AGMA load check (1)")
    r.add_argument("--housing-area", type=float, default=None, metavar="M2",
                   help="heat-shedding housing area A, m² (default with --heat-transfer: 9e-5·a^1.85, a ribbed "
                        "housing)")
    r.add_argument("--ambient", type=float, default=20.0, metavar="C", help="ambient temperature, °C (20)")
    r.add_argument("--oil-limit", type=float, default=90.0, metavar="C", help="highest oil temperature, °C (90)")
    r.add_argument("--no-load-loss", type=float, default=0.0, metavar="W", help="no-load (churning) loss, W (0)")
    add_rack_args(p)
    c = p.add_argument_group("checks of a worm pair (limits and switches)")
    for opt in worm_options().values():
        flag = "--" + opt.name.replace("_", "-")
        if opt.kind == "limit":
            lo, hi = opt.range
            c.add_argument(flag, dest=opt.name, type=_limit, default=opt.default, metavar="VALUE",
                           help=f"{_WORM_HELP.get(opt.name, opt.help)} ({opt.default:g}; {lo:g} to {hi:g}, or none "
                                "to drop the check)")
        else:
            c.add_argument(flag, dest=opt.name, action=argparse.BooleanOptionalAction, default=opt.default,
                           help=f"{_WORM_HELP.get(opt.name, opt.help)} ({'on' if opt.default else 'off'} by default)")
    add_json_flag(p)
    return p


def _checks(args) -> dict:
    return {name: getattr(args, name) for name in worm_options()}


def _named(exc: GearDesignError) -> GearDesignError:
    """The error with each library keyword named by its option (``m_x must be`` -> ``--module must be``)."""
    text = str(exc)
    for keyword, flag in _FLAGS.items():
        text = re.sub(rf"(?<![\w\-.'\"]){re.escape(keyword)}(?![\w'\"])(?= must| = |:|\b is)", flag, text)
    return GearDesignError(text)


def run(args) -> int:
    try:
        return _run(args)
    except GearDesignError as exc:
        raise _named(exc) from None


def _run(args) -> int:
    from ..gears.worm.pair import WormPair

    rack = rack_from_args(args)
    checks = _checks(args)
    if args.module is None:
        return _select(args, rack, checks)
    for flag, value in (("--z1", args.z1), ("--z2", args.z2), ("--q", args.q)):
        if value is None:
            raise GearDesignError(f"{flag} is needed with --module (or leave out --module to select from the series)")
    if args.center_distance is not None and args.x2 is not None:
        raise GearDesignError("give --x2 or --center-distance, not both (the centre distance fixes x2)")
    if args.center_distance is not None and args.optimize_x2 is not None:
        raise GearDesignError("give --optimize-x2 or --center-distance, not both (the centre distance fixes x2)")
    kw = dict(flank_form=args.flank_form, rack=rack, worm_length_mm=args.worm_length, face_width_mm=args.face_width)
    if args.center_distance is not None:
        pair = WormPair.from_center_distance(args.center_distance, args.module, args.z1, args.z2, args.q, **kw)
    else:
        pair = WormPair(args.module, args.z1, args.z2, args.q, args.x2 or 0.0, **kw)
    optimum = None
    if args.optimize_x2 is not None:
        optimum = pair.optimize_x2(args.optimize_x2, **checks)
        pair = pair.with_x2(optimum.x2)
    geo = pair.geometry()
    table = pair.checks(**checks)
    failed = table.loc[~table["ok"], "check"].tolist()
    efficiency, rating, capacity = _rating(args, pair)
    if rating is not None:
        failed += [f"rating {k}" for k, v in rating.margins.items() if v < 0]
    if args.json:
        print_json({"ok": not failed and (optimum is None or optimum.success), "failing_checks": failed,
                    "input": {"m_x": pair.m_x, "z1": pair.z1, "z2": pair.z2, "q": pair.q, "x2": pair.x2,
                              "flank_form": pair.flank_form, "alpha_deg": rack.alpha_deg, "ha": rack.ha, "c": rack.c,
                              "rho_f": rack.rho_f, "worm_length_mm": pair.worm_length_mm,
                              "face_width_mm": pair.face_width_mm},
                    "geometry": geo.to_dict(),
                    "checks": frame_records(table[["check", "value", "limit", "margin", "ok"]]),
                    **({"measurements": frame_records(pair.measurements())} if args.measurements else {}),
                    **({"optimum": optimum.to_dict()} if optimum is not None else {}),
                    **({"efficiency": efficiency} if efficiency is not None else {}),
                    **({"rating": rating.to_dict(), "load_capacity": capacity} if rating is not None else {})})
        return 1 if failed or (optimum is not None and not optimum.success) else 0
    print_verdict(failed, check_details(table))
    print_wrapped(repr(pair))
    if optimum is not None:
        print(f"\nBest x2 ({optimum.objective})\n{optimum!r}")
    print_frame(table[["check", "value", "limit", "margin", "ok", "label"]], "\nChecks (margin >= 0 holds)")
    print_frame(geo.table()[["quantity", "symbol", "value", "unit"]], "\nGeometry", float_format="{:.8g}")
    if args.measurements:
        print_frame(pair.measurements(), "\nMeasuring sizes (zero backlash)", float_format="{:.5f}")
    if rating is not None:
        print(f"\n{rating!r}")
        if capacity:
            print(f"  carries T2 = {capacity['T2_max']:.6g} N·m at the minimum safeties (governing: "
                  f"{capacity['governing']})")
    elif efficiency is not None:
        print(f"\nEfficiency at n1 = {args.speed:g} rpm (worm driving unless said)")
        for key in ("v_g", "mu", "friction_method", "rho_deg", "eta_z", "eta_z_reverse", "self_locking_static",
                    "self_locking_dynamic"):
            value = efficiency[key]
            print(f"  {key:22}{value:.6g}" if isinstance(value, float) else f"  {key:22}{value}")
    return 1 if failed or (optimum is not None and not optimum.success) else 0


def _rating(args, pair):
    """(efficiency dict, WormRating, load capacity dict) the options ask for: None where they do not."""
    if args.speed is None:
        for flag, name in (("--torque", "torque"), ("--mu", "mu"), ("--bearing-span", "bearing_span"),
                           ("--heat-transfer", "heat_transfer"), ("--housing-area", "housing_area"),
                           ("--casting", "casting"), ("--application-factor", "application_factor")):
            if getattr(args, name) is not None:
                raise GearDesignError(f"{flag} needs --speed (the worm speed, rpm)")
        return None, None, None
    efficiency = pair.efficiency(args.speed, mu=args.mu, mu_static=args.mu_static)
    if args.torque is None:
        return efficiency, None, None
    from ..gears.worm.rating import load_capacity
    from ..gears.worm.temperature import housing_area_estimate

    options = {name: getattr(args, flag) for flag, name in _RATING_FLAGS if getattr(args, flag) is not None}
    if args.heat_transfer is not None and args.housing_area is None:
        options["A_housing"] = float(housing_area_estimate(pair.geometry().a))
    rating = pair.rating(args.torque, args.speed, **options)
    capacity = load_capacity(rating, P_const=args.no_load_loss) if rating.margins else None
    return efficiency, rating, capacity


def _select(args, rack, checks) -> int:
    from ..gears.worm.series import select_worm

    if args.ratio is None and args.z2 is None:
        raise GearDesignError("--module is needed (a pair), or --ratio (a choice from the series)")
    if args.q is not None and args.q <= 0:
        raise GearDesignError(f"--q must be > 0, got {args.q:g}")
    if not 1 <= args.top <= 10_000:
        raise GearDesignError(f"--top must be in [1, 10000], got {args.top}")
    s = select_worm(args.ratio, args.center_distance, z1=args.z1, z2=args.z2, q=args.q,
                    objective=args.optimize_x2 or "min_abs_x2", checks=checks, flank_form=args.flank_form, rack=rack)
    top = s.table.head(args.top)
    if args.json:
        print_json({"ok": s.found, "choice": s.choice, "candidates": frame_records(top)})
        return 0 if s.found else 1
    print_verdict_line(s.found, s.choice)
    print_frame(top[_SELECT_SHOW], f"\nBest {len(top)} of {len(s.table)} candidates")
    return 0 if s.found else 1
