"""``geardesign bearing``: select the smallest catalog bearing of a series that reaches a life, or check a given one.

Exit status 0 when the bearing passes (or a bearing is found), 1 when it fails a check (or none of the
series passes: the output names the check), 2 on bad input (one line on stderr naming the option).
"""
from __future__ import annotations

import re

from ..drives import bearing
from ..errors import GearDesignError
from .output import add_json_flag, frame_records, print_frame, print_json, print_wrapped

# the library's argument names -> this command's options, for the one-line error
_OPTIONS = {"F_r_n": "--fr", "F_a_n": "--fa", "n_rpm": "--speed", "life_h": "--life-h", "bore_mm": "--bore",
            "reliability": "--reliability", "kappa": "--kappa", "e_c": "--ec", "series": "--series",
            "designation": "--designation", "bearing_type": "--type", "s0_min": "--s0-min", "lubrication": "--lubrication"}
SHOW = ["rank", "designation", "d_mm", "D_mm", "B_mm", "C_kn", "C0_kn", "P_n", "L10h", "Lnmh", "s0",
        "speed_limit_rpm", "min_margin", "limiting_check", "feasible"]


def add_parser(subparsers):
    p = subparsers.add_parser(
        "bearing", help="select or check a rolling bearing (ISO 281 life, static safety, speed)",
        description="The smallest bearing of the series (NTN CAT. 2203/E tables: 62, 63 deep groove, 72B, 73B "
                    "angular contact 40 deg, NU2, NU3 cylindrical roller; SKF 17000 tables: 302, 303, 320X, 322, 323 "
                    "tapered roller) whose bore fits a seat of at least --bore "
                    "and that reaches --life-h under --fr and --fa at --speed, with its static safety and allowable "
                    "speed checked; with --designation, the checks of that bearing instead. The first line is the "
                    "verdict. Exit status 0 when the bearing passes, 1 when it fails a check or no bearing of the "
                    "series passes, 2 on bad input.")
    p.add_argument("--series", default=None,
                   help=f"series to choose from, comma separated: {', '.join(bearing.SERIES)} (default 62, or "
                        f"every series of --type)")
    p.add_argument("--type", dest="bearing_type", default=None, choices=tuple(bearing.BEARING_TYPES),
                   help="bearing type: choose from all its series (with --series: check they are of it); for a "
                        "tapered roller bearing --fa is its whole axial load, the induced 0.5 Fr/Y included")
    p.add_argument("--designation", default=None, metavar="NAME",
                   help="check this catalog bearing (e.g. 6208, 7310B, NU210EA) instead of selecting one")
    p.add_argument("--bore", type=float, default=None, metavar="MM",
                   help="least bore: the shaft's seat diameter, mm (required to select)")
    p.add_argument("--fr", type=float, required=True, metavar="N", help="radial load Fr, N")
    p.add_argument("--fa", type=float, default=0.0, metavar="N", help="axial load Fa, N (default 0)")
    p.add_argument("--speed", type=float, required=True, metavar="RPM", help="speed of the bearing, rpm")
    p.add_argument("--life-h", dest="life_h", type=float, default=None, metavar="H",
                   help="required life, h (required to select; with --designation: check against it)")
    p.add_argument("--reliability", type=float, default=90.0, metavar="PCT",
                   help="reliability, %%: 90, 95, 96, 97, 98 or 99 (life factor a1; default 90)")
    p.add_argument("--kappa", type=float, default=None, metavar="K",
                   help="viscosity ratio kappa = nu/nu1 for the modified life (with --ec)")
    p.add_argument("--ec", dest="e_c", type=float, default=None, metavar="E",
                   help="contamination factor e_C, 0..1, for the modified life (with --kappa)")
    p.add_argument("--lubrication", default="grease", choices=bearing.LUBRICATIONS,
                   help="which allowable speed of the catalog applies (default grease)")
    p.add_argument("--s0-min", dest="s0_min", type=float, default=None, metavar="S",
                   help="least static safety C0/P0 (default: 1 ball, 1.5 roller bearings)")
    p.add_argument("--top", type=int, default=8, help="candidates to list when selecting (default 8; 0 = all)")
    add_json_flag(p)
    return p


