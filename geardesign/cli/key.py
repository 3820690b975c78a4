"""``geardesign key``: select a parallel key for a shaft and hub, or give a key's capacity.

Exit status 0 when a key fits and passes, 1 when nothing fits (or, with --length and --torque, when the
given key does not carry the torque), 2 on bad input.
"""
from __future__ import annotations

from ..drives import key
from ..errors import GearDesignError
from .output import add_json_flag, print_json, print_verdict_line, print_wrapped


def add_parser(subparsers):
    p = subparsers.add_parser(
        "key", help="select a parallel key (GOST 23360 / DIN 6885) or compute its torque capacity",
        description="The key of the shaft's standard section with the longest standard length that fits the hub "
                    "(hub length less an allowance), checked for crushing and shear; two keys at 180 deg when one is "
                    "not enough. With --length, the torque capacity of that key instead (with --torque too: "
                    "whether it carries it). Exit status 0 when the key passes, 1 when nothing fits or the given "
                    "key is too weak, 2 on bad input.")
    p.add_argument("--d", type=float, required=True, metavar="MM", help="shaft diameter [mm]")
    p.add_argument("--torque", type=float, metavar="N_M",
                   help="torque [N·m] (required unless --length; with --length: check that key against it)")
    p.add_argument("--hub-length", type=float, dest="hub_length", metavar="MM", help="hub length [mm]")
    p.add_argument("--length", type=float, metavar="MM", help="key length [mm]: report the capacity of this key")
    p.add_argument("--crush", type=float, default=key.DEFAULT_CRUSH_MPA, metavar="MPA",
                   help=f"allowable crushing stress [MPa] (default {key.DEFAULT_CRUSH_MPA:g})")
    p.add_argument("--shear", type=float, default=key.DEFAULT_SHEAR_MPA, metavar="MPA",
                   help=f"allowable shear stress [MPa] (default {key.DEFAULT_SHEAR_MPA:g})")
    p.add_argument("--end", default="rounded", choices=key.ENDS, help="key ends (default rounded)")
    p.add_argument("--keys", type=int, default=None, choices=(1, 2),
                   help="number of keys (select: the most to try, default 2; capacity: default 1)")
    add_json_flag(p)
    return p


def run(args) -> int:
    if args.length is not None:
        cap = key.capacity(args.d, args.length, args.crush, args.shear, end=args.end, n_keys=args.keys or 1)
        ok = args.torque is None or cap["torque_nm"] >= args.torque
        if args.json:
            print_json({"ok": ok, **cap.to_dict()})
        else:
            print_verdict_line(ok, f"{cap['torque_nm']:.1f} N·m {'>=' if ok else '<'} the torque {args.torque:g} N·m"
                               if args.torque is not None else f"the key carries {cap['torque_nm']:.1f} N·m")
            print_wrapped(f"key {cap['b_mm']:g}x{cap['h_mm']:g}x{args.length:g} on d = {args.d:g} mm "
                  f"({cap['n_keys']} key{'s' if cap['n_keys'] > 1 else ''}, l_p = {cap['working_length_mm']:g} mm): "
                  f"carries {cap['torque_nm']:.1f} N·m, limited by {cap['governing']} "
                  f"(crushing {cap['torque_crush_nm']:.1f} N·m, shear {cap['torque_shear_nm']:.1f} N·m)")
        return 0 if ok else 1
    if args.torque is None or args.hub_length is None:
        raise GearDesignError("--torque and --hub-length are required to select a key (or give --length)")
    sel = key.select(args.d, args.torque, args.hub_length, args.crush, args.shear, end=args.end,
                     max_keys=args.keys or 2)
    if args.json:
        print_json({"ok": bool(sel.feasible), **sel.to_dict()})
    else:
        print_verdict_line(bool(sel.feasible), sel.message.split(" (")[0])   # the repr below gives the details
        for line in repr(sel).splitlines():
            print_wrapped(line, indent="    ")
    return 0 if sel.feasible else 1
