"""Options several subcommands share, defined once: the check options (from the check registry), the
shift objective and method (choices from the library's registries), an output file that is never
silently replaced, and the Dask cluster a batch runs on."""
from __future__ import annotations

import argparse
import contextlib

from ..gears.checks import options as check_options

__all__ = ["add_check_args", "checks_from_args", "add_load_args", "load_from_args", "add_strength_args",
           "strength_from_args", "add_rack_args", "rack_from_args", "add_solver_args", "add_output_file",
           "add_cluster_args", "cluster_from_args", "local_workers"]

# the older spellings of --no-undercut and --no-interference, kept working
_ALIASES = {"undercut": "--allow-undercut", "interference": "--allow-interference"}


def _limit(text: str):
    """A check limit on the command line: a number, or "none" to drop the check."""
    if text.strip().lower() == "none":
        return None
    try:
        return float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number or 'none', got {text!r}") from None


def add_check_args(p, exclude=(), load: bool = True) -> None:
    """One option per registered check option (:func:`geardesign.gears.checks.options`): a limit as
    ``--eps-alpha-min VALUE`` (``none`` drops the check), a flag as ``--undercut``/``--no-undercut``; with
    ``load``, the load case of the strength checks (:func:`add_load_args`)."""
    from ..gears.strength.user_options import STRENGTH_OPTIONS

    # a strength option that is also a check's limit (--sh-min) names that check's option a second way
    aliases = {o.keyword: [o.flag] for o in STRENGTH_OPTIONS if o.limit}
    g = p.add_argument_group("checks (limits and switches; see docs/extending.md for adding one)")
    for opt in check_options().values():
        if not opt.cli or opt.name in exclude:
            continue
        flag = "--" + opt.name.replace("_", "-")
        if opt.kind == "limit":
            lo, hi = opt.range
            default = "none: off" if opt.default is None else f"{opt.default:g}"
            g.add_argument(flag, *aliases.get(opt.name, ()), dest=opt.name, type=_limit, default=opt.default,
                           metavar="VALUE", help=f"{opt.help} ({default}; {lo:g} to {hi:g}, or none to drop the check)")
        else:
            g.add_argument(flag, action=argparse.BooleanOptionalAction, default=None,
                           help=f"{opt.help} ({'on' if opt.default else 'off'} by default)")
            if opt.name in _ALIASES:
                g.add_argument(_ALIASES[opt.name], dest=opt.name, action="store_false",
                               help=f"the same as --no-{opt.name}")
    if load:
        add_load_args(p)


def checks_from_args(args) -> dict:
    """The check options the command line set, as :func:`~geardesign.gears.checks.make_checks`
    keywords: every limit, and the switches given (the others keep the caller's defaults)."""
    out = {}
    for name, opt in check_options().items():
        value = getattr(args, name, None)
        if hasattr(args, name) and (opt.kind == "limit" or value is not None):
            out[name] = value
    if hasattr(args, "torque"):
        out.update(load_from_args(args))
    return out


def add_solver_args(p, default_objective: str | None = None, objective_help: str | None = None) -> None:
    """--objective (the registry's names) and --method (the shift methods; exact by default)."""
    from ..shifts.objectives import OBJECTIVES
    from ..shifts.optimize import METHODS

    p.add_argument("--objective", choices=sorted(OBJECTIVES), default=default_objective,
                   help=objective_help or "what the optimal shifts maximise or minimise (default max_x_sum): "
                   + "; ".join(f"{k}: {o.description}" for k, o in OBJECTIVES.items()))
    p.add_argument("--method", choices=METHODS, default="exact", help="shift solver: " + ", ".join(METHODS)
                   + " (exact)")


def add_output_file(p, flag: str, metavar: str, what: str) -> None:
    """``flag`` FILE writes ``what`` there; --overwrite allows replacing an existing file."""
    p.add_argument(flag, metavar=metavar, default=None, help=f"write {what} to this {metavar}")
    p.add_argument("--overwrite", action="store_true", help=f"replace an existing {flag} file")


