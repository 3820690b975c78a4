"""``geardesign shaft``: a shaft on its bearings: reactions, moment and deflection diagrams, critical speed and
the DIN 743 safety of its notches.

Exit status 0 when every checked section reaches S_min (or none is checked), 1 when one fails (the first
line names it), 2 on bad input (one line on stderr naming the option).
"""
from __future__ import annotations

import re

from ..drives import din743
from ..drives.shaft_beam import ShaftLoad, ShaftModel, analyse_shaft
from ..errors import GearDesignError
from .output import add_json_flag, print_frame, print_json, print_wrapped

_LOAD_KEYS = {"x": "x_mm", "fy": "fy_n", "fz": "fz_n", "fx": "fx_n", "y": "y_mm", "z": "z_mm", "torque": "torque_nm",
              "my": "my_nm", "mz": "mz_nm", "mass": "mass_kg", "name": "name"}
_NOTCH_KEYS = {"x": "x_mm", "kind": "kind", "r": "r_mm", "t": "t_mm", "keys": "keys", "beta_sigma": "beta_sigma",
               "beta_tau": "beta_tau", "name": "name"}


def add_parser(subparsers):
    p = subparsers.add_parser(
        "shaft", help="a shaft on its bearings: reactions, diagrams, deflection, critical speed, DIN 743 safety",
        description="A stepped shaft on two or more rigid supports carrying point loads (forces in two planes, "
                    "axial forces at a radius, torques): support reactions, bending moment and torque diagrams, "
                    "deflection and slope at each load, the first bending critical speed (Rayleigh, Dunkerley), "
                    "and the DIN 743 fatigue and static safety at each --notch. The first line is the verdict. "
                    "Exit status 0 when every notch reaches --s-min, 1 when one fails, 2 on bad input.")
    p.add_argument("file", nargs="?", default=None, metavar="TOML",
                   help="a shaft described in TOML: a [shaft] table with sections = [[length, d], ...], "
                        "supports = [x, ...], material, and [[shaft.load]] / [[shaft.notch]] tables with the keys of "
                        "--load and --notch (options given too are added: loads and notches, or replace: the rest)")
    p.add_argument("--sections", default=None, metavar="LxD,...",
                   help="consecutive sections from x = 0 as length x diameter [x bore], mm, e.g. 40x35,120x45,40x35")
    p.add_argument("--supports", default=None, metavar="X,X[,...]", help="support (bearing) positions x, mm")
    p.add_argument("--load", action="append", default=[], metavar="KEY=V,...",
                   help="a load: x (mm), fy, fz, fx (N), y, z (mm: where fx acts), torque (N·m, input +, "
                        "output −), my, mz (N·m), mass (kg), name; repeat for each element")
    p.add_argument("--notch", action="append", default=[], metavar="KEY=V,...",
                   help="a section to check: x (mm), kind (smooth, key, press_fit, shoulder, groove, given), r, t "
                        "(mm), keys (1 or 2), beta_sigma, beta_tau (for kind=given), name")
    p.add_argument("--material", default=None,
                   help="shaft material of catalogs/shaft_materials_din743.csv (default 42CrMo4)")
    p.add_argument("--rz", type=float, default=6.3, metavar="UM", help="surface roughness Rz, µm (default 6.3)")
    p.add_argument("--peak-factor", dest="peak_factor", type=float, default=1.0, metavar="K",
                   help="maximum load / nominal load for the static proof (default 1)")
    p.add_argument("--torque-amplitude", dest="torque_amplitude", type=float, default=0.0, metavar="F",
                   help="torque amplitude as a fraction of the torque (default 0: steady)")
    p.add_argument("--load-case", dest="load_case", type=int, default=2, choices=(1, 2),
                   help="DIN 743 load case: 1 mean stress constant, 2 mean/amplitude constant (default 2)")
    p.add_argument("--s-min", dest="s_min", type=float, default=din743.S_MIN, metavar="S",
                   help=f"least safety, fatigue and static (default {din743.S_MIN:g}, DIN 743-1)")
    p.add_argument("--axial-support", dest="axial_support", type=int, default=0, metavar="I",
                   help="index of the support taking the axial force (default 0, the first)")
    p.add_argument("--least", action="store_true",
                   help="also find the least factor on all diameters that reaches --s-min")
    p.add_argument("--plot", default=None, metavar="PNG", help="write the moment, torque and deflection diagrams")
    p.add_argument("--overwrite", action="store_true", help="replace an existing --plot file")
    add_json_flag(p)
    return p