def _option_names(exc: GearDesignError) -> GearDesignError:
    """The library's message with its argument names as this command's options."""
    text = str(exc)
    for name, option in _OPTIONS.items():
        text = re.sub(rf"(?<![\w-]){re.escape(name)}\b", option, text)
    return GearDesignError(text)


def _verdict(check: bearing.BearingCheck) -> str:
    if check.ok:
        return f"OK: {check.message}"
    return f"FAILS: {check.limiting_check} ({check.message.split(': ', 1)[1]})"


def _series(names, bearing_type) -> list[str]:
    """The series to choose from: --series, or every series of --type, or 62."""
    if names is None:
        if bearing_type is None:
            return ["62"]
        kind = bearing.BEARING_TYPES[bearing_type]
        return [s for s, (_, k) in bearing.SERIES.items() if k == kind]
    series = [s.strip() for s in names.split(",") if s.strip()]
    if bearing_type is not None:
        kind = bearing.BEARING_TYPES[bearing_type]
        other = [s for s in series if s in bearing.SERIES and bearing.SERIES[s][1] != kind]
        if other:
            raise GearDesignError(f"--series {', '.join(other)} is not of --type {bearing_type} (its series: "
                                  f"{', '.join(s for s, (_, k) in bearing.SERIES.items() if k == kind)})")
    return series


def run(args) -> int:
    if args.top < 0:
        raise GearDesignError(f"--top must be >= 0, got {args.top}")
    series = _series(args.series, args.bearing_type)
    kw = dict(F_r_n=args.fr, F_a_n=args.fa, n_rpm=args.speed, life_h=args.life_h, reliability=args.reliability,
              kappa=args.kappa, e_c=args.e_c, lubrication=args.lubrication, s0_min=args.s0_min)
    try:
        if args.designation is not None:
            check = bearing.check_bearing(args.designation, **kw)
            if args.bearing_type is not None and \
                    bearing.SERIES[check.series][1] != bearing.BEARING_TYPES[args.bearing_type]:
                raise GearDesignError(f"--designation {args.designation} is a {bearing.SERIES[check.series][1]} "
                                      f"bearing, not of --type {args.bearing_type}")
            selection = None
        else:
            if args.bore is None:
                raise GearDesignError("--bore (the seat diameter, mm) is needed to select a bearing "
                                      "(or give --designation to check one)")
            if args.life_h is None:
                raise GearDesignError("--life-h (the required life, h) is needed to select a bearing")
            selection = bearing.select_bearing(series, args.bore, **kw)
            check = selection.checked
    except GearDesignError as exc:
        raise _option_names(exc) from None
    if args.json:
        if selection is None:
            print_json({"ok": check.ok, **check.to_dict()})
        else:
            top = selection.table if args.top == 0 else selection.table.head(args.top)
            print_json({"ok": selection.found, "message": selection.message,
                        "bearing": None if check is None else check.to_dict(), "candidates": frame_records(top)})
        return 0 if (check is not None and check.ok) else 1
    if selection is not None and check is None:
        near = selection.table.sort_values("min_margin", ascending=False, kind="stable").iloc[0]
        print_wrapped(f"FAILS: {near['limiting_check']} ({selection.message})")
    elif selection is not None:
        print_wrapped(f"OK: {selection.message}")
    else:
        print_wrapped(_verdict(check))
    if check is not None:
        for line in repr(check).splitlines()[1:]:
            print_wrapped(line.strip())
        if check.a_iso != 1.0 or check.a1 != 1.0:
            print_wrapped(f"modified life Lnm = a1 a_ISO L10: a1 = {check.a1:g}, a_ISO = {check.a_iso:.4g}")
    if selection is not None:
        top = selection.table if args.top == 0 else selection.table.head(args.top)
        print()
        print_frame(top[SHOW], title=f"candidates ({len(top)} of {len(selection.table)}, feasible first, then by D):")
    return 0 if (check is not None and check.ok) else 1
