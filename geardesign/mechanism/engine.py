"""A piston engine: identical slider-cranks on one crankshaft, each with its firing phase, and the crankshaft's torque
over the working cycle (:class:`Engine`, :class:`EngineTorque`, :func:`engine_torque`).

Every cylinder has the same torque curve M(φ) (gas and inertia forces, seed 004), shifted by its firing phase ψ_c:
M_c(φ) = M(φ − ψ_c). The cycle angle φ is cylinder 1's: from the top dead centre at the start of intake for a
four-stroke engine (firing at 360°), from the firing top dead centre for a two-stroke one.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..errors import GearDesignError
from ..results import Result, compact_repr
from ..validate import hint_unknown_arguments, one_number, require_count, require_finite, require_range
from .cylinders import (CYLINDERS_MAX, crank_pin_torques, even_phases, excess_work, firing_phases,
                        fluctuation_coefficient, journal_torques, reversal_angles)
from .kinematics import SPEED_RANGE_RPM, crank_speed, state
from .kinetostatics import GRAVITY_M_S2, forces_from_state
from .pressure import ATMOSPHERE_MPA, PRESSURE_RANGE_MPA, IndicatorDiagram, gas_force
from .slider_crank import INERTIA_MAX_KG_M2, SliderCrank

__all__ = ["Engine", "EngineTorque", "TorqueCurve", "engine_torque", "POINTS_RANGE", "SPEED_RANGE_RPM"]

POINTS_RANGE = (8, 100_000)         # samples over the cycle (100 000: 0.0072° steps over 720°)


@dataclass(frozen=True, eq=False)
class TorqueCurve:
    """The crankshaft's torque over one working cycle: what a load spectrum counts. It unpacks as three,
    ``angle, torque, n = curve``: ``crank_angle_deg`` evenly spaced over [0, cycle), ``torque_nm`` the resultant on
    the last journal (driving: positive in the power stroke), ``n_rpm`` the crankshaft's mean speed."""

    crank_angle_deg: np.ndarray
    torque_nm: np.ndarray
    n_rpm: float

    def __iter__(self):
        return iter((self.crank_angle_deg, self.torque_nm, self.n_rpm))

    def __repr__(self) -> str:
        return (f"TorqueCurve({self.crank_angle_deg.size} points, torque {self.torque_nm.min():.6g} … "
                f"{self.torque_nm.max():.6g} N·m, {self.n_rpm:g} rpm)")


