"""The shafts of a drive: what carries its gears, sprockets and couplings, where they sit, and the options of
the shaft, bearing and efficiency analysis (:mod:`geardesign.drives.shafting_analysis` runs it).

:class:`Shafting` switches the analysis on (``Drive(..., shafting=Shafting())``) and holds its options;
:class:`DriveShaft` describes one shaft the user has drawn (a *given* layout); every shaft that carries a gear
of the drive and is not given gets the *default layout* of :func:`default_layout`, the one a reducer designer
draws for a horizontal, unfolded parallel-axis reducer (docs/shafts_in_drive.md):

- the shafts lie in one horizontal plane, shaft k at y = Σ a_w of the stages before it (a chain's line of
  centres horizontal too, leaving in +y); the axes are x; every shaft sits in the same two housing walls,
  so each has two bearings, A at x_A and B at x_A + span;
- the gear stages sit side by side between the walls, each pair in its own plane, in the order of the power
  flow: the first one ``clearance_mm`` from bearing A (bearing centre to the gear's face), the next
  ``gear_gap_mm`` beyond the previous one's face, the last ``clearance_mm`` from bearing B; so
  span = Σ b + (N − 1)·gap + 2·clearance;
- a coupling (on the input shaft, and on the output shaft when the last stage is a gear pair) or a sprocket
  sits overhung ``overhang_mm`` beyond a bearing: what brings power in at the left end (x < x_A), what takes
  it out at the right end;
- the shaft has three diameters stepping by :data:`STEP_MM`: the ends d_b − 5 (the overhung hubs), the
  bearing seats d_b (a bearing bore of the catalog series) over ``clearance_mm``/2 each side of the
  bearing's centre, and the gear seats d_b + 5 between them; shoulders with fillets of :data:`FILLET_MM`; a gear
  whose keyed rim would be too thin is cut on the shaft (its body a section:
  :func:`geardesign.drives.shafting_analysis.cut_on_shaft`);
- a drawn shaft (:class:`DriveShaft`) sets the planes of the gears it carries and the default shafts follow.

Forces (:mod:`geardesign.gears.forces`, operating pitch circle; :mod:`geardesign.drives.chain.pull`): shaft 0
turns positive about +x, each gear mesh reverses the sense, a chain keeps it; the pinion's axial force points
toward +x (its helix hand chosen so; the wheel's toward −x), taken by bearing A (the locating bearing).
"""
from __future__ import annotations

import numbers
from dataclasses import dataclass, field

from ..errors import GearDesignError
from ..validate import one_number, require_choice, require_count, require_range

__all__ = ["Shafting", "DriveShaft", "STEP_MM", "FILLET_MM", "PEAK_FACTOR", "SHAFT_LIFE_H", "BEARING_SERIES",
           "SHAFT_BEARING_TYPES", "ARRANGEMENTS", "default_positions", "series_of_type"]

STEP_MM = 5.0          # diameter step between the ends, the bearing seats and the gear seats (shoulder 2.5 mm)
FILLET_MM = 1.0        # the shoulders' fillet radius
PEAK_FACTOR = 2.0      # maximum/nominal load of DIN 743's static proof (a motor's starting torque): a choice
SHAFT_LIFE_H = 20_000.0   # required bearing life, h (a reducer in one-shift service for about 10 years)
# the bearings a reducer designer reaches for: deep groove ball bearings (light and medium series), and cylindrical
# roller bearings where the radial load is heavy and there is no axial force (the selection takes the smallest
# outside diameter that carries the load; a type NU bearing is refused where an axial force acts)
BEARING_SERIES = ("62", "63", "NU2", "NU3")
# the bearing types a drive's shaft can be given (Shafting.bearing_type), as the catalogs' types
# (geardesign.drives.bearing.BEARING_TYPES); "auto" chooses (docs/shafts_in_drive.md): a deep groove ball bearing
# (or a cylindrical roller bearing where no axial force acts) on the seat when one reaches the life, else a pair of
# tapered roller bearings on the seat, else the same at the next bore up. Single angular contact ball bearings
# are not offered: mounted in pairs they take induced axial loads whose factor the catalog rows do not give.
SHAFT_BEARING_TYPES = ("auto", "deep_groove", "cylindrical_roller", "tapered")
# a tapered pair's mounting: "X" face to face (each cup held by the housing's cover on its outer side: an axial
# force on the shaft is taken by the bearing it points to), "O" back to back (by the other one)
ARRANGEMENTS = ("X", "O")


