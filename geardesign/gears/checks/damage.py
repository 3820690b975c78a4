"""Service life as checks (ISO 6336-6): each gear's Miner damage sum for pitting and for the root under a load
spectrum, D <= D_max (1 by default), margin 1 − D/D_max; built when :func:`~geardesign.gears.checks.make_checks`
is given a ``spectrum``.

The spectrum travels in the context of ``make_checks`` (so in a ``checks`` dict of every solver, region, atlas and
tooth-count search) with what :func:`~geardesign.gears.strength.service_life.pair_life` needs: ``spectrum`` (a
:class:`~geardesign.gears.spectrum.LoadSpectrum`, or a list of them: several load cases, each of which must hold),
``material`` (and ``material2``), ``face_width_mm``, ``strength`` (the chain's options), ``life_h`` (the required
life; None: each spectrum's duration), ``sn_curve``, ``mean_stress_factor`` and ``alternating`` (a gear whose root
bends both ways whatever the spectrum's sign: an idler, a planet). The damage comes from the chain run
over the spectrum's bins at the solver's own geometry, the gradients in (x1, x2) from central differences evaluated
in the same call.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from ...errors import GearDesignError
from .base import Check, Option, register, register_context
from .strength import (_GRADIENT_STENCIL, _HESSIAN_STENCIL, _HESSIAN_STEP, _difference, _in_range, _where_it_holds,
                       pair_context)

__all__ = ["DamageSpec", "PittingDamage", "RootDamage", "damage_spec", "DAMAGE_CONTEXT", "DAMAGE_MAX"]

DAMAGE_MAX = Option("damage_max", "limit", 1.0, "largest Miner damage sum D of each gear (pitting and root) over the "
                    "required life, with a load spectrum", source="ISO 6336-6:2019 (Palmgren-Miner rule)",
                    range=(1e-6, 10.0), sweep=True)
# the keywords of make_checks that describe a spectrum's load case (besides the strength checks' material, width
# and options, which they share)
DAMAGE_CONTEXT = ("spectrum", "life_h", "sn_curve", "mean_stress_factor", "alternating")
_MODES = ("H1", "H2", "F1", "F2")
_FD_STEP = 1e-6


@dataclass(frozen=True, eq=False)      # one object per case: its values are memoised per geometry by identity
class DamageSpec:
    """One spectrum's load case of the damage checks."""

    spectrum: object
    material1: object
    material2: object = None
    face_width_mm: float | None = None
    options: tuple = ()
    life_h: float | None = None
    sn_curve: str = "iso"
    mean_stress_factor: object = None
    case: int = 1
    alternating: tuple = (False, False)

    def width(self, geo: dict):
        """The face width of the designs of ``geo`` (the load case's, a per-design width, or the mesh's)."""
        if self.face_width_mm is not None:
            return self.face_width_mm
        return geo.get("_face_width_mm", geo["_mesh"].face_width_mm)

    def damage(self, geo: dict, gradients: bool = False) -> dict:
        """D_H1, D_H2, D_F1, D_F2 at the designs of ``geo`` and, with ``gradients``, ``dD_<mode>`` (∂/∂x1, ∂/∂x2),
        kept in ``geo`` so that the four checks share one evaluation."""
        memo = geo.setdefault("_damage", {})
        if (self, True) in memo:
            return memo[(self, True)]
        # one design: its gradients with it (five designs cost ~1.3 of one in the chain's call; the solvers ask for
        # them next anyway)
        gradients = gradients or isinstance(geo["_x1"], float)
        if (self, gradients) not in memo:
            offsets = _STENCIL if gradients else _STENCIL[:1]
            D = self._values(geo, offsets)
            scalar = isinstance(geo["_x1"], float)
            out = {}
            for mode, v in D.items():
                out["D_" + mode] = float(v[0]) if scalar else v[0]
                if gradients:
                    grad = (_difference(v[0], v[1], v[2], _FD_STEP), _difference(v[0], v[3], v[4], _FD_STEP))
                    out["dD_" + mode] = tuple(float(g) for g in grad) if scalar else grad
            memo[(self, gradients)] = out
        return memo[(self, gradients)]

    def model(self, geo: dict) -> "DamageModel":
        """The quadratic model of ln D around the one design of ``geo`` (a float geometry), from one call of the chain
        on 13 designs (kept in ``geo``, which the four checks share): what the solvers walk on (Check.modelled_at)."""
        memo = geo.setdefault("_damage", {})
        if (self, "model") not in memo:
            h, D = _HESSIAN_STEP, self._values(geo, _GRADIENT_STENCIL + _HESSIAN_STENCIL)
            parts = {}
            for mode, v in D.items():
                with np.errstate(divide="ignore", invalid="ignore"):
                    q = [math.log(float(a)) if a > 0 else -math.inf for a in v]
                if not math.isfinite(q[0]) or not all(map(math.isfinite, q)):
                    # no damage here, or a neighbour without it (the S-N curve's horizontal end): D itself, linear
                    parts[mode] = ("linear", float(v[0]), tuple(float(_difference(v[0], v[i], v[i + 1], _FD_STEP))
                                                              for i in (1, 3)))
                    continue
                grad = tuple(float(_difference(q[0], q[i], q[i + 1], _FD_STEP)) for i in (1, 3))
                h11 = (q[5] - 2.0 * q[0] + q[6]) / (h * h)
                h22 = (q[7] - 2.0 * q[0] + q[8]) / (h * h)
                h12 = (q[9] - q[10] - q[11] + q[12]) / (4.0 * h * h)
                parts[mode] = ("log", q[0], grad, (h11, h12, h22))
            memo[(self, "model")] = DamageModel(geo["_x1"], geo["_x2"], parts)
        return memo[(self, "model")]

    def _values(self, geo: dict, offsets) -> dict:
        """Miner's sums at the designs of ``geo`` moved by each offset: arrays (len(offsets), *shape)."""
        from ..geometry import mesh_geometry
        from ..strength.chain import CHAIN_GEOMETRY_FIELDS
        from ..strength.service_life import pair_life, require_teeth_of

        mesh = geo["_mesh"]
        width = self.width(geo)
        if width is None:
            raise GearDesignError("the damage checks need a face width: give face_width_mm with the spectrum")
        x1, x2 = np.asarray(geo["_x1"], dtype=float), np.asarray(geo["_x2"], dtype=float)
        shape = np.broadcast_shapes(x1.shape, x2.shape)
        n_pts = len(offsets)
        X1 = np.stack([np.broadcast_to(x1 + a, shape) for a, _ in offsets]).reshape(n_pts, -1)
        X2 = np.stack([np.broadcast_to(x2 + b, shape) for _, b in offsets]).reshape(n_pts, -1)
        M = np.broadcast_to(np.asarray(geo["_m"], dtype=float), shape).reshape(1, -1)
        # a tooth search batches several pairs in one geometry: the spectrum's cycles depend on each pair's ratio,
        # so pair_life runs once per pair of tooth counts
        Z1, Z2 = (np.broadcast_to(np.broadcast_to(np.asarray(geo[k], dtype=float), shape).reshape(1, -1), X1.shape)
                  for k in ("_z1", "_z2"))
        D = {k: np.full(X1.size, np.nan) for k in _MODES}
        with np.errstate(all="ignore"):
            g = mesh_geometry(mesh.unchecked(Z1[:1], Z2[:1]), M, X1, X2, full=False)
            idx = np.flatnonzero(np.broadcast_to(_in_range(g, X1, X2), X1.shape))
            if idx.size:
                flat = {k: np.broadcast_to(g[k], X1.shape).ravel()[idx] for k in CHAIN_GEOMETRY_FIELDS}
                b = width if np.ndim(width) == 0 else np.broadcast_to(
                    np.broadcast_to(np.asarray(width, dtype=float), shape).reshape(1, -1), X1.shape).ravel()[idx]
                m_at = np.broadcast_to(M, X1.shape).ravel()[idx]
                x1_at, x2_at = X1.ravel()[idx], X2.ravel()[idx]
                z_at = np.stack([Z1.ravel()[idx], Z2.ravel()[idx]])
                for z1, z2 in np.unique(z_at, axis=1).T:
                    mine = np.flatnonzero((z_at[0] == z1) & (z_at[1] == z2))
                    z1, z2 = int(z1), int(z2)
                    # here, not in pair_life: the refusal below would be taken for a failing design, one by one
                    require_teeth_of(self.spectrum, (z1, z2))

                    def call(sel, mine=mine, z1=z1, z2=z2):
                        at = mine[sel]
                        out = pair_life(m_at[at], z1, z2, x1_at[at], x2_at[at], spectrum=self.spectrum,
                                        material1=self.material1, material2=self.material2,
                                        face_width_mm=b if np.ndim(b) == 0 else b[at], life_h=self.life_h,
                                        sn_curve=self.sn_curve, mean_stress_factor=self.mean_stress_factor,
                                        alternating=self.alternating,
                                        beta_deg=mesh.beta_deg, internal=mesh.internal, rack=mesh.rack,
                                        tip_shortening=mesh.tip_shortening,
                                        geometry={**{k: v[at] for k, v in flat.items()}, "_z1": z1, "_z2": z2},
                                        **dict(self.options))
                        return {k: np.asarray(out["D_" + k], dtype=float) for k in _MODES}

                    # the designs the chain refuses alone get NaN (a failing margin), found by halving; a refusal
                    # of every design (a material the root needs more of, a bad option) is raised, as the strength
                    # checks raise it: design by design it cost a call per design and ended as "no finite result"
                    for k, v in _where_it_holds(call, mine.size, _MODES).items():
                        D[k][idx[mine]] = v
        return {k: v.reshape((n_pts,) + shape) for k, v in D.items()}