@dataclass(frozen=True)
class Engine:
    """An engine of ``cylinders`` identical slider-cranks (``mechanism``, with its ``cylinder_bore_mm``) under one
    indicator diagram ``diagram`` (its ``strokes``: 2 or 4), turning at ``n_rpm``.

    Firing phases: ``phases_deg`` given per cylinder (degrees of cylinder 1's cycle, cylinder 1 at 0), or from
    ``throws_deg`` and ``firing_order`` (:func:`~geardesign.mechanism.cylinders.firing_phases`), or even firing
    along ``firing_order`` (cylinder order by default). Cylinders are numbered from the front (timing-gear) end.
    ``mechanical_efficiency`` η_m gives the effective torque M_e = η_m·M_i; ``flywheel_inertia_kg_m2`` (everything
    turning with the crankshaft) the coefficient of fluctuation. ``axis_tilts_deg`` tilts each cylinder's axis from the
    upward vertical in the sense of rotation (a V engine's banks; default upright), which turns its weights
    (``gravity_m_s2`` = 0 leaves them out); a V engine's bank angle also goes into its throws (cylinder 1's crank
    angle when that cylinder is at top dead centre).
    """

    mechanism: SliderCrank
    diagram: IndicatorDiagram
    n_rpm: float
    cylinders: int = 1
    firing_order: tuple | None = None
    throws_deg: tuple | None = None
    phases_deg: tuple | None = None
    mechanical_efficiency: float | None = None
    flywheel_inertia_kg_m2: float | None = None
    crankcase_pressure_mpa: float = ATMOSPHERE_MPA
    gravity_m_s2: float = GRAVITY_M_S2
    axis_tilts_deg: tuple | None = None
    name: str = ""
    _phases: np.ndarray = field(init=False, repr=False, compare=False, default=None)
    _tilts: np.ndarray = field(init=False, repr=False, compare=False, default=None)

    def __post_init__(self):
        if not isinstance(self.mechanism, SliderCrank):
            raise GearDesignError(f"mechanism must be a SliderCrank, got {type(self.mechanism).__name__}")
        if not isinstance(self.diagram, IndicatorDiagram):
            raise GearDesignError(f"diagram must be an IndicatorDiagram, got {type(self.diagram).__name__}")
        self.mechanism.need_bore()
        one_number("n_rpm", require_range("n_rpm", self.n_rpm, *SPEED_RANGE_RPM, lo_open=True, unit="rpm"))
        if not isinstance(self.name, str):
            raise GearDesignError(f"name must be text, got {self.name!r}")
        n = require_count("cylinders", self.cylinders, 1, CYLINDERS_MAX)
        cycle = self.diagram.cycle_deg
        if self.phases_deg is not None:
            if self.throws_deg is not None or self.firing_order is not None:
                raise GearDesignError("give phases_deg, or throws_deg with firing_order, not both")
            phases = np.asarray(require_range("phases_deg", self.phases_deg, 0.0, cycle, hi_open=True), float).ravel()
            if phases.size != n:
                raise GearDesignError(f"phases_deg must give one phase per cylinder ({n}), got {phases.size}")
        elif self.throws_deg is not None:
            throws = np.ravel(self.throws_deg)
            if throws.size != n:
                raise GearDesignError(f"throws_deg must give one crank angle per cylinder ({n}), got {throws.size}")
            if self.firing_order is None and self.diagram.strokes == 4 and n > 1:
                raise GearDesignError("a four-stroke engine's throws_deg need its firing_order (each cylinder "
                                      "reaches top dead centre twice per cycle)")
            order = self.firing_order if self.firing_order is not None else \
                tuple(int(i) + 1 for i in np.argsort(np.mod(throws, 360.0), kind="stable"))
            phases = firing_phases(throws, order, cycle)
        else:
            phases = even_phases(n, cycle, self.firing_order)
        if self.mechanical_efficiency is not None:
            one_number("mechanical_efficiency", require_range("mechanical_efficiency", self.mechanical_efficiency,
                                                              0.0, 1.0, lo_open=True))
        if self.flywheel_inertia_kg_m2 is not None:
            one_number("flywheel_inertia_kg_m2", require_range(
                "flywheel_inertia_kg_m2", self.flywheel_inertia_kg_m2, 0.0, INERTIA_MAX_KG_M2, lo_open=True,
                unit="kg·m²"))
        one_number("crankcase_pressure_mpa", require_range("crankcase_pressure_mpa", self.crankcase_pressure_mpa,
                                                           *PRESSURE_RANGE_MPA, unit="MPa"))
        one_number("gravity_m_s2", require_range("gravity_m_s2", self.gravity_m_s2, 0.0, 100.0, unit="m/s²"))
        tilts = np.zeros(n)
        if self.axis_tilts_deg is not None:
            tilts = np.asarray(require_range("axis_tilts_deg", self.axis_tilts_deg, -180.0, 180.0), float).ravel()
            if tilts.size != n:
                raise GearDesignError(f"axis_tilts_deg must give one tilt per cylinder ({n}), got {tilts.size}")
        object.__setattr__(self, "_phases", phases)
        object.__setattr__(self, "_tilts", tilts)

    @property
    def cycle_deg(self) -> float:
        return self.diagram.cycle_deg

    @property
    def phases(self) -> np.ndarray:
        """The firing phase of each cylinder 1..n (degrees of cylinder 1's cycle)."""
        return self._phases.copy()

    def cylinder_torque(self, crank_angle_deg, cylinder: int = 1) -> np.ndarray:
        """The driving torque (N·m) of cylinder ``cylinder`` (1..n: its axis's tilt) at its own cycle angles
        (degrees): gas, inertia and weights."""
        c = int(require_count("cylinder", cylinder, 1, self.cylinders))
        return self._torques(require_finite("crank_angle_deg", crank_angle_deg), self._tilts[c - 1])[1]

    def _torques(self, own_deg, tilt_deg=0.0):
        """(gas torque, whole torque) of one cylinder at its own cycle angles (N·m): the kinematics once."""
        mech = self.mechanism
        fg = gas_force(self.diagram.pressure(own_deg), mech.cylinder_bore_mm, self.crankcase_pressure_mpa)
        st = state(np.radians(own_deg), mech.crank_radius_mm, mech.rod_length_mm, mech.offset_mm,
                   crank_speed(self.n_rpm))
        tau = np.radians(tilt_deg)       # gravity in the cylinder's frame (kinetostatics._gravity)
        g = self.gravity_m_s2
        forces = forces_from_state(mech, own_deg, st, fg, -g * np.sin(tau), -g * np.cos(tau))
        return fg * st.v / st.omega, forces.torque_nm      # the gas torque F_g·v_B/ω (virtual power)

    def analyse(self, points: int = 720) -> EngineTorque:
        """The torque curves over one cycle at ``points`` even crank angles: per cylinder, summed, on every journal
        and crank pin, with the mean, extremes, unevenness, reversals and (with an inertia) the fluctuation."""
        points = require_count("points", points, *POINTS_RANGE)
        cycle = self.cycle_deg
        step = cycle / points
        phi = np.arange(points) * step
        shift = self._phases / step
        same = self.gravity_m_s2 == 0 or bool(np.all(self._tilts == self._tilts[0]))
        on_grid = same and bool(np.all(np.abs(shift - np.round(shift)) <= 1e-9))
        # identical cylinders: with every phase on the grid, one cylinder's curve rolled by its phase is each
        # cylinder's (the same numbers at the same angles); otherwise each is evaluated at its own angles
        if on_grid:         # cylinder c at sample j is the one curve at sample j − k_c (round the cycle)
            gas, torque = self._torques(phi, self._tilts[0])
            idx = (np.arange(points)[None, :] - np.round(shift).astype(int)[:, None]) % points
            per_cyl, gas = torque[idx], gas[idx]
        else:               # one cylinder at a time: the temporaries stay one curve long
            both = [self._torques(phi - p, t) for p, t in zip(self._phases, self._tilts)]
            gas = np.stack([g for g, _ in both])
            per_cyl = np.stack([m for _, m in both])
        gas = gas.sum(axis=0)
        total = per_cyl.sum(axis=0)
        mean = float(total.mean())
        _, swing = excess_work(total, cycle)
        delta = (fluctuation_coefficient(swing, self.flywheel_inertia_kg_m2, self.n_rpm)
                 if self.flywheel_inertia_kg_m2 is not None else None)
        # no unevenness without work over the cycle (μ's mean would be <= 0): None, as the summary says
        mu = float((total.max() - total.min()) / mean) if mean > 0 else None
        eta = self.mechanical_efficiency
        return EngineTorque(
            engine=self, crank_angle_deg=phi, cylinder_torque_nm=per_cyl, torque_nm=total, gas_torque_nm=gas,
            inertia_torque_nm=total - gas, journal_torque_nm=journal_torques(per_cyl),
            crank_pin_torque_nm=crank_pin_torques(per_cyl), mean_torque_nm=mean,
            effective_torque_nm=None if eta is None else eta * mean, max_torque_nm=float(total.max()),
            min_torque_nm=float(total.min()), unevenness=mu, reversal_angles_deg=reversal_angles(phi, total),
            excess_work_j=swing, fluctuation=delta, power_kw=mean * float(crank_speed(self.n_rpm)) / 1000.0)

    def torque_curve(self, points: int = 720) -> TorqueCurve:
        """(crank angles (deg), the resultant torque (N·m), the speed (rpm)) over one cycle: :func:`engine_torque`."""
        return self.analyse(points).curve()

    def __repr__(self) -> str:
        return compact_repr(self)


