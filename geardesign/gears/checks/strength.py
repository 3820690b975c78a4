"""Load capacity as checks (ISO 6336): the contact safety S_H >= S_Hmin and each gear's root safety
S_F >= S_Fmin, built when :func:`~geardesign.gears.checks.make_checks` is given a load.

The load and what the chain needs besides the geometry travel in the context of ``make_checks`` (and so
in a ``checks`` dict of every solver, region, atlas and tooth-count search): ``load`` (a
:class:`~geardesign.gears.strength.Load`), ``material`` (and ``material2``), ``face_width_mm`` (default:
the pair's face width) and ``strength`` (a dict of :func:`~geardesign.gears.strength.pair_strength`
options: accuracy grade, lubricant, roughness, given factors, root method, ...). The safety factors come
from the vectorised chain evaluated on the solver's own geometry; their gradients in (x1, x2) are central
differences of the chain, evaluated with the design in the same vectorised call (five designs for the
price of about one). Margins S/S_min − 1. The checks are ``costly`` (see Check.costly): the solvers evaluate
them only where a decision reads them, and walk on their quadratic model (:meth:`StrengthSpec.model`) where
they would otherwise call the chain hundreds of times.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass, replace

import numpy as np

from ...errors import GearDesignError
from ...validate import one_number, require_range
from ..geometry import mesh_geometry, mesh_geometry_float
from ..strength.defaults import FACE_WIDTH_RANGE_MM, MIN_SAFETY_SOURCE, S_FMIN, S_HMIN
from .base import Check, Option, register, register_context

__all__ = ["StrengthSpec", "StrengthModel", "ContactStrength", "RootStrength", "strength_spec", "STRENGTH_CONTEXT", "SAFETY_RANGE"]

SAFETY_RANGE = (0.5, 10.0)
CONTACT_SAFETY = Option("S_Hmin", "limit", S_HMIN, "smallest contact (pitting) safety factor S_H, with a load",
                        source=MIN_SAFETY_SOURCE, range=SAFETY_RANGE, sweep=True)
ROOT_SAFETY = Option("S_Fmin", "limit", S_FMIN, "smallest tooth-root (bending) safety factor S_F, with a load",
                     source=MIN_SAFETY_SOURCE, range=SAFETY_RANGE, sweep=True)
# the keywords of make_checks that describe the load case (they switch the strength checks on)
STRENGTH_CONTEXT = ("load", "material", "material2", "face_width_mm", "strength")
_FD_STEP = 1e-6   # in x: the chain is smooth there; central differences hold ~1e-9 relative
_HESSIAN_STEP = 1e-4   # second differences: truncation ~h² and rounding ~1e-16/h², both ~1e-8
_QUANTITIES = ("S_H1", "S_H2", "S_F1", "S_F2")
_DICT_OPTIONS = ("factors", "shaft")   # the options of pair_strength that are dicts


@functools.lru_cache(maxsize=64)
def _keywords(items: tuple) -> dict:
    """:meth:`StrengthSpec.keywords` of a spec's option items."""
    from ..strength.options import gathered   # here: as the chain itself (see _evaluate)

    return gathered({k: dict(v) if k in _DICT_OPTIONS and v is not None else v for k, v in items})