_STENCIL = _GRADIENT_STENCIL
LN_DAMAGE_MAX = 600.0    # the Taylor model's ln D is read up to this (DamageModel.damage)


class DamageModel:
    """D of each gear and mode from a second-order Taylor polynomial of ln D around one design (x1, x2)
    (:meth:`DamageSpec.model`), read like :meth:`DamageSpec.damage`: a stand-in the solvers walk on, confirmed by
    the chain where they stop. Where D is 0 at the design or a neighbour, D itself to first order."""

    def __init__(self, x1: float, x2: float, parts: dict):
        self.x1, self.x2, self.parts = x1, x2, parts

    def damage(self, geo: dict, gradients: bool = False) -> dict:
        d1, d2 = geo["_x1"] - self.x1, geo["_x2"] - self.x2
        out = {}
        for mode, part in self.parts.items():
            if part[0] == "linear":
                _, v0, (g1, g2) = part
                out["D_" + mode] = np.maximum(v0 + g1 * d1 + g2 * d2, 0.0)
                out["dD_" + mode] = (g1, g2)
                continue
            _, q0, (g1, g2), (h11, h12, h22) = part
            a1, a2 = g1 + h11 * d1 + h12 * d2, g2 + h12 * d1 + h22 * d2
            # ln D at most 600 (D = 4e260, far past any damage_max <= 10): far from its centre the quadratic overflowed
            # exp (fuzz: a warning, inf damage); the margin's sign and the walk's direction D·a stay as they were
            D = np.exp(np.minimum(q0 + 0.5 * ((g1 + a1) * d1 + (g2 + a2) * d2), LN_DAMAGE_MAX))
            out["D_" + mode], out["dD_" + mode] = D, (D * a1, D * a2)
        if isinstance(geo["_x1"], float):
            out = {k: (tuple(map(float, v)) if isinstance(v, tuple) else float(v)) for k, v in out.items()}
        return out