def series_of_type(bearing_type: str, series=None) -> tuple:
    """The catalog series (:data:`geardesign.drives.bearing.SERIES`) of a shaft bearing type (one of
    :data:`SHAFT_BEARING_TYPES` but "auto"), those of ``series`` alone when given.

    >>> series_of_type("tapered")
    ('302', '303', '320X', '322', '323')
    >>> series_of_type("deep_groove", ("62", "NU2"))
    ('62',)
    """
    from .bearing import BEARING_TYPES, SERIES

    kind = BEARING_TYPES[bearing_type]
    return tuple(s for s, (_, k) in SERIES.items() if k == kind and (series is None or s in series))


@dataclass(frozen=True)
class DriveShaft:
    """A shaft of the drive as the user drew it: shaft ``at`` (0: input, k: output of stage k); ``sections``
    (length_mm, d_mm[, bore_mm]) from its left end x = 0; ``supports_mm`` the two bearing positions (the first
    the locating one); ``positions`` {stage name or "coupling": x_mm} of every element it carries (a gear
    stage's pinion or wheel, a chain stage's sprocket, the coupling at the drive's input or output);
    ``widths`` {name: hub length mm} for the key checks (default: a gear's face width, 1.5·d for a hub);
    ``bearings`` the two bearings' catalog designations (None: chosen from the series for the seat and the
    life); ``material`` (None: the Shafting's).

    >>> DriveShaft(1, ((200.0, 40.0),), (20.0, 180.0), {"fast": 60.0, "slow": 130.0}).at
    1
    """

    at: int
    sections: tuple
    supports_mm: tuple
    positions: dict
    widths: dict | None = None
    bearings: tuple | None = None
    material: object = None

    def __post_init__(self):
        object.__setattr__(self, "at", require_count("at (shaft number)", self.at, 0, 64))
        from .shaft_beam import ShaftModel

        model = ShaftModel(self.sections, self.supports_mm)    # sections and supports checked there
        if len(model.supports_mm) != 2:
            raise GearDesignError(f"shaft {self.at}: supports_mm must give the two bearing positions, got "
                                  f"{list(self.supports_mm)}")
        object.__setattr__(self, "sections", model.sections)
        object.__setattr__(self, "supports_mm", model.supports_mm)
        if not isinstance(self.positions, dict) or not self.positions:
            raise GearDesignError(f"shaft {self.at}: positions must be a dict {{stage name or 'coupling': x_mm}}, "
                                  f"got {self.positions!r}")
        pos = {}
        for name, x in self.positions.items():
            pos[str(name)] = float(one_number(f"shaft {self.at} position of {name!r}", require_range(
                f"shaft {self.at} position of {name!r}", x, 0.0, model.length_mm, unit="mm")))
        object.__setattr__(self, "positions", pos)
        widths = {}
        for name, w in (self.widths or {}).items():
            widths[str(name)] = float(one_number(f"shaft {self.at} width of {name!r}", require_range(
                f"shaft {self.at} width of {name!r}", w, 0.0, 1e4, lo_open=True, unit="mm")))
        object.__setattr__(self, "widths", widths)
        if self.bearings is not None:
            b = tuple(self.bearings)
            if len(b) != 2 or not all(isinstance(v, str) for v in b):
                raise GearDesignError(f"shaft {self.at}: bearings must be two catalog designations, got "
                                      f"{self.bearings!r}")
            object.__setattr__(self, "bearings", b)
        if self.material is not None:
            from .din743 import _material

            _material(self.material)      # an unknown steel is refused here, by name

    @property
    def length_mm(self) -> float:
        return float(sum(s[0] for s in self.sections))