def add_cluster_args(p) -> None:
    """--workers N (a local Dask cluster of N processes) and --scheduler ADDRESS (a running one)."""
    g = p.add_argument_group("cluster (needs Dask: pip install \"geardesign[dask]\")")
    g.add_argument("--workers", default=None, metavar="N",
                   help="solve on a local Dask cluster of N processes, started and closed for this command")
    g.add_argument("--scheduler", default=None, metavar="ADDRESS",
                   help="solve on the Dask cluster whose scheduler is at ADDRESS (e.g. tcp://host:8786)")


def local_workers(args) -> int:
    """--workers as a count, checked (1 when not given); the size limits scale with it."""
    from ..errors import GearDesignError
    from ..parallel import LOCAL_WORKERS_MAX
    from ..validate import require_count

    if args.workers is None:
        return 1
    try:
        n = int(args.workers)
    except ValueError:
        raise GearDesignError(f"--workers must be a whole number in [1, {LOCAL_WORKERS_MAX}], "
                              f"got {args.workers!r}") from None
    return require_count("--workers", n, 1, LOCAL_WORKERS_MAX)


@contextlib.contextmanager
def cluster_from_args(args):
    """The Client that --workers / --scheduler ask for (None: solve here), open for the block."""
    from ..errors import GearDesignError
    from ..parallel import cluster

    if args.workers is not None and args.scheduler is not None:
        raise GearDesignError("give --workers or --scheduler, not both")
    n = local_workers(args)
    with cluster(workers=n if args.workers is not None else None, address=args.scheduler) as client:
        yield client


def add_load_args(p, planetary: bool = False, limits: bool = False, spectrum: bool = True) -> None:
    """The load case of the strength checks (ISO 6336): a torque or a power at a speed, the material(s),
    the life and the application factor; given, the strength checks join the others. ``planetary``: the
    sun's load of a planetary set, with the planet's and the ring's materials, K_γ and the face width; the
    strength model's options (:func:`add_strength_args`; ``limits``: with --sh-min and --sf-min, for a command
    without the check options); ``spectrum``: a pair's load spectrum too (:func:`add_spectrum_args`)."""
    g = p.add_argument_group("load capacity (ISO 6336; any of these switches the strength checks on)")
    on = "the sun" if planetary else "gear 1 (--on-gear)"
    g.add_argument("--torque", type=float, default=None, metavar="NM", help=f"torque on {on}, N·m")
    g.add_argument("--power", type=float, default=None, metavar="KW", help="power, kW (instead of --torque)")
    g.add_argument("--speed", type=float, default=None, metavar="RPM",
                   help="speed of the sun, rpm" if planetary else "speed of the gear the load is on, rpm")
    g.add_argument("--material", default=None, metavar="NAME",
                   help=("material of every gear (unless --planet-material, --ring-material)" if planetary else
                         "material of both gears (or of gear 1 with --material2)")
                   + ", a name of the ISO 6336-5 catalog, e.g. 42CrMo4, 18CrNiMo7-6, C45")
    if planetary:
        g.add_argument("--planet-material", default=None, metavar="NAME", help="material of the planets")
        g.add_argument("--ring-material", default=None, metavar="NAME", help="material of the ring")
        g.add_argument("--k-gamma", type=float, default=1.0, metavar="K",
                       help="mesh load factor K_gamma of the planets' load sharing (ISO 6336-1 6.4; 1.0 even)")
        g.add_argument("--face-width", dest="strength_width", type=float, default=None, metavar="MM",
                       help="face width of the meshes, mm (needed with a load)")
    else:
        g.add_argument("--on-gear", type=int, default=1, choices=(1, 2), help="the gear --torque and --speed are of (1)")
        g.add_argument("--material2", default=None, metavar="NAME", help="material of gear 2 (default: --material)")
    g.add_argument("--life-h", type=float, default=None, metavar="H",
                   help="required life, hours (default: endurance, Z_NT = Y_NT = 1)")
    g.add_argument("--application-factor", type=float, default=1.0, metavar="K_A",
                   help="application factor K_A (ISO 6336-1 6.3; 1.0 uniform)")
    if not planetary:
        g.add_argument("--strength-width", type=float, default=None, metavar="MM",
                       help="face width for the strength checks, mm (default: --face-width)")
    if spectrum:
        add_spectrum_args(p, planetary)
    add_strength_args(g, limits=limits)


