"""``geardesign measure``: the sizes a shop measures on one gear (span W_k over k teeth, the dimension over balls
and pins, the chordal tooth thickness) with the sizes its tooth-thickness allowances give, and the ISO 1328-1:2013
flank tolerances of a class.

Exit status 0 when every size touches inside the involute (and a helical span fits the face), 1 when one is
flagged, 2 on bad input.
"""
from __future__ import annotations

from ..errors import GearDesignError
from ..gears.measurement import tooth_measurements
from ..gears.tolerances import flank_tolerances
from .output import add_json_flag, print_frame, print_json
from .options import add_rack_args, rack_from_args

# (field, label, unit) of the human table, in order
ROWS = (
    ("k", "teeth spanned k", ""), ("w_k", "span W_k", "mm"), ("w_k_max", "  largest (A_sne / A_sni)", "mm"),
    ("w_k_min", "  smallest", "mm"), ("d_wk", "  anvils touch on diameter", "mm"), ("span_ok", "  span usable", ""),
    ("face_width_min_mm", "  least face width (helical)", "mm"), ("ball_mm", "ball diameter D_M (stocked)", "mm"),
    ("ball_exact_mm", "  exact ball (touches on d_y)", "mm"),
    ("d_m", "  ball centre circle d_M", "mm"), ("m_d", "dimension over balls M_d (ring: between)", "mm"),
    ("m_d_max", "  largest", "mm"), ("m_d_min", "  smallest", "mm"), ("d_ball", "  ball touches on diameter", "mm"),
    ("ball_ok", "  ball usable", ""), ("pin_mm", "pin diameter", "mm"), ("m_d_pin", "dimension over pins", "mm"),
    ("s_n", "normal tooth thickness s_n", "mm"), ("s_chord", "chordal thickness", "mm"),
    ("s_chord_max", "  largest", "mm"), ("s_chord_min", "  smallest", "mm"), ("h_chord", "chordal height", "mm"),
    ("x_e_sne", "generating shift x_E (A_sne)", ""), ("x_e_sni", "generating shift x_E (A_sni)", ""),
)


def add_parser(sub):
    p = sub.add_parser("measure", help="span, dimension over balls/pins, chordal thickness and ISO 1328 tolerances "
                                       "of one gear",
                       description="The measuring sizes of one spur or helical, external or internal gear "
                                   "(ISO 21771; a ring with the GOST 19274 sign of x) with its tooth-thickness "
                                   "allowances, and the ISO 1328-1:2013 flank tolerances of a class. Exit status 0 "
                                   "when every size can be measured, 1 when one is flagged (a span or ball outside "
                                   "the involute, a gear too narrow for the span), 2 on bad input.")
    p.add_argument("--module", "-m", type=float, required=True, help="module, mm (normal module of a helical gear)")
    p.add_argument("--z", type=float, required=True, help="number of teeth")
    p.add_argument("--x", type=float, default=0.0, help="profile shift coefficient (0)")
    p.add_argument("--beta", type=float, default=0.0, metavar="DEG", help="helix angle, degrees (0: spur)")
    p.add_argument("--internal", action="store_true", help="a ring gear (a positive x moves its flanks outward)")
    p.add_argument("--face-width", dest="face_width_mm", type=float, default=None, metavar="MM", help="face width b, mm")
    p.add_argument("--tip-diameter", type=float, default=None, metavar="MM",
                   help="tip diameter d_a, mm (default d +- 2(h_a* +- x)m, no tip shortening)")
    p.add_argument("--k", type=float, default=None, help="teeth spanned (default: chosen to touch mid-flank)")
    p.add_argument("--ball", type=float, default=None, metavar="MM", help="ball diameter (default: touches mid-flank)")
    p.add_argument("--pin", type=float, default=None, metavar="MM", help="pin diameter (default: the ball's)")
    p.add_argument("--allowance", type=float, nargs="+", default=[0.0], metavar="MM",
                   help="normal tooth-thickness allowance A_sne [A_sni], mm: <= 0, negative thins the tooth "
                        "(A_sni <= A_sne <= 0; one value: both)")
    p.add_argument("--accuracy-class", type=float, default=None, metavar="A",
                   help="ISO 1328-1:2013 flank tolerance class 1..11: print its tolerances")
    add_rack_args(p)
    add_json_flag(p)
    return p


def allowance_from(values, option: str = "--allowance"):
    """A_sne, or (A_sne, A_sni), of a command line's allowance option, refused by the option's name when it
    would thicken the tooth (A_sne > 0) or has its lower value above its upper one."""
    from ..gears.measurement import THICKNESS_SIGN, refuse_thickening

    if values is None:
        return 0.0
    if len(values) > 2:
        raise GearDesignError(f"{option} takes A_sne and optionally A_sni, got {len(values)} values")
    if len(values) == 2 and values[1] > values[0]:
        raise GearDesignError(f"{option}: the lower allowance A_sni = {values[1]:g} mm exceeds the upper A_sne = "
                              f"{values[0]:g} mm; {THICKNESS_SIGN}")
    refuse_thickening(option, values[0])
    return values[0] if len(values) == 1 else (values[0], values[1])


def run(args) -> int:
    t = tooth_measurements(args.module, args.z, args.x, beta_deg=args.beta, internal=args.internal,
                           rack=rack_from_args(args), k=args.k, ball_mm=args.ball, pin_mm=args.pin,
                           thickness_allowance_mm=allowance_from(args.allowance), face_width_mm=args.face_width_mm,
                           tip_diameter_mm=args.tip_diameter)
    tol = None
    if args.accuracy_class is not None:
        b = args.face_width_mm if args.face_width_mm is not None and args.face_width_mm >= 4.0 else None
        tol = flank_tolerances(args.module, args.z, args.accuracy_class, beta_deg=args.beta, face_width_mm=b)
    if args.json:
        print_json({"ok": bool(t.ok), "measurements": t.to_dict(), "tolerances": None if tol is None else tol.to_dict()})
        return 0 if t.ok else 1
    import pandas as pd

    flagged = ([] if t.internal or t.span_ok else [f"span_ok (W_k over k = {t.k:g} touches at d = {t.d_wk:.4g} mm)"]) + (
        [] if t.ball_ok else [f"ball_ok (D_M = {t.ball_mm:.4g} mm touches at d = {t.d_ball:.4g} mm)"])
    print("OK: every size can be measured." if t.ok else "FAILS: " + "; ".join(flagged) + ": not measurable there")
    kind = ("ring" if t.internal else "gear") + (f", helical beta = {t.beta_deg:g} deg" if t.beta_deg else "")
    print(f"Measuring sizes: {kind}, m = {t.m_n:g} mm, z = {t.z}, x = {t.x:.6g}, "
          f"A_sne / A_sni = {t.a_sne:g} / {t.a_sni:g} mm")
    rows = [(label, getattr(t, name), unit) for name, label, unit in ROWS if not (name == "face_width_min_mm"
                                                                                 and not t.beta_deg)]
    frame = pd.DataFrame([(a, b if isinstance(b, (bool, int)) else float(b), c) for a, b, c in rows],
                         columns=["quantity", "value", "unit"])
    print_frame(frame, float_format="{:.5f}")
    for note in t.notes:
        print(f"note: {note}")
    if tol is not None:
        print_frame(tol.to_frame(), f"\nISO 1328-1:2013 class {tol.accuracy_class} (d = {tol.d_mm:.4g} mm), µm")
    return 0 if t.ok else 1
