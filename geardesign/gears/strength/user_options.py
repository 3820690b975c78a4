"""The strength options a user sets, defined once: each one's keyword of
:func:`~geardesign.gears.strength.pair_strength` (or a given factor of its ``factors``), its command-line
flag, its unit and help. The commands' options (:func:`geardesign.cli.options.add_strength_args`), the
scene keys of ``[gear.load]``, ``[teeth.load]`` and ``[[drive.stage]]`` and the CLI's error messages (a
Python keyword named by its flag) are built from :data:`STRENGTH_OPTIONS`: a new option here appears
everywhere.

One accuracy system for the user, named twice: ``accuracy_grade`` is the **ISO 1328-1:1995 grade** (0 to 12)
whose deviations f_pb, f_fα, F_β, f_Hβ the ISO 6336 factors read (ISO/TR 6336-30 uses that edition); the
drawing's tolerances are the **ISO 1328-1:2013 flank tolerance class** (1 to 11, ``accuracy_class``,
``geardesign measure --accuracy-class``). Both step a tolerance by √2 per grade from grade 5, but their
formulas differ (:mod:`geardesign.gears.tolerances`), so the same number is not the same gear and neither is
converted into the other: each part is given its own number under its own name.
"""
from __future__ import annotations

from dataclasses import dataclass

from . import defaults as dflt
from .accuracy import GRADE_RANGE

__all__ = ["StrengthOption", "STRENGTH_OPTIONS", "strength_option", "FACTORS_FLAG", "scene_keys", "options_from_table"]

FACTORS_FLAG = "--factor"


@dataclass(frozen=True)
class StrengthOption:
    """One user-facing option of the strength model.

    ``keyword``: the keyword of :func:`pair_strength` it sets, or with ``factor`` the name of a given factor in
    its ``factors`` dict (also the scene key). ``flag``: the command-line option. ``limit``: the option is also
    the limit of the check of that name (S_Hmin: ``contact_strength``), which the commands that take check
    limits already have. ``default`` and ``range`` as the strength model checks them (the range None: a given
    factor's own, :class:`~geardesign.gears.strength.chain._Given`).
    """

    keyword: str
    flag: str
    metavar: str
    unit: str
    help: str
    default: object = None
    range: tuple | None = None
    factor: bool = False
    limit: bool = False

    def describe(self) -> str:
        """The option's help with its default: what ``--help`` prints."""
        default = "" if self.default is None else f"; default {self.default:g}"
        return f"{self.help}{default}"


STRENGTH_OPTIONS = (
    StrengthOption("accuracy_grade", "--accuracy-grade", "Q", "",
                   "ISO 1328-1:1995 accuracy grade Q, 0 to 12, of the deviations the strength factors read "
                   "(f_pb, f_falpha, F_beta, f_Hbeta); not the ISO 1328-1:2013 tolerance class of the drawing "
                   "(measure --accuracy-class)", dflt.ACCURACY_GRADE, GRADE_RANGE),
    StrengthOption("f_ma", "--fma", "UM", "µm",
                   "mesh misalignment from manufacture f_ma, µm (ISO 6336-1 7.6.2.1; default f_Hbeta of the grade: "
                   "no helix adjustment; 0: helix matched by modification or lapping)", factor=True),
    StrengthOption("nu40", "--nu40", "MM2_S", "mm²/s",
                   "lubricant's kinematic viscosity at 40 °C, mm²/s (an ISO VG grade number)", dflt.NU40_MM2_S,
                   dflt.NU40_RANGE),
    StrengthOption("Rz_flank_um", "--rz-flank", "UM", "µm", "mean peak-to-valley roughness R_z of the flanks, µm",
                   dflt.RZ_FLANK_UM, dflt.RZ_RANGE_UM),
    StrengthOption("Rz_root_um", "--rz-root", "UM", "µm", "mean peak-to-valley roughness R_z of the root fillets, µm",
                   dflt.RZ_ROOT_UM, (dflt.RZ_RANGE_UM[0], dflt.RZ_ROOT_MAX_UM)),
    StrengthOption("S_Hmin", "--sh-min", "S", "", "smallest contact safety factor S_Hmin (sigma_HP = sigma_HG/S_Hmin)",
                   dflt.S_HMIN, (0.5, 10.0), limit=True),
    StrengthOption("S_Fmin", "--sf-min", "S", "", "smallest root safety factor S_Fmin (sigma_FP = sigma_FG/S_Fmin)",
                   dflt.S_FMIN, (0.5, 10.0), limit=True),
)


_BY_KEYWORD = {o.keyword: o for o in STRENGTH_OPTIONS}


def strength_option(keyword: str) -> StrengthOption:
    """The option of ``keyword`` (KeyError for another)."""
    return _BY_KEYWORD[keyword]


def scene_keys(limits: bool = True) -> dict:
    """The scene keys of the strength options, as neutral descriptions (``kind``, ``lo``, ``hi``, as
    :meth:`~geardesign.drives.stage_kinds.base.StageKind.scene_keys` gives them): one per option (``limits``
    False leaves out S_Hmin and S_Fmin, which a section's ``[checks]`` sets) and ``factors``, a table of given
    factors by name (their ranges checked by the strength model)."""
    from .chain import GIVEN_FACTORS   # here: a scene without a load never reads the chain

    keys = {o.keyword: dict(kind="float", lo=o.range[0], hi=o.range[1]) if o.range else dict(kind="float", lo=0.0)
            for o in STRENGTH_OPTIONS if limits or not o.limit}
    keys["factors"] = {name: dict(kind="float") for name in sorted(GIVEN_FACTORS)}
    return keys


def options_from_table(table: dict) -> tuple[dict, dict]:
    """(the :func:`pair_strength` options of a table with :func:`scene_keys`' keys, the table's other keys): a
    given factor among the options (f_ma) joins the ``factors``."""
    options, rest = {}, {}
    for key, value in table.items():
        (options if key in _BY_KEYWORD or key == "factors" else rest)[key] = value
    factors = dict(options.pop("factors", None) or {})
    for key in [k for k in options if _BY_KEYWORD[k].factor]:
        if key in factors:
            from ...errors import GearDesignError

            raise GearDesignError(f"{key} given twice, as a key and in factors: give one")
        factors[key] = options.pop(key)
    if factors:
        options["factors"] = factors
    return options, rest
