"""A gear stage's efficiency from its losses: the mesh's load-dependent loss (ISO/TR 14179-2,
:mod:`geardesign.gears.efficiency`), a given no-load loss, and the friction of the stage's rolling bearings
(SKF model, :mod:`geardesign.drives.bearing_friction`): η = 1 − P_loss/P_in, P_loss = P_VZP + P_VZ0 + ΣP_VL.

:func:`stage_efficiency` is what a drive calls for each gear stage; the heat to dissipate is P_loss.
Not modelled (docs/efficiency.md): the gears' churning and windage (ISO/TR 14179-1's formula was read only
without its units and coefficients, ISO/TR 14179-2's and Changenet-Velex's not at all; give a measured or
estimated ``no_load_loss_w``), seals, the oil pump, the bearings' oil-bath drag.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import pandas as pd

from ..errors import GearDesignError
from ..gears.efficiency import Lubricant, MeshLoss, mesh_loss
from ..results import Result
from ..validate import one_number, require_choice, require_range
from .bearing_friction import K_RS, bearing_friction

__all__ = ["BearingLoad", "StageEfficiency", "stage_efficiency"]


@dataclass(frozen=True)
class BearingLoad:
    """A bearing of the stage: its catalog ``designation`` (deep groove ball, series 62/63), the ``shaft``
    it sits on (1: gear 1's, 2: gear 2's, turning at that gear's speed) and its radial and axial loads (N)."""

    designation: str
    shaft: int
    F_r_n: float
    F_a_n: float = 0.0

    def __post_init__(self):
        if self.shaft not in (1, 2) or isinstance(self.shaft, bool):
            raise GearDesignError(f"shaft must be 1 or 2 (the gear whose shaft carries the bearing), "
                                  f"got {self.shaft!r}")


@dataclass(frozen=True)
class StageEfficiency(Result):
    """Losses (W) and efficiency of one gear stage (see :func:`stage_efficiency`)."""

    power_in_w: float
    mesh_loss_w: float
    no_load_loss_w: float
    bearing_loss_w: float
    loss_w: float
    efficiency: float
    mesh_efficiency: float
    mesh: MeshLoss
    bearings: tuple
    oil_temperature_c: float
    viscosity_mm2s: float
    eta_mpas: float

    _success_field = "finite"
    _table_fields = ("table",)

    @property
    def finite(self) -> bool:
        return math.isfinite(self.efficiency)

    @property
    def heat_w(self) -> float:
        """The heat the stage gives off, P_loss (W)."""
        return self.loss_w

    @property
    def table(self) -> pd.DataFrame:
        rows = [("mesh, load-dependent (ISO/TR 14179-2)", self.mesh_loss_w),
                ("mesh, no-load (given)", self.no_load_loss_w)]
        rows += [(f"bearing {b.designation}, {b.n_rpm:.6g} rpm (SKF model)", b.power_loss_w) for b in self.bearings]
        t = pd.DataFrame(rows, columns=["loss", "power_w"])
        t["share_of_input"] = t["power_w"] / self.power_in_w
        return t

    def to_dict(self) -> dict:
        out = {k: v for k, v in super().to_dict().items() if k not in ("mesh", "bearings")}
        out["mu_mz"], out["H_V"], out["H_V_ohlendorf"] = self.mesh.mu_mz, self.mesh.H_V, self.mesh.H_V_ohlendorf
        out["bearings"] = [{"designation": b.designation, "n_rpm": b.n_rpm, "M_nmm": b.M_nmm,
                            "power_loss_w": b.power_loss_w} for b in self.bearings]
        return out

    def __repr__(self) -> str:
        return (f"StageEfficiency(η = {self.efficiency:.5f}: P_in = {self.power_in_w:.6g} W, losses mesh "
                f"{self.mesh_loss_w:.4g} W (μ_mZ = {self.mesh.mu_mz:.4f}, H_V = {self.mesh.H_V:.4f}), no-load "
                f"{self.no_load_loss_w:.4g} W, bearings {self.bearing_loss_w:.4g} W)")


def stage_efficiency(pair, load, lubricant: Lubricant, oil_temperature_c: float, Ra_um: float = 0.5,
                     bearings=None, no_load_loss_w: float = 0.0, lubrication: str = "oil_bath",
                     method: str = "integrated") -> StageEfficiency:
    """Losses and efficiency of the gear stage ``pair`` (a :class:`~geardesign.gears.pair.GearPair` with its
    face width) under ``load`` (a :class:`~geardesign.gears.strength.Load`: torque or power at the speed of
    the gear it names; the power it gives is the stage's input), with ``lubricant`` at
    ``oil_temperature_c``, the flanks' mean roughness ``Ra_um`` = (R_a1 + R_a2)/2 (µm), the stage's
    ``bearings`` (:class:`BearingLoad` items, or None), a ``no_load_loss_w`` of the gears (churning, not
    computed: 0 unless given) and the bearings' ``lubrication`` ("oil_bath", "oil_jet", "grease", "oil_air").

    η = 1 − (P_VZP + P_VZ0 + ΣP_VL)/P_in. An FZG type C pair at 200 N·m and 1500 rpm, ISO VG 100 at 70 °C:

    >>> from geardesign.gears.pair import GearPair
    >>> from geardesign.gears.strength import Load
    >>> pair = GearPair(4.5, 16, 24, 0.1817, 0.1715, face_width_mm=14)
    >>> r = stage_efficiency(pair, Load(torque_nm=200, n_rpm=1500), Lubricant(100, 11), 70.0,
    ...                      bearings=[BearingLoad("6306", 1, 3000), BearingLoad("6306", 1, 3000)])
    >>> 0.98 < r.efficiency < r.mesh_efficiency < 1.0
    True
    """
    from ..gears.strength.load import Load

    if not isinstance(load, Load):
        raise GearDesignError(f"load must be a geardesign Load (torque or power at a speed), got {load!r}")
    if not isinstance(lubricant, Lubricant):
        raise GearDesignError(f"lubricant must be a geardesign Lubricant (viscosities at 40 and 100 °C), "
                              f"got {lubricant!r}")
    t_oil = one_number("oil_temperature_c", require_range("oil_temperature_c", oil_temperature_c, -40.0, 200.0,
                                                          unit="°C"))
    p0 = one_number("no_load_loss_w", require_range("no_load_loss_w", no_load_loss_w, 0.0, 1e9, unit="W"))
    require_choice("lubrication", lubrication, tuple(K_RS))
    z1, z2 = pair.z1, pair.z2
    if load.on_gear == 1:
        T1, n1 = load.torque_nm, load.n_rpm
    else:
        T1, n1 = load.torque_nm * z1 / z2, load.n_rpm * z2 / z1
    n_shaft = {1: n1, 2: n1 * z1 / z2}
    nu = float(lubricant.viscosity_mm2s(t_oil))
    eta = float(lubricant.dynamic_viscosity_mpas(t_oil))
    mesh = mesh_loss(pair, T1, n1, eta, Ra_um, lubricant.lubricant_factor, method=method)
    frictions = []
    if bearings is not None and not isinstance(bearings, (list, tuple)):
        raise GearDesignError(f"bearings must be a list of BearingLoad items, got {type(bearings).__name__}")
    for b in bearings or ():
        if not isinstance(b, BearingLoad):
            raise GearDesignError(f"bearings must hold BearingLoad items (designation, shaft, F_r_n, F_a_n), got {b!r}")
        frictions.append(bearing_friction(b.designation, b.F_r_n, b.F_a_n, n_shaft[b.shaft], nu, lubrication))
    frictions = tuple(frictions)
    p_bearings = sum(f.power_loss_w for f in frictions)
    p_in = mesh.power_w
    loss = mesh.loss_w + p0 + p_bearings
    if not loss < p_in:         # no efficiency in (0, 1]: at a vanishing power it was −inf (fuzz)
        raise GearDesignError(f"the stage's losses ({loss:.4g} W: mesh {mesh.loss_w:.4g}, bearings {p_bearings:.4g}, "
                              f"no-load {p0:.4g}) reach its input power ({p_in:.4g} W): it does not run at this load")
    return StageEfficiency(power_in_w=p_in, mesh_loss_w=mesh.loss_w, no_load_loss_w=p0, bearing_loss_w=p_bearings,
                           loss_w=loss, efficiency=1.0 - loss / p_in, mesh_efficiency=1.0 - mesh.loss_w / p_in,
                           mesh=mesh, bearings=frictions, oil_temperature_c=t_oil, viscosity_mm2s=nu, eta_mpas=eta)