def damage_spec(context: dict) -> tuple:
    """The damage load cases of ``make_checks``' context (one :class:`DamageSpec` per spectrum), () without one."""
    from ..spectrum import LoadSpectrum

    spectra = context.get("spectrum")
    if spectra is None:
        given = [k for k in DAMAGE_CONTEXT[1:] if context.get(k) is not None]
        if given:
            raise GearDesignError(f"{', '.join(given)} given without a spectrum: the damage checks need spectrum= "
                                  f"(a geardesign LoadSpectrum)")
        return ()
    spectra = list(spectra) if isinstance(spectra, (list, tuple)) else [spectra]
    if not spectra or not all(isinstance(s, LoadSpectrum) for s in spectra):
        raise GearDesignError(f"spectrum must be a geardesign LoadSpectrum or a list of them, got "
                              f"{type(context['spectrum']).__name__}")
    from ...validate import one_number, require_choice, require_range
    from ..strength.load import LIFE_RANGE_H
    from ..strength.service_life import SN_CURVES, _alternating, _mean_stress

    mat1, mat2, width, frozen = pair_context(context, "damage")
    life = context.get("life_h")
    if life is not None:
        life = one_number("life_h", require_range("life_h", life, *LIFE_RANGE_H, lo_open=True, unit="h"))
    sn = require_choice("sn_curve", context.get("sn_curve") or "iso", SN_CURVES)
    y_m = context.get("mean_stress_factor")
    alternating = _alternating(context.get("alternating") or (False, False))
    if y_m is None and any(alternating):
        raise GearDesignError(f"gear {alternating.index(True) + 1}'s root bends both ways (alternating: its teeth meet "
                              f"two mates on opposite flanks, as a planet's do): give mean_stress_factor=Y_M, the mean "
                              f"stress influence factor of ISO 6336-3:2019 for alternating bending")
    for s in spectra:          # a reversing spectrum without Y_M refused here, once, not at every design
        _mean_stress(y_m, s.reverses)
    return tuple(DamageSpec(s, mat1, mat2, width, frozen, life, sn, y_m if y_m is None else _mean_stress(y_m, True),
                            case=i, alternating=alternating) for i, s in enumerate(spectra, start=1))


