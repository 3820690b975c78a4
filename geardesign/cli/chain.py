"""``geardesign chain``: size a roller-chain drive from a catalog.

Exit status 0 when a candidate passes every check, 1 when none does (the output says which
check stops each chain family), 2 on bad input. ``--top N`` lists the feasible candidates in the
objective's order, then the failing ones nearest to passing (largest worst margin first).
"""
from __future__ import annotations

from ..drives import chain
from ..catalogs.tables import CHAIN_CATALOGS
from ..errors import GearDesignError
from .output import add_json_flag, frame_records, print_frame, print_json, print_verdict_line, print_wrapped

# where the default service factor comes from (catalogs/chain_operating_factors.csv: each factor's source)
K_E_DEFAULT_SOURCE = ("the default: K_d K_a K_n K_reg K_lub K_mode each 1, uniform load, drip lubrication, one "
                      "shift; catalogs/chain_operating_factors.csv; set --k-e")


def service_factor(k_e: float, given) -> str:
    """K_e with where it comes from: the --k-e given, or the default and its source."""
    return f"K_e = {k_e:g} (given by --k-e)" if given is not None else f"K_e = {k_e:g} ({K_E_DEFAULT_SOURCE})"


def _verdict(result) -> str:
    """The verdict's text: the chosen chain and its limiting check, or the closest candidate's failing one."""
    rows = result.candidates
    if result.best is not None:
        b = result.best
        return (f"{b['designation']} x{int(b['strands'])}, z1/z2 = {int(b['z1'])}/{int(b['z2'])}, limiting "
                f"{b['limiting_check']} (margin {float(b['min_margin']):+.3f})")
    if not len(rows):
        return "no candidate"
    c = rows.sort_values("min_margin", ascending=False, kind="stable").iloc[0]
    return (f"{c['limiting_check']} (margin {float(c['min_margin']):+.3f}) of the closest candidate "
            f"{c['designation']} x{int(c['strands'])}, z1 = {int(c['z1'])}: no chain passes")

SHOW = ["rank", "designation", "pitch_mm", "strands", "z1", "z2", "links", "center_distance_mm", "speed_m_s",
        "force_n", "pressure_mpa", "allowable_pressure_mpa", "safety_factor", "allowable_safety_factor",
        "mass_kg_m", "min_margin", "limiting_check", "feasible"]
SHOW_POWER = ["rank", "designation", "pitch_mm", "strands", "z1", "z2", "links", "center_distance_mm", "speed_m_s",
              "force_n", "rated_power_kw", "design_power_kw", "rating_limit", "safety_factor", "mass_kg_m",
              "min_margin", "limiting_check", "feasible"]


def _strands(text: str):
    try:
        values = tuple(int(s) for s in text.split(",") if s.strip())
    except ValueError:
        raise GearDesignError(f"--strands must be whole numbers separated by commas, e.g. 1,2, got {text!r}") from None
    if not values:
        raise GearDesignError(f"--strands must list at least one strand count, got {text!r}")
    return values


def feasible_then_nearest(candidates):
    """The feasible candidates in their ranked order, then the failing ones by their worst margin, the
    nearest to passing first (a chain far over its allowed pressure is of no help as a second choice)."""
    feasible = candidates[candidates["feasible"].astype(bool)]
    failing = candidates[~candidates["feasible"].astype(bool)]
    failing = failing.sort_values("min_margin", ascending=False, kind="stable")
    import pandas as pd

    out = pd.concat([feasible, failing])
    if "rank" in out:
        out = out.assign(rank=range(1, len(out) + 1))
    return out


