"""The scene schema: a tiny language of typed keys, and one table of keys per section, built from
the library's own defaults, ranges and choices (each section's table imports only what that
section models, on first use)."""
from __future__ import annotations

import functools
import math
import sys
import warnings
from dataclasses import dataclass

from ..errors import GearDesignError
from ..validate import _short

__all__ = ["SECTIONS", "section_schema", "validate_table", "Where", "type_name", "engine_schema"]

SECTIONS = ("engine", "gear", "teeth", "planetary", "chain", "key", "study", "drive")


@dataclass(frozen=True)
class _Key:
    """One scene key: its kind, whether it is required, its default and its range."""

    kind: str                   # "float", "int", "bool", "str", "choice", "floats", "ints", "float_or_str"
    required: bool = False
    default: object = None
    lo: float | None = None
    hi: float | None = None
    lo_open: bool = False
    choices: tuple = ()
    length: int | None = None   # for lists: exact length

    def expected(self) -> str:
        rng = ""
        if self.lo is not None or self.hi is not None:
            left = "(" if self.lo_open else "["
            lo = "-inf" if self.lo is None else f"{self.lo:g}"
            hi = "inf" if self.hi is None else f"{self.hi:g}"
            rng = f" in {left}{lo}, {hi}]"
        if self.kind == "float":
            return "a number" + rng
        if self.kind == "int":
            return "a whole number" + rng
        if self.kind == "bool":
            return "true or false"
        if self.kind == "str":
            return "a string"
        if self.kind == "choice":
            return "one of " + ", ".join(repr(c) for c in self.choices)
        if self.kind == "float_or_str":
            return "a number" + rng + " or one of " + ", ".join(repr(c) for c in self.choices)
        n = f"a list of {self.length} " if self.length else "a list of "
        what = "numbers" if self.kind == "floats" else "whole numbers"
        return f"{n}{what}{rng}"


def _F(**kw):
    return _Key("float", **kw)


def _I(**kw):
    return _Key("int", **kw)


def _rack_schema() -> dict:
    from ..gears.rack import ALPHA_RANGE_DEG, C_RANGE, HA_RANGE, BasicRack

    std = BasicRack()
    return {"alpha_deg": _F(default=std.alpha_deg, lo=ALPHA_RANGE_DEG[0], hi=ALPHA_RANGE_DEG[1]),
            "ha": _F(default=std.ha, lo=HA_RANGE[0], hi=HA_RANGE[1]),
            "c": _F(default=std.c, lo=C_RANGE[0], hi=C_RANGE[1]),
            "rho_f": _F(default=std.rho_f, lo=0.0)}   # its upper limit depends on the rest: BasicRack checks it


def _checks_schema() -> dict:
    """One key per registered check option (:func:`geardesign.gears.checks.options`)."""
    from ..gears.checks import options

    return {name: (_F(lo=opt.range[0], hi=opt.range[1]) if opt.kind == "limit" else _Key("bool"))
            for name, opt in options().items()}


def _shift_keys() -> dict:
    """Keys the [gear] and [teeth] sections share with optimize_shifts: the solver, the checks,
    the rack and the kind of pair (helical: ``module`` is the normal module; internal: gear 2 is
    a ring with z2 > z1 teeth)."""
    from ..gears.mesh import BETA_RANGE_DEG, FACE_WIDTH_RANGE_MM
    from ..shifts.objectives import OBJECTIVES
    from ..shifts.optimize import METHODS

    return {"beta_deg": _F(default=0.0, lo=BETA_RANGE_DEG[0], hi=BETA_RANGE_DEG[1]),
            "internal": _Key("bool", default=False),
            "face_width_mm": _F(lo=FACE_WIDTH_RANGE_MM[0], hi=FACE_WIDTH_RANGE_MM[1], lo_open=True),
            "objective": _Key("choice", choices=tuple(OBJECTIVES)),   # default: max_x_sum, or balanced_sliding with a_w
            "method": _Key("choice", default="exact", choices=METHODS),
            "checks": _checks_schema(), "rack": _rack_schema(), "load": _load_schema()}