def _numbers(text, option):
    try:
        return [float(v) for v in text.split(",") if v.strip()]
    except ValueError:
        raise GearDesignError(f"{option} must be numbers separated by commas, got {text!r}") from None


def _sections(text):
    out = []
    for part in (s for s in text.split(",") if s.strip()):
        try:
            out.append(tuple(float(v) for v in part.lower().split("x")))
        except ValueError:
            raise GearDesignError(f"--sections: each section is length x diameter [x bore] in mm, got {part!r}") \
                from None
        if len(out[-1]) not in (2, 3):
            raise GearDesignError(f"--sections: each section is length x diameter [x bore] in mm, got {part!r}")
    if not out:
        raise GearDesignError("--sections must list at least one section")
    return out


def _pairs(text, keys, option):
    out = {}
    for part in (s for s in text.split(",") if s.strip()):
        if "=" not in part:
            raise GearDesignError(f"{option}: expected key=value pairs, got {part!r}")
        k, v = (s.strip() for s in part.split("=", 1))
        if k not in keys:
            raise GearDesignError(f"{option}: unknown key {k!r} (keys: {', '.join(keys)})")
        if k in ("name", "kind"):
            out[keys[k]] = v
        else:
            try:
                out[keys[k]] = int(v) if k == "keys" else float(v)
            except ValueError:
                raise GearDesignError(f"{option}: {k} must be a number, got {v!r}") from None
    if "x_mm" not in out:
        raise GearDesignError(f"{option} {text!r} needs its position x")
    return out


# the library's argument names -> this command's options, for the one-line error
_OPTIONS = {"Rz_um": "--rz", "peak_factor": "--peak-factor", "torque_amplitude": "--torque-amplitude",
            "S_min": "--s-min", "axial_support": "--axial-support", "load_case": "--load-case"}


def _with_option(exc, option):
    text = str(exc)
    for name, opt in _OPTIONS.items():
        if re.search(rf"(?<![\w-]){re.escape(name)}\b", text):
            return GearDesignError(re.sub(rf"(?<![\w-]){re.escape(name)}\b", opt, text))
    return GearDesignError(text if text.startswith("--") else f"{option}: {text}")


_FILE_KEYS = ("sections", "supports", "material", "load", "notch")
FILE_BYTES_MAX = 1 << 20