def add_spectrum_args(p, planetary: bool = False) -> None:
    """A load spectrum (ISO 6336-6): --spectrum FILE (a CSV), the S-N curve beyond the knee, Y_M; given, the damage
    checks join the others (with --material, --life-h the required life). ``planetary``: the sun's spectrum of a
    planetary set (its planets' roots bend both ways: Y_M needed)."""
    g = p.add_argument_group("service life under a load spectrum (ISO 6336-6; --spectrum switches the damage "
                             "checks on)")
    g.add_argument("--spectrum", default=None, metavar="CSV",
                   help="the load spectrum: a CSV with columns torque_nm, n_rpm (or --speed for all bins) and one of "
                        "time_h, cycles, share (share: with --life-h); "
                        + ("torques on the sun, negative on the other flank (the planet's flanks then summed over "
                           "both meshes: set:pitting_damage_planet, set:root_damage_planet)"
                           if planetary else "torques of gear --on-gear, negative on the other flank"))
    from ..gears.spectrum import SN_CURVES   # a light module (numpy, csv)

    g.add_argument("--sn-curve", default="iso", choices=SN_CURVES,
                   help="the S-N curve beyond its knee (iso: ISO 6336-2/-3 as tabled; docs/life.md)")
    g.add_argument("--mean-stress-factor", type=float, default=None, metavar="Y_M",
                   help=("Y_M of the planets' roots, which bend both ways (ISO 6336-3:2019; needed with --spectrum)"
                         if planetary else
                         "Y_M of both gears' roots for a spectrum whose torque reverses (ISO 6336-3:2019)"))


def spectrum_from_args(args) -> dict:
    """The damage checks' context from --spectrum (empty without it); a bad file refused naming --spectrum."""
    from ..errors import GearDesignError

    path = getattr(args, "spectrum", None)
    if path is None:
        if getattr(args, "mean_stress_factor", None) is not None:
            raise GearDesignError("--mean-stress-factor needs --spectrum")
        return {}
    from ..gears.spectrum import LoadSpectrum   # here: only a command with a spectrum reads it

    from ..files import read_text_bounded
    from ..gears.spectrum import SPECTRUM_BYTES_MAX

    try:
        # bounded: a device such as /dev/zero is one endless line
        text = read_text_bounded(path, "spectrum file", SPECTRUM_BYTES_MAX)
        has_speed = "n_rpm" in next((line for line in text.splitlines() if line.strip()
                                     and not line.lstrip().startswith("#")), "").split(",")
        spec = LoadSpectrum.from_csv(path, n_rpm=None if has_speed else args.speed,
                                     duration_h=args.life_h, on_gear=getattr(args, "on_gear", 1))
    except (GearDesignError, OSError, UnicodeDecodeError) as exc:
        text = str(exc) if isinstance(exc, GearDesignError) else f"{path!r} cannot be read: {getattr(exc, 'strerror', None) or exc}"
        raise GearDesignError(f"--spectrum: {text}") from None
    out = {"spectrum": spec, "sn_curve": args.sn_curve, "life_h": args.life_h}
    if args.mean_stress_factor is not None:
        out["mean_stress_factor"] = args.mean_stress_factor
    return out


def _factor(text: str) -> tuple:
    """``NAME=VALUE`` of ``--factor``: a given factor of the strength model (its name checked, with the
    nearest names on a miss) and its value."""
    import difflib

    from ..gears.strength.chain import GIVEN_FACTORS   # here: only --factor reads the chain's names

    name, sep, value = text.partition("=")
    name = name.strip()
    if not sep or not name:
        raise argparse.ArgumentTypeError(f"expected NAME=VALUE (e.g. K_Hbeta=1.3), got {text!r}")
    if name not in GIVEN_FACTORS:
        near = difflib.get_close_matches(name, sorted(GIVEN_FACTORS), n=3, cutoff=0.5)
        raise argparse.ArgumentTypeError(f"unknown factor {name!r}" + (f"; nearest: {', '.join(near)}" if near else "")
                                         + "; the names are geardesign.gears.strength.GIVEN_FACTORS (docs/strength.md)")
    try:
        return name, float(value)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{name}: expected a number after '=', got {value.strip()!r}") from None