def _load_schema() -> dict:
    """[gear.load]: the load case of the strength checks (ISO 6336), as :class:`geardesign.gears.strength.Load`
    and the materials of the catalog, and the strength model's options (accuracy_grade, nu40, ..., [gear.load.factors];
    :data:`geardesign.gears.strength.user_options.STRENGTH_OPTIONS`); the face width is the section's
    ``face_width_mm``."""
    from ..gears.strength.load import (APPLICATION_FACTOR_RANGE, LIFE_RANGE_H, POWER_RANGE_KW, SPEED_RANGE_RPM,
                                       TORQUE_RANGE_NM)
    from ..gears.strength.user_options import scene_keys as strength_scene_keys

    return {"torque_nm": _F(lo=TORQUE_RANGE_NM[0], hi=TORQUE_RANGE_NM[1], lo_open=True),
            "power_kw": _F(lo=POWER_RANGE_KW[0], hi=POWER_RANGE_KW[1], lo_open=True),
            "n_rpm": _F(required=True, lo=SPEED_RANGE_RPM[0], hi=SPEED_RANGE_RPM[1], lo_open=True),
            "on_gear": _I(default=1, lo=1, hi=2),
            "application_factor": _F(default=1.0, lo=APPLICATION_FACTOR_RANGE[0], hi=APPLICATION_FACTOR_RANGE[1]),
            "life_h": _F(lo=LIFE_RANGE_H[0], hi=LIFE_RANGE_H[1], lo_open=True),
            "material": _Key("str", required=True), "material2": _Key("str"),
            # the strength model's options (S_Hmin and S_Fmin: the section's [checks] limits)
            **{k: _stage_key(v) for k, v in strength_scene_keys(limits=False).items()}}


def _gear_schema() -> dict:
    from ..gears.geometry import M_RANGE_MM, X_ABS_MAX
    from ..gears.mesh import Z_MAX, Z_MIN
    from ..shifts.problem import DEFAULT_BOUNDS, X_WINDOW_LIMIT

    return {"module": _F(required=True, lo=M_RANGE_MM[0], hi=M_RANGE_MM[1]),
            "z1": _I(required=True, lo=Z_MIN, hi=Z_MAX), "z2": _I(required=True, lo=Z_MIN, hi=Z_MAX),
            "x1": _F(lo=-X_ABS_MAX, hi=X_ABS_MAX), "x2": _F(lo=-X_ABS_MAX, hi=X_ABS_MAX),
            "a_w": _F(lo=0.0, lo_open=True), "tip_shortening": _Key("bool", default=True),
            "bounds": _Key("floats", default=DEFAULT_BOUNDS, lo=-X_WINDOW_LIMIT, hi=X_WINDOW_LIMIT, length=2),
            "mesh_drawing": _Key("bool", default=False), "data_block": _Key("bool", default=False),
            "accuracy_class": _I(lo=1, hi=11), "spectrum": _spectrum_schema(), **_shift_keys()}


def _spectrum_schema() -> dict:
    """[gear.spectrum]: a load spectrum (ISO 6336-6) from a CSV file (relative to the scene; its columns:
    :meth:`geardesign.LoadSpectrum.from_csv`) or, without ``file`` in a scene with an ``[engine]``, the engine's
    torque curve counted per tooth and flank in ``levels`` classes (:meth:`geardesign.LoadSpectrum.from_curve`);
    the required life, the S-N curve beyond the knee, Y_M, the materials; the damage checks join the section's
    checks and the life is reported at the optimum (docs/life.md, docs/engine.md)."""
    from ..gears.spectrum import MEAN_STRESS_FACTOR_RANGE, SN_CURVES, SPEED_RANGE_RPM, TIME_RANGE_H
    from ..gears.strength.load import LIFE_RANGE_H

    return {"file": _Key("str"),
            "levels": _I(lo=1, hi=10_000),
            "n_rpm": _F(lo=SPEED_RANGE_RPM[0], hi=SPEED_RANGE_RPM[1], lo_open=True),
            "duration_h": _F(lo=TIME_RANGE_H[0], hi=TIME_RANGE_H[1], lo_open=True),
            "on_gear": _I(default=1, lo=1, hi=2),
            "life_h": _F(lo=LIFE_RANGE_H[0], hi=LIFE_RANGE_H[1], lo_open=True),
            "sn_curve": _Key("choice", default="iso", choices=SN_CURVES),
            "mean_stress_factor": _F(lo=MEAN_STRESS_FACTOR_RANGE[0], hi=MEAN_STRESS_FACTOR_RANGE[1]),
            "material": _Key("str", required=True), "material2": _Key("str")}


