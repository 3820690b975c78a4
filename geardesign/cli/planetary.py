"""``geardesign planetary``: a planetary set — check given shifts, find the best ones, or find tooth
counts for a ratio."""
from __future__ import annotations

from ..errors import GearDesignError
from ..files import all_or_nothing, check_output_path, write_file_atomic
from ..gears.planetary import ARRANGEMENTS, DEFAULT_NEIGHBOUR_CLEARANCE, PlanetarySet
from ..profiles.planetary import plot_planetary
from .options import add_cluster_args, add_output_file, add_solver_args, cluster_from_args
from .output import (add_json_flag, check_details, failing_margins, print_frame, print_json, print_verdict,
                     print_verdict_line, print_wrapped)
from .options import add_check_args, add_load_args, checks_from_args
from .options import add_rack_args, rack_from_args


def add_parser(sub):
    p = sub.add_parser("planetary", help="planetary set: coaxial shifts of sun, planets and ring; tooth counts",
                       description="A simple planetary set (sun, N planets, ring). With --x-sun/--x-planet: "
                                   "check those shifts (the ring's from coaxiality unless --x-ring). Without: the "
                                   "best coaxial shifts. With --ratio: tooth counts for the ratio, each solved. "
                                   "Exit status 0 when the set passes every check (an optimum or a feasible row "
                                   "exists), 1 when a check fails or nothing is feasible, 2 on bad input.")
    p.add_argument("--module", "-m", type=float, required=True, help="module, mm")
    p.add_argument("--planets", type=int, required=True, help="number of planets N")
    p.add_argument("--z-sun", type=int, default=None, help="number of teeth of the sun (not with --ratio)")
    p.add_argument("--z-planet", type=int, default=None, help="number of teeth of each planet")
    p.add_argument("--z-ring", type=int, default=None, help="number of teeth of the ring gear")
    p.add_argument("--x-sun", type=float, default=None, help="given shift of the sun (with --x-planet)")
    p.add_argument("--x-planet", type=float, default=None, help="given shift of the planets (with --x-sun)")
    p.add_argument("--x-ring", type=float, default=None, help="given shift of the ring (default: coaxial)")
    p.add_argument("--center-distance", type=float, default=None, metavar="A",
                   help="fixed carrier arm a_w, mm: fixes x_sun + x_planet, the objective picks the split")
    p.add_argument("--arrangement", choices=tuple(ARRANGEMENTS), default="ring_fixed",
                   help="fixed member (ring_fixed: sun in, carrier out; carrier_fixed: sun in, ring out; "
                        "sun_fixed: ring in, carrier out)")
    p.add_argument("--beta", type=float, default=0.0, metavar="DEG", help="helix angle, degrees (0: spur)")
    p.add_argument("--neighbour-clearance", type=float, default=DEFAULT_NEIGHBOUR_CLEARANCE, metavar="K",
                   help=f"least gap between adjacent planet tips, in modules ({DEFAULT_NEIGHBOUR_CLEARANCE:g})")
    p.add_argument("--ratio", type=float, default=None,
                   help="find tooth counts for this ratio n_in/n_out, signed (< -1 for carrier_fixed: the ring "
                        "turns backwards)")
    p.add_argument("--ratio-tol", type=float, default=0.02, help="relative ratio tolerance (0.02)")
    p.add_argument("--z-sun-range", default="12:40", metavar="LO:HI", help="sun teeth searched (12:40)")
    p.add_argument("--nonstandard-max", type=int, default=2,
                   help="largest |z_ring - z_sun - 2 z_planet| searched (2; 0: standard sets only)")
    add_solver_args(p, objective_help="what the optimum maximises or minimises over both meshes (default "
                                      "max_x_sum; balanced_sliding with --center-distance; max_eps_alpha "
                                      "for --ratio)")
    add_output_file(p, "--plot", "PNG", "the feasible (x_sun, x_planet) region")
    p.add_argument("--drawing", metavar="PNG", default=None, help="write the set's drawing (circles) to this PNG")
    p.add_argument("--html", metavar="HTML", default=None,
                   help="write the region as an interactive page (hover: every check's margin; works offline)")
    add_rack_args(p)
    add_check_args(p, exclude=("eps_gamma_min",), load=False)
    add_load_args(p, planetary=True)
    add_json_flag(p)
    add_cluster_args(p)   # used with --ratio (the tooth-count search)
    return p


def _checks(args) -> dict:
    out = checks_from_args(args)      # with the sun's load when one is given
    if out.get("spectrum") is not None and out.get("mean_stress_factor") is None:
        # said of the planet (the damage check's own message names a pair's "gear 2"): every spectrum needs it
        raise GearDesignError("--mean-stress-factor is needed with --spectrum: the planet's root bends both ways (it "
                              "meets the sun on one flank and the ring on the other); give Y_M of ISO 6336-3:2019 "
                              "for alternating bending (0.7 in older texts for an idler)")
    out["neighbour_clearance"] = args.neighbour_clearance
    return out