def add_parser(subparsers):
    p = subparsers.add_parser(
        "chain", help="size a roller-chain drive from a catalog (GOST 13568, ISO 606, ANSI B29.1)",
        description="Evaluate every catalog chain x strands x z1 for a drive and rank the feasible ones. "
                    "Every check is a margin (>= 0 holds). Exit status 0 when a candidate passes every check, "
                    "1 when none does, 2 on bad input.")
    load = p.add_mutually_exclusive_group(required=True)
    load.add_argument("--torque", type=float, metavar="N_M", help="torque on the small sprocket [N·m]")
    load.add_argument("--power", type=float, metavar="KW", help="power transmitted [kW]")
    p.add_argument("--n1", type=float, required=True, metavar="RPM", help="small-sprocket speed [rpm]")
    p.add_argument("--ratio", type=float, required=True, help="speed ratio u = n1/n2 (1 to 10)")
    p.add_argument("--z1", type=int, help="small-sprocket teeth (default: odd counts 13 .. 29-2u)")
    p.add_argument("--catalog", default="gost13568",
                   help=f"chain catalog: {', '.join(CHAIN_CATALOGS)} or a CSV path (default gost13568)")
    p.add_argument("--strands", default="1,2,3", help="strand counts to try, comma separated (default 1,2,3)")
    p.add_argument("--k-e", type=float, dest="k_e",
                   help="service (operating) factor K_e, the product K_d K_a K_n K_reg K_lub K_mode (default 1: uniform "
                        "load, drip lubrication, one shift; catalogs/chain_operating_factors.csv)")
    p.add_argument("--p-allow", type=float, dest="p_allow", metavar="MPA",
                   help="allowable hinge pressure [p] (default: table by pitch and n1)")
    p.add_argument("--s-allow", type=float, dest="s_allow", help="allowable safety factor [s] (default: table)")
    p.add_argument("--center-distance", type=float, dest="center_distance", metavar="MM",
                   help="target centre distance [mm] (default 40 pitches)")
    p.add_argument("--objective", default="min_mass", choices=chain.OBJECTIVES,
                   help="how feasible candidates are ranked (default min_mass)")
    p.add_argument("--method", default="hinge_pressure", choices=chain.METHODS,
                   help="the check of the chain's load (default hinge_pressure)")
    p.add_argument("--top", type=int, default=10,
                   help="candidates to list: the feasible ones first, then the failing ones nearest to passing "
                        "(default 10; 0 = all)")
    add_json_flag(p)
    return p


def run(args) -> int:
    result = chain.design(
        torque_nm=args.torque, power_kw=args.power, n1_rpm=args.n1, ratio=args.ratio, z1=args.z1,
        catalog=args.catalog, strands=_strands(args.strands), k_e=args.k_e,
        allowable_pressure_mpa=args.p_allow, allowable_safety_factor=args.s_allow,
        center_distance_mm=args.center_distance, objective=args.objective, method=args.method)
    if args.top < 0:
        raise GearDesignError(f"--top must be >= 0, got {args.top}")
    ranked = feasible_then_nearest(result.candidates)
    top = ranked if args.top == 0 else ranked.head(args.top)
    cols = SHOW if args.method == "hinge_pressure" else SHOW_POWER
    if args.json:
        out = {"ok": bool(result.success), **result.to_dict()}
        out["candidates"] = frame_records(top.drop(columns=[c for c in ("edition", "source", "note") if c in top]))
        print_json(out)
    else:
        print_verdict_line(result.success, f"{_verdict(result)}; {service_factor(result.k_e, args.k_e)}")
        print_wrapped(result.message)
        if result.pitch_estimate_mm:
            print_wrapped("pitch estimate (starting point): " + ", ".join(
                f"{k} strand{'s' if k > 1 else ''} t >= {v:.2f} mm" for k, v in result.pitch_estimate_mm.items()))
        if result.best is not None:
            b = result.best
            print_wrapped(f"sprockets: pitch diameters {b['sprocket1_pitch_diameter_mm']:.2f} / "
                  f"{b['sprocket2_pitch_diameter_mm']:.2f} mm, tip {b['sprocket1_tip_diameter_mm']:.2f} / "
                  f"{b['sprocket2_tip_diameter_mm']:.2f} mm, root {b['sprocket1_root_diameter_mm']:.2f} / "
                  f"{b['sprocket2_root_diameter_mm']:.2f} mm")
        print()
        print_frame(top[[c for c in cols if c in top.columns]],
                    title=f"candidates ({len(top)} of {len(result.candidates)}, K_e = {result.k_e:g}"
                          f"{'' if args.k_e is not None else ', the default'}):")
        if not result.success:
            print()
            print_frame(result.blocking, title="what stops each chain family (best candidate of each):")
        for note in result.notes:
            print_wrapped(f"note: {note}")
    return 0 if result.success else 1