def _drive_spectrum_schema() -> dict:
    """[drive.spectrum]: the drive's load spectrum, a CSV file (relative to the scene; the columns of
    :meth:`geardesign.LoadSpectrum.from_csv`) of torques and speeds at the drive's input shaft (no ``n_rpm`` column:
    the input speed), read relative to its nominal input as every gear stage's duty cycle
    (:class:`geardesign.DutyCycle`); ``life_h`` the required life (and the hours a ``share`` column divides; a stage's
    own ``life_h`` wins; neither: the spectrum's duration), the S-N curve beyond the knee and Y_M of the stages that
    do not set their own (docs/drive_train.md)."""
    from ..gears.spectrum import MEAN_STRESS_FACTOR_RANGE, SN_CURVES
    from ..gears.strength.load import LIFE_RANGE_H

    return {"file": _Key("str", required=True),
            "life_h": _F(lo=LIFE_RANGE_H[0], hi=LIFE_RANGE_H[1], lo_open=True),
            "sn_curve": _Key("choice", choices=SN_CURVES),
            "mean_stress_factor": _F(lo=MEAN_STRESS_FACTOR_RANGE[0], hi=MEAN_STRESS_FACTOR_RANGE[1])}


def _teeth_schema() -> dict:
    from ..gears.geometry import M_RANGE_MM
    from ..gears.mesh import Z_MAX, Z_MIN

    return {"ratio": _F(required=True, lo=1.0, hi=20.0), "ratio_tol": _F(default=0.02, lo=0.0, hi=0.5),
            "module": _Key("float_or_str", lo=M_RANGE_MM[0], hi=M_RANGE_MM[1], choices=("series",)),
            "a_w": _Key("float_or_str", lo=0.0, lo_open=True, choices=("series",)),
            "z1_range": _Key("ints", default=(8, 40), lo=Z_MIN, hi=Z_MAX, length=2),
            "z_sum_max": _I(lo=2 * Z_MIN, hi=2 * Z_MAX), "top": _I(default=10, lo=1, hi=1000), **_shift_keys()}


def _planetary_schema() -> dict:
    from ..gears.geometry import M_RANGE_MM, X_ABS_MAX
    from ..gears.mesh import BETA_RANGE_DEG, Z_MAX, Z_MIN
    from ..gears.planetary import (ARRANGEMENTS, DEFAULT_NEIGHBOUR_CLEARANCE, N_PLANETS_RANGE,
                                   NEIGHBOUR_CLEARANCE_RANGE)
    from ..shifts.objectives import OBJECTIVES
    from ..shifts.optimize import METHODS
    from ..shifts.planetary_teeth import NONSTANDARD_MAX_RANGE, Z_SUN_RANGE_LIMIT

    z = dict(lo=Z_MIN, hi=Z_MAX)
    x = dict(lo=-X_ABS_MAX, hi=X_ABS_MAX)
    checks = _checks_schema()
    checks.pop("jamming")
    checks.pop("eps_gamma_min")
    checks["neighbour_clearance"] = _F(default=DEFAULT_NEIGHBOUR_CLEARANCE, lo=NEIGHBOUR_CLEARANCE_RANGE[0],
                                       hi=NEIGHBOUR_CLEARANCE_RANGE[1])
    return {"module": _F(required=True, lo=M_RANGE_MM[0], hi=M_RANGE_MM[1]),
            "n_planets": _I(required=True, lo=N_PLANETS_RANGE[0], hi=N_PLANETS_RANGE[1]),
            "z_sun": _I(**z), "z_planet": _I(**z), "z_ring": _I(**z),
            "x_sun": _F(**x), "x_planet": _F(**x), "x_ring": _F(**x), "a_w": _F(lo=0.0, lo_open=True),
            "arrangement": _Key("choice", default="ring_fixed", choices=tuple(ARRANGEMENTS)),
            "beta_deg": _F(default=0.0, lo=BETA_RANGE_DEG[0], hi=BETA_RANGE_DEG[1]),
            "objective": _Key("choice", choices=tuple(OBJECTIVES)),
            "method": _Key("choice", default="exact", choices=METHODS),
            "ratio": _F(lo=-1e4, hi=1e4), "ratio_tol": _F(default=0.02, lo=0.0, hi=0.5),
            "z_sun_range": _Key("ints", default=(12, 40), lo=Z_SUN_RANGE_LIMIT[0], hi=Z_SUN_RANGE_LIMIT[1], length=2),
            "nonstandard_max": _I(default=2, lo=NONSTANDARD_MAX_RANGE[0], hi=NONSTANDARD_MAX_RANGE[1]),
            "drawing": _Key("bool", default=True), "top": _I(default=10, lo=1, hi=1000),
            "checks": checks, "rack": _rack_schema(), "spectrum": _planetary_spectrum_schema()}


