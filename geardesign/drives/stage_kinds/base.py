"""The stage protocol: what a kind of drive stage (a bought unit, a gear pair, a chain, ...) tells the
drive, the search, the scenes and the diagram, and the registry that maps stage classes and kind
names to their :class:`StageKind`.

A stage kind is one object with these parts (defaults here fit a stage with nothing to choose):

- **ratio**: :meth:`~StageKind.ratio_span` (the ratios the stage can take) and
  :meth:`~StageKind.fixed_ratio` (the one it has when fully given);
- **search options**: :meth:`~StageKind.options` (the alternatives inside a ratio window, as
  arrays with a ``ratio`` column), :meth:`~StageKind.rows` (alternatives of equal ratio that
  multiply the designs, e.g. catalog rows);
- **margins in a batch**: :meth:`~StageKind.batch` (every margin, size and mass of many designs at
  once), or, for a kind whose options are costly (``solved = True``), :meth:`~StageKind.solve` one
  option at a time inside the branch and bound with :meth:`~StageKind.bound` below its cost
  (:meth:`~StageKind.solve_many` several at once, when :meth:`~StageKind.solve_ahead` says that
  shares work);
- **analyse**: :meth:`~StageKind.analyse` receives the flow into and out of the stage
  (:class:`StageFlow`: speed rpm, torque N·m) and returns its checks, size, mass and summary;
- **scenes**: :meth:`~StageKind.scene_keys` and :meth:`~StageKind.from_scene`;
- **diagram**: :meth:`~StageKind.draw` and :attr:`~StageKind.colour`.

``register(kind)`` adds a kind (``unregister(name)`` removes one); the drive, the search, the scenes
and the diagram find it by :func:`kind_of` (a stage object) or :func:`kind_named` (a scene's or a
summary's ``kind``).
"""
from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np

from ...errors import GearDesignError

__all__ = ["StageKind", "ToothedKind", "StageFlow", "Designs", "Batch", "register", "unregister", "kind_of", "kind_named", "kind_names",
           "kinds"]


@dataclass(frozen=True)
class StageFlow:
    """The flow through one stage: its input shaft's speed [rpm] and torque [N·m] and its output
    shaft's (n_out = n_in/u, T_out = T_in·u·η; the drive's power flow computes them)."""

    n_in_rpm: float
    torque_in_nm: float
    n_out_rpm: float
    torque_out_nm: float


@dataclass(frozen=True)
class Designs:
    """One stage's view of N designs, handed to :meth:`StageKind.batch`: ``option`` its option
    columns at each design ({column: array (N,)}), ``rows`` its row per design (or None), and the
    flow into and out of it (arrays (N,), rpm and N·m)."""

    option: dict
    rows: object
    n_in_rpm: np.ndarray
    torque_in_nm: np.ndarray
    n_out_rpm: np.ndarray
    torque_out_nm: np.ndarray


@dataclass
class Batch:
    """What :meth:`StageKind.batch` returns for N designs: ``margins`` {check: array (N,)},
    ``size_mm2`` and ``mass_kg`` (arrays (N,) or 0.0), ``info`` (the kind's own arrays, read back
    by its :meth:`~StageKind.design_columns` and :meth:`~StageKind.fix`)."""

    margins: dict
    size_mm2: object = 0.0
    mass_kg: object = 0.0
    info: object = None


