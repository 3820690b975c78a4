"""``geardesign pair``: geometry and checks of one spur pair."""
from __future__ import annotations

import sys

from ..gears.checks import DEFAULT_EPS_ALPHA_MIN, DEFAULT_SA_MIN
from ..errors import GearDesignError
from ..gears.geometry import GEOMETRY_FIELDS
from ..gears.pair import GearPair
from ..gears.rack import BasicRack
from .options import add_output_file
from .output import add_json_flag, frame_records, print_frame, print_json


def add_rack_args(p) -> None:
    g = p.add_argument_group("basic rack (ISO 53 / GOST 13755 defaults)")
    g.add_argument("--alpha-deg", type=float, default=20.0, help="pressure angle, degrees (20)")
    g.add_argument("--ha", type=float, default=1.0, help="addendum coefficient h_a* (1.0)")
    g.add_argument("--c", type=float, default=0.25, help="clearance coefficient c* (0.25)")
    g.add_argument("--rho-f", type=float, default=0.38, help="root fillet coefficient rho_f* (0.38)")


def rack_from_args(args) -> BasicRack:
    return BasicRack(alpha_deg=args.alpha_deg, ha=args.ha, c=args.c, rho_f=args.rho_f)


def add_limit_args(p) -> None:
    g = p.add_argument_group("check limits")
    g.add_argument("--eps-alpha-min", type=float, default=DEFAULT_EPS_ALPHA_MIN,
                   help=f"minimum contact ratio ({DEFAULT_EPS_ALPHA_MIN:g})")
    g.add_argument("--sa-min", type=float, default=DEFAULT_SA_MIN,
                   help=f"minimum tip thickness / module ({DEFAULT_SA_MIN:g}; normal section for helical gears)")
    g.add_argument("--eps-gamma-min", type=float, default=None,
                   help="minimum total contact ratio eps_alpha + eps_beta (helical; needs --face-width)")


def add_pair_args(p) -> None:
    """The pair: module, tooth counts, shifts or a housing centre distance, tip shortening, rack."""
    p.add_argument("--module", "-m", type=float, required=True, help="module, mm")
    p.add_argument("--z1", type=float, required=True, help="teeth of gear 1")
    p.add_argument("--z2", type=float, required=True, help="teeth of gear 2")
    p.add_argument("--x1", type=float, default=None, help="profile shift of gear 1 (0)")
    p.add_argument("--x2", type=float, default=None, help="profile shift of gear 2 (0)")
    p.add_argument("--center-distance", type=float, default=None, metavar="A",
                   help="operating centre distance a_w of the housing, mm. With x1 only: x2 = x_sum(a_w) - x1; "
                        "with neither: the split that balances specific sliding; with both x1 and x2: the "
                        "proposed shifts are kept and a center_distance check compares their a_w with A")
    p.add_argument("--no-tip-shortening", action="store_true",
                   help="keep d_a = d + 2(h_a* + x)m instead of shortening tips by dy*m")
    add_kind_args(p)
    add_rack_args(p)


def add_kind_args(p) -> None:
    """--beta, --internal, --face-width: the kind of pair (see geardesign.gears.mesh.Mesh)."""
    g = p.add_argument_group("helical and internal pairs")
    g.add_argument("--beta", type=float, default=0.0, metavar="DEG",
                   help="reference helix angle, degrees (0: spur); --module is then the normal module")
    g.add_argument("--internal", action="store_true",
                   help="gear 2 is a ring gear with z2 > z1 teeth (a positive x2 moves its flanks outward)")
    g.add_argument("--face-width", type=float, default=None, metavar="MM",
                   help="face width b, mm, for the overlap ratio eps_beta")


def kind_from_args(args) -> dict:
    return dict(beta_deg=args.beta, internal=args.internal, face_width=args.face_width)


def limits_from_args(args) -> dict:
    """The check limits of add_limit_args as make_checks options."""
    out = {"eps_alpha_min": args.eps_alpha_min, "sa_min": args.sa_min}
    if args.eps_gamma_min is not None:
        out["eps_gamma_min"] = args.eps_gamma_min
    return out