def _planetary_spectrum_schema() -> dict:
    """[planetary.spectrum]: a load spectrum on the sun (ISO 6336-6), spelled as [gear.spectrum] (a CSV ``file``
    relative to the scene, ``n_rpm``, ``duration_h``, ``life_h``, ``sn_curve``, ``mean_stress_factor``), with the
    set's materials (``material``, ``planet_material``, ``ring_material``) and the meshes' ``face_width_mm``; Y_M is
    needed (the planet's root bends both ways). The damage checks of both meshes join the set's checks
    (docs/life.md)."""
    from ..gears.mesh import FACE_WIDTH_RANGE_MM

    spec = _spectrum_schema()
    for k in ("levels", "on_gear", "material2"):     # the sun carries it; no [engine] curve; a set's materials
        spec.pop(k)
    spec["file"] = _Key("str", required=True)
    spec["mean_stress_factor"] = _F(required=True, lo=spec["mean_stress_factor"].lo, hi=spec["mean_stress_factor"].hi)
    spec.update(planet_material=_Key("str"), ring_material=_Key("str"),
                face_width_mm=_F(required=True, lo=FACE_WIDTH_RANGE_MM[0], hi=FACE_WIDTH_RANGE_MM[1], lo_open=True))
    return spec


def _chain_schema() -> dict:
    from ..drives import chain as c

    return {"torque_nm": _F(lo=c.TORQUE_RANGE_NM[0], hi=c.TORQUE_RANGE_NM[1]),
            "power_kw": _F(lo=c.POWER_RANGE_KW[0], hi=c.POWER_RANGE_KW[1]),
            "n1_rpm": _F(required=True, lo=c.N1_RANGE_RPM[0], hi=c.N1_RANGE_RPM[1]),
            "ratio": _F(required=True, lo=c.RATIO_RANGE[0], hi=c.RATIO_RANGE[1]),
            "catalog": _Key("str", default="gost13568"),   # a built-in chain table or a CSV beside the scene
            "k_e": _F(lo=c.K_E_RANGE[0], hi=c.K_E_RANGE[1]),
            "allowable_pressure_mpa": _F(lo=0.0, lo_open=True),
            "allowable_safety_factor": _F(lo=c.SAFETY_FACTOR_RANGE[0], hi=c.SAFETY_FACTOR_RANGE[1]),
            "strands": _Key("ints", default=(1, 2, 3), lo=c.STRANDS_RANGE[0], hi=c.STRANDS_RANGE[1]),
            "z1": _I(lo=c.Z1_RANGE[0], hi=c.Z1_RANGE[1]),
            "center_distance_mm": _F(lo=c.CENTER_DISTANCE_MIN_MM, hi=c.CENTER_DISTANCE_MAX_MM),
            "objective": _Key("choice", default=c.OBJECTIVES[0], choices=c.OBJECTIVES),
            "method": _Key("choice", default=c.METHODS[0], choices=c.METHODS),
            "sag_factor": _F(default=6.0, lo=c.SAG_FACTOR_RANGE[0], hi=c.SAG_FACTOR_RANGE[1]),
            "top": _I(default=10, lo=1, hi=1000),
            "conditions": {k: _Key("float_or_str", lo=c.FACTOR_RANGE[0], hi=c.FACTOR_RANGE[1], choices=())
                           for k in c.FACTOR_NAMES}}