def _build_damage(cls, value, context: dict) -> list:
    """The class's checks for each spectrum of the context (none without one)."""
    specs = context.get("damage_specs") or ()
    gears = cls.per_gear["internal" if context["internal"] else "external"]
    return [cls(gear=j, limit=value, spec=s) for s in specs for j in gears]


class _Damage(Check):
    """A gear's Miner damage sum D <= D_max; margin 1 − D/D_max (ISO 6336-6:2019)."""

    mode = ""
    per_gear = {"external": (1, 2), "internal": (1, 2)}
    fd_gradient = True
    build = classmethod(_build_damage)
    # −∂margin/∂limit at the boundary: margin 1 − D/D_max rises with D_max (D = D_max there), as a jamming margin does
    margin_per_limit = property(lambda self: -1.0 / self.limit)
    # a check on the chain itself is costly (the solvers walk on its model); the same check on a DamageModel is not
    costly = property(lambda self: isinstance(self.spec, DamageSpec))

    def modelled_at(self, geo):
        """The check on the quadratic model of ln D around the design of ``geo`` (see Check.modelled_at)."""
        return replace(self, spec=self.spec.model(geo)) if self.costly else self

    def _name(self):
        case = "" if self.spec is None or self.spec.case == 1 else f"case{self.spec.case}_"
        return f"{case}{self.kind_name}{self.gear}"

    def value(self, geo):
        return self.spec.damage(geo)[f"D_{self.mode}{self.gear}"]

    def margin(self, geo):
        return 1.0 - self.value(geo) / self.limit

    def gradient(self, geo):
        d1, d2 = self.spec.damage(geo, gradients=True)[f"dD_{self.mode}{self.gear}"]
        return -d1 / self.limit, -d2 / self.limit


@register
@dataclass(frozen=True)
class PittingDamage(_Damage):
    """Pitting damage of ``gear`` under the spectrum, D_H <= D_max (ISO 6336-6 with ISO 6336-2's S-N curve); margin
    1 − D_H/D_max. Built only with a spectrum (see the module docstring)."""

    option, colour, order, kind_name, mode = DAMAGE_MAX, "orchid", 82, "pitting_damage", "H"

    gear: int = 1
    limit: float = 1.0
    spec: DamageSpec | None = None

    def __post_init__(self):
        object.__setattr__(self, "name", self.name or self._name())
        object.__setattr__(self, "label", self.label or f"pitting damage of gear {self.gear} D_H <= {self.limit:g} "
                                                        f"(ISO 6336-6)")


@register
@dataclass(frozen=True)
class RootDamage(_Damage):
    """Tooth-root damage of ``gear`` under the spectrum, D_F <= D_max (ISO 6336-6 with ISO 6336-3's S-N curve);
    margin 1 − D_F/D_max. Built only with a spectrum (see the module docstring)."""

    option, colour, order, kind_name, mode = DAMAGE_MAX, "darkcyan", 83, "root_damage", "F"

    gear: int = 1
    limit: float = 1.0
    spec: DamageSpec | None = None

    def __post_init__(self):
        object.__setattr__(self, "name", self.name or self._name())
        object.__setattr__(self, "label", self.label or f"root damage of gear {self.gear} D_F <= {self.limit:g} "
                                                        f"(ISO 6336-6)")


register_context(DAMAGE_CONTEXT, lambda context: {"damage_specs": damage_spec(context)})
