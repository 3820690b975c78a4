"""``geardesign pair``: geometry and checks of one spur pair."""
from __future__ import annotations

import sys

from ..errors import GearDesignError
from ..files import check_output_path
from ..gears.checks.strength import STRENGTH_CONTEXT
from ..gears.pair import PAIR_CHECK_COLUMNS, GearPair
from ..gears.quantities import GEOMETRY_COLUMNS, geometry_rows
from ..scene.html import pair_report
from .measure import ROWS
from .options import add_check_args, add_output_file, add_rack_args, checks_from_args, rack_from_args
from .output import (Rows, add_json_flag, check_details, frame_records, print_frame, print_json, print_verdict,
                     print_wrapped)


def add_pair_args(p) -> None:
    """The pair: module, tooth counts, shifts or a housing centre distance, tip shortening, rack."""
    p.add_argument("--module", "-m", type=float, required=True, help="module, mm")
    p.add_argument("--z1", type=float, required=True, help="number of teeth of gear 1 (the pinion), a whole number >= 3")
    p.add_argument("--z2", type=float, required=True,
                   help="number of teeth of gear 2 (the wheel; with --internal the ring, z2 > z1)")
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
    g.add_argument("--face-width", dest="face_width_mm", type=float, default=None, metavar="MM",
                   help="face width b, mm, for the overlap ratio eps_beta")


def kind_from_args(args) -> dict:
    return dict(beta_deg=args.beta, internal=args.internal, face_width_mm=args.face_width_mm)


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
                                   "of a spur or helical, external or internal pair: the verdict first, then the "
                                   "checks, then the geometry in the handbook's layout (gear 1 | gear 2). "
                                   "Exit status 0 when every check holds, 1 when one fails (the first line names "
                                   "it), 2 on bad input.")
    add_pair_args(p)
    add_check_args(p)
    g = p.add_argument_group("drawing sizes (ISO 21771 allowances, ISO 1340 data block)")
    g.add_argument("--measurements", action="store_true",
                   help="also the measuring sizes of both gears (span, over balls, chordal; see geardesign measure)")
    for i in (1, 2):
        g.add_argument(f"--allowance{i}", type=float, nargs="+", default=None, metavar="MM",
                       help=f"tooth-thickness allowance A_sne [A_sni] of gear {i}, mm: <= 0, negative thins the tooth "
                            f"(A_sni <= A_sne <= 0; one value: both); for --measurements, --backlash, --data-block")
    g.add_argument("--center-distance-allowance", type=float, nargs=2, default=None, metavar=("A_AI", "A_AE"),
                   help="lower and upper centre-distance allowances, mm (for --backlash, --data-block)")
    g.add_argument("--backlash", action="store_true", help="also the least and most backlash the allowances give")
    g.add_argument("--data-block", type=float, default=None, nargs="?", const=0, metavar="CLASS",
                   help="also both gears' drawing data blocks (ISO 1340), with the ISO 1328-1 class CLASS if given")
    add_json_flag(p)
    add_output_file(p, "--report", "HTML", "a one-page calculation report (inputs, geometry, checks, contour, mesh)")
    return p


def _allowances(args) -> tuple:
    """(A_sn of gear 1, of gear 2, centre-distance (A_ai, A_ae) or 0) from the command line, refused by option
    before any output (with the --data-block class)."""
    from .measure import allowance_from

    a = [allowance_from(getattr(args, f"allowance{i}"), f"--allowance{i}") for i in (1, 2)]
    if args.data_block and not 1 <= args.data_block <= 11:    # checked before anything is printed
        raise GearDesignError(f"--data-block CLASS must be an ISO 1328-1:2013 flank tolerance class 1..11 (or none), "
                              f"got {args.data_block:g}")
    ca = args.center_distance_allowance
    if ca is not None and ca[0] > ca[1]:
        raise GearDesignError(f"--center-distance-allowance: the lower A_ai = {ca[0]:g} mm exceeds the upper "
                              f"A_ae = {ca[1]:g} mm")
    return a[0], a[1], (tuple(ca) if ca is not None else 0.0)


def _measurements(pair, as_json: bool, allowances=(0.0, 0.0)):
    """Both gears' measuring sizes: records for JSON, else a printed table (``--measurements``)."""
    import pandas as pd

    gears = tuple(pair.measurements(gear=i, thickness_allowance_mm=a) for i, a in ((1, allowances[0]),
                                                                                  (2, allowances[1])))
    if as_json:
        return [g.to_dict() for g in gears]
    # the least face width is a helical span's; a spur gear has none
    rows = [r for r in ROWS if not (r[0] == "face_width_min_mm" and not pair.beta_deg)]
    frame = pd.DataFrame([(label, *(getattr(g, name) for g in gears), unit) for name, label, unit in rows],
                         columns=["quantity", "gear 1", "gear 2", "unit"])
    given = any(a != 0.0 for a in allowances)
    print_frame(frame, "\nMeasuring sizes" + (f" (A_sne / A_sni: gear 1 {gears[0].a_sne:g} / {gears[0].a_sni:g}, gear 2 "
                                                f"{gears[1].a_sne:g} / {gears[1].a_sni:g} mm)" if given else
                                                " (no allowances: --allowance1, --allowance2 give them)"),
                float_format="{:.5f}")
    for i, g in enumerate(gears, 1):
        for note in g.notes:
            print(f"note (gear {i}): {note}")
    return None