class StageKind:
    """One kind of drive stage; subclass it and :func:`register` an instance.

    ``name``: the kind's name (scenes' ``kind = ...``, summaries' ``kind``); ``stage_class``: the
    dataclass of its stages (it must have ``name`` and ``efficiency``); ``colour``: its fill in the
    diagram (the checks' word; ``color``, its old name, works for one release with a DeprecationWarning);
    ``solved``: its options are solved one at a time in the branch and bound.
    """

    name: str = ""
    stage_class: type = object
    colour: str = "#d9d9d9"
    solved: bool = False
    unsolved_label: str = "margins"   # what a solved option lacks when it has no margins

    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        if "color" in cls.__dict__:   # a kind written before the rename: its colour still draws
            warnings.warn(f"stage kind {cls.__name__}: the class attribute color is deprecated, name it colour "
                          f"(one name per quantity, docs/glossary.md)", DeprecationWarning, stacklevel=2)
            if "colour" not in cls.__dict__:
                cls.colour = cls.__dict__["color"]

    @property
    def color(self) -> str:
        """The old name of :attr:`colour` (read only)."""
        warnings.warn("StageKind.color is deprecated: use colour (one name per quantity, docs/glossary.md)",
                      DeprecationWarning, stacklevel=2)
        return self.colour

    # -- ratio
    def ratio_span(self, stage) -> tuple:
        """(lowest, highest) ratio the stage can take."""
        r = self.fixed_ratio(stage)
        return (r, r)

    def fixed_ratio(self, stage) -> float:
        """The ratio of a fully given stage (``Drive.analyse`` needs it)."""
        return float(stage.ratio)

    # -- the search
    def options(self, stage, ratio_lo: float, ratio_hi: float) -> dict:
        """The stage's alternatives with a ratio in [ratio_lo, ratio_hi]: a dict of equal-length
        arrays with at least ``ratio``."""
        r = self.fixed_ratio(stage)
        ratio = np.array([r])
        return dict(ratio=ratio if ratio_lo * (1 - 1e-12) <= r <= ratio_hi * (1 + 1e-12) else ratio[:0])

    def rows(self, stage):
        """Alternatives of the same ratio that multiply every design (an int array), or None."""
        return None

    def batch(self, stage, designs) -> Batch:
        """Margins, size and mass of many designs at once (``designs``: a
        :class:`Designs` view of this stage)."""
        return Batch(margins={})

    def solve(self, stage, option: dict, objective: str, flow=None) -> dict:
        """One option solved (``solved`` kinds): dict(feasible, reason, margins, ...). ``flow``: the
        :class:`StageFlow` into the stage when :meth:`load_dependent` says the solve needs it, else None."""
        raise NotImplementedError(f"stage kind {self.name!r} solves nothing one by one")

    def solve_ahead(self, stage, objective: str) -> int:
        """How many of the walk's next groups :meth:`solve_many` should take at once, when solving options
        together shares work (the search then hands it the options it will likely need next); 0: one by one."""
        return 0

    def solve_many(self, stage, options: list, objective: str, flows: list) -> list:
        """:meth:`solve` of several options (``flows``: theirs, or Nones), in order; a kind may share
        work between them (the same solutions as one by one)."""
        return [self.solve(stage, o, objective, f) for o, f in zip(options, flows)]

    def solve_count(self) -> int:
        """How many costly solves the kind has done so far (for the optimum's count)."""
        return 0

    # -- one cache of solved work across Dask workers (geardesign.drives.spread)
    def solved_for(self, options: list) -> dict:
        """What this process has solved that :meth:`solve_many` of ``options`` may reuse, to send along
        with them to a worker ({} for a kind that keeps nothing)."""
        return {}

    def shared_by(self, option: dict):
        """What options that share solved work have in common (they go to one worker), None for nothing."""
        return None

    def solve_shared(self, stage, options: list, objective: str, flows: list, known: dict) -> tuple:
        """On a worker: :meth:`solve_many` with ``known`` (:meth:`solved_for` of the caller) reused;
        returns (solutions, what was newly solved here, for :meth:`absorb`)."""
        return self.solve_many(stage, options, objective, flows), {}

    def absorb(self, solved: dict) -> None:
        """Take what a worker newly solved into this process's cache (counted in :meth:`solve_count`)."""

    def solved_cost(self, stage, sol: dict) -> tuple:
        """(size mm², mass kg) of a feasible solved option."""
        return 0.0, 0.0

    def rank_factor(self, stage, sol: dict) -> float:
        """The factor on the size or mass of a drive with this feasible solved option when the search ranks it (the
        size and mass it reports stay as they are): 1, a preference none."""
        return 1.0

    def bound(self, stage, options: dict) -> tuple:
        """Lower bounds (size mm², mass kg) of each option whatever the solve gives (arrays)."""
        zero = np.zeros(options["ratio"].shape)
        return zero, zero

    def bound_at(self, stage, option: dict, flow) -> tuple:
        """Lower bounds (size mm², mass kg) of one option at one input flow (a load-dependent kind;
        by default its :meth:`bound`)."""
        size, mass = self.bound(stage, {k: np.atleast_1d(v) for k, v in option.items()})
        return float(size[0]), float(mass[0])

    def load_dependent(self, stage) -> bool:
        """True when a solved option depends on the flow into the stage (sized by its load)."""
        return False

    def cost_grows_with_load(self, stage) -> bool:
        """True when a solved option's cost (size and mass) only grows as the torque into the stage rises
        along the drive's power flow (its speed falling in proportion): the search then bounds the option's
        cost over a cell of torques by its cost at the cell's least torque. A kind sized by a model that
        holds this (the strength of a pair grows with √T; the speed's factors move it by a few %) says so."""
        return False

    def design_columns(self, stage, option: dict, info, c: int) -> dict:
        """The columns of design ``c`` in the optimum's table (besides ``<name>.ratio``)."""
        return {}

    def solved_columns(self, stage, sol) -> dict:
        """The columns a solved option adds to the table (``sol`` None: not solved, NaN)."""
        return {}

    def fix(self, stage, option: dict, info, c: int, objective: str, flow=None):
        """The stage with every free variable fixed at design ``c``."""
        return stage

    def resize(self, stage, fixed, option: dict, objective: str, flow, f_sh_um: float):
        """The stage sized again for a mesh misalignment f_sh (µm, at its load level F_m/b, as the strength chain
        takes it) from its shafts, larger than ``fixed`` (the stage as the search fixed it), with the stage's
        own strength options otherwise; None when the kind is not sized by its load or nothing larger holds."""
        return None

    # -- analyse
    def analyse(self, stage, flow: StageFlow, objective: str) -> dict:
        """dict(stage, margins {check: float}, size, mass, summary {name, kind, ratio, efficiency, ...})."""
        raise NotImplementedError

    # -- scenes
    def scene_keys(self) -> dict:
        """The keys of a ``[[drive.stage]]`` table of this kind besides ``kind`` and ``name``:
        name -> dict(kind=..., required=, default=, lo=, hi=, lo_open=, choices=, length=) (the
        scene schema's key kinds), or name -> dict(table=<a shared scene table>, without=(...))."""
        return {}

    def scene_spec(self, spec: dict, folder) -> dict:
        """The validated table with paths made relative to the scene's ``folder``."""
        return spec

    def from_scene(self, spec: dict):
        """The stage of a validated ``[[drive.stage]]`` table (``kind`` removed)."""
        return self.stage_class(**spec)

    # -- diagram
    wheels = False    # draws wheels on its shafts (a bought unit's box sits between them, clear of the neighbours')

    def first_offset(self, summary: dict) -> float:
        """The radius of the wheel this stage draws on its input shaft (how far right of the input block, or
        of a box before it, that shaft sits)."""
        return 0.0

    def last_offset(self, summary: dict) -> float:
        """The radius of the wheel this stage draws on its output shaft (a box after it starts beyond it)."""
        return 0.0

    def draw(self, canvas, x: float, summary: dict) -> tuple:
        """Draw the stage from shaft x (``canvas``: :class:`~geardesign.drives.diagram.Canvas`);
        (x of its output shaft, the label above it or '')."""
        canvas.box(x + 0.15, 1.3, 0.9, self.colour, f"{summary['name']}\nu = {summary['ratio']:g}")
        return x + 1.6, ""