def _key_schema() -> dict:
    from ..drives import key as k

    return {"name": _Key("str"), "d_mm": _F(required=True, lo=0.0, hi=k.LENGTH_MAX_MM, lo_open=True),
            "torque_nm": _F(required=True, lo=0.0, hi=k.TORQUE_MAX_NM, lo_open=True),
            "hub_length_mm": _F(required=True, lo=0.0, hi=k.LENGTH_MAX_MM, lo_open=True),
            "allowable_crush_mpa": _F(default=k.DEFAULT_CRUSH_MPA, lo=0.0, hi=k.ALLOWABLE_MPA_MAX, lo_open=True),
            "allowable_shear_mpa": _F(default=k.DEFAULT_SHEAR_MPA, lo=0.0, hi=k.ALLOWABLE_MPA_MAX, lo_open=True),
            "end": _Key("choice", default=k.ENDS[0], choices=k.ENDS),
            "max_keys": _I(default=k.MAX_KEYS, lo=1, hi=k.MAX_KEYS)}


def _study_schema() -> dict:
    return {"target": _Key("choice", default="gear", choices=("gear", "chain")),
            "parameter": _Key("str", required=True), "values": _Key("floats", required=True),
            "parameter2": _Key("str"), "values2": _Key("floats"),
            "tornado": _Key("bool", default=True), "step": _F(default=0.02, lo=0.0, hi=0.5, lo_open=True)}


def stage_kinds() -> tuple:
    """The stage kinds a ``[[drive.stage]]`` may name: every registered one."""
    from ..drives.stage_kinds import kind_names
    return kind_names()


def _stage_key(spec):
    """A scene key from a stage kind's neutral description (StageKind.scene_keys)."""
    if "table" in spec:      # one of the scene's shared tables
        shared = {"checks": _checks_schema}[spec["table"]]()
        return {k: v for k, v in shared.items() if k not in spec.get("without", ())}
    if isinstance(spec.get("kind"), str):
        return _Key(**spec)
    return {k: _stage_key(v) for k, v in spec.items()}


