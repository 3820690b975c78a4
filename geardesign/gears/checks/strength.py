"""Load capacity as checks (ISO 6336): the contact safety S_H >= S_Hmin and each gear's root safety
S_F >= S_Fmin, built when :func:`~geardesign.gears.checks.make_checks` is given a load.

The load and what the chain needs besides the geometry travel in the context of ``make_checks`` (and so
in a ``checks`` dict of every solver, region, atlas and tooth-count search): ``load`` (a
:class:`~geardesign.gears.strength.Load`), ``material`` (and ``material2``), ``face_width_mm`` (default:
the pair's face width) and ``strength`` (a dict of :func:`~geardesign.gears.strength.pair_strength`
options: accuracy grade, lubricant, roughness, given factors, root method, ...). The safety factors come
from the vectorised chain evaluated on the solver's own geometry; their gradients in (x1, x2) are central
differences of the chain, evaluated with the design in the same vectorised call (five designs for the
price of about one). Margins S/S_min − 1.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...errors import GearDesignError
from ..strength.defaults import MIN_SAFETY_SOURCE, S_FMIN, S_HMIN
from .base import Check, Option, register, register_context

__all__ = ["StrengthSpec", "ContactStrength", "RootStrength", "strength_spec", "STRENGTH_CONTEXT", "SAFETY_RANGE"]

SAFETY_RANGE = (0.5, 10.0)
CONTACT_SAFETY = Option("S_Hmin", "limit", S_HMIN, "smallest contact (pitting) safety factor S_H, with a load",
                        source=MIN_SAFETY_SOURCE, range=SAFETY_RANGE, sweep=True)
ROOT_SAFETY = Option("S_Fmin", "limit", S_FMIN, "smallest tooth-root (bending) safety factor S_F, with a load",
                     source=MIN_SAFETY_SOURCE, range=SAFETY_RANGE, sweep=True)
# the keywords of make_checks that describe the load case (they switch the strength checks on)
STRENGTH_CONTEXT = ("load", "material", "material2", "face_width_mm", "strength")
_FD_STEP = 1e-6   # in x: the chain is smooth there; central differences hold ~1e-9 relative


@dataclass(frozen=True)
class StrengthSpec:
    """A load case of the strength checks: the load, the materials, the face width and the options of
    :func:`~geardesign.gears.strength.pair_strength` (as sorted items)."""

    load: object
    material1: object
    material2: object = None
    face_width_mm: float | None = None
    options: tuple = ()

    def safety(self, geo: dict, gradients: bool = False) -> dict:
        """S_H (the smaller of both gears'), S_F1, S_F2 at the designs of ``geo`` and, with ``gradients``,
        their gradients (``d<name>``: (∂/∂x1, ∂/∂x2)), kept in ``geo`` so that the three checks share one
        evaluation. One design (the local solvers' float path) gets its gradients in the same call: five
        designs cost about what one does there; a grid gets them only when asked (five times the work)."""
        memo = geo.setdefault("_strength", {})
        stencil = gradients or isinstance(geo["_x1"], float)
        if (self, True) in memo:
            return memo[(self, True)]
        if (self, stencil) not in memo:
            memo[(self, stencil)] = self._evaluate(geo, stencil)
        return memo[(self, stencil)]

    def _evaluate(self, geo: dict, stencil: bool) -> dict:
        # here: the chain loads the materials catalog (pandas), which a pair without a load never needs
        from ..geometry import mesh_geometry
        from ..strength.chain import CHAIN_GEOMETRY_FIELDS, pair_strength
        from ..strength.root import X_RANGE

        mesh = geo["_mesh"]
        width = self.face_width_mm if self.face_width_mm is not None else mesh.face_width_mm
        if width is None:
            raise GearDesignError("the strength checks need a face width: give face_width_mm with the load")
        x1, x2 = np.asarray(geo["_x1"], dtype=float), np.asarray(geo["_x2"], dtype=float)
        h = _FD_STEP
        n_pts = 5 if stencil else 1
        X1 = np.stack([x1, x1 + h, x1 - h, x1, x1][:n_pts]).reshape(n_pts, -1)
        X2 = np.stack([x2, x2, x2, x2 + h, x2 - h][:n_pts]).reshape(n_pts, -1)
        M, Z1, Z2 = (np.broadcast_to(np.asarray(geo[k], dtype=float), x1.shape).reshape(1, -1)
                     for k in ("_m", "_z1", "_z2"))
        with np.errstate(all="ignore"):
            g5 = mesh_geometry(mesh.unchecked(Z1, Z2), M, X1, X2, full=False)
            # the chain's formulas hold for gears that mesh with ε_α >= 1 (ISO 6336's own range) and for the
            # root form factors' |x| <= 3; elsewhere the design fails its geometry anyway, and its safety
            # factors are NaN (a failing margin)
            valid = ((g5["eps_alpha"] >= 1.0) & (g5["rho_p1"] > 0) & (g5["rho_p2"] > 0)
                     & (X_RANGE[0] <= X1) & (X1 <= X_RANGE[1]) & (X_RANGE[0] <= X2) & (X2 <= X_RANGE[1]))
            valid = np.broadcast_to(valid, X1.shape)
            S = {k: np.full(X1.shape, np.nan) for k in ("S_H1", "S_H2", "S_F1", "S_F2")}
            if valid.any():
                sub = {k: np.broadcast_to(g5[k], X1.shape)[valid] for k in CHAIN_GEOMETRY_FIELDS + ("_z1", "_z2")}
                args = (np.broadcast_to(M, X1.shape)[valid], np.broadcast_to(Z1, X1.shape)[valid],
                        np.broadcast_to(Z2, X1.shape)[valid], X1[valid], X2[valid])

                def chain(index):
                    return pair_strength(*(a[index] for a in args), load=self.load, material1=self.material1,
                                         material2=self.material2, face_width_mm=width, beta_deg=mesh.beta_deg,
                                         internal=mesh.internal, rack=mesh.rack, tip_shortening=mesh.tip_shortening,
                                         geometry={k: v[index] for k, v in sub.items()}, **dict(self.options))

                out = _where_defined(chain, args[0].size, tuple(S))
                for k in S:
                    S[k][valid] = out[k]
        shape = x1.shape
        res = {"S_H": np.minimum(S["S_H1"], S["S_H2"]), "S_F1": S["S_F1"], "S_F2": S["S_F2"]}
        res = {name: v.reshape((n_pts,) + shape) for name, v in res.items()}
        scalar = isinstance(geo["_x1"], float)
        result = {}
        for name, v in res.items():
            v = np.asarray(v, dtype=float)
            result[name] = float(v[0]) if scalar else v[0]
            if stencil:
                grad = (_difference(v[0], v[1], v[2], h), _difference(v[0], v[3], v[4], h))
                result["d" + name] = tuple(float(g) for g in grad) if scalar else grad
        return result


def _where_defined(chain, n: int, names: tuple) -> dict:
    """``chain(index)`` over the designs 0..n-1, NaN where the chain refuses a design (a shift past the root
    section's range of ISO 6336-3, say, that the geometry's own checks would fail anyway): the refused
    designs are found by halving, so a few of them cost a few more calls, not one call per design."""
    try:
        return chain(slice(0, n))
    except GearDesignError:
        if n == 1:
            return {k: np.full(1, np.nan) for k in names}
    index = np.arange(n)
    halves = (index[: n // 2], index[n // 2:])
    parts = [_where_defined(lambda sub, h=h: chain(h[sub]), h.size, names) for h in halves]
    return {k: np.concatenate([np.broadcast_to(p[k], (h.size,)) for p, h in zip(parts, halves)]) for k in names}


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
        if given:
            raise GearDesignError(f"{', '.join(given)} given without a load: the strength checks need load= "
                                  f"(a geardesign Load)")
        return None
    if not isinstance(load, Load):
        raise GearDesignError(f"load must be a geardesign Load, got {type(load).__name__}")
    if context.get("material") is None:
        raise GearDesignError("the strength checks need material= (a geardesign Material or a name such as '42CrMo4')")
    from ..strength.chain import _material   # a name is looked up once here, not at every evaluation

    mat1 = _material(context["material"], "material")
    mat2 = None if context.get("material2") is None else _material(context["material2"], "material2")
    options = context.get("strength") or {}
    if not isinstance(options, dict):
        raise GearDesignError(f"strength must be a dict of pair_strength options, got {type(options).__name__}")
    frozen = tuple(sorted((k, _hashable(v)) for k, v in options.items()))
    return StrengthSpec(load, mat1, mat2, context.get("face_width_mm"), frozen)


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


@register
@dataclass(frozen=True)
class ContactStrength(Check):
    """Contact (pitting) safety S_H = min(S_H1, S_H2) >= S_Hmin (ISO 6336-2:2019); margin S_H/S_Hmin − 1.
    Built only with a load (see the module docstring)."""

    option, colour, order, kind_name = CONTACT_SAFETY, "deeppink", 80, "contact_strength"
    fd_gradient = True
    margin_per_limit = property(lambda self: 1.0 / self.limit)   # −∂margin/∂limit at the boundary
    build = classmethod(_build_with_spec)

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