_BY_NAME: dict = {}
_BY_CLASS: dict = {}


class ToothedKind(StageKind):
    """A kind whose stage has tooth counts z1, z2 (given, or chosen from its ``pairs``): the gear pair's and the
    chain's ratio span, fixed ratio and options."""

    def ratio_span(self, stage) -> tuple:
        if stage.z1 is not None and stage.z2 is not None:
            return (stage.z2 / stage.z1, stage.z2 / stage.z1)
        return stage.ratio_range

    def fixed_ratio(self, stage) -> float:
        if stage.z1 is None or stage.z2 is None:
            raise GearDesignError(f"analyse() needs every ratio: stage '{stage.name}' has free tooth counts "
                                  f"(give z1 and z2, or use optimize())")
        return stage.z2 / stage.z1

    def options(self, stage, ratio_lo: float, ratio_hi: float) -> dict:
        z1, z2 = stage.pairs(ratio_lo, ratio_hi)
        return dict(z1=z1, z2=z2, ratio=z2 / z1)


def register(kind: StageKind) -> StageKind:
    """Add ``kind`` (replacing a kind of the same name); returns it."""
    if not isinstance(kind, StageKind) or not kind.name or not isinstance(kind.stage_class, type):
        raise GearDesignError(f"a stage kind must be a StageKind with a name and a stage_class, got {kind!r}")
    unregister(kind.name)
    _BY_NAME[kind.name] = kind
    _BY_CLASS[kind.stage_class] = kind
    return kind


def unregister(name: str) -> None:
    """Remove the kind ``name`` (nothing when there is none)."""
    kind = _BY_NAME.pop(name, None)
    if kind is not None:
        _BY_CLASS.pop(kind.stage_class, None)


def kinds() -> tuple:
    """Every registered kind, in the order registered."""
    return tuple(_BY_NAME.values())


def kind_names() -> tuple:
    return tuple(_BY_NAME)


def kind_of(stage) -> StageKind:
    """The kind of a stage object; a GearDesignError naming the stage classes when it has none."""
    for cls in type(stage).__mro__:
        if cls in _BY_CLASS:
            return _BY_CLASS[cls]
    names = [k.stage_class.__name__ for k in _BY_NAME.values()]
    allowed = ", ".join(names[:-1]) + " or " + names[-1] if len(names) > 1 else "".join(names)
    raise GearDesignError(f"stages must be {allowed}, got {type(stage).__name__}")


def kind_named(name: str) -> StageKind:
    """The kind called ``name``."""
    if name not in _BY_NAME:
        raise GearDesignError(f"stage kind must be one of {', '.join(repr(k) for k in _BY_NAME)}, got {name!r}")
    return _BY_NAME[name]