@dataclass(frozen=True)
class StrengthSpec:
    """A load case of the strength checks: the load, the materials, the face width and the options of
    :func:`~geardesign.gears.strength.pair_strength` (as sorted items)."""

    load: object
    material1: object
    material2: object = None
    face_width_mm: float | None = None
    options: tuple = ()

    def keywords(self) -> dict:
        """The options as :func:`~geardesign.gears.strength.pair_strength` keywords, those of the gears' making
        and rating gathered into one ``options=`` StrengthOptions (made once per load case: the solvers call
        the chain at every design); the dicts (``factors``, ``shaft``) that were frozen into sorted items for
        the spec's hash, dicts again."""
        return _keywords(self.options)

    def safety(self, geo: dict, gradients: bool = False) -> dict:
        """S_H (the smaller of both gears'), S_F1, S_F2 at the designs of ``geo`` and, with ``gradients``,
        their gradients (``d<name>``: (∂/∂x1, ∂/∂x2)), kept in ``geo`` so that the three checks share one
        evaluation. One design (the local solvers' float path) runs the chain on Python floats, a grid on
        arrays; either gets its gradients only when asked (five designs' work)."""
        memo = geo.setdefault("_strength", {})
        stencil = gradients
        if (self, True) in memo:
            return memo[(self, True)]
        if (self, stencil) not in memo:
            memo[(self, stencil)] = self._evaluate(geo, stencil)
        return memo[(self, stencil)]

    def _evaluate(self, geo: dict, stencil: bool) -> dict:
        h = _FD_STEP
        S = self._chain(geo, _GRADIENT_STENCIL if stencil else _GRADIENT_STENCIL[:1])
        res = {"S_H": np.minimum(S["S_H1"], S["S_H2"]), "S_F1": S["S_F1"], "S_F2": S["S_F2"]}
        scalar = isinstance(geo["_x1"], float)
        result = {}
        for name, v in res.items():
            result[name] = float(v[0]) if scalar else v[0]
            if stencil:
                grad = (_difference(v[0], v[1], v[2], h), _difference(v[0], v[3], v[4], h))
                result["d" + name] = tuple(float(g) for g in grad) if scalar else grad
        return result

    def _chain(self, geo: dict, offsets) -> dict:
        """S_H1, S_H2, S_F1, S_F2 by the vectorised chain at the designs of ``geo`` moved by each (Δx1, Δx2) of
        ``offsets``, in one call: arrays (len(offsets), *shape of the designs)."""
        # here: the chain loads the materials catalog (pandas), which a pair without a load never needs
        from ..strength.chain import CHAIN_GEOMETRY_FIELDS, pair_strength

        mesh = geo["_mesh"]
        width = self.width(geo)
        if width is None:
            raise GearDesignError("the strength checks need a face width: give face_width_mm with the load")
        if isinstance(geo["_x1"], float):
            return self._chain_floats(geo, offsets, width, pair_strength, CHAIN_GEOMETRY_FIELDS)
        x1, x2 = np.asarray(geo["_x1"], dtype=float), np.asarray(geo["_x2"], dtype=float)
        n_pts = len(offsets)
        X1 = np.stack([x1 + a for a, _ in offsets]).reshape(n_pts, -1)
        X2 = np.stack([x2 + b for _, b in offsets]).reshape(n_pts, -1)
        M, Z1, Z2 = (np.broadcast_to(np.asarray(geo[k], dtype=float), x1.shape).reshape(1, -1)
                     for k in ("_m", "_z1", "_z2"))
        with np.errstate(all="ignore"):
            g5 = mesh_geometry(mesh.unchecked(Z1, Z2), M, X1, X2, full=False)
            # the chain's formulas hold for gears that mesh with ε_α >= 1 (ISO 6336's own range) and for the
            # root form factors' |x| <= 3; elsewhere the design fails its geometry anyway, and its safety
            # factors are NaN (a failing margin)
            idx = np.flatnonzero(np.broadcast_to(_in_range(g5, X1, X2), X1.shape))
            S = {k: np.full(X1.size, np.nan) for k in _QUANTITIES}
            if idx.size:
                flat = {k: np.broadcast_to(g5[k], X1.shape).ravel()
                        for k in CHAIN_GEOMETRY_FIELDS + ("_z1", "_z2", "_m", "_x1", "_x2")}
                per_design = np.ndim(width) > 0
                if per_design:
                    flat["_b"] = np.broadcast_to(np.broadcast_to(np.asarray(width, dtype=float), x1.shape).reshape(1, -1),
                                                 X1.shape).ravel()
                # a load per design (Load.per_design: a drive sizing a stage at each flow) goes with its designs: the
                # designs in range, and the halves _where_it_holds tries, took all its values (a broadcast error, fuzz)
                per_load = np.ndim(self.load.torque_nm) > 0
                if per_load:
                    for key, v in (("_T", self.load.torque_nm), ("_n", self.load.n_rpm)):
                        flat[key] = np.broadcast_to(np.broadcast_to(np.asarray(v, dtype=float), x1.shape).reshape(1, -1),
                                                    X1.shape).ravel()

                def call(sel):
                    at = {k: v[idx[sel]] for k, v in flat.items()}
                    b = at.pop("_b") if per_design else width
                    load = (type(self.load).per_design(at.pop("_T"), at.pop("_n"), self.load.application_factor,
                                                       self.load.life_h) if per_load else self.load)
                    out = pair_strength(at["_m"], at["_z1"], at["_z2"], at["_x1"], at["_x2"], load=load,
                                        material1=self.material1, material2=self.material2, face_width_mm=b,
                                        beta_deg=mesh.beta_deg, internal=mesh.internal, rack=mesh.rack,
                                        tip_shortening=mesh.tip_shortening, geometry=at, **self.keywords())
                    # without the root side (option root=False) S_F is not computed: NaN
                    return {k: out[k] if k in out else np.full(np.shape(at["_x1"]), np.nan) for k in _QUANTITIES}

                for k, v in _where_it_holds(call, idx.size).items():
                    S[k][idx] = v
        return {k: v.reshape((n_pts,) + x1.shape) for k, v in S.items()}

    def _chain_floats(self, geo: dict, offsets, width, pair_strength, fields) -> dict:
        """:meth:`_chain` of one design on the chain's float path (a design at a time: each ~5x cheaper than a
        small array call); a design outside the chain's range or refused by it gets NaN (a failing margin)."""
        mesh, m = geo["_mesh"], geo["_m"]
        S = {k: np.full((len(offsets), 1), np.nan) for k in _QUANTITIES}
        for j, (a, b) in enumerate(offsets):
            x1, x2 = geo["_x1"] + a, geo["_x2"] + b
            g = geo if a == b == 0.0 else mesh_geometry_float(mesh, m, x1, x2, full=False)
            try:
                if not _in_range(g, x1, x2):
                    continue
                out = pair_strength(m, mesh.z1, mesh.z2, x1, x2, load=self.load, material1=self.material1,
                                    material2=self.material2, face_width_mm=width, beta_deg=mesh.beta_deg,
                                    internal=mesh.internal, rack=mesh.rack, tip_shortening=mesh.tip_shortening,
                                    geometry={**{k: float(g[k]) for k in fields}, "_z1": mesh.z1, "_z2": mesh.z2},
                                    **self.keywords())
            except GearDesignError:
                continue
            if a == b == 0.0:    # the design's whole chain output: its factor table (StrengthResult) needs no rerun
                geo.setdefault("_strength", {})[(self, "chain")] = out
            for k in _QUANTITIES:
                S[k][j, 0] = out.get(k, np.nan)
        return {k: v.reshape((len(offsets),)) for k, v in S.items()}

    def width(self, geo: dict):
        """The face width [mm] of the designs of ``geo``: the load case's, else a width per design (a drive's
        sizing grid puts an array in ``geo["_face_width_mm"]``), else the mesh's (None: not given)."""
        if self.face_width_mm is not None:
            return self.face_width_mm
        return geo.get("_face_width_mm", geo["_mesh"].face_width_mm)

    def chain_output(self, geo: dict) -> dict | None:
        """The chain's whole output for the one design of ``geo`` (a float geometry) after its checks were
        evaluated there (None before): what :func:`~geardesign.gears.strength.from_chain` turns into a
        StrengthResult without running the chain again."""
        return geo.get("_strength", {}).get((self, "chain"))

    def model(self, geo: dict) -> "StrengthModel":
        """The quadratic model of the safety factors around the one design of ``geo`` (a float geometry): values
        and gradients as :meth:`safety` gives them, second derivatives by central differences, from one call of
        the chain on 13 designs (kept in ``geo``, which the three checks share)."""
        memo = geo.setdefault("_strength", {})
        if (self, "model") not in memo:
            h, S = _HESSIAN_STEP, self._chain(geo, _GRADIENT_STENCIL + _HESSIAN_STENCIL)
            parts = {}
            for q, v in S.items():
                v = [float(a) for a in v]
                grad = tuple(float(_difference(v[0], v[i], v[i + 1], _FD_STEP)) for i in (1, 3))
                h11 = (v[5] - 2.0 * v[0] + v[6]) / (h * h)
                h22 = (v[7] - 2.0 * v[0] + v[8]) / (h * h)
                h12 = (v[9] - v[10] - v[11] + v[12]) / (4.0 * h * h)
                # a second difference that leaves the chain's range (NaN): no curvature on that side
                parts[q] = (v[0], grad, tuple(c if c == c else 0.0 for c in (h11, h12, h22)))
            memo[(self, "model")] = StrengthModel(geo["_x1"], geo["_x2"], parts)
        return memo[(self, "model")]


