"""A worm gear stage (:class:`WormStage`) as a stage kind: a cylindrical worm pair of given axial module, q and
starts whose wheel's teeth the search may choose in a ratio range (z2 = u·z1), every worm check a margin in one
vectorised pass of :func:`~geardesign.gears.worm.geometry.worm_geometry`; drawn as the worm across its wheel.

The stage's efficiency enters the drive's power flow as a number. Give it (``efficiency=0.87``, a catalogue's or a
measured one), or leave it None and it comes from the function installed with :func:`set_worm_efficiency`
(``fn(pair) -> η`` of the stage's :class:`~geardesign.gears.worm.pair.WormPair`): the ISO/TS 14521 model of
``geardesign.gears.worm.efficiency`` is meant to be installed there, and a user's own model can take its place.
Without either, a stage is refused by name. A stage whose wheel's teeth are free needs a number (each choice would
have its own efficiency, and the power flow of the search holds one per stage).

With the wheel's ``casting`` the stage carries the AGMA load check (ANSI/AGMA 6034-B92 as Shigley ch. 15 prints
it, :mod:`geardesign.gears.worm.agma`) at the torque and speed its drive gives it, and ``m_x=None`` sizes it by
that load, as ``GearStage(None, material=...)`` is sized: the smallest centre distance of GOST 2144-76 (then
first-row modules of GOST 19672-74, then the smallest |x2|) whose module and q hold every worm check, the load
check included, at the stage's own torque and speed (:func:`size_worm`). Its efficiency is a number, or
``"computed"``: then the drive finds its size and its efficiency together, a bounded fixed point
(:func:`size_worm_computed`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from ...errors import GearDesignError
from ...gears import checks as _checks
from ...gears.rack import STANDARD_RACK, BasicRack, require_rack
from ...gears.worm.checks import AGMA_SAFETY_RANGE, WormLoad
from ...gears.worm.geometry import FLANK_FORMS, Q_MAX, Z1_RANGE, worm_geometry, x2_from_center_distance
from ...gears.worm.pair import WormPair
from ...results import compact_repr
from ...validate import one_number, require_choice, require_int, require_positive, require_range
from ..stages import EFFICIENCY_RANGE, _efficiency, _name, _range, disc_mass_kg, stage_area_mm2
from .base import Batch, StageKind

__all__ = ["WormStage", "WormKind", "set_worm_efficiency", "WORM_RATIO_RANGE", "size_worm", "WormSizing",
           "size_worm_computed", "SIZING_ROUNDS"]

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
    """A cylindrical worm gear stage: axial module ``m_x`` (mm; None: sized by the load, see below), diameter
    quotient ``q`` (None with ``m_x=None``: chosen with the size from the ISO 3 R10 numbers 6.3 … 25), ``z1`` starts
    and ``z2`` wheel teeth (None: chosen in ``ratio_range``), the wheel's shift ``x2`` or the centre distance ``a``
    (mm) that fixes it, the flank form and basic rack, ``efficiency`` (a number; ``"computed"``: the mesh efficiency at the
    speed its drive gives it, :meth:`at_speed`, recorded in ``efficiency_n1_rpm``; None: from
    :func:`set_worm_efficiency`'s function),
    the worm's check options ``checks`` (a dict of :func:`~geardesign.gears.checks.make_checks` options; the worm
    length check is off by default: the stage's worm is as long as its mesh needs; ``S_AGMAmin`` the load check's
    smallest safety). ``casting`` ("sand", "chill", "centrifugal": the bronze wheel's) adds the AGMA load check at
    the stage's own torque and speed, with the application factor ``application_factor`` (K_A); with it,
    ``m_x=None`` sizes the stage (:func:`size_worm`; its efficiency a number, or ``"computed"`` with z2 given:
    :func:`size_worm_computed` in the drive).

    >>> import geardesign as gd
    >>> s = gd.WormStage(m_x=4, q=12.5, z1=4, z2=50, a=125, efficiency=0.87, name="gear motor")   # seed 002's u
    >>> s.pair().x2, s.pair().geometry().u
    (0.0, 12.5)
    """

    m_x: float | None
    q: float | None
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
    casting: str | None = None
    application_factor: float = 1.0

    kind = "worm"

    __repr__ = compact_repr

    def __post_init__(self):
        if self.m_x is not None:
            object.__setattr__(self, "m_x", one_number("m_x", require_positive("m_x", self.m_x, unit="mm")))
        elif self.casting is None:
            raise GearDesignError(f"worm stage '{self.name}': m_x=None sizes the stage by its load, which needs the "
                                  "wheel's casting ('sand', 'chill' or 'centrifugal': the AGMA load check)")
        if self.q is not None:
            object.__setattr__(self, "q", one_number("q", require_range("q", self.q, 1.0, Q_MAX)))
        elif self.m_x is not None:
            raise GearDesignError(f"worm stage '{self.name}': q is needed with m_x (q=None only for a stage sized "
                                  "by its load, m_x=None)")
        if self.casting is not None:
            from ...gears.worm.agma import _casting
            _casting(self.casting)
        object.__setattr__(self, "application_factor", one_number("application_factor", require_range(
            "application_factor", self.application_factor, 1.0, 10.0)))
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
        if self.m_x is None and not isinstance(self.efficiency, (int, float)) and self.efficiency != "computed":
            raise GearDesignError(f"worm stage '{self.name}': a stage sized by its load (m_x=None) needs its "
                                  f"efficiency as a number in (0, 1] or 'computed' (sized and computed together, "
                                  f"docs/worm_rating.md), got {self.efficiency!r}")
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
            raise GearDesignError(f"worm stage '{self.name}': efficiency is needed: a number in (0, 1] or 'computed' "
                                  "(the mesh efficiency at the worm speed, docs/worm_rating.md); no default model is "
                                  "installed (geardesign.drives.stage_kinds.set_worm_efficiency)")
        else:
            object.__setattr__(self, "efficiency", _efficiency(_EFFICIENCY[0](self.pair())))

    def at_speed(self, n1_rpm: float, torque_out=None) -> "WormStage":
        """The stage with ``efficiency='computed'`` given its number: the worm-driving mesh efficiency η_z of its
        pair at the worm speed ``n1_rpm`` (:meth:`WormPair.efficiency`: the sliding speed's friction, AGMA 6034 as
        Shigley prints it; docs/worm_rating.md). A drive does this with the speed its power flow gives the stage;
        the mesh efficiency does not depend on the load, and the speeds do not depend on the efficiencies.

        A stage sized by its load (``m_x=None``) needs ``torque_out``, the wheel torque (N·m) its drive gives it
        as a function of its efficiency: it is sized and its efficiency computed together
        (:func:`size_worm_computed`), and the stage returned has its size and its efficiency."""
        if self.m_x is None:
            if torque_out is None:
                raise GearDesignError(f"worm stage '{self.name}' is sized by its load (m_x=None): its computed "
                                      "efficiency needs the torque out of it (torque_out, a function of η)")
            return size_worm_computed(self, n1_rpm, torque_out)
        eta = float(self.pair().efficiency(n1_rpm)["eta_z"])
        return replace(self, efficiency=eta, efficiency_n1_rpm=float(n1_rpm))

    @property
    def sized(self) -> bool:
        """True when the stage's module is chosen by its load (``m_x=None``)."""
        return self.m_x is None

    def load_at(self, torque_out_nm, n_in_rpm):
        """The :class:`~geardesign.gears.worm.checks.WormLoad` of the AGMA check at the wheel torque and worm speed
        (arrays allowed), or None without a ``casting``."""
        if self.casting is None:
            return None
        return WormLoad(torque_out_nm, n_in_rpm, self.casting, self.application_factor)

    def x2_for(self, z2):
        """The wheel's shift at ``z2`` teeth: the one ``a`` fixes, else the given x2."""
        return x2_from_center_distance(self.a, self.m_x, np.asarray(z2, float), self.q) if self.a is not None \
            else self.x2 + 0.0 * np.asarray(z2, float)

    def pair(self) -> WormPair:
        """The stage's :class:`WormPair` (its z2 given)."""
        if self.m_x is None:
            raise GearDesignError(f"worm stage '{self.name}' is sized by its load (m_x=None): size_worm() or the "
                                  "drive gives its pair")
        if self.z2 is None:
            raise GearDesignError(f"worm stage '{self.name}' has free wheel teeth (give z2, or use optimize())")
        return WormPair(self.m_x, self.z1, self.z2, self.q, float(self.x2_for(self.z2)), self.flank_form, self.rack)


# -- sizing by load ------------------------------------------------------------------------------------------
_CANDIDATES: dict = {}
_CANDIDATES_MAX = 256      # cached candidate sets (one per stage kind of sizing and wheel teeth)


def _geometric_checks(stage):
    return [c for c in _checks.make_checks(kind="worm", **stage.checks) if c.name != "agma_load"]


def _candidates(stage: WormStage, z2: int) -> dict:
    """The series sizes a sized stage may take with ``z2`` wheel teeth, smallest first, each holding every geometric
    check: centre distances of GOST 2144-76 (rows 1 and 2; or the stage's ``a``) × modules of GOST 19672-74 (row 1
    before row 2 at one centre distance) × q (the stage's, or the R10 defaults), x2 = a/m_x − (q + z2)/2, ordered
    by a, then the module's row, then |x2|, then the module. Cached per stage setting and z2."""
    key = (stage.z1, int(z2), stage.q, stage.a, stage.flank_form, stage.rack, tuple(sorted(stage.checks.items())))
    hit = _CANDIDATES.get(key)
    if hit is not None:
        return hit
    from ...catalogs.tables import load_catalog
    from ...gears.worm.series import default_q_values, worm_center_distance_series

    a_s = np.array([stage.a]) if stage.a is not None else worm_center_distance_series()
    frame = load_catalog("worm_modules")
    modules = frame["module_mm"].to_numpy(float)
    rows = frame["series"].to_numpy(int)
    qs = np.array([stage.q]) if stage.q is not None else default_q_values()
    A, M, Q = (g.ravel() for g in np.meshgrid(a_s, modules, qs, indexing="ij"))
    R = np.broadcast_to(rows[None, :, None], (a_s.size, modules.size, qs.size)).ravel()
    x2 = A / M - (Q + z2) / 2.0
    keep = (np.abs(x2) <= 3.0) & (Q > 2.0 * (stage.rack.ha + stage.rack.c))
    A, M, Q, R, x2 = A[keep], M[keep], Q[keep], R[keep], x2[keep]
    geo = worm_geometry(M, stage.z1, float(z2), Q, x2, stage.flank_form, stage.rack, validate=False)
    ok = (geo["d_f2"] > 0) & np.isfinite(geo["sa2"]) & (geo["eps_alpha"] > 0) & (geo["z2"] / stage.z1 >= 3.0)
    for c in _geometric_checks(stage):
        with np.errstate(all="ignore"):
            ok &= np.nan_to_num(np.asarray(c.margin(geo), float) * np.ones(A.shape), nan=-np.inf) >= -_checks.FEASIBILITY_TOL
    order = np.lexsort((M, np.abs(x2), R, A))
    order = order[ok[order]]
    geo = {k: np.asarray(v)[order] if np.ndim(v) else v for k, v in geo.items()}
    out = dict(a=A[order], m_x=M[order], q=Q[order], x2=x2[order], module_series=R[order], geo=geo)
    if len(_CANDIDATES) >= _CANDIDATES_MAX:
        _CANDIDATES.pop(next(iter(_CANDIDATES)))
    _CANDIDATES[key] = out
    return out


@dataclass(frozen=True)
class WormSizing:
    """The size :func:`size_worm` chose: ``index`` into the candidates (−1: none holds the load; then the largest
    capacity, the closest failing one, is taken), the candidate's ``m_x``, ``q``, ``a``, ``x2``, its allowable
    output torque ``T2_all`` (N·m) at the speed, the load check's ``S_AGMA`` and ``feasible``, and the next smaller
    candidate's name and failing check (``smaller``: None when it is the smallest)."""

    feasible: bool
    m_x: float
    q: float
    a: float
    x2: float
    T2_all: float
    S_AGMA: float
    smaller: tuple | None


def _chosen(stage: WormStage, cand: dict, n1, torque_out):
    """Per design: the index of the first candidate (smallest first) whose AGMA capacity carries ``torque_out``
    (N·m) at the worm speed ``n1`` (rpm) with S_AGMAmin, and its capacity; where none does, the candidate of the
    largest capacity. ``n1`` and ``torque_out`` arrays (N,); one capacity evaluation per distinct speed."""
    from ...gears.worm.agma import agma_capacity

    s_min = float(stage.checks.get("S_AGMAmin", 1.0))
    n1 = np.asarray(n1, float)
    T = np.asarray(torque_out, float)
    idx = np.zeros(T.shape, dtype=np.int64)
    cap = np.zeros(T.shape)
    if cand["a"].size == 0:
        return idx - 1, cap
    for speed in np.unique(n1):
        at = n1 == speed
        with np.errstate(all="ignore"):
            c = np.nan_to_num(agma_capacity(cand["geo"], speed, stage.casting, stage.application_factor)["T2_all"],
                              nan=0.0)
        # the first candidate i with c_i >= t is the first where the running maximum reaches t (it is monotone)
        running = np.maximum.accumulate(c)
        i = np.searchsorted(running, T[at] * s_min * (1.0 - 1e-12), side="left")
        fails = i >= c.size
        i = np.where(fails, int(np.argmax(c)), np.minimum(i, c.size - 1))
        idx[at], cap[at] = i, c[i]
    return idx, cap


def size_worm(stage: WormStage, z2: int, n1_rpm: float, torque_out_nm: float) -> WormSizing:
    """The smallest series worm pair of a sized stage (``m_x=None``) with ``z2`` wheel teeth that holds every worm
    check at the wheel torque ``torque_out_nm`` (N·m) and worm speed ``n1_rpm`` (rpm): the first of the candidates
    (GOST 2144-76 centre distances, GOST 19672-74 modules, q; smallest centre distance first, see
    :func:`_candidates`) whose geometric checks hold and whose AGMA capacity carries the load (S_AGMA >= S_AGMAmin).
    ``smaller`` names the candidate just before it and the check that fails there."""
    if stage.casting is None:
        raise GearDesignError(f"worm stage '{stage.name}': sizing by load needs the wheel's casting")
    z2 = int(require_int("z2", z2, 3, Z2_MAX))
    n1 = one_number("n1_rpm", require_positive("n1_rpm", n1_rpm, unit="rpm"))
    T = one_number("torque_out_nm", require_positive("torque_out_nm", torque_out_nm, unit="N·m"))
    cand = _candidates(stage, z2)
    if cand["a"].size == 0:
        raise GearDesignError(f"worm stage '{stage.name}': no series size with z1/z2 = {stage.z1}/{z2} holds the "
                              "geometric checks (give q, a or other check limits)")
    idx, cap = _chosen(stage, cand, np.array([n1]), np.array([T]))
    i = int(idx[0])
    s_min = float(stage.checks.get("S_AGMAmin", 1.0))
    S = float(cap[0]) / T
    feasible = S >= s_min * (1.0 - 1e-12)
    smaller = None
    if i > 0:
        j = i - 1
        smaller = (f"a {cand['a'][j]:g} mm, m_x {cand['m_x'][j]:g} mm, q {cand['q'][j]:g}", "agma_load")
    return WormSizing(feasible, float(cand["m_x"][i]), float(cand["q"][i]), float(cand["a"][i]), float(cand["x2"][i]),
                      float(cap[0]), S, smaller)


SIZING_ROUNDS = 12     # rounds of size_worm_computed's fixed point before it gives up


def size_worm_computed(stage: WormStage, n1_rpm: float, torque_out) -> WormStage:
    """A stage sized by its load (``m_x=None``) with ``efficiency='computed'``: its size and its efficiency found
    together, the size depending on the wheel torque and the torque (with the input power given) on the
    efficiency. ``torque_out(eta)`` gives the wheel torque (N·m) at the stage's efficiency η (the drive's power
    flow); ``n1_rpm`` the worm speed (the speeds do not depend on the efficiencies).

    A bounded fixed point: the first round sizes the stage (:func:`size_worm`) at η = 1, the largest torque the
    input power can give; each round then computes the mesh efficiency η_z of the size found at the stage's speed
    (:meth:`WormStage.at_speed`) and sizes again at the torque that η_z gives, until the size (a, m_x, q) is the
    one of the round before: that size carries the torque its own efficiency gives. A size seen before that is not
    the last (a cycle), or no settled size in :data:`SIZING_ROUNDS` rounds, is refused by name (give the
    efficiency as a number). Returns the stage with its size (``m_x``, ``q``, ``a``), ``efficiency`` (η_z of that
    size at ``n1_rpm``) and ``efficiency_n1_rpm``."""
    if stage.z2 is None:
        raise GearDesignError(f"worm stage '{stage.name}': efficiency='computed' needs z2 (the wheel it is "
                              "computed for)")
    if not callable(torque_out):
        raise GearDesignError(f"torque_out must be a function of the stage's efficiency, got "
                              f"{type(torque_out).__name__}")
    n1 = one_number("n1_rpm", require_positive("n1_rpm", n1_rpm, unit="rpm"))
    s_min = float(stage.checks.get("S_AGMAmin", 1.0))
    eta, seen, rated, holds = 1.0, [], None, {}
    for _ in range(SIZING_ROUNDS):
        sz = size_worm(stage, stage.z2, n1, torque_out(eta))
        size = (sz.a, sz.m_x, sz.q)
        if seen and size == seen[-1]:
            return rated
        if size in seen:
            cycle = seen[seen.index(size):]
            shown = " → ".join(f"a {a:g} mm (m_x {m:g}, q {q:g})" for a, m, q in cycle + [size])
            good = [c for c in cycle if holds[c]]
            hint = (f"; a {good[0][0]:g} mm (m_x {good[0][1]:g}, q {good[0][2]:g}) carries the torque its own "
                    f"efficiency gives: give that size with efficiency='computed', or" if good else "; give")
            raise GearDesignError(f"worm stage '{stage.name}': efficiency='computed' does not settle on one size: "
                                  f"sized by its load at its own efficiency the size cycles {shown}{hint} the "
                                  "efficiency as a number")
        seen.append(size)
        rated = replace(stage, m_x=sz.m_x, q=sz.q, a=sz.a).at_speed(n1)
        eta = rated.efficiency
        holds[size] = sz.T2_all >= s_min * torque_out(eta) * (1.0 - 1e-12)
    raise GearDesignError(f"worm stage '{stage.name}': efficiency='computed' did not settle on one size in "
                          f"{SIZING_ROUNDS} rounds (sizes a = {', '.join(f'{s[0]:g}' for s in seen)} mm); give the "
                          "efficiency as a number")


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

    def cost_grows_with_load(self, stage) -> bool:
        """A sized stage's smallest series size that carries the load grows with it (the AGMA capacity grows
        slower than the torque as the speed falls along the power flow: C_v ~ v_g^−0.571)."""
        return stage.sized

    def batch(self, stage, designs) -> Batch:
        z2 = designs.option["z2"]
        if stage.sized:
            return self._sized_batch(stage, designs)
        geo = _geometry(stage, z2)
        exists = (geo["d_f2"] > 0) & np.isfinite(geo["sa2"]) & (geo["eps_alpha"] > 0)
        load = stage.load_at(np.asarray(designs.torque_out_nm, float), np.asarray(designs.n_in_rpm, float))
        margins = {}
        for c in _checks.make_checks(kind="worm", **stage.checks, **({"worm_load": load} if load else {})):
            with np.errstate(all="ignore"):
                v = np.nan_to_num(np.asarray(c.margin(geo), float) * np.ones(z2.shape), nan=-np.inf)
            margins[c.name] = np.where(exists, v, -np.inf)
        size, mass = _size_mass(geo)
        return Batch(margins=margins, size_mm2=size, mass_kg=mass, info=dict(z2=z2, x2=np.asarray(geo["x2"])))

    def _sized_batch(self, stage, designs) -> Batch:
        """Each design's smallest series size that carries its own torque at its own speed (:func:`size_worm`,
        vectorised: one capacity evaluation per wheel and speed)."""
        z2 = np.asarray(designs.option["z2"], float)
        n = z2.size
        T = np.broadcast_to(np.asarray(designs.torque_out_nm, float), z2.shape)
        n1 = np.broadcast_to(np.asarray(designs.n_in_rpm, float), z2.shape)
        names = [c.name for c in _geometric_checks(stage)] + ["agma_load"]
        margins = {k: np.full(n, -np.inf) for k in names}
        info = {k: np.full(n, np.nan) for k in ("m_x", "q", "a", "x2")}
        size, mass = np.full(n, np.inf), np.full(n, np.inf)
        s_min = float(stage.checks.get("S_AGMAmin", 1.0))
        for zz in np.unique(z2):
            at = np.flatnonzero(z2 == zz)
            cand = _candidates(stage, int(zz))
            if cand["a"].size == 0:
                continue
            idx, cap = _chosen(stage, cand, n1[at], T[at])
            g = {k: (v[idx] if np.ndim(v) else v) for k, v in cand["geo"].items()}
            for c in _geometric_checks(stage):
                margins[c.name][at] = np.asarray(c.margin(g), float) * np.ones(at.size)
            with np.errstate(divide="ignore", invalid="ignore"):
                margins["agma_load"][at] = cap / (T[at] * s_min) - 1.0
            for k in info:
                info[k][at] = cand[k][idx]
            size[at], mass[at] = _size_mass(g)
        return Batch(margins=margins, size_mm2=size, mass_kg=mass, info=dict(z2=z2, **info))

    def design_columns(self, stage, option: dict, info, c: int) -> dict:
        p = stage.name
        out = {f"{p}.z1": stage.z1, f"{p}.z2": int(info["z2"][c]), f"{p}.x2": float(info["x2"][c])}
        if stage.sized:
            out.update({f"{p}.m_x": float(info["m_x"][c]), f"{p}.q": float(info["q"][c]), f"{p}.a": float(info["a"][c])})
        return out

    def fix(self, stage, option: dict, info, c: int, objective: str, flow=None):
        if stage.sized:
            return replace(stage, z2=int(info["z2"][c]), m_x=float(info["m_x"][c]), q=float(info["q"][c]),
                           a=float(info["a"][c]))
        return replace(stage, z2=int(info["z2"][c]))

    def analyse(self, stage, flow, objective: str) -> dict:
        """The worm pair's checks (every margin; with a casting the AGMA load check at the flow: the wheel torque
        and the worm speed), size, mass and summary; a sized stage is sized first (:func:`size_worm`)."""
        if stage.sized:
            if stage.z2 is None:
                raise GearDesignError(f"analyse() needs every ratio: worm stage '{stage.name}' has free wheel teeth "
                                      f"(give z2, or use optimize())")
            sz = size_worm(stage, stage.z2, flow.n_in_rpm, flow.torque_out_nm)
            stage = replace(stage, m_x=sz.m_x, q=sz.q, a=sz.a)
        pair = stage.pair()
        g = pair.geometry()
        load = stage.load_at(flow.torque_out_nm, flow.n_in_rpm)
        table = pair.checks(**stage.checks, **({"worm_load": load} if load else {}))
        size, mass = _size_mass(g.to_dict())
        summary = dict(name=stage.name, kind="worm", ratio=g.u, efficiency=stage.efficiency, z1=stage.z1,
                       z2=stage.z2, m_x=stage.m_x, q=stage.q, x2=pair.x2, a=g.a, gamma_m_deg=g.gamma_m_deg,
                       flank_form=stage.flank_form)
        out = dict(stage=stage, pair=pair, margins=dict(zip(table["check"], table["margin"].astype(float))),
                   size=float(size), mass=float(mass), summary=summary)
        if load is not None:
            r = pair.rating(flow.torque_out_nm, flow.n_in_rpm, casting=stage.casting,
                            application_factor=stage.application_factor,
                            minimums={"S_AGMA": float(stage.checks.get("S_AGMAmin", 1.0))})
            out["rating"] = r
            summary.update(casting=stage.casting, S_AGMA=r.S_AGMA, T2_all_nm=flow.torque_out_nm * r.S_AGMA,
                           eta_z=r.eta_z)
        return out

    # -- scenes
    def scene_keys(self) -> dict:
        f = "float"
        return {"m_x": dict(kind=f, lo=0.0, lo_open=True), "q": dict(kind=f, lo=1.0, hi=Q_MAX),
                "z1": dict(kind="int", required=True, lo=Z1_RANGE[0], hi=Z1_RANGE[1]),
                "z2": dict(kind="int", lo=3, hi=Z2_MAX), "x2": dict(kind=f, default=0.0, lo=-10.0, hi=10.0),
                "a": dict(kind=f, lo=0.0, lo_open=True),
                "ratio_range": dict(kind="floats", lo=WORM_RATIO_RANGE[0], hi=WORM_RATIO_RANGE[1], length=2),
                "efficiency": dict(kind="float_or_str", lo=EFFICIENCY_RANGE[0], hi=EFFICIENCY_RANGE[1], lo_open=True,
                                   choices=("computed",)),
                "flank_form": dict(kind="choice", default="ZA", choices=tuple(FLANK_FORMS)),
                "casting": dict(kind="choice", choices=("sand", "chill", "centrifugal")),
                "application_factor": dict(kind=f, default=1.0, lo=1.0, hi=10.0),
                "S_AGMAmin": dict(kind=f, lo=AGMA_SAFETY_RANGE[0], hi=AGMA_SAFETY_RANGE[1])}

    def from_scene(self, spec: dict):
        kw = dict(spec)
        if "ratio_range" in kw:
            kw["ratio_range"] = tuple(kw["ratio_range"])
        kw.setdefault("m_x", None)
        kw.setdefault("q", None)
        if "S_AGMAmin" in kw:
            kw["checks"] = {"S_AGMAmin": kw.pop("S_AGMAmin")}
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
                f"x2 {s['x2']:.3f}, a {s['a']:.1f} mm, γ {s['gamma_m_deg']:.2f}°"
                + (f", S_AGMA {s['S_AGMA']:.2f}" if "S_AGMA" in s else ""))
        return xc, text