def drive_schema(part: str = "") -> dict:
    """The keys of ``[drive]`` (part ""), ``[drive.motor]``, each stage kind and ``[[drive.shaft]]``
    (the [drive] section's tables nest stages and shafts; scene/drive.py loads and runs it)."""
    from ..drives import drive as d
    from ..drives import motor as mo

    if part == "":
        return {"power_kw": _F(lo=d.POWER_RANGE_KW[0], hi=d.POWER_RANGE_KW[1]),
                "output_torque_nm": _F(lo=d.TORQUE_RANGE_NM[0], hi=d.TORQUE_RANGE_NM[1]),
                "n_in_rpm": _F(lo=d.SPEED_RANGE_RPM[0], hi=d.SPEED_RANGE_RPM[1]),
                "total_ratio": _F(lo=d.TOTAL_RATIO_RANGE[0], hi=d.TOTAL_RATIO_RANGE[1]),
                "ratio_tol": _F(default=0.03, lo=d.RATIO_TOL_RANGE[0], hi=d.RATIO_TOL_RANGE[1]),
                "objective": _Key("choice", default=d.OBJECTIVES[0], choices=d.OBJECTIVES),
                "top": _I(default=10, lo=1, hi=d.TOP_MAX),
                "motor": {"power_kw": _F(required=True, lo=mo.POWER_RANGE_KW[0], hi=mo.POWER_RANGE_KW[1]),
                          "n_rpm": _F(required=True, lo=mo.SPEED_RANGE_RPM[0], hi=mo.SPEED_RANGE_RPM[1]),
                          "service_factor": _F(default=1.0, lo=mo.SERVICE_FACTOR_RANGE[0], hi=mo.SERVICE_FACTOR_RANGE[1]),
                          "catalog": _Key("choice", default=mo.MOTOR_CATALOGS[0], choices=mo.MOTOR_CATALOGS)},
                "spectrum": _drive_spectrum_schema()}
    if part in stage_kinds():
        from ..drives.stage_kinds import kind_named

        keys = {name: _stage_key(spec) for name, spec in kind_named(part).scene_keys().items()}
        return {"kind": _Key("choice", required=True, choices=stage_kinds()), "name": _Key("str"), **keys}
    if part == "shaft":   # a [key] whose torque is the shaft's own, and the shaft it sits on
        keys = {name: spec for name, spec in section_schema("key").items() if name != "torque_nm"}
        return {"at": _I(required=True, lo=0, hi=d.STAGES_MAX), **keys}
    if part == "shaft_layout":   # a [[drive.shaft]] with lengths_mm: a shaft as drawn (DriveShaft)
        from ..drives.shafting import SHAFT_BEARING_TYPES

        return {"at": _I(required=True, lo=0, hi=d.STAGES_MAX),
                "lengths_mm": _Key("floats", required=True, lo=0.0, lo_open=True),
                "diameters_mm": _Key("floats", required=True, lo=0.0, lo_open=True),
                "supports_mm": _Key("floats", required=True, lo=0.0, length=2),
                "bearing_a": _Key("str"), "bearing_b": _Key("str"), "material": _Key("str"),
                "bearing_type": _Key("choice", choices=SHAFT_BEARING_TYPES)}
    if part == "shaft_bearings":   # a [[drive.shaft]] with only at and bearing_type: a default shaft's bearing type
        from ..drives.shafting import SHAFT_BEARING_TYPES

        return {"at": _I(required=True, lo=0, hi=d.STAGES_MAX),
                "bearing_type": _Key("choice", required=True, choices=SHAFT_BEARING_TYPES)}
    if part == "shafting":       # [drive.shafting]: the shafts, bearings and efficiencies (Shafting)
        from ..drives.bearing import SERIES
        from ..drives.bearing_friction import K_RS
        from ..drives.shafting import ARRANGEMENTS, PEAK_FACTOR, SHAFT_BEARING_TYPES, SHAFT_LIFE_H

        return {"material": _Key("str", default="42CrMo4"), "S_min": _F(default=1.2, lo=0.5, hi=10.0),
                "peak_factor": _F(default=PEAK_FACTOR, lo=1.0, hi=10.0),
                "life_h": _F(default=SHAFT_LIFE_H, lo=0.0, hi=1e7, lo_open=True),
                "reliability": _F(default=90.0, lo=90.0, hi=99.0),
                "bearing_series": _Key("choice", choices=tuple(SERIES)),      # none: every series of the types
                "bearing_type": _Key("choice", default="auto", choices=SHAFT_BEARING_TYPES),
                "arrangement": _Key("choice", default="X", choices=ARRANGEMENTS),
                "clearance_mm": _F(default=20.0, lo=5.0, hi=500.0), "gear_gap_mm": _F(default=10.0, lo=0.0, hi=500.0),
                "overhang_mm": _F(default=60.0, lo=10.0, hi=2000.0),
                "nu40": _F(lo=1.0, hi=1e6), "nu100": _F(lo=1.0, hi=1e6),
                "oil_temperature_c": _F(default=70.0, lo=-40.0, hi=200.0), "Ra_um": _F(default=0.5, lo=0.01, hi=10.0),
                "lubrication": _Key("choice", default="oil_bath", choices=tuple(K_RS)),
                "no_load_loss_w": _F(default=0.0, lo=0.0, hi=1e9)}
    raise KeyError(part)




def _drive_schema() -> dict:
    return drive_schema("")


