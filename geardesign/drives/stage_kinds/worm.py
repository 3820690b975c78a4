"""A worm gear stage (:class:`WormStage`) as a stage kind: a cylindrical worm pair of given axial module, q and
starts whose wheel's teeth the search may choose in a ratio range (z2 = u·z1), every worm check a margin in one
vectorised pass of :func:`~geardesign.gears.worm.geometry.worm_geometry`; drawn as the worm across its wheel.

The stage's efficiency enters the drive's power flow as a number. Give it (``efficiency=0.87``, a catalogue's or a
measured one), or leave it None and it comes from the function installed with :func:`set_worm_efficiency`
(``fn(pair) -> η`` of the stage's :class:`~geardesign.gears.worm.pair.WormPair`): the ISO/TS 14521 model of
``geardesign.gears.worm.efficiency`` is meant to be installed there, and a user's own model can take its place.
Without either, a stage is refused by name. A stage whose wheel's teeth are free needs a number (each choice would
have its own efficiency, and the power flow of the search holds one per stage).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from ...errors import GearDesignError
from ...gears import checks as _checks
from ...gears.rack import STANDARD_RACK, BasicRack, require_rack
from ...gears.worm.geometry import FLANK_FORMS, Q_MAX, Z1_RANGE, worm_geometry, x2_from_center_distance
from ...gears.worm.pair import WormPair
from ...results import compact_repr
from ...validate import one_number, require_choice, require_int, require_positive, require_range
from ..stages import EFFICIENCY_RANGE, _efficiency, _name, _range, disc_mass_kg, stage_area_mm2
from .base import Batch, StageKind

__all__ = ["WormStage", "WormKind", "set_worm_efficiency", "WORM_RATIO_RANGE"]

# the ratio span of one worm stage: 5 … 80 for power drives (issue 39: "one stage gives 5…80"), to 300 for
# indexing drives; the range a stage may ask for
WORM_RATIO_RANGE = (1.0, 300.0)
Z2_MAX = 400

_EFFICIENCY = [None]


def set_worm_efficiency(fn):
    """Install the function that gives a worm stage its efficiency when none is given: ``fn(pair) -> η`` of a
    :class:`~geardesign.gears.worm.pair.WormPair` (None removes it); returns the one installed before."""
    if fn is not None and not callable(fn):
        raise GearDesignError(f"the worm efficiency function must be callable, got {type(fn).__name__}")
    before, _EFFICIENCY[0] = _EFFICIENCY[0], fn
    return before


@dataclass(frozen=True)
class WormStage:
    """A cylindrical worm gear stage: axial module ``m_x`` (mm), diameter quotient ``q``, ``z1`` starts and ``z2``
    wheel teeth (None: chosen in ``ratio_range``), the wheel's shift ``x2`` or the centre distance ``a`` (mm) that
    fixes it, the flank form and basic rack, ``efficiency`` (a number; ``"computed"``: the mesh efficiency at the
    speed its drive gives it, :meth:`at_speed`, recorded in ``efficiency_n1_rpm``; None: from
    :func:`set_worm_efficiency`'s function),
    the worm's check options ``checks`` (a dict of :func:`~geardesign.gears.checks.make_checks` options; the worm
    length check is off by default: the stage's worm is as long as its mesh needs).

    >>> import geardesign as gd
    >>> s = gd.WormStage(m_x=4, q=12.5, z1=4, z2=50, a=125, efficiency=0.87, name="gear motor")   # seed 002's u
    >>> s.pair().x2, s.pair().geometry().u
    (0.0, 12.5)
    """

    m_x: float
    q: float
    z1: int
    z2: int | None = None
    x2: float = 0.0
    a: float | None = None
    ratio_range: tuple = (8.0, 80.0)
    efficiency: float | str | None = None
    name: str = "worm"
    flank_form: str = "ZA"
    rack: BasicRack = STANDARD_RACK
    checks: dict | None = None
    efficiency_n1_rpm: float | None = None

    kind = "worm"

    __repr__ = compact_repr

    def __post_init__(self):
        object.__setattr__(self, "m_x", one_number("m_x", require_positive("m_x", self.m_x, unit="mm")))
        object.__setattr__(self, "q", one_number("q", require_range("q", self.q, 1.0, Q_MAX)))
        object.__setattr__(self, "z1", int(require_int("z1", self.z1, *Z1_RANGE)))
        if self.z2 is not None:
            object.__setattr__(self, "z2", int(require_int("z2", self.z2, 3, Z2_MAX)))
        object.__setattr__(self, "x2", one_number("x2", require_range("x2", self.x2, -10.0, 10.0)))
        if self.a is not None:
            object.__setattr__(self, "a", one_number("a (center distance)",
                                                     require_positive("a (center distance)", self.a, unit="mm")))
        object.__setattr__(self, "ratio_range", _range("ratio_range", self.ratio_range, *WORM_RATIO_RANGE))
        object.__setattr__(self, "name", _name(self.name, "worm"))
        require_choice("flank_form", self.flank_form, FLANK_FORMS)
        object.__setattr__(self, "rack", require_rack(self.rack))
        # the worm is as long as its mesh needs (b_1 = b_1min): that check holds by construction unless asked for
        object.__setattr__(self, "checks", {"worm_length_min": False, **(self.checks or {})})
        _checks.make_checks(kind="worm", **self.checks)      # the options checked now, by name
        if isinstance(self.efficiency, str):
            if self.efficiency != "computed":
                raise GearDesignError(f"worm stage '{self.name}': efficiency must be a number in (0, 1] or "
                                      f"'computed', got {self.efficiency!r}")
            if self.z2 is None:
                raise GearDesignError(f"worm stage '{self.name}': efficiency='computed' needs z2 (the wheel it is "
                                      "computed for)")
        elif self.efficiency is not None:
            object.__setattr__(self, "efficiency", _efficiency(self.efficiency))
        elif self.z2 is None:
            raise GearDesignError(f"worm stage '{self.name}': efficiency is needed when z2 is free (each wheel would "
                                  "have its own; the drive's power flow holds one number per stage)")
        elif _EFFICIENCY[0] is None:
            raise GearDesignError(f"worm stage '{self.name}': efficiency is needed (a number in (0, 1]): no worm "
                                  "efficiency model is installed (geardesign.drives.stage_kinds.set_worm_efficiency)")
        else:
            object.__setattr__(self, "efficiency", _efficiency(_EFFICIENCY[0](self.pair())))

    def at_speed(self, n1_rpm: float) -> "WormStage":
        """The stage with ``efficiency='computed'`` given its number: the worm-driving mesh efficiency η_z of its
        pair at the worm speed ``n1_rpm`` (:meth:`WormPair.efficiency`: the sliding speed's friction, AGMA 6034 as
        Shigley prints it; docs/worm_rating.md). A drive does this with the speed its power flow gives the stage;
        the mesh efficiency does not depend on the load, and the speeds do not depend on the efficiencies."""
        eta = float(self.pair().efficiency(n1_rpm)["eta_z"])
        return replace(self, efficiency=eta, efficiency_n1_rpm=float(n1_rpm))

    def x2_for(self, z2):
        """The wheel's shift at ``z2`` teeth: the one ``a`` fixes, else the given x2."""
        return x2_from_center_distance(self.a, self.m_x, np.asarray(z2, float), self.q) if self.a is not None \
            else self.x2 + 0.0 * np.asarray(z2, float)

    def pair(self) -> WormPair:
        """The stage's :class:`WormPair` (its z2 given)."""
        if self.z2 is None:
            raise GearDesignError(f"worm stage '{self.name}' has free wheel teeth (give z2, or use optimize())")
        return WormPair(self.m_x, self.z1, self.z2, self.q, float(self.x2_for(self.z2)), self.flank_form, self.rack)


def _geometry(stage: WormStage, z2) -> dict:
    z2 = np.asarray(z2, float)
    return worm_geometry(stage.m_x, stage.z1, z2, stage.q, stage.x2_for(z2), stage.flank_form, stage.rack,
                         validate=False)


def _size_mass(geo: dict):
    size = stage_area_mm2(geo["a"], geo["d_a1"], geo["d_e2"])
    mass = disc_mass_kg(geo["d_a1"], geo["b_1"]) + disc_mass_kg(geo["d_e2"], geo["b_2"])
    return size, mass


class WormKind(StageKind):
    name = "worm"
    stage_class = WormStage
    colour = "#c7e9c0"

    def ratio_span(self, stage) -> tuple:
        if stage.z2 is not None:
            return (stage.z2 / stage.z1, stage.z2 / stage.z1)
        return stage.ratio_range

    def fixed_ratio(self, stage) -> float:
        if stage.z2 is None:
            raise GearDesignError(f"analyse() needs every ratio: worm stage '{stage.name}' has free wheel teeth "
                                  f"(give z2, or use optimize())")
        return stage.z2 / stage.z1

    def options(self, stage, ratio_lo: float, ratio_hi: float) -> dict:
        if stage.z2 is not None:
            z2 = np.array([stage.z2])
        else:
            lo = max(ratio_lo, stage.ratio_range[0]) * stage.z1
            hi = min(ratio_hi, stage.ratio_range[1]) * stage.z1
            z2 = np.arange(max(3, math.ceil(lo * (1 - 1e-12))), min(Z2_MAX, math.floor(hi * (1 + 1e-12))) + 1)
        ratio = z2 / stage.z1
        keep = (ratio >= ratio_lo * (1 - 1e-12)) & (ratio <= ratio_hi * (1 + 1e-12))
        return dict(z2=z2[keep].astype(float), ratio=ratio[keep])

    def batch(self, stage, designs) -> Batch:
        z2 = designs.option["z2"]
        geo = _geometry(stage, z2)
        exists = (geo["d_f2"] > 0) & np.isfinite(geo["sa2"]) & (geo["eps_alpha"] > 0)
        margins = {c.name: np.where(exists, np.nan_to_num(np.asarray(c.margin(geo), float) * np.ones(z2.shape),
                                                          nan=-np.inf), -np.inf)
                   for c in _checks.make_checks(kind="worm", **stage.checks)}
        size, mass = _size_mass(geo)
        return Batch(margins=margins, size_mm2=size, mass_kg=mass, info=dict(z2=z2, x2=np.asarray(geo["x2"])))

    def design_columns(self, stage, option: dict, info, c: int) -> dict:
        p = stage.name
        return {f"{p}.z1": stage.z1, f"{p}.z2": int(info["z2"][c]), f"{p}.x2": float(info["x2"][c])}

    def fix(self, stage, option: dict, info, c: int, objective: str, flow=None):
        return replace(stage, z2=int(info["z2"][c]))

    def analyse(self, stage, flow, objective: str) -> dict:
        """The worm pair's checks (every margin), size, mass and summary."""
        pair = stage.pair()
        g = pair.geometry()
        table = pair.checks(**stage.checks)
        size, mass = _size_mass(g.to_dict())
        return dict(stage=stage, pair=pair, margins=dict(zip(table["check"], table["margin"].astype(float))),
                    size=float(size), mass=float(mass),
                    summary=dict(name=stage.name, kind="worm", ratio=g.u, efficiency=stage.efficiency, z1=stage.z1,
                                 z2=stage.z2, m_x=stage.m_x, q=stage.q, x2=pair.x2, a=g.a,
                                 gamma_m_deg=g.gamma_m_deg, flank_form=stage.flank_form))

    # -- scenes
    def scene_keys(self) -> dict:
        f = "float"
        return {"m_x": dict(kind=f, required=True, lo=0.0, lo_open=True), "q": dict(kind=f, required=True, lo=1.0,
                                                                                  hi=Q_MAX),
                "z1": dict(kind="int", required=True, lo=Z1_RANGE[0], hi=Z1_RANGE[1]),
                "z2": dict(kind="int", lo=3, hi=Z2_MAX), "x2": dict(kind=f, default=0.0, lo=-10.0, hi=10.0),
                "a": dict(kind=f, lo=0.0, lo_open=True),
                "ratio_range": dict(kind="floats", lo=WORM_RATIO_RANGE[0], hi=WORM_RATIO_RANGE[1], length=2),
                "efficiency": dict(kind="float_or_str", lo=EFFICIENCY_RANGE[0], hi=EFFICIENCY_RANGE[1], lo_open=True,
                                   choices=("computed",)),
                "flank_form": dict(kind="choice", default="ZA", choices=tuple(FLANK_FORMS))}

    def from_scene(self, spec: dict):
        kw = dict(spec)
        if "ratio_range" in kw:
            kw["ratio_range"] = tuple(kw["ratio_range"])
        return WormStage(**kw)

    # -- diagram
    wheels = True

    def first_offset(self, summary: dict) -> float:
        return 0.3

    def last_offset(self, summary: dict) -> float:
        return 0.9

    def draw(self, canvas, x: float, summary: dict) -> tuple:
        """The worm (a short cylinder seen from the side, its axis on the input shaft) across the wheel's circle,
        whose centre is the output shaft."""
        s = summary
        r_worm, r_wheel = 0.3, 0.9
        xc = x + r_worm + r_wheel - 0.15           # the worm's tip reaches into the wheel: they mesh
        canvas.circle(xc, r_wheel, self.colour)
        canvas.box(x - r_worm, 2 * r_worm, 0.5, "#a1d99b", "")
        text = (f"{s['name']}: {s['flank_form']} worm, z {s['z1']}/{s['z2']}, m_x {s['m_x']:g}, q {s['q']:g}\n"
                f"x2 {s['x2']:.3f}, a {s['a']:.1f} mm, γ {s['gamma_m_deg']:.2f}°")
        return xc, text