def pair_from_args(args) -> tuple[GearPair, float | None]:
    """The pair the arguments describe, and the housing centre distance to check it against (or None)."""
    rack = rack_from_args(args)
    shorten = not args.no_tip_shortening
    if args.center_distance is not None and args.x1 is not None and args.x2 is not None:
        return GearPair(args.module, args.z1, args.z2, args.x1, args.x2, rack, shorten, **kind_from_args(args)), args.center_distance
    if args.center_distance is not None:
        if args.x2 is not None:
            raise GearDesignError("--x2 with --center-distance needs --x1 too (or give neither: the split "
                                  "then balances specific sliding)")
        return GearPair.from_center_distance(args.module, args.z1, args.z2, args.center_distance,
                                             x1=args.x1, rack=rack, tip_shortening=shorten, **kind_from_args(args)), None
    return GearPair(args.module, args.z1, args.z2, args.x1 or 0.0, args.x2 or 0.0, rack, shorten, **kind_from_args(args)), None


def add_parser(sub):
    p = sub.add_parser("pair", help="geometry and checks of one gear pair",
                       description="Geometry (ISO 21771; GOST 16532-70 external, GOST 19274-73 internal) and checks "
                                   "of a spur or helical, external or internal pair.")
    add_pair_args(p)
    add_limit_args(p)
    add_json_flag(p)
    add_output_file(p, "--report", "HTML", "a one-page calculation report (inputs, geometry, checks, contour, mesh)")
    return p


def run(args) -> int:
    if args.report:
        from ..files import check_output_path
        check_output_path(args.report, overwrite=args.overwrite, suffixes=(".html", ".htm"), what="--report")
    pair, housing = pair_from_args(args)
    if args.report:
        from ..scene.html import pair_report
        pair_report(pair, args.report, overwrite=args.overwrite, eps_alpha_min=args.eps_alpha_min,
                    sa_min=args.sa_min, housing_a_w=housing, eps_gamma_min=args.eps_gamma_min)
        print(f"report written to {args.report}", file=sys.stderr)   # stderr: --json keeps stdout pure
    rack, shorten = pair.rack, not args.no_tip_shortening
    geo = pair.geometry()
    table = pair.checks(eps_alpha_min=args.eps_alpha_min, sa_min=args.sa_min, housing_a_w=housing,
                        eps_gamma_min=args.eps_gamma_min)
    if args.json:
        print_json({
            "input": {"m": pair.m, "z1": pair.z1, "z2": pair.z2, "x1": pair.x1, "x2": pair.x2,
                      "alpha_deg": rack.alpha_deg, "ha": rack.ha, "c": rack.c, "rho_f": rack.rho_f,
                      "tip_shortening": shorten, "beta_deg": pair.beta_deg, "internal": pair.internal,
                      "face_width_mm": pair.face_width},
            "geometry": geo.to_dict(),
            "checks": frame_records(table[["check", "value", "limit", "margin", "ok"]]),
        })
        return 0
    kind = (("internal " if pair.internal else "") + (f"helical (beta = {pair.beta_deg:g} deg) " if pair.beta_deg
                                                      else "spur ")).capitalize()
    print(f"{kind}pair m = {pair.m:g} mm, z1/z2 = {pair.z1}/{pair.z2}, x1 = {pair.x1:.6g}, x2 = {pair.x2:.6g}, "
          f"rack {rack.alpha_deg:g} deg / {rack.ha:g} / {rack.c:g} / {rack.rho_f:g}"
          f"{'' if shorten else ', no tip shortening'}")
    frame = geo.to_frame()
    frame["unit"] = [GEOMETRY_FIELDS[k][0] for k in frame["quantity"]]
    print_frame(frame[["quantity", "value", "unit", "description"]], "\nGeometry", float_format="{:.8g}")
    print_frame(table[["check", "value", "limit", "margin", "ok", "label"]], "\nChecks (margin >= 0 holds)")
    failed = table.loc[~table["ok"], "check"].tolist()
    print("\nAll checks hold." if not failed else f"\nFailing checks: {', '.join(failed)}")
    return 0