def engine_schema() -> dict:
    """The keys of ``[engine]``, ``[engine.mechanism]`` and ``[engine.pressure]``, from the library's ranges."""
    from ..mechanism.cylinders import CYLINDERS_MAX
    from ..mechanism.engine import POINTS_RANGE, SPEED_RANGE_RPM
    from ..mechanism.kinetostatics import GRAVITY_M_S2
    from ..mechanism.pressure import ATMOSPHERE_MPA, PRESSURE_RANGE_MPA
    from ..mechanism.slider_crank import INERTIA_MAX_KG_M2, MASS_MAX_KG

    p_lo, p_hi = PRESSURE_RANGE_MPA
    mass = dict(default=0.0, lo=0.0, hi=MASS_MAX_KG)
    pos = dict(lo=0.0, lo_open=True)
    return {
        "n_rpm": _F(required=True, lo=SPEED_RANGE_RPM[0], hi=SPEED_RANGE_RPM[1], lo_open=True),
        "cylinders": _I(default=1, lo=1, hi=CYLINDERS_MAX),
        "strokes": _I(default=4, lo=2, hi=4),
        "firing_order": _Key("ints", lo=1, hi=CYLINDERS_MAX), "throws_deg": _Key("floats", lo=-720.0, hi=720.0),
        "phases_deg": _Key("floats", lo=0.0, hi=720.0), "axis_tilts_deg": _Key("floats", lo=-180.0, hi=180.0),
        "mechanical_efficiency": _F(lo=0.0, hi=1.0, lo_open=True),
        "flywheel_inertia_kg_m2": _F(lo=0.0, hi=INERTIA_MAX_KG_M2, lo_open=True),
        "crankcase_pressure_mpa": _F(default=ATMOSPHERE_MPA, lo=p_lo, hi=p_hi),
        "gravity_m_s2": _F(default=GRAVITY_M_S2, lo=0.0, hi=100.0),
        "points": _I(default=720, lo=POINTS_RANGE[0], hi=POINTS_RANGE[1]),
        "name": _Key("str"),
        "mechanism": {
            "crank_radius_mm": _F(required=True, **pos), "rod_length_mm": _F(required=True, **pos),
            "rod_cg_mm": _F(default=0.0, lo=0.0), "offset_mm": _F(default=0.0),
            "piston_mass_kg": _F(**mass), "rod_mass_kg": _F(**mass),
            "rod_inertia_kg_m2": _F(default=0.0, lo=0.0, hi=INERTIA_MAX_KG_M2),
            "crank_mass_kg": _F(**mass), "crank_cg_mm": _F(default=0.0),
            "cylinder_bore_mm": _F(required=True, **pos)},
        "pressure": {
            "kind": _Key("choice", required=True, choices=("otto", "table", "csv")),
            # kind = "otto": the parametric cycle (mechanism.pressure.otto_pressure)
            "compression_ratio": _F(lo=1.0, hi=40.0, lo_open=True),
            "intake_pressure_mpa": _F(default=0.09, lo=p_lo, hi=p_hi, lo_open=True),
            "exhaust_pressure_mpa": _F(default=0.11, lo=p_lo, hi=p_hi, lo_open=True),
            "peak_pressure_mpa": _F(lo=p_lo, hi=p_hi, lo_open=True),
            "polytropic_compression": _F(default=1.37, lo=1.0, hi=1.7),
            "polytropic_expansion": _F(default=1.25, lo=1.0, hi=1.7),
            "table_points": _I(default=1440, lo=POINTS_RANGE[0], hi=POINTS_RANGE[1]),
            # kind = "table": absolute pressures at cycle angles
            "crank_angle_deg": _Key("floats", lo=0.0, hi=720.0), "pressure_mpa": _Key("floats", lo=p_lo, hi=p_hi),
            # kind = "csv": a file with the columns crank_angle_deg, pressure_mpa (relative to the scene)
            "csv": _Key("str")}}


def _engine_schema() -> dict:
    return engine_schema()


_BUILDERS = {"": lambda: {"title": _Key("str"), "description": _Key("str")}, "gear": _gear_schema,
             "teeth": _teeth_schema, "planetary": _planetary_schema, "chain": _chain_schema, "key": _key_schema,
             "study": _study_schema, "drive": _drive_schema, "engine": _engine_schema}


def section_schema(name: str) -> dict:
    """The keys of one section (``""`` for the top level): name -> _Key, or a nested table. Built
    once per state of the check registry (a registered check's option is a key of [gear.checks]);
    a scene that models no gear does not import the checks for it."""
    base = sys.modules.get("geardesign.gears.checks.base")
    return _section_schema(name, base.registry_version() if base is not None else -1)