def _range(text: str) -> tuple[int, int]:
    try:
        lo, hi = (int(v) for v in text.split(":"))
    except ValueError:
        raise GearDesignError(f"--z-sun-range must be LO:HI whole numbers, got {text!r}") from None
    return lo, hi


def _save(path, ax, overwrite):
    import matplotlib.pyplot as plt


    try:
        write_file_atomic(path, lambda tmp: ax.figure.savefig(tmp, dpi=120, bbox_inches="tight", format="png"))
    finally:
        plt.close(ax.figure)


def run(args) -> int:
    if args.ratio is not None and (args.plot or args.drawing):
        raise GearDesignError("--plot and --drawing draw one set: give its tooth counts (--z-sun, --z-planet, "
                              "--z-ring) instead of --ratio, e.g. those of the row --ratio chooses")
    for flag in ("plot", "drawing"):
        if getattr(args, flag):
            check_output_path(getattr(args, flag), overwrite=args.overwrite, suffixes=(".png",), what=f"--{flag}")
    if args.html:
        if args.ratio is not None or args.x_sun is not None:
            raise GearDesignError("--html draws the region of an optimisation: not with --ratio or --x-sun/--x-planet")
        check_output_path(args.html, overwrite=args.overwrite, suffixes=(".html", ".htm"), what="--html")
    if args.plot or args.drawing:
        import matplotlib
        matplotlib.use("Agg")
    if args.ratio is not None:
        return _teeth(args)
    if args.workers is not None or args.scheduler is not None:
        raise GearDesignError("--workers and --scheduler go with --ratio (the tooth-count search)")
    missing = [f"--{n.replace('_', '-')}" for n in ("z_sun", "z_planet", "z_ring") if getattr(args, n) is None]
    if missing:
        raise GearDesignError(f"{', '.join(missing)} needed (or --ratio to search tooth counts)")
    if (args.x_sun is None) != (args.x_planet is None):
        raise GearDesignError("--x-sun and --x-planet go together: give both to check a set")
    if args.x_sun is not None:
        return _check(args)
    return _optimize(args)


def _set_kwargs(args) -> dict:
    return dict(rack=rack_from_args(args), beta_deg=args.beta, arrangement=args.arrangement)


def _check(args) -> int:

    sizes = (args.module, args.z_sun, args.z_planet, args.z_ring, args.planets)
    s = (PlanetarySet.coaxial(*sizes, args.x_sun, args.x_planet, **_set_kwargs(args)) if args.x_ring is None
         else PlanetarySet(*sizes, args.x_sun, args.x_planet, args.x_ring, **_set_kwargs(args)))
    table = s.checks(_checks(args))
    ok = bool(table["ok"].all())
    with all_or_nothing():      # every file of the command, or none
        if args.plot:           # the region, the given shifts marked on it
            from ..shifts.planetary import planetary_region   # here: it loads pandas (not for --help)
            reg = planetary_region(*sizes[1:], sizes[0], checks=_checks(args), rack=rack_from_args(args),
                                   beta_deg=args.beta)
            _save(args.plot, reg.plot(proposed=(s.x_sun, s.x_planet)), args.overwrite)
        if args.drawing:
            _save(args.drawing, plot_planetary(s), args.overwrite)
    if args.json:
        print_json({"x_sun": s.x_sun, "x_planet": s.x_planet, "x_ring": s.x_ring, "a_w": s.a_w,
                    "a_w_planet_ring": s.a_w_planet_ring, "ratio": s.ratio, "ok": ok,
                    "checks": table[["check", "mesh", "margin", "ok", "value", "limit"]]})
        return 0 if ok else 1
    print_verdict(table.loc[~table["ok"], "check"].tolist(), check_details(table))
    print_wrapped(f"Planetary set {s.meshes.title}, m = {s.m:g} mm: x = {s.x_sun:.6g}/{s.x_planet:.6g}/{s.x_ring:.6g}, "
          f"a_w = {s.a_w:.8g} mm (planet-ring {s.a_w_planet_ring:.8g} mm), ratio {s.ratio:.6g} ({s.arrangement})")
    print_frame(table[["check", "margin", "ok", "value", "limit"]])
    _print_strength(args, s)
    return 0 if ok else 1