def _data_blocks(pair, args, allowances) -> list:
    """Both gears' data blocks (``--data-block [CLASS]``; 0: no class stated)."""
    from ..gears.data_block import data_block

    cls = args.data_block or None
    hand = ("right", "left") if pair.beta_deg else (None, None)
    return [data_block(pair, i, cls, helix_hand=hand[i - 1], thickness_allowance_mm=allowances[i - 1],
                       center_distance_allowance_mm=allowances[2] if isinstance(allowances[2], tuple) else None)
            for i in (1, 2)]


def describe(pair, shorten: bool) -> str:
    """The pair in one line: kind, module, tooth counts, shifts, rack."""
    rack = pair.rack
    kind = (("internal " if pair.internal else "") + (f"helical (beta = {pair.beta_deg:g} deg) " if pair.beta_deg
                                                      else "spur ")).capitalize()
    return (f"{kind}pair m = {pair.m:g} mm, z1/z2 = {pair.z1}/{pair.z2}, x1 = {pair.x1:.6g}, x2 = {pair.x2:.6g}, "
            f"rack {rack.alpha_deg:g} deg / {rack.ha:g} / {rack.c:g} / {rack.rho_f:g}"
            f"{'' if shorten else ', no tip shortening'}")


def run(args) -> int:
    if args.report:
        check_output_path(args.report, overwrite=args.overwrite, suffixes=(".html", ".htm"), what="--report")
    pair, housing = pair_from_args(args)
    checks = checks_from_args(args)
    allowances = _allowances(args)
    if args.report:
        pair_report(pair, args.report, overwrite=args.overwrite, eps_alpha_min=args.eps_alpha_min,
                    sa_min=args.sa_min, housing_a_w=housing, eps_gamma_min=args.eps_gamma_min,
                    **{k: v for k, v in checks.items() if k in STRENGTH_CONTEXT})
        print(f"report written to {args.report}", file=sys.stderr)   # stderr: --json keeps stdout pure
    rack, shorten = pair.rack, not args.no_tip_shortening
    geo = pair.geometry()
    # plain rows, not pair.checks()'s DataFrame: a plain `pair` then never imports pandas (issue 36 §3)
    table = Rows(PAIR_CHECK_COLUMNS, pair.check_rows(**checks, housing_a_w=housing))
    failed = [name for name, margin, ok, *_ in table.rows if not ok]
    strength = _strength(pair, checks)
    life = _life(pair, checks)
    if args.json:
        print_json({
            "ok": not failed, "failing_checks": failed,
            "input": {"m": pair.m, "z1": pair.z1, "z2": pair.z2, "x1": pair.x1, "x2": pair.x2,
                      "alpha_deg": rack.alpha_deg, "ha": rack.ha, "c": rack.c, "rho_f": rack.rho_f,
                      "tip_shortening": shorten, "beta_deg": pair.beta_deg, "internal": pair.internal,
                      "face_width_mm": pair.face_width_mm},
            "geometry": geo.to_dict(),
            "checks": frame_records(table.select("check", "value", "limit", "margin", "ok")),
            **({"measurements": _measurements(pair, True, allowances[:2])} if args.measurements else {}),
            **({"backlash": pair.backlash(*allowances).to_dict()} if args.backlash else {}),
            **({"data_block": [frame_records(t) for t in _data_blocks(pair, args, allowances)]}
               if args.data_block is not None else {}),
            **({"strength": strength.to_dict()} if strength is not None else {}),
            **({"life": life.to_dict()} if life is not None else {}),
        })
        return 1 if failed else 0
    print_verdict(failed, check_details(table))
    print_wrapped(describe(pair, shorten))
    print_frame(table.select("check", "value", "limit", "margin", "ok", "label"), "\nChecks (margin >= 0 holds)")
    print_frame(Rows(GEOMETRY_COLUMNS, geometry_rows(geo, helical=bool(pair.beta_deg))), "\nGeometry",
                float_format="{:.8g}")
    if args.measurements:
        _measurements(pair, False, allowances[:2])
    if args.backlash:
        print(f"\n{pair.backlash(*allowances)!r}")
    if args.data_block is not None:
        for i, t in enumerate(_data_blocks(pair, args, allowances), 1):
            print_frame(t, f"\nData block of gear {i} (ISO 1340)")
    if strength is not None:
        print(f"\n{strength!r}")
        print_frame(strength.factors, "\nISO 6336 factors (gear 0: the pair)", float_format="{:.6g}")
    if life is not None:
        print(f"\n{life!r}")
        for note in life.notes:
            print(f"note: {note}")
        cols = ["torque_nm", "n_rpm", "time_h", "n1", "K_v", "K_Hbeta", "sigma_H1", "sigma_F1", "D_H1", "D_H2",
                "D_F1", "D_F2"]
        print_frame(life.bins[cols], "\nISO 6336-6 bins (n1: load cycles of a pinion tooth over the required life; "
                                     "D: the bin's n/N)", float_format="{:.5g}")
    return 1 if failed else 0


def _life(pair, checks: dict):
    """The pair's ISO 6336-6 service life under the command line's spectrum, or None without one."""
    if "spectrum" not in checks:
        return None
    return pair.life(checks["spectrum"], checks["material"], material2=checks.get("material2"),
                     face_width_mm=checks["face_width_mm"], life_h=checks.get("life_h"), sn_curve=checks["sn_curve"],
                     mean_stress_factor=checks.get("mean_stress_factor"), **checks.get("strength", {}))


def _strength(pair, checks: dict):
    """The pair's ISO 6336 result for the command line's load case, or None without one."""
    if "load" not in checks:
        return None
    return pair.strength(checks["load"], checks["material"], material2=checks["material2"],
                         face_width_mm=checks["face_width_mm"], **checks.get("strength", {}))