hint_unknown_arguments(Engine, {"speed_rpm": "the crankshaft's speed is n_rpm",
                                "eta_m": "the mechanical efficiency is mechanical_efficiency",
                                "firing_phases_deg": "name them phases_deg"})


@dataclass(frozen=True, repr=False)
class EngineTorque(Result):
    """The crankshaft's torque over one working cycle of an :class:`Engine` (arrays over ``crank_angle_deg``).

    ``torque_nm`` is the resultant (the last journal's, driving the load), ``cylinder_torque_nm`` (cylinders ×
    points) each cylinder's, ``journal_torque_nm`` (cylinders + 1 × points) and ``crank_pin_torque_nm`` seed 004's
    M_zi and M_qi; ``gas_torque_nm`` + ``inertia_torque_nm`` = ``torque_nm`` (inertia including the weights). The mean
    is the indicated torque M_i, ``unevenness`` μ = (M_max − M_min)/M_mean (None when M_mean <= 0), ``excess_work_j``
    the swing ΔE of the excess work, ``fluctuation`` δ = ΔE/(J·ω²) when the engine has a flywheel inertia.
    """

    engine: Engine
    crank_angle_deg: np.ndarray
    cylinder_torque_nm: np.ndarray
    torque_nm: np.ndarray
    gas_torque_nm: np.ndarray
    inertia_torque_nm: np.ndarray
    journal_torque_nm: np.ndarray
    crank_pin_torque_nm: np.ndarray
    mean_torque_nm: float
    effective_torque_nm: float | None
    max_torque_nm: float
    min_torque_nm: float
    unevenness: float | None
    reversal_angles_deg: np.ndarray
    excess_work_j: float
    fluctuation: float | None
    power_kw: float

    @property
    def success(self) -> bool:
        """True when the engine does work over the cycle (a positive mean torque)."""
        return self.mean_torque_nm > 0

    @property
    def n_rpm(self) -> float:
        return float(self.engine.n_rpm)

    def curve(self) -> TorqueCurve:
        """(crank_angle_deg, torque_nm, n_rpm): the resultant torque over the cycle, for a load spectrum."""
        return TorqueCurve(self.crank_angle_deg.copy(), self.torque_nm.copy(), self.n_rpm)

    def table(self):
        """One row per crank angle: the resultant, gas and inertia torques, each cylinder's, each journal's (M_z1 …)
        and each crank pin's (M_q1 …), N·m."""
        import pandas as pd

        cols = {"crank_angle_deg": self.crank_angle_deg, "torque_nm": self.torque_nm,
                "gas_torque_nm": self.gas_torque_nm, "inertia_torque_nm": self.inertia_torque_nm}
        for i, m in enumerate(self.cylinder_torque_nm, 1):
            cols[f"cylinder{i}_torque_nm"] = m
        for i, m in enumerate(self.journal_torque_nm, 1):
            cols[f"journal{i}_torque_nm"] = m
        for i, m in enumerate(self.crank_pin_torque_nm, 1):
            cols[f"crank_pin{i}_torque_nm"] = m
        return pd.DataFrame(cols)

    def to_frame(self):
        return self.table()

    def summary(self) -> list[str]:
        """The result in a few lines: what a user reads first."""
        e = self.engine
        lines = [f"{e.cylinders}-cylinder {e.diagram.strokes}-stroke engine at {e.n_rpm:g} rpm, firing phases "
                 + ", ".join(f"{p:g}" for p in e.phases) + f" deg; {self.crank_angle_deg.size} points over "
                 f"{e.cycle_deg:g} deg",
                 f"mean (indicated) torque M_i = {self.mean_torque_nm:.6g} N·m, indicated power "
                 f"{self.power_kw:.6g} kW"]
        if self.effective_torque_nm is not None:
            lines.append(f"effective torque M_e = η_m·M_i = {e.mechanical_efficiency:g} × {self.mean_torque_nm:.6g} "
                         f"= {self.effective_torque_nm:.6g} N·m")
        mu = (f"unevenness μ = (M_max − M_min)/M_mean = {self.unevenness:.4g}" if self.success else
              "no unevenness: the mean torque is not positive (the engine does no work over the cycle)")
        lines.append(f"torque {self.min_torque_nm:.6g} … {self.max_torque_nm:.6g} N·m, {mu}")
        rev = self.reversal_angles_deg
        lines.append("the torque reverses at " + ", ".join(f"{a:.1f}" for a in rev) + " deg" if rev.size
                     else "the torque keeps its sign over the cycle")
        lines.append(f"excess work swing ΔE = {self.excess_work_j:.6g} J" + (
            f"; coefficient of fluctuation δ = ΔE/(J·ω²) = {self.fluctuation:.4g} with J = "
            f"{e.flywheel_inertia_kg_m2:g} kg·m²" if self.fluctuation is not None else ""))
        return lines

    def plot(self, ax=None, journals: bool = False):
        """The torque curves (:func:`geardesign.mechanism.plot.plot_torque`)."""
        from .plot import plot_torque

        return plot_torque(self, ax=ax, journals=journals)

    def to_dict(self) -> dict:
        from ..results import plain

        out = {k: plain(getattr(self, k)) for k in ("mean_torque_nm", "effective_torque_nm", "max_torque_nm",
                                                     "min_torque_nm", "unevenness", "reversal_angles_deg",
                                                     "excess_work_j", "fluctuation", "power_kw")}
        out.update(n_rpm=self.n_rpm, cylinders=self.engine.cylinders, strokes=self.engine.diagram.strokes,
                   phases_deg=plain(self.engine.phases), points=int(self.crank_angle_deg.size),
                   success=self.success, status=self.status)
        return out

    def __repr__(self) -> str:
        return "EngineTorque(" + "\n  ".join(self.summary()) + ")"


def engine_torque(engine: Engine, points: int = 720) -> TorqueCurve:
    """The crankshaft's resultant torque over one working cycle of ``engine`` at ``points`` even crank angles:
    ``(crank_angle_deg, torque_nm, n_rpm)`` — the curve a load spectrum counts.

    >>> mech = SliderCrank(70, 250, rod_cg_mm=75, piston_mass_kg=2.0, rod_mass_kg=4.7, cylinder_bore_mm=120)
    >>> diagram = IndicatorDiagram.otto(70, 250, 7.0, peak_pressure_mpa=4.5)
    >>> angle, torque, n = engine_torque(Engine(mech, diagram, 1700, cylinders=2), points=720)
    >>> angle.shape, torque.shape, n
    ((720,), (720,), 1700.0)
    """
    if not isinstance(engine, Engine):
        raise GearDesignError(f"engine must be an Engine, got {type(engine).__name__}")
    return engine.analyse(points).curve()