def add_strength_args(g, limits: bool = True) -> None:
    """One option per user-facing strength option (:data:`~geardesign.gears.strength.user_options.STRENGTH_OPTIONS`)
    and ``--factor NAME=VALUE`` (repeatable, any given factor). ``limits`` False leaves out the options that are
    also check limits (--sh-min, --sf-min): the check options of :func:`add_check_args` carry them there."""
    from ..gears.strength.user_options import FACTORS_FLAG, STRENGTH_OPTIONS

    for opt in STRENGTH_OPTIONS:
        if opt.limit and not limits:
            continue
        g.add_argument(opt.flag, dest=opt.keyword, type=float, default=None, metavar=opt.metavar,
                       help=opt.describe())
    g.add_argument(FACTORS_FLAG, dest="factors", action="append", type=_factor, default=None, metavar="NAME=VALUE",
                   help="a factor given instead of computed (ISO 6336 allows measured values), e.g. K_Hbeta=1.3; "
                        "repeat for more; the names: geardesign.gears.strength.GIVEN_FACTORS (docs/strength.md)")


def strength_from_args(args) -> dict:
    """The strength options the command line gave, as :func:`~geardesign.gears.strength.pair_strength` keywords
    (``factors`` a dict of the given factors); the options not given are left out (the model's defaults)."""
    from ..errors import GearDesignError
    from ..gears.strength.user_options import FACTORS_FLAG, STRENGTH_OPTIONS

    out, factors = {}, {}
    for name, value in getattr(args, "factors", None) or ():
        if name in factors:
            raise GearDesignError(f"{FACTORS_FLAG} {name} given twice ({factors[name]:g} and {value:g})")
        factors[name] = value
    for opt in STRENGTH_OPTIONS:
        value = getattr(args, opt.keyword, None)
        if value is None or (opt.limit and value == opt.default):
            continue
        if opt.factor:
            if opt.keyword in factors:
                raise GearDesignError(f"{opt.flag} and {FACTORS_FLAG} '{opt.keyword}=...' both given: give one")
            factors[opt.keyword] = value
        else:
            out[opt.keyword] = value
    if factors:
        out["factors"] = factors
    return out


# the load options of a pair and of a planetary set: the set's extra ones go to its checks dict as they are
_SET_LOAD = ("planet_material", "ring_material")


def load_from_args(args) -> dict:
    """The load case as :func:`~geardesign.gears.checks.make_checks` context keywords (empty without one): a load,
    a spectrum (:func:`spectrum_from_args`) or both."""
    from ..errors import GearDesignError

    extra = {k: getattr(args, k) for k in _SET_LOAD if getattr(args, k, None) is not None}
    given = [args.torque, args.power, args.speed, args.material, getattr(args, "material2", None), args.life_h,
             *extra.values()]
    options = strength_from_args(args)
    spectrum = spectrum_from_args(args)
    if spectrum and args.torque is None and args.power is None:   # the damage checks alone
        if args.material is None:
            raise GearDesignError("--spectrum needs --material")
        width = args.strength_width if args.strength_width is not None else getattr(args, "face_width_mm", None)
        out = {**spectrum, "material": args.material, "face_width_mm": width, **extra}
        if hasattr(args, "k_gamma"):      # a planetary set's sun spectrum
            return {**out, "strength": {"K_gamma": args.k_gamma, **options}}
        return {**out, "material2": getattr(args, "material2", None), **({"strength": options} if options else {})}
    if all(v is None for v in given):
        if options:
            from ..gears.strength.user_options import FACTORS_FLAG, strength_option

            flags = [FACTORS_FLAG if k == "factors" else strength_option(k).flag for k in options]
            raise GearDesignError(f"{', '.join(flags)}: the strength options need a load (--torque or --power, "
                                  f"--speed and --material)")
        return {}
    from ..gears.strength import Load   # here: only a command with a load reads the strength model

    load = Load(torque_nm=args.torque, power_kw=args.power, n_rpm=args.speed, on_gear=getattr(args, "on_gear", 1),
                application_factor=args.application_factor, life_h=args.life_h)
    width = args.strength_width if args.strength_width is not None else getattr(args, "face_width_mm", None)
    out = {"load": load, "material": args.material, "face_width_mm": width, **extra, **spectrum}
    if hasattr(args, "k_gamma"):
        out["strength"] = {"K_gamma": args.k_gamma, **options}
    else:
        out["material2"] = args.material2
        if options:
            out["strength"] = options
    return out