def _print_strength(args, s) -> None:
    """With a load: each mesh's ISO 6336 result (S_H, S_F of its gears, the stresses, the governing check), as
    ``pair`` and ``drive`` show a pair's; the checks table alone gave only the margins."""
    ch = _checks(args)
    if ch.get("load") is None:
        return
    from ..gears.strength.planetary_meshes import planetary_strength   # here: loads pandas

    opts = {"S_Hmin": ch["S_Hmin"], "S_Fmin": ch["S_Fmin"], **(ch.get("strength") or {})}
    res = planetary_strength(s, ch["load"], ch["material"], face_width_mm=ch["face_width_mm"],
                             K_gamma=opts.pop("K_gamma", 1.0), planet_material=ch.get("planet_material"),
                             ring_material=ch.get("ring_material"), **opts)
    for tag, r in res.items():
        print(f"\nstrength of the {tag} mesh (ISO 6336; the sun's {ch['load'].torque_nm:.6g} N·m at "
              f"{ch['load'].n_rpm:.6g} rpm shared over {s.n_planets} planets):")
        print(r)


def _optimize(args) -> int:
    from ..shifts.planetary import optimize_planetary_shifts, planetary_region   # here: loads pandas

    kw = dict(rack=rack_from_args(args), beta_deg=args.beta)
    r = optimize_planetary_shifts(args.z_sun, args.z_planet, args.z_ring, args.planets, args.module,
                                  a_w=args.center_distance, objective=args.objective, checks=_checks(args),
                                  method=args.method, arrangement=args.arrangement, **kw)
    # every file of the command, or none: the drawing needs a feasible set, so without one nothing is written
    write = (args.plot or args.drawing or args.html) and (r.success or not args.drawing)
    with all_or_nothing():
        if (args.plot or args.html) and write:
            reg = planetary_region(args.z_sun, args.z_planet, args.z_ring, args.planets, args.module,
                                   checks=_checks(args), **kw)
            marks = dict(optimum=(r.x_sun, r.x_planet) if r.success else None,
                         x_sum=(r.x_sun + r.x_planet) if args.center_distance is not None else None)
            if args.plot:
                _save(args.plot, reg.plot(**marks), args.overwrite)
            if args.html:
                reg.to_html(args.html, overwrite=args.overwrite, **marks)
        if args.drawing and write:
            s = PlanetarySet(args.module, args.z_sun, args.z_planet, args.z_ring, args.planets, r.x_sun, r.x_planet,
                             r.x_ring, arrangement=args.arrangement, **kw)
            _save(args.drawing, plot_planetary(s), args.overwrite)
    if args.json:
        print_json({"ok": bool(r.success), **r.to_dict()})
        return 0 if r.success else 1
    print_verdict_line(r.success, f"optimum x = {r.x_sun:.6g}/{r.x_planet:.6g}/{r.x_ring:.6g}, every check holds"
                       if r.success else f"{failing_margins(r.margins, r.conflict or None)}: no feasible shifts")
    for line in repr(r).splitlines():
        print_wrapped(line, indent=" " * 14)
    if r.success:
        print_frame(r.to_frame(), "\nChecks at the optimum (margin >= 0 holds; sensitivity = d fun / d limit)")
        _print_strength(args, PlanetarySet(args.module, args.z_sun, args.z_planet, args.z_ring, args.planets, r.x_sun,
                                           r.x_planet, r.x_ring, arrangement=args.arrangement, **kw))
    for flag, what in (("plot", "region"), ("drawing", "drawing"), ("html", "interactive region")):
        if getattr(args, flag, None) and write:
            print(f"{what} written to {getattr(args, flag)}")
    if (args.plot or args.drawing) and not write:
        print("no feasible set to draw: nothing written")
    return 0 if r.success else 1


def _teeth(args) -> int:
    from ..shifts.planetary_teeth import DEFAULT_OBJECTIVE, select_planetary_teeth   # here: loads pandas

    with cluster_from_args(args) as client:
        sel = select_planetary_teeth(args.ratio, args.planets, args.module, ratio_tol=args.ratio_tol,
                                     z_sun_range=_range(args.z_sun_range), nonstandard_max=args.nonstandard_max,
                                     arrangement=args.arrangement, objective=args.objective or DEFAULT_OBJECTIVE,
                                     checks=_checks(args), method=args.method, rack=rack_from_args(args),
                                     beta_deg=args.beta, client=client)
    if args.json:
        print_json({"ok": bool(sel.found)} | sel.to_dict() | {"message": sel.message})
        return 0 if sel.found else 1
    print_verdict_line(bool(sel.found), sel.message)
    cols = ["z_sun", "z_planet", "z_ring", "standard", "ratio", "feasible", "x_sun", "x_planet", "x_ring", "a_w",
            "fun", "reason"]
    print_frame(sel.table[cols].head(25), f"\n{len(sel.table)} candidates ({sel.n_solved} solved), best first:")
    return 0 if sel.found else 1