@functools.cache
def _section_schema(name: str, version: int) -> dict:
    return _BUILDERS[name]()


class Where:
    def __init__(self, path):
        self.path = str(path)

    def fail(self, section: str, key: str | None, text: str):
        # a section or key name comes from the user's file: cut like a value (validate._short)
        where = f"[{_cut(section)}]" if section else "top level"
        if key is not None:
            where += f" {_cut(key)}"
        raise GearDesignError(f"{self.path}: {where}: {text}")


def _cut(name) -> str:
    text = str(name)
    return text if len(text) <= 60 else text[:40] + f"... ({len(text)} characters)"


def type_name(v) -> str:
    return {bool: "boolean", int: "integer", float: "float", str: "string", list: "array",
            dict: "table"}.get(type(v), type(v).__name__)


def _check_value(where: Where, section: str, key: str, spec: _Key, v):
    def bad(extra=""):
        where.fail(section, key, f"expected {spec.expected()}, got {_short(v)} ({type_name(v)}){extra}")

    def in_range(x):
        if spec.lo is not None and (x <= spec.lo if spec.lo_open else x < spec.lo):
            return False
        return not (spec.hi is not None and x > spec.hi)

    def number(x, whole):
        if isinstance(x, bool) or not isinstance(x, (int, float)):
            return None
        if isinstance(x, float) and not math.isfinite(x):
            return None
        if whole:
            if isinstance(x, float) and not x.is_integer():
                return None
            return int(x)
        return float(x)

    k = spec.kind
    if k == "bool":
        if not isinstance(v, bool):
            bad()
        return v
    if k == "str":
        if not isinstance(v, str):
            bad()
        return v
    if k == "choice":
        if not isinstance(v, str) or v not in spec.choices:
            bad()
        return v
    if k in ("float", "int", "float_or_str"):
        if k == "float_or_str" and isinstance(v, str):
            if spec.choices and v not in spec.choices:
                bad()
            return v
        x = number(v, k == "int")
        if x is None or not in_range(x):
            bad()
        return x
    # lists
    if not isinstance(v, list) or not v or (spec.length and len(v) != spec.length):
        bad()
    out = []
    for item in v:
        x = number(item, k == "ints")
        if x is None or not in_range(x):
            bad(f"; the element {_short(item)} is not")
        out.append(x)
    return tuple(out)


# keys renamed for one name per quantity (docs/glossary.md): (section, old key) -> new key. A scene with the old
# key still loads for one release, with a DeprecationWarning naming the new one.
RENAMED_KEYS = {("drive.motor", "speed_rpm"): "n_rpm"}


def _renamed(where: Where, section: str, table: dict) -> dict:
    out = dict(table)
    for (sec, old), new in RENAMED_KEYS.items():
        if sec == section and old in out:
            if new in out:
                where.fail(section, old, f"give {new} only (its old name {old} is deprecated)")
            warnings.warn(f"[{section}] {old} is deprecated: name it {new} (one name per quantity, docs/glossary.md)",
                          DeprecationWarning, stacklevel=2)
            out[new] = out.pop(old)
    return out


def validate_table(where: Where, section: str, table: dict, schema: dict) -> dict:
    out = {}
    if RENAMED_KEYS:
        table = _renamed(where, section, table)
    for key, v in table.items():
        if key not in schema:
            allowed = ", ".join(schema)
            where.fail(section, key, f"unknown key; expected one of {allowed}")
        spec = schema[key]
        if isinstance(spec, dict):
            if not isinstance(v, dict):
                where.fail(section, key, f"expected a table [{section}.{key}], got {_short(v)} ({type_name(v)})")
            out[key] = validate_table(where, f"{section}.{key}", v, spec)
        else:
            out[key] = _check_value(where, section, key, spec, v)
    for key, spec in schema.items():
        if isinstance(spec, dict):
            continue
        if key not in out:
            if spec.required:
                where.fail(section, key, f"missing; expected {spec.expected()}")
            if spec.default is not None:
                out[key] = spec.default
    return out
