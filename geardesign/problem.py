"""A profile-shift problem: tooth counts, rack, the checks a case asks for, and an objective.

Shared by the region (:mod:`geardesign.region`) and the optimisers (:mod:`geardesign.shift`).
Everything is evaluated in one vectorised geometry call over any array of (x1, x2).
Objectives are maximised internally as F = sense · fun; :attr:`Objective.sense` is +1 for
"max_*" goals and −1 for "min_*" goals.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from . import checks as _checks
from .errors import GearDesignError, require_int, require_positive
from .geometry import Z_MIN, _core
from .rack import BasicRack

__all__ = ["OBJECTIVES", "Problem", "Objective"]


@dataclass(frozen=True)
class Objective:
    name: str
    sense: int          # +1 maximise fun, −1 minimise fun
    kind: str           # "smooth", "minimax" (max of pieces) or "margin" (Chebyshev centre)
    description: str


OBJECTIVES = {
    "max_x_sum": Objective("max_x_sum", +1, "smooth",
                           "largest x1 + x2 (largest α_w: contact strength)"),
    "max_eps_alpha": Objective("max_eps_alpha", +1, "smooth", "largest transverse contact ratio ε_α"),
    "balanced_sliding": Objective("balanced_sliding", -1, "minimax",
                                  "smallest max(|ϑ1|, |ϑ2|) at the roots; equal sliding at both ends "
                                  "where no check stops it"),
    "min_specific_pressure": Objective("min_specific_pressure", -1, "smooth",
                                       "smallest specific pressure coefficient at the pitch point"),
    "max_margin": Objective("max_margin", +1, "margin",
                            "the point farthest (in x) from every check's boundary (robust design)"),
}

_FD_STEP = 1e-6


class Problem:
    """The checks and the objective of one tooth pair, as vectorised functions of (x1, x2).

    With ``x_sum`` given (a fixed centre distance) the design has one free variable, x1,
    and x2 = x_sum − x1.
    """

    def __init__(self, z1, z2, rack=None, checks=None, objective="max_x_sum", m=1.0,
                 tip_shortening=True, x_sum=None):
        self.z1 = int(require_int("z1", z1, Z_MIN))
        self.z2 = int(require_int("z2", z2, Z_MIN))
        self.m = float(require_positive("m (module)", m, unit="mm"))
        self.rack = rack or BasicRack()
        if not isinstance(self.rack, BasicRack):
            raise GearDesignError(f"rack must be a geardesign.BasicRack, got {type(self.rack).__name__}")
        self.checks = _checks.resolve_checks(checks)
        if objective not in OBJECTIVES:
            raise GearDesignError(f"objective must be one of {sorted(OBJECTIVES)}, got {objective!r}")
        self.objective = OBJECTIVES[objective]
        self.tip_shortening = bool(tip_shortening)
        self.x_sum = None if x_sum is None else float(x_sum)
        self.names = [c.name for c in self.checks]

    # --- evaluation ---------------------------------------------------------------------
    def geo(self, x1, x2) -> dict:
        return _core(self.m, self.z1, self.z2, x1, x2, self.rack, self.tip_shortening)

    def margins(self, geo) -> np.ndarray:
        """(K, ...) margins; designs whose geometry does not exist get −inf."""
        out = np.stack([np.asarray(c.margin(geo), dtype=float) * np.ones_like(geo["a"])
                        for c in self.checks]) if self.checks else np.zeros((0,) + geo["a"].shape)
        return np.where(np.isnan(out), -np.inf, out)

    def margin_gradients(self, geo, x1, x2) -> np.ndarray:
        """(K, 2, ...) ∂margin/∂(x1, x2): analytic, central differences for custom checks."""
        grads = []
        for c in self.checks:
            g = c.gradient(geo)
            if g is None:
                h = _FD_STEP
                g = ((c.margin(self.geo(x1 + h, x2)) - c.margin(self.geo(x1 - h, x2))) / (2 * h),
                     (c.margin(self.geo(x1, x2 + h)) - c.margin(self.geo(x1, x2 - h))) / (2 * h))
            grads.append(np.stack([np.broadcast_to(g[0], geo["a"].shape), np.broadcast_to(g[1], geo["a"].shape)]))
        return np.stack(grads) if grads else np.zeros((0, 2) + geo["a"].shape)

    def pieces(self, geo) -> np.ndarray:
        """(P, ...) pieces whose minimum is the maximised function F = sense·fun."""
        name = self.objective.name
        if name == "max_x_sum":
            return (geo["_x1"] + geo["_x2"])[None]
        if name == "max_eps_alpha":
            return geo["eps_alpha"][None]
        if name == "min_specific_pressure":
            return -geo["spec_pressure_pitch"][None]
        if name == "balanced_sliding":
            return np.stack([-np.abs(geo["sliding1_root"]), -np.abs(geo["sliding2_root"])])
        if name == "max_margin":
            return np.zeros((1,) + geo["a"].shape)
        raise AssertionError(name)

    def piece_gradients(self, geo, x1, x2) -> np.ndarray:
        """(P, 2, ...) gradients of :meth:`pieces` (analytic where cheap, else central differences)."""
        name = self.objective.name
        shape = geo["a"].shape
        if name == "max_x_sum":
            return np.ones((1, 2) + shape)
        if name == "max_eps_alpha":
            g = _checks.ContactRatio().gradient(geo)
            return np.stack([np.broadcast_to(g[0], shape), np.broadcast_to(g[1], shape)])[None]
        if name == "max_margin":
            return np.zeros((1, 2) + shape)
        if name == "min_specific_pressure":
            # Γ ∝ 1/tan α_w depends on x1 + x2 only: ∂(−Γ)/∂x_j = Γ · 2 tan α / (z_Σ tan³α_w cos²α_w)
            t_w = geo["_sin_w"] / np.sqrt(1.0 - geo["_sin_w"] ** 2)
            cos2 = 1.0 - geo["_sin_w"] ** 2
            g = geo["spec_pressure_pitch"] * 2.0 * geo["_ta"] / ((geo["_z1"] + geo["_z2"]) * t_w ** 3 * cos2)
            return np.stack([g, g])[None]
        return self._fd_gradient(self.pieces, x1, x2)

    def _fd_gradient(self, func, x1, x2) -> np.ndarray:
        """(R, 2, n) central differences of func(geo) -> (R, n), all four shifted points in one call."""
        h = _FD_STEP
        x1, x2 = np.ravel(x1), np.ravel(x2)
        n = x1.size
        geo4 = self.geo(np.concatenate([x1 + h, x1 - h, x1, x1]), np.concatenate([x2, x2, x2 + h, x2 - h]))
        f4 = np.asarray(func(geo4)).reshape(-1, 4, n)
        return np.stack([(f4[:, 0] - f4[:, 1]) / (2 * h), (f4[:, 2] - f4[:, 3]) / (2 * h)], axis=1)

    def _normalised(self, geo) -> np.ndarray:
        """(K, n) margin/‖∇margin‖: each check's first-order distance in x to its boundary."""
        M = self.margins(geo)
        G = self.margin_gradients(geo, geo["_x1"], geo["_x2"])
        with np.errstate(invalid="ignore", divide="ignore"):
            P = M / np.sqrt(G[:, 0] ** 2 + G[:, 1] ** 2)
        return np.where(np.isfinite(P), P, -np.inf)

    def fun(self, geo) -> np.ndarray:
        """The objective in its natural sense (what the user asked to max- or minimise)."""
        if self.objective.kind == "margin":
            return self._normalised(geo).min(axis=0)
        return self.objective.sense * self.pieces(geo).min(axis=0)

    # --- the design variables -----------------------------------------------------------
    @property
    def nvar(self) -> int:
        """Free variables: (x1, x2), or x1 alone when the x-sum is fixed."""
        return 2 if self.x_sum is None else 1

    def xy(self, V):
        """(x1, x2) arrays from free-variable points V of shape (n, nvar)."""
        V = np.atleast_2d(np.asarray(V, dtype=float))
        if self.x_sum is None:
            return V[:, 0], V[:, 1]
        return V[:, 0], self.x_sum - V[:, 0]

    def evaluate(self, V, grads: bool = True):
        """Pieces (P, n) and margins (K, n) at points V (n, nvar), and with ``grads`` their
        gradients in the free variables, (P, nvar, n) and (K, nvar, n).

        Every objective is "maximise the smallest piece subject to margins >= 0": one piece for
        smooth objectives, two for balanced sliding, and the normalised margins for max_margin.
        """
        x1, x2 = self.xy(V)
        geo = self.geo(x1, x2)
        M = self.margins(geo)
        P = self._normalised(geo) if self.objective.kind == "margin" else self.pieces(geo)
        if not grads:
            return P, M
        GM = self.margin_gradients(geo, x1, x2)
        if self.objective.kind == "margin":
            GP = self._fd_gradient(self._normalised, x1, x2)
        else:
            GP = self.piece_gradients(geo, x1, x2)
        if self.x_sum is not None:   # d/dx1 along x2 = x_sum − x1
            GM = (GM[:, 0] - GM[:, 1])[:, None]
            GP = (GP[:, 0] - GP[:, 1])[:, None]
        return P, M, GP, GM


# The x window searched: [−1.5, 3] covers every shift used in practice (handbook blocking
# contours span about −1 … 2.5); with the default checks the tip thickness closes the region
# from above and undercut from below, well inside it.
DEFAULT_BOUNDS = (-1.5, 3.0)