_REFUSAL_SPLITS = 64   # calls of the chain spent finding the designs it refuses among many


def _where_it_holds(call, n: int, keys=_QUANTITIES) -> dict:
    """``call(sel)`` for the designs 0 … n−1 (a dict of arrays by ``keys``). The chain refuses a whole call for one
    design outside a range it checks inside itself (the root's notch parameter q_s, say, of a design the geometry
    fails anyway): the designs it refuses alone then get NaN (a failing margin), found by halving. A refusal of
    every design (a bad option, or a single design out of range) is raised, as is one that takes more than
    _REFUSAL_SPLITS calls to pin down."""
    budget = [_REFUSAL_SPLITS]

    def part(sel):   # the values of sel, None where the chain refuses every design of it
        try:
            return call(sel)
        except GearDesignError:
            if sel.size == 1:
                return None
            budget[0] -= 2
            if budget[0] < 0:
                raise
            halves = [part(h) for h in (sel[:sel.size // 2], sel[sel.size // 2:])]
            if all(h is None for h in halves):
                return None
            halves = [h if h is not None else {k: np.full(s.size, np.nan) for k in keys}
                      for h, s in zip(halves, (sel[:sel.size // 2], sel[sel.size // 2:]))]
            return {k: np.concatenate([h[k] for h in halves]) for k in keys}

    try:
        return call(np.arange(n))
    except GearDesignError:
        out = part(np.arange(n)) if n > 1 else None
        if out is None:
            raise
        return out


def _in_range(g: dict, x1, x2):
    """True where the chain's formulas hold: 1 <= ε_α <= 3 (ISO 6336's own range) and the root form factors'
    |x| <= 3 (a design outside a factor's domain inside that gets NaN from the chain: a failing margin)."""
    from ..strength.root import EPS_ALPHA_RANGE, X_RANGE

    return ((EPS_ALPHA_RANGE[0] <= g["eps_alpha"]) & (g["eps_alpha"] <= EPS_ALPHA_RANGE[1])
            & (X_RANGE[0] <= x1) & (x1 <= X_RANGE[1]) & (X_RANGE[0] <= x2) & (x2 <= X_RANGE[1]))


_GRADIENT_STENCIL = ((0.0, 0.0), (_FD_STEP, 0.0), (-_FD_STEP, 0.0), (0.0, _FD_STEP), (0.0, -_FD_STEP))
_HESSIAN_STENCIL = ((_HESSIAN_STEP, 0.0), (-_HESSIAN_STEP, 0.0), (0.0, _HESSIAN_STEP), (0.0, -_HESSIAN_STEP),
                    (_HESSIAN_STEP, _HESSIAN_STEP), (_HESSIAN_STEP, -_HESSIAN_STEP),
                    (-_HESSIAN_STEP, _HESSIAN_STEP), (-_HESSIAN_STEP, -_HESSIAN_STEP))


class StrengthModel:
    """S_H, S_F1, S_F2 and their gradients from second-order Taylor polynomials of S_H1, S_H2, S_F1, S_F2 around
    one design (x1, x2) (:meth:`StrengthSpec.model`), read like :meth:`StrengthSpec.safety`: a stand-in the
    solvers walk on, confirmed by the chain where they stop. S_H is the smaller of the two gears' models (its
    kink kept)."""

    def __init__(self, x1: float, x2: float, parts: dict):
        self.x1, self.x2, self.parts = x1, x2, parts

    def safety(self, geo: dict, gradients: bool = False) -> dict:
        d1, d2 = geo["_x1"] - self.x1, geo["_x2"] - self.x2
        val, grad = {}, {}
        for q, (v0, (g1, g2), (h11, h12, h22)) in self.parts.items():
            a1, a2 = g1 + h11 * d1 + h12 * d2, g2 + h12 * d1 + h22 * d2
            val[q] = v0 + 0.5 * ((g1 + a1) * d1 + (g2 + a2) * d2)
            grad[q] = (a1, a2)
        first = val["S_H1"] <= val["S_H2"]
        out = {"S_H": np.where(first, val["S_H1"], val["S_H2"]), "S_F1": val["S_F1"], "S_F2": val["S_F2"],
               "dS_H": tuple(np.where(first, a, b) for a, b in zip(grad["S_H1"], grad["S_H2"])),
               "dS_F1": grad["S_F1"], "dS_F2": grad["S_F2"]}
        if isinstance(geo["_x1"], float):
            out = {k: (tuple(map(float, v)) if isinstance(v, tuple) else float(v)) for k, v in out.items()}
        return out


def _difference(v0, up, down, h):
    """∂v by central differences, one-sided where one neighbour lies outside the chain's range."""
    central = (up - down) / (2.0 * h)
    return np.where(np.isfinite(central), central, np.where(np.isfinite(up), (up - v0) / h, (v0 - down) / h))


def strength_spec(context: dict) -> StrengthSpec | None:
    """The load case of ``make_checks``' context, or None without a load; a material or options without
    a load are refused (they would silently check nothing)."""
    from ..strength.load import Load

    load = context.get("load")
    if load is None:
        given = [k for k in STRENGTH_CONTEXT[1:] if context.get(k) is not None]
        if given and context.get("spectrum") is None:    # a spectrum's damage checks read them too
            raise GearDesignError(f"{', '.join(given)} given without a load: the strength checks need load= "
                                  f"(a geardesign Load)")
        return None
    if not isinstance(load, Load):
        raise GearDesignError(f"load must be a geardesign Load, got {type(load).__name__}")
    return StrengthSpec(load, *pair_context(context, "strength"))


def pair_context(context: dict, what: str) -> tuple:
    """(material 1, material 2 or None, the strength options frozen, face width or None) of make_checks' context,
    each checked by name: what a load case's checks (``what``: "strength", "damage") share."""
    if context.get("material") is None:
        raise GearDesignError(f"the {what} checks need material= (a geardesign Material or a name such as '42CrMo4')")
    from ..strength.chain import _material, check_options   # a name is looked up once here, not at every evaluation

    mat1 = _material(context["material"], "material")
    mat2 = None if context.get("material2") is None else _material(context["material2"], "material2")
    options = context.get("strength") or {}
    if not isinstance(options, dict):
        raise GearDesignError(f"strength must be a dict of pair_strength options, got {type(options).__name__}")
    frozen = tuple(sorted((k, _hashable(v)) for k, v in check_options(options).items()))
    width = context.get("face_width_mm")
    if width is not None:      # one number: the spec is hashed (its values are memoised per geometry)
        width = one_number("face_width_mm", require_range("face_width_mm", width, *FACE_WIDTH_RANGE_MM, unit="mm"))
    return mat1, mat2, width, frozen


def _hashable(value):
    if isinstance(value, dict):
        return tuple(sorted((k, _hashable(v)) for k, v in value.items()))
    if isinstance(value, list):
        return tuple(value)
    return value


def _build_with_spec(cls, value, context: dict) -> list:
    """The class's checks for the context's load case (none without a load)."""
    spec = context.get("strength_spec")
    if spec is None:
        return []
    gears = (None,) if cls.per_gear is None else cls.per_gear["internal" if context["internal"] else "external"]
    return [cls(limit=value, spec=spec) if j is None else cls(gear=j, limit=value, spec=spec) for j in gears]


def _modelled_at(self, geo):
    """The check on the quadratic model of the chain around the design of ``geo`` (see Check.modelled_at)."""
    return replace(self, spec=self.spec.model(geo)) if self.costly else self


# a check on the chain itself is costly; the same check on a StrengthModel is not
_costly = property(lambda self: isinstance(self.spec, StrengthSpec))



@register
@dataclass(frozen=True)
class ContactStrength(Check):
    """Contact (pitting) safety S_H = min(S_H1, S_H2) >= S_Hmin (ISO 6336-2:2019); margin S_H/S_Hmin − 1.
    Built only with a load (see the module docstring)."""

    option, colour, order, kind_name = CONTACT_SAFETY, "deeppink", 80, "contact_strength"
    fd_gradient = True
    margin_per_limit = property(lambda self: 1.0 / self.limit)   # −∂margin/∂limit at the boundary
    build = classmethod(_build_with_spec)
    costly, modelled_at = _costly, _modelled_at

    limit: float = S_HMIN
    spec: StrengthSpec | None = None

    def __post_init__(self):
        object.__setattr__(self, "name", self.name or "contact_strength")
        object.__setattr__(self, "label", self.label or "contact safety S_H >= S_Hmin (ISO 6336-2)")

    def value(self, geo):
        return self.spec.safety(geo)["S_H"]

    def margin(self, geo):
        return self.value(geo) / self.limit - 1.0

    def gradient(self, geo):
        d1, d2 = self.spec.safety(geo, gradients=True)["dS_H"]
        return d1 / self.limit, d2 / self.limit


@register
@dataclass(frozen=True)
class RootStrength(Check):
    """Tooth-root (bending) safety of ``gear``, S_F >= S_Fmin (ISO 6336-3:2019); margin S_F/S_Fmin − 1.
    Built only with a load (see the module docstring)."""

    option, colour, order, kind_name = ROOT_SAFETY, "teal", 81, "root_strength"
    per_gear = {"external": (1, 2), "internal": (1, 2)}
    fd_gradient = True
    margin_per_limit = property(lambda self: 1.0 / self.limit)
    build = classmethod(_build_with_spec)
    costly, modelled_at = _costly, _modelled_at

    gear: int = 1
    limit: float = S_FMIN
    spec: StrengthSpec | None = None

    def __post_init__(self):
        object.__setattr__(self, "name", self.name or f"root_strength{self.gear}")
        object.__setattr__(self, "label", self.label or f"root safety of gear {self.gear} S_F >= S_Fmin (ISO 6336-3)")

    def value(self, geo):
        return self.spec.safety(geo)[f"S_F{self.gear}"]

    def margin(self, geo):
        return self.value(geo) / self.limit - 1.0

    def gradient(self, geo):
        d1, d2 = self.spec.safety(geo, gradients=True)[f"dS_F{self.gear}"]
        return d1 / self.limit, d2 / self.limit


register_context(STRENGTH_CONTEXT, lambda context: {"strength_spec": strength_spec(context)})
