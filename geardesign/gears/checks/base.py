"""The check base class, the option each check is switched and limited by, and the registry.

A check is a named constraint with a signed, dimensionless margin (>= 0 where it holds). Each
built-in check class declares once, as class attributes, everything the rest of the package
needs to know about it:

* ``option`` — the :class:`Option` that turns it on or sets its limit (its keyword in
  :func:`make_checks`, its default, allowed range, help text, source, whether sweeps may vary it);
  several classes may share one option (``undercut`` builds one check per gear);
* ``pair_kinds`` — built for ``"external"`` pairs, ``"internal"`` (ring) pairs, or both;
* ``per_gear`` — the gears it is built for by kind (a check of the whole mesh: ``None``);
* ``colour`` — its colour in every plot (gear 2 drawn dashed);
* ``order`` — its place in the list :func:`make_checks` returns.

:func:`register` adds a class to the registry; :func:`make_checks`, the CLI's limit options, the
scene schema, the contour colours and the sweeps read it, so a new built-in check is one class
in one module (see docs/extending.md).
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass
import numpy as np

from ...errors import GearDesignError
from ...validate import _show, one_number, require_bool, require_range

__all__ = ["Check", "Option", "register", "registered", "options", "option", "make_checks", "resolve_checks",
           "evaluate", "margins", "check_colour", "registry_version", "unregister", "register_context", "FEASIBILITY_TOL", "UNDEFINED", "CONTEXT_KEYWORDS"]

# A margin >= −FEASIBILITY_TOL holds. The solvers land on a boundary to rounding (|margin| ~ 1e-15);
# the result, the check table and ok() then agree on such a point (issue 29 §2): one tolerance, here.
FEASIBILITY_TOL = 1e-12
# The kinds of pair a check class may be built for (its ``pair_kinds``).
PAIR_KINDS = ("external", "internal", "worm")


@dataclass(frozen=True)
class Option:
    """One keyword of :func:`make_checks`: what it sets, its default, range and source.

    ``kind`` is ``"limit"`` (a number, ``None`` drops the checks) or ``"flag"`` (True/False).
    ``sweep``: :func:`geardesign.sweep` may vary it. ``cli``: the commands expose it as
    ``--name-with-dashes`` (a limit) or ``--name``/``--no-name`` (a flag).
    """

    name: str
    kind: str
    default: object
    help: str
    source: str = ""
    range: tuple | None = None
    sweep: bool = False
    cli: bool = True

    def value(self, given):
        """The validated value of this option (``given``), as make_checks uses it."""
        if self.kind == "flag":
            return require_bool(self.name, given)
        if given is None:
            return None
        return one_number(self.name, require_range(self.name, given, *self.range))


@dataclass(frozen=True)
class Check:
    """Base of all checks: a name, a readable label and a limit."""

    name: str = ""
    label: str = ""
    limit: float = 0.0

    # registry attributes (see the module docstring); a check outside the registry leaves them
    option = None
    pair_kinds = ("external", "internal")
    per_gear = None            # e.g. {"external": (1, 2), "internal": (1,)}
    colour = None
    order = 1000

    # True for checks that read fields only reports need (geometry.REPORT_FIELDS): the solvers
    # then compute the full geometry
    needs_report_fields = False
    # True for checks whose gradients are central differences (~1e-10 noise): the solvers then loosen
    # the tolerances that would chase it
    fd_gradient = False
    # True for checks that cost far more than the geometry (the ISO 6336 chain): the solvers then evaluate
    # them only where a decision reads them, and walk on a quadratic model of them (``modelled_at``)
    costly = False

    @classmethod
    def build(cls, value, context: dict) -> list:
        """The checks this class adds for its option's ``value`` (a limit, or True) in ``context``
        (``internal``, ``cutter``, and what higher layers pass)."""
        kind = context.get("kind") or ("internal" if context["internal"] else "external")
        limit = {} if cls.option is None or cls.option.kind == "flag" else {"limit": value}
        if cls.per_gear is None:
            return [cls(**limit)]
        return [cls(gear=j, **limit) for j in cls.per_gear[kind]]

    def value(self, geo: dict):
        raise NotImplementedError

    def limit_value(self, geo: dict):
        return self.limit

    def margin(self, geo: dict):
        return self.value(geo) - self.limit_value(geo)

    def gradient(self, geo: dict):
        raise NotImplementedError

    # The optimisers see each check as smooth parts whose minimum is its margin (one part
    # for most checks); a kink of the margin then becomes a corner between two parts.
    n_parts = 1

    def part_margins(self, geo: dict) -> list:
        return [self.margin(geo)]

    def part_gradients(self, geo: dict) -> list:
        return [self.gradient(geo)]

    def modelled_at(self, geo: dict) -> "Check":
        """A cheap stand-in of a ``costly`` check: the same check on a quadratic model of its values around
        the one design of ``geo`` (the check itself for a check that is not costly)."""
        return self


_REGISTRY: list[type] = []
_VERSION = [0]   # bumped by register: the cached defaults and option table follow it


def register(cls: type) -> type:
    """Class decorator: add a :class:`Check` subclass with an ``option`` to the registry."""
    if not (isinstance(cls, type) and issubclass(cls, Check)) or not isinstance(cls.option, Option):
        raise GearDesignError(f"register takes a Check subclass with an Option, got {_show(cls)}")
    known = options()
    if cls.option.name in known and known[cls.option.name] != cls.option:
        raise GearDesignError(f"option {cls.option.name!r} is declared twice, differently")
    if cls not in _REGISTRY:
        _REGISTRY.append(cls)
        _REGISTRY.sort(key=lambda c: c.order)
        _VERSION[0] += 1
    return cls


def unregister(cls: type) -> None:
    """Remove ``cls`` from the registry (tests that register a check of their own clean up with it)."""
    if cls in _REGISTRY:
        _REGISTRY.remove(cls)
        _VERSION[0] += 1


def registry_version() -> int:
    """A number that changes whenever the registry does: caches of what is built from it key on it."""
    return _VERSION[0]


def registered() -> tuple[type, ...]:
    """The registered check classes in the order :func:`make_checks` builds them."""
    return tuple(_REGISTRY)


def options() -> dict[str, Option]:
    """Every :func:`make_checks` option by name, in registry order."""
    out = {}
    for cls in _REGISTRY:
        out.setdefault(cls.option.name, cls.option)
    return out


def option(name: str) -> Option:
    """The :class:`Option` called ``name``."""
    table = options()
    if name not in table:
        raise GearDesignError(f"unknown check option {name!r}; allowed: {', '.join(table)}")
    return table[name]


def check_colour(name: str):
    """The colour of the check called ``name`` in every plot, or None for a check nobody coloured:
    a registered class's (matched by the names it builds), else one whose ``kind_name`` is ``name``
    with its gear digit stripped (checks outside the registry: the housing's, a planetary set's)."""
    kind = name.rstrip("12")
    for cls in _REGISTRY:
        if cls.colour is not None and _check_names(cls).intersection({name, kind}):
            return cls.colour
    stack = list(Check.__subclasses__())
    while stack:
        cls = stack.pop()
        stack += cls.__subclasses__()
        if cls.colour is not None and getattr(cls, "kind_name", None) in (name, kind):
            return cls.colour
    return None


@functools.cache
def _names_cached(cls: type, version: int) -> frozenset:
    names = set()
    for kind in cls.pair_kinds:
        value = True if cls.option.kind == "flag" else (cls.option.default if cls.option.default is not None
                                                        else cls.option.range[0])
        names |= {c.name for c in cls.build(value, _context(internal=kind == "internal", kind=kind))}
    return frozenset(names | {n.rstrip("12") for n in names})


def _check_names(cls: type) -> frozenset:
    return _names_cached(cls, _VERSION[0])


# keywords of make_checks that are not options of one check: what the checks are built for (a load
# model adds its own with register_context)
CONTEXT_KEYWORDS = ["internal", "cutter", "extra"]
_CONTEXT_BUILDERS: list = []


def register_context(keywords, builder) -> None:
    """Let :func:`make_checks` take ``keywords`` (a load case, say) and hand them to the checks' ``build``:
    ``builder(context) -> dict`` adds what the checks read (the strength checks' load case)."""
    CONTEXT_KEYWORDS.extend(k for k in keywords if k not in CONTEXT_KEYWORDS)
    if builder not in _CONTEXT_BUILDERS:
        _CONTEXT_BUILDERS.append(builder)


def _context(internal=False, cutter=None, **more) -> dict:
    context = {"internal": internal, "cutter": cutter, **more}
    for builder in _CONTEXT_BUILDERS:
        context.update(builder(context))
    return context


def make_checks(*, internal: bool = False, cutter=None, extra=(), kind: str | None = None,
                **opts) -> tuple[Check, ...]:
    """The checks a case asks for: each registered check whose option is on (defaults: no
    undercut, no interference, s_a >= 0.25·m, ε_α >= 1.2; a ring pair's own checks).

    ``opts`` are the registered options (:func:`options`): a limit set to ``None`` or a flag set to
    ``False`` drops its checks. ``internal``: the checks of a ring pair; ``cutter`` the
    :class:`~geardesign.gears.ring.ShaperCutter` of the ring checks (standard size for the module
    by default); ``extra`` adds :class:`Check` objects (e.g. a
    :class:`~geardesign.gears.checks.external.CustomCheck`). ``kind`` names the pair kind whose checks are built
    where it is neither "external" nor "internal" (``"worm"``: :mod:`geardesign.gears.worm.checks`).

    >>> [c.name for c in make_checks(sa_min=0.4, undercut=False)]
    ['interference1', 'interference2', 'tip_thickness1', 'tip_thickness2', 'contact_ratio']
    >>> [c.name for c in make_checks(internal=True)][:6]
    ['undercut1', 'interference1', 'interference2', 'ring_tip', 'tip_interference', 'cutter_trimming']
    """
    require_bool("internal", internal)
    known = options()
    more = {k: opts.pop(k) for k in list(opts) if k in CONTEXT_KEYWORDS}
    unknown = sorted(set(opts) - set(known))
    if unknown:
        raise GearDesignError(f"checks: unknown option {', '.join(map(repr, unknown))}; allowed: "
                              f"{', '.join(list(known) + list(CONTEXT_KEYWORDS))}")
    values = {name: opt.value(opts.get(name, opt.default)) for name, opt in known.items()}
    if kind is not None and kind not in PAIR_KINDS:
        raise GearDesignError(f"kind must be one of {list(PAIR_KINDS)} or None, got {_show(kind)}")
    kind = kind or ("internal" if internal else "external")
    context = _context(internal=internal, cutter=cutter, kind=kind, **more)
    out: list[Check] = []
    for cls in _REGISTRY:
        value = values[cls.option.name]
        if kind in cls.pair_kinds and value is not None and value is not False:
            out += cls.build(value, context)
    out += _extra_checks(extra)
    names = [c.name for c in out]
    dup = {n for n in names if names.count(n) > 1}
    if dup:
        raise GearDesignError(f"check names must be unique, got duplicates {sorted(dup)}")
    return tuple(out)


def _extra_checks(extra) -> list:
    if isinstance(extra, Check):
        extra = (extra,)
    if not isinstance(extra, (list, tuple)):
        raise GearDesignError(f"extra must be a list of geardesign.gears.checks.Check objects, got {_show(extra)}")
    for c in extra:
        if not isinstance(c, Check):
            raise GearDesignError(f"extra checks must be geardesign.gears.checks.Check objects, got {_show(c)}")
    return list(extra)


@functools.cache
def _defaults(internal: bool, version: int) -> tuple:
    return make_checks(internal=internal)


def resolve_checks(checks, internal: bool = False) -> tuple[Check, ...]:
    """Accept None (defaults), a dict of :func:`make_checks` keywords, or a sequence of Checks;
    ``internal`` picks the ring pair's checks where the caller leaves the choice to the defaults."""
    if checks is None:
        return _defaults(bool(internal), _VERSION[0])
    if isinstance(checks, dict):
        return make_checks(**{"internal": internal, **checks})
    if isinstance(checks, (str, bytes, Check)) or not hasattr(checks, "__iter__"):
        raise GearDesignError(f"checks must be None, a dict of make_checks options or a list of Check objects, "
                              f"got {_show(checks)}")
    try:
        checks = tuple(checks)
    except TypeError:    # a 0-d array has __iter__ but does not iterate
        raise GearDesignError(f"checks must be None, a dict of make_checks options or a list of Check objects, "
                              f"got {_show(checks)}") from None
    for c in checks:
        if not isinstance(c, Check):
            raise GearDesignError(f"checks must be Check objects, got {_show(c)}")
    return checks


@functools.cache
def _check_table_class():
    """CheckTable, built on first use: pandas is imported only when a table is asked for."""
    import pandas as pd

    class CheckTable(pd.DataFrame):
        """The checks of one design, a DataFrame whose printout leaves out the long ``label``
        column, so that check, margin and ok fit a plain terminal (the labels stay in the frame)."""

        @property
        def _constructor(self):
            return CheckTable

        def __repr__(self) -> str:
            cols = [c for c in self.columns if c != "label"]
            text = pd.DataFrame(self[cols]).to_string(float_format=lambda v: f"{v:.6g}")
            return text + ("\n(each check's meaning: the 'label' column)" if "label" in self.columns else "")

    return CheckTable


UNDEFINED = " (undefined for this design: a quantity the check needs does not exist here, so it fails)"


def evaluate(geo: dict, checks):
    """Rows ``check, label, value, limit, margin, ok`` for one design (geo of 0-d arrays). A
    margin that does not exist (NaN: e.g. no cutter–ring mesh at this ring shift) is −inf, a
    failing check, and its label says so, as :func:`margins` treats it in the solvers. A margin
    within :data:`FEASIBILITY_TOL` of zero holds."""
    rows = []
    for c in checks:
        value = float(np.asarray(c.value(geo)))
        limit = float(np.asarray(c.limit_value(geo)))
        margin = float(np.asarray(c.margin(geo)))
        label = c.label
        if math.isnan(margin):
            margin, label = -math.inf, label + UNDEFINED
        rows.append((c.name, label, value, limit, margin, bool(margin >= -FEASIBILITY_TOL)))
    return _check_table_class()(rows, columns=["check", "label", "value", "limit", "margin", "ok"])


def margins(geo: dict, checks) -> dict[str, np.ndarray]:
    """Margin arrays by check name; NaN geometry (designs that do not exist) gives −inf."""
    out = {}
    for c in checks:
        out[c.name] = np.fmax(c.margin(geo), -np.inf)   # fmax passes the number where one is NaN
    return out