@dataclass(frozen=True)
class Shafting:
    """Options of the drive's shafts, bearings and computed efficiencies (the default layout: module docstring).

    ``layout``: :class:`DriveShaft` items for the shafts the user draws (the others get the default layout);
    ``material``: the shafts' steel (a name of ``catalogs/shaft_materials_din743.csv`` or a dict, DIN 743-3);
    ``S_min``: the least DIN 743 safety (fatigue and static, DIN 743-1 clause 4.1: 1.2); ``peak_factor``: the
    maximum load of the static proof over the nominal one; ``life_h``: the required bearing life L10h (h),
    ``reliability`` (%, a1); ``bearing_type``: the shafts' bearings, one of :data:`SHAFT_BEARING_TYPES` for every
    shaft or a dict {shaft k: type} (a shaft it does not name: "auto"); "auto" takes deep groove ball bearings (or
    cylindrical roller bearings where no axial force acts) on the seat when one reaches the life, else a pair of
    tapered roller bearings on it, else the same at the next bore up (docs/shafts_in_drive.md); ``arrangement``: a
    tapered pair's mounting, "X" (face to face) or "O" (back to back); ``bearing_series``: the catalog series the
    bearings may be chosen from (None: every series of the types in use; the smallest bearing of the least bore
    that fits the seat and reaches the life is taken); ``clearance_mm``, ``gear_gap_mm``,
    ``overhang_mm``: the default layout's lengths; ``lubricant`` (a :class:`~geardesign.gears.efficiency.Lubricant`)
    with ``oil_temperature_c``, ``Ra_um`` and ``lubrication``: the gear stages' efficiencies computed (ISO/TR
    14179-2 mesh loss, SKF bearing friction) and used in the power flow where the stage's efficiency was not
    given (None: the stages' efficiencies as they are); ``no_load_loss_w``: a churning loss per gear stage;
    ``stiff``: how stiff the default shafts are made: False, as DIN 743, the keys and the bearings size them (K_Hβ
    takes the f_sh they give); "gears" (the default), besides that a gear pair that fails a check with K_Hβ from its
    shafts gets them one or two bores thicker where that makes it hold
    (:func:`~geardesign.drives.shafting_analysis.stiffened_for_gears`); True, thickened until the mesh misalignment
    f_sh of each gear pair is at most ISO 6336-1 eq. (44)'s estimate, the one the gear's strength (and a stage sized
    by its load) assumed (eq. (44) models a pinion shaft alone, and an intermediate shaft whose wheel sits beside a
    heavily loaded pinion tilts far more: True can ask for shafts thicker than the pinion,
    docs/shafts_in_drive.md); ``min_bore_mm``: {shaft k: mm}, the least bearing
    bore of a default shaft (the search keeps a re-sized design's shafts at least as thick as before).
    """

    layout: tuple = ()
    material: object = "42CrMo4"
    S_min: float = 1.2
    peak_factor: float = PEAK_FACTOR
    life_h: float = SHAFT_LIFE_H
    reliability: float = 90.0
    bearing_series: object = None
    bearing_type: object = "auto"
    arrangement: str = "X"
    clearance_mm: float = 20.0
    gear_gap_mm: float = 10.0
    overhang_mm: float = 60.0
    lubricant: object = None
    oil_temperature_c: float = 70.0
    Ra_um: float = 0.5
    lubrication: str = "oil_bath"
    no_load_loss_w: float = 0.0
    stiff: object = "gears"
    min_bore_mm: object = None
    _material: dict = field(default=None, init=False, repr=False, compare=False)

    def __post_init__(self):
        from .bearing import SERIES, reliability_factor
        from .din743 import _material

        layout = tuple(self.layout or ())
        for s in layout:
            if not isinstance(s, DriveShaft):
                raise GearDesignError(f"layout must hold DriveShaft items, got {type(s).__name__}")
        ats = [s.at for s in layout]
        if len(set(ats)) != len(ats):
            raise GearDesignError(f"layout gives shaft(s) {sorted({a for a in ats if ats.count(a) > 1})} twice")
        object.__setattr__(self, "layout", layout)
        object.__setattr__(self, "_material", _material(self.material))
        object.__setattr__(self, "S_min", one_number("S_min", require_range("S_min", self.S_min, 0.5, 10.0)))
        object.__setattr__(self, "peak_factor", one_number("peak_factor", require_range(
            "peak_factor", self.peak_factor, 1.0, 10.0)))
        object.__setattr__(self, "life_h", one_number("life_h", require_range(
            "life_h", self.life_h, 0.0, 1e7, lo_open=True, unit="h")))
        reliability_factor(self.reliability)
        if self.bearing_series is not None:
            series = (self.bearing_series,) if isinstance(self.bearing_series, str) else tuple(self.bearing_series)
            if not series:
                raise GearDesignError(f"bearing_series must name one of {', '.join(SERIES)}")
            for s in series:
                require_choice("bearing_series", s, tuple(SERIES))
            object.__setattr__(self, "bearing_series", series[0] if len(series) == 1 else series)
        types = self.bearing_type
        if isinstance(types, dict):
            checked = {}
            for k, t in types.items():
                k = require_count("bearing_type's shaft number", k, 0, 64)
                checked[k] = require_choice(f"bearing_type of shaft {k}", t, SHAFT_BEARING_TYPES)
            types = checked
        else:
            require_choice("bearing_type", types, SHAFT_BEARING_TYPES)
        object.__setattr__(self, "bearing_type", types)
        for t in set(types.values()) if isinstance(types, dict) else {types}:
            if not self.series_for(t):
                kinds = SHAFT_BEARING_TYPES[1:] if t == "auto" else (t,)
                raise GearDesignError(f"bearing_series {', '.join(self.series)} holds no series of bearing type "
                                      f"{t!r} (its series: {', '.join(s for k in kinds for s in series_of_type(k))})")
        require_choice("arrangement", self.arrangement, ARRANGEMENTS)
        for name, lo, hi in (("clearance_mm", 5.0, 500.0), ("gear_gap_mm", 0.0, 500.0), ("overhang_mm", 10.0, 2000.0)):
            object.__setattr__(self, name, one_number(name, require_range(name, getattr(self, name), lo, hi,
                                                                          unit="mm")))
        if self.lubricant is not None:
            from ..gears.efficiency import Lubricant

            if not isinstance(self.lubricant, Lubricant):
                raise GearDesignError(f"lubricant must be a geardesign Lubricant (nu40, nu100), got {self.lubricant!r}")
        object.__setattr__(self, "oil_temperature_c", one_number("oil_temperature_c", require_range(
            "oil_temperature_c", self.oil_temperature_c, -40.0, 200.0, unit="°C")))
        object.__setattr__(self, "Ra_um", one_number("Ra_um", require_range("Ra_um", self.Ra_um, 0.01, 10.0,
                                                                            unit="µm")))
        from .bearing_friction import K_RS

        require_choice("lubrication", self.lubrication, tuple(K_RS))
        from ..validate import require_bool

        if self.stiff != "gears":
            object.__setattr__(self, "stiff", require_bool("stiff", self.stiff))
        object.__setattr__(self, "min_bore_mm", _min_bores(self.min_bore_mm))
        object.__setattr__(self, "no_load_loss_w", one_number("no_load_loss_w", require_range(
            "no_load_loss_w", self.no_load_loss_w, 0.0, 1e9, unit="W")))

    @property
    def series(self) -> tuple:
        """The series the bearings may be chosen from (the given ones, else every series of the types in use)."""
        if self.bearing_series is None:
            types = set(self.bearing_type.values()) | {"auto"} if isinstance(self.bearing_type, dict) \
                else {self.bearing_type}
            return tuple(dict.fromkeys(s for t in SHAFT_BEARING_TYPES if t in types for s in self.series_for(t)))
        return (self.bearing_series,) if isinstance(self.bearing_series, str) else tuple(self.bearing_series)

    def type_of(self, at: int) -> str:
        """The bearing type of shaft ``at`` (one of :data:`SHAFT_BEARING_TYPES`)."""
        if isinstance(self.bearing_type, dict):
            return self.bearing_type.get(at, "auto")
        return self.bearing_type

    def series_for(self, bearing_type: str) -> tuple:
        """The series a bearing type chooses from, in the order "auto" tries them (the radial ones, then the tapered
        ones), restricted to ``bearing_series`` when given."""
        given = None if self.bearing_series is None else (
            (self.bearing_series,) if isinstance(self.bearing_series, str) else tuple(self.bearing_series))
        kinds = ("deep_groove", "cylindrical_roller", "tapered") if bearing_type == "auto" else (bearing_type,)
        return tuple(s for t in kinds for s in series_of_type(t, given))

    def given(self, at: int):
        """The DriveShaft the user gave for shaft ``at``, or None."""
        return next((s for s in self.layout if s.at == at), None)