def add_rack_args(p) -> None:
    """--alpha-deg, --ha, --c, --rho-f: the basic rack, defaults the standard one's (BasicRack)."""
    from ..gears.rack import BasicRack

    std = BasicRack()
    g = p.add_argument_group("basic rack (ISO 53 / GOST 13755 defaults)")
    g.add_argument("--alpha-deg", type=float, default=std.alpha_deg, help=f"pressure angle, degrees ({std.alpha_deg:g})")
    g.add_argument("--ha", type=float, default=std.ha, help=f"addendum coefficient h_a* ({std.ha:g})")
    g.add_argument("--c", type=float, default=std.c, help=f"clearance coefficient c* ({std.c:g})")
    g.add_argument("--rho-f", type=float, default=std.rho_f, help=f"root fillet coefficient rho_f* ({std.rho_f:g})")


def rack_from_args(args):
    """The BasicRack of :func:`add_rack_args`' options."""
    from ..gears.rack import BasicRack

    return BasicRack(alpha_deg=args.alpha_deg, ha=args.ha, c=args.c, rho_f=args.rho_f)


class OneLineParser(argparse.ArgumentParser):
    """An ArgumentParser whose errors are one line on stderr naming the option, exit status 2 (argparse's own
    prints the whole usage block first); its subcommands' parsers are of this class too."""

    def error(self, message):
        self.exit(2, f"{self.prog}: error: {' '.join(message.split())} (see {self.prog} --help)\n")


# the library's keywords that an error message may name, by the command-line option that sets them: the load
# (Load's keywords), the strength options (their one definition) and a few of the commands' own
_KEYWORD_FLAGS = {"torque_nm": "--torque", "power_kw": "--power", "n_rpm": "--speed", "life_h": "--life-h",
                  "application_factor": "--application-factor", "K_gamma": "--k-gamma", "material1": "--material",
                  "material": "--material", "material2": "--material2", "on_gear": "--on-gear",
                  "face_width_mm": "--face-width", "n1_rpm": "--n1", "k_e": "--k-e", "beta_deg": "--beta",
                  "alpha_deg": "--alpha-deg", "rho_f": "--rho-f", "planet_material": "--planet-material",
                  "ring_material": "--ring-material", "center_distance_mm": "--center-distance",
                  "allowable_pressure_mpa": "--p-allow", "allowable_safety_factor": "--s-allow",
                  "mean_stress_factor": "--mean-stress-factor", "sn_curve": "--sn-curve"}
# plain words (not identifiers) are renamed only where they start what is said of them
_PLAIN_WORD_AFTER = r"(?= must| given| is needed|: )"


def option_names(message: str, parser) -> str:
    """``message`` of a GearDesignError with each library keyword the command sets by an option named by that
    option (``n_rpm must be ...`` -> ``--speed must be ...``, ``factors['K_Hbeta']`` -> ``--factor K_Hbeta``);
    keywords of options ``parser`` does not have are left as they are."""
    import re

    from ..gears.strength.user_options import FACTORS_FLAG, STRENGTH_OPTIONS

    flags = {s for a in parser._actions for s in a.option_strings}
    table = {**_KEYWORD_FLAGS, **{o.keyword: o.flag for o in STRENGTH_OPTIONS}}
    if FACTORS_FLAG in flags:
        message = re.sub(r"(?<![\w\-.])factors\[['\"](\w+)['\"]\]", lambda m: f"{FACTORS_FLAG} {m.group(1)}",
                         message)
    # an option spelled as its keyword with dashes (--z1 for z1, --z-sun-range for z_sun_range): named so too, where
    # the keyword is an identifier (an underscore or a digit in it: never a word of the prose)
    same = {f[2:].replace("-", "_"): f for f in flags if f.startswith("--")}
    table.update({k: f for k, f in same.items() if k not in table and ("_" in k or any(c.isdigit() for c in k))})
    for keyword, flag in table.items():
        if flag not in flags:
            continue
        tail = "" if ("_" in keyword or any(c.isdigit() for c in keyword)) else _PLAIN_WORD_AFTER
        message = re.sub(rf"(?<![\w\-.'\"\[]){re.escape(keyword)}(?![\w'\"]){tail}", flag, message)
    return message
