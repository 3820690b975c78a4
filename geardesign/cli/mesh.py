"""``geardesign mesh``: the meshing drawing of a pair (external or internal, spur or helical in the
transverse section), its line-of-action diagrams, and both gears' generated outlines as SVG, DXF or CSV."""
from __future__ import annotations

import os

from ..errors import GearDesignError
from ..files import all_or_nothing, check_output_path, write_file_atomic
from ..gears.ring import ShaperCutter
from ..profiles import mesh as profiles_mesh
from ..profiles.drawing import contact_points, line_of_action_diagrams, plot_diagrams, plot_mesh
from .output import add_json_flag, check_details, print_json, print_verdict, print_wrapped
from .pair import add_pair_args, pair_from_args

# flag -> (suffix, what is written)
OUTPUTS = {
    "--plot": (".png", "the meshing drawing"),
    "--diagrams": (".png", "the diagrams of specific sliding and pressure along the line of action"),
    "--svg": (".svg", "both gears' outlines in mesh, SVG in mm"),
    "--dxf": (".dxf", "both gears' outlines in mesh, DXF in mm (layers gear1, gear2)"),
    "--csv": (".csv", "both gears' outline points in mesh, CSV in mm"),
}


def add_parser(sub):
    p = sub.add_parser("mesh", help="meshing drawing, line-of-action diagrams and profile export of a pair",
                       description="Both gears' teeth as their cutters generate them (a rack; a ring's shaper "
                                   "cutter), in mesh at a_w: the drawing (circles, line of action N1N2 with its "
                                   "active part and contact zones), the diagrams of specific sliding and pressure "
                                   "along N1N2, and the outlines as SVG/DXF/CSV (gear 1 about the origin, gear 2 "
                                   "about (0, a_w), a ring about (0, -a_w) with its rim as gear2_rim; mm). "
                                   "Exit status 0 when the pair passes every check (default limits, as `pair`), "
                                   "1 when one fails (the text and the drawing's title name it; the files are "
                                   "written either way), 2 on bad input.")
    add_pair_args(p)
    g = p.add_argument_group("the ring's shaper cutter (--internal)")
    g.add_argument("--cutter-teeth", type=float, default=None, metavar="Z0",
                   help="teeth of the shaper cutter that generates the ring (default: the checks' cutter for the "
                        "module, see geardesign.ShaperCutter)")
    g.add_argument("--cutter-shift", type=float, default=0.0, metavar="X0", help="the cutter's profile shift (0)")
    p.add_argument("--roll-deg", type=float, default=0.0, help="turn gear 1 by this angle (gear 2 follows), degrees")
    for flag, (suffix, what) in OUTPUTS.items():
        p.add_argument(flag, metavar=f"FILE{suffix}", default=None, help=f"write {what}")
    p.add_argument("--overwrite", action="store_true", help="replace existing output files")
    add_json_flag(p)
    return p


def _targets(args) -> dict:
    """Every requested output file, checked before any work (suffix, folder, overwrite, no repeats)."""
    targets = {}
    for flag, (suffix, _) in OUTPUTS.items():
        value = getattr(args, flag[2:])
        if value is not None:
            targets[flag] = check_output_path(value, overwrite=args.overwrite, suffixes=(suffix,), what=flag)
    seen = {}
    for flag, path in targets.items():
        key = os.path.abspath(path)
        if key in seen:
            raise GearDesignError(f"{flag} {str(path)!r} is also given to {seen[key]}: give each output its own file")
        seen[key] = flag
    return targets


def _save_figure(ax, path) -> None:
    import matplotlib.pyplot as plt

    try:
        write_file_atomic(path, lambda tmp: ax.figure.savefig(tmp, dpi=120, bbox_inches="tight", format="png"))
    finally:
        plt.close(ax.figure)


def _cutter(args, pair):
    if not pair.internal:
        if args.cutter_teeth is not None or args.cutter_shift != 0.0:
            raise GearDesignError("--cutter-teeth and --cutter-shift describe a ring's shaper cutter: give --internal")
        return None
    return ShaperCutter(z0=args.cutter_teeth, x0=args.cutter_shift)


def run(args) -> int:
    targets = _targets(args)
    pair, _ = pair_from_args(args)
    cutter = _cutter(args, pair)

    geo = pair._geo
    if "--plot" in targets or "--diagrams" in targets:
        import matplotlib
        matplotlib.use("Agg")
    with all_or_nothing():      # every file of the command, or none
        if "--plot" in targets:
            _save_figure(plot_mesh(pair, roll_deg=args.roll_deg, cutter=cutter), targets["--plot"])
        if "--diagrams" in targets:
            _save_figure(plot_diagrams(pair)[0], targets["--diagrams"])
        for flag in ("--svg", "--dxf", "--csv"):
            if flag in targets:
                profiles_mesh.export_profiles(pair, targets[flag], overwrite=args.overwrite, roll_deg=args.roll_deg,
                                              cutter=cutter)

    c = contact_points(geo)
    d = line_of_action_diagrams(geo, n=2, s_mm=[0.5 * c["g"]])
    g_alpha = d["s_E"] - d["s_A"]
    double = max(g_alpha - d["p_b"], 0.0)
    table = pair.checks()
    failed = table.loc[~table["ok"], "check"].tolist()
    summary = {
        "ok": not failed, "failing_checks": failed,
        "m": pair.m, "z1": pair.z1, "z2": pair.z2, "x1": pair.x1, "x2": pair.x2,
        "a_w_mm": float(geo["a_w"]), "alpha_w_deg": float(geo["alpha_w_deg"]), "eps_alpha": float(geo["eps_alpha"]),
        "line_of_action_mm": {"N1N2": d["g"], "N1A": d["s_A"], "N1P": d["s_P"], "N1E": d["s_E"],
                              "active_A_to_E": g_alpha, "base_pitch": d["p_b"],
                              "double_contact_each_end": double, "single_contact": g_alpha - 2 * double},
        "internal": bool(pair.internal), "beta_deg": pair.beta_deg,
        "points_mm": {k: c[k].tolist() for k in ("N1", "N2", "A", "P", "E")},
        "files": {flag: str(path) for flag, path in targets.items()},
    }
    if args.json:
        print_json(summary)
        return 1 if failed else 0
    print_verdict(failed, check_details(table))
    lo = summary["line_of_action_mm"]
    kind = ("Internal " if pair.internal else "") + (f"helical (beta = {pair.beta_deg:g} deg) " if pair.beta_deg else "spur ")
    print_wrapped(f"{kind[0].upper() + kind[1:]}pair m = {pair.m:g} mm, z1/z2 = {pair.z1}/{pair.z2}, x1/x2 = {pair.x1:.6g}/{pair.x2:.6g}: "
          f"a_w = {summary['a_w_mm']:.6g} mm, alpha_w = {summary['alpha_w_deg']:.6g} deg, "
          f"eps_alpha = {summary['eps_alpha']:.4g}")
    print_wrapped(f"Line of action N1N2 = {lo['N1N2']:.6g} mm; from N1: A {lo['N1A']:.6g}, P {lo['N1P']:.6g}, "
          f"E {lo['N1E']:.6g} mm; active A-E {lo['active_A_to_E']:.6g} mm = "
          f"{lo['double_contact_each_end']:.6g} double + {lo['single_contact']:.6g} single + "
          f"{lo['double_contact_each_end']:.6g} double (p_b = {lo['base_pitch']:.6g} mm)")
    for flag, path in targets.items():
        print(f"wrote {path} ({OUTPUTS[flag][1]})")
    return 1 if failed else 0