def thicker_bores(bores: dict, more: dict) -> dict:
    """{shaft: least bore} of ``bores`` and ``more`` together, each shaft's larger (a least bore only grows).

    >>> thicker_bores({0: 30.0, 1: 40.0}, {1: 35.0, 2: 50.0})
    {0: 30.0, 1: 40.0, 2: 50.0}
    """
    return {**bores, **{k: max(d, bores.get(k, 0.0)) for k, d in more.items()}}


def _min_bores(given) -> dict:
    """``min_bore_mm`` checked by name: None or {shaft k >= 0: a bore in mm}."""
    if given is None:
        return {}
    if not isinstance(given, dict):
        raise GearDesignError(f"min_bore_mm must be a dict {{shaft: bore mm}}, got {type(given).__name__}")
    out = {}
    for k, d in given.items():
        if isinstance(k, bool) or not isinstance(k, numbers.Integral) or k < 0:
            raise GearDesignError(f"min_bore_mm: a shaft is a whole number >= 0, got {k!r}")
        out[int(k)] = one_number(f"min_bore_mm[{k}]", require_range(f"min_bore_mm[{k}]", d, 0.0, 2000.0,
                                                                      lo_open=True, unit="mm"))
    return out


def default_positions(widths: list, clearance_mm: float, gap_mm: float) -> tuple:
    """(plane positions from bearing A, span) of gear planes of face widths ``widths`` (mm) side by side between
    two bearings: the first plane clearance + b1/2 from A, each next gap + (b_prev + b)/2 further, B clearance +
    b_last/2 beyond the last; span = Σb + (N − 1)·gap + 2·clearance.

    >>> default_positions([40.0, 60.0], 20.0, 10.0)
    ([40.0, 100.0], 150.0)
    """
    xs, x = [], clearance_mm
    for i, b in enumerate(widths):
        x += (gap_mm if i else 0.0) + b / 2.0
        xs.append(x)
        x += b / 2.0
    return xs, x + clearance_mm