def _from_file(path):
    """The [shaft] table of a TOML file: sections, supports, material, and the load and notch tables as the
    key=value texts of --load and --notch (one parser for both ways in)."""
    import tomllib
    from pathlib import Path

    p = Path(path)
    if not p.is_file():
        raise GearDesignError(f"TOML file {str(p)!r} does not exist")
    if p.stat().st_size > FILE_BYTES_MAX:
        raise GearDesignError(f"TOML file {str(p)!r} is larger than {FILE_BYTES_MAX} bytes")
    try:
        raw = tomllib.loads(p.read_bytes().decode("utf-8"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as exc:
        raise GearDesignError(f"TOML file {str(p)!r}: {exc}") from None
    shaft = raw.get("shaft")
    if not isinstance(shaft, dict) or set(raw) - {"shaft"}:
        raise GearDesignError(f"TOML file {str(p)!r} must hold one [shaft] table (and nothing else)")
    unknown = set(shaft) - set(_FILE_KEYS)
    if unknown:
        raise GearDesignError(f"TOML file [shaft]: unknown key(s) {', '.join(sorted(unknown))} "
                              f"(keys: {', '.join(_FILE_KEYS)})")

    def text(items, what):
        if not isinstance(items, list) or not all(isinstance(i, dict) for i in items):
            raise GearDesignError(f"TOML file [[shaft.{what}]]: each must be a table of key = value")
        for i in items:
            for k, v in i.items():
                if isinstance(v, str) and ("," in v or "=" in v):
                    raise GearDesignError(f"TOML file [[shaft.{what}]] {k} = {v!r}: no ',' or '=' in a value")
                if not isinstance(v, (str, int, float)) or isinstance(v, bool):
                    raise GearDesignError(f"TOML file [[shaft.{what}]] {k}: a number or a name, got {v!r}")
        return [",".join(f"{k}={v}" for k, v in i.items()) for i in items]

    out = {"loads": text(shaft.get("load", []), "load"), "notches": text(shaft.get("notch", []), "notch")}
    sec = shaft.get("sections")
    if sec is not None:
        if not isinstance(sec, list) or not all(isinstance(v, list) for v in sec):
            raise GearDesignError("TOML file [shaft] sections must be a list of [length, d] or [length, d, bore]")
        out["sections"] = ",".join("x".join(str(x) for x in v) for v in sec)
    sup = shaft.get("supports")
    if sup is not None:
        if not isinstance(sup, list):
            raise GearDesignError("TOML file [shaft] supports must be a list of positions")
        out["supports"] = ",".join(str(x) for x in sup)
    if "material" in shaft:
        out["material"] = str(shaft["material"])
    return out


def run(args) -> int:
    if args.plot is not None:
        from ..files import check_output_path
        check_output_path(args.plot, overwrite=args.overwrite)
    spec = _from_file(args.file) if args.file is not None else {"loads": [], "notches": []}
    sections_text = args.sections if args.sections is not None else spec.get("sections")
    supports_text = args.supports if args.supports is not None else spec.get("supports")
    if sections_text is None or supports_text is None:
        raise GearDesignError("--sections and --supports are required (or a TOML file giving them)")
    args.material = args.material or spec.get("material") or "42CrMo4"
    args.load = spec["loads"] + args.load
    args.notch = spec["notches"] + args.notch
    sections = _sections(sections_text)
    supports = _numbers(supports_text, "--supports")
    loads = [ShaftLoad(**_pairs(t, _LOAD_KEYS, "--load")) for t in args.load]
    try:
        model = ShaftModel(sections, supports, loads, axial_support=args.axial_support)
    except GearDesignError as exc:
        option = ("--sections" if "section" in str(exc) else "--load" if "load" in str(exc) or "torque" in str(exc)
                  else "--supports")
        raise _with_option(exc, option) from None
    notches = []
    for t in args.notch:
        kv = _pairs(t, _NOTCH_KEYS, "--notch")
        x, name = kv.pop("x_mm"), kv.pop("name", "")
        try:
            notches.append(din743.ShaftNotch(x, din743.Notch(**kv), name))
        except GearDesignError as exc:
            raise _with_option(exc, "--notch") from None
    try:
        din743.shaft_material(args.material)
    except GearDesignError as exc:
        raise _with_option(exc, "--material") from None
    analysis = analyse_shaft(model)
    kw = dict(Rz_um=args.rz, peak_factor=args.peak_factor, torque_amplitude=args.torque_amplitude,
              load_case=args.load_case, S_min=args.s_min)
    if not 0.0 < args.s_min <= 100.0 or args.s_min != args.s_min:
        raise GearDesignError(f"--s-min must be in (0, 100], got {args.s_min!r}")
    safety, scale = None, None
    if notches:
        try:
            safety = din743.shaft_safety(analysis, notches, args.material, **kw)
        except GearDesignError as exc:
            raise _with_option(exc, "--notch") from None
        if args.least:
            try:
                scale = din743.least_shaft_scale(model, notches, args.material, **kw)
            except GearDesignError as exc:
                raise _with_option(exc, "--least") from None
    ok = safety is None or safety.ok
    if args.plot is not None:
        from ..drives.shaft_plot import plot_shaft
        plot_shaft(analysis, args.plot, overwrite=args.overwrite)
    if args.json:
        out = {"ok": ok, "message": safety.message if safety else "no section checked",
               "analysis": analysis.to_dict(), "safety": None if safety is None else safety.to_dict()}
        if scale is not None:
            out["least_scale"] = scale
            out["least_diameters_mm"] = [s[1] * scale for s in model.sections]
        print_json(out)
        return 0 if ok else 1
    if safety is None:
        print_wrapped("OK: no section checked (give --notch for the DIN 743 safety); diagrams and deflections below")
    else:
        print_wrapped(("OK: " if ok else "FAILS: din743_safety (") + safety.message + ("" if ok else ")"))
    for line in repr(analysis).splitlines()[1:]:
        print_wrapped(line.strip())
    print_wrapped(f"first bending critical speed: {analysis.critical_speed_rpm:.0f} rpm (Rayleigh, upper estimate), "
                  f"{analysis.critical_speed_dunkerley_rpm:.0f} rpm (Dunkerley, lower); mass {analysis.mass_kg:.4g} kg")
    if len(analysis.elements):
        print()
        print_frame(analysis.elements, title="deflection and slope at each load:")
    if safety is not None:
        print()
        print_frame(safety.table, title=f"DIN 743 safety ({args.material}, load case F{args.load_case}, "
                                        f"S_min {args.s_min:g}):")
    if scale is not None:
        print()
        print_wrapped(f"least shaft of this shape: every diameter x {scale:.4f} "
                      f"({', '.join(f'{s[1] * scale:.4g}' for s in model.sections)} mm)")
    return 0 if ok else 1
