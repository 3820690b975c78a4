"""geardesign: gear geometry and drive checks as constraints, optimised.

>>> import geardesign as gd
>>> pair = gd.GearPair(m=8, z1=17, z2=26, x1=0.898, x2=0.517)
>>> round(pair.geometry().eps_alpha, 3)
1.153

The package is layered; each layer imports only the ones before it:

- :mod:`geardesign.errors`, :mod:`geardesign.validate`, :mod:`geardesign.results`, :mod:`geardesign.files`,
  :mod:`geardesign.inline` (a result's picture in a notebook), :mod:`geardesign.renamed` (old keywords, for one
  release)
- :mod:`geardesign.catalogs` — CSV tables and standard series; :mod:`geardesign.mechanism` — the engine's
  slider-crank: kinematics, kinetostatics, the crankshaft's torque over the cycle
- :mod:`geardesign.gears` — involute, rack, mesh, geometry, checks, :class:`GearPair`
- :mod:`geardesign.shifts` — the shift problem, its methods, region, atlas, tooth counts
- :mod:`geardesign.profiles` — tooth profiles as the cutter generates them
- :mod:`geardesign.drives` — sprockets, chains, keys, motors; stages and the linked drive
- :mod:`geardesign.sensitivity` — sweeps and local sensitivities
- :mod:`geardesign.scene` — TOML scenes and their reports; one-page HTML reports of a pair and a drive
- :mod:`geardesign.cli` — the ``geardesign`` command

Names are loaded on first use (PEP 562), so ``import geardesign`` costs little more than numpy and
a scene loads only what its sections need.
"""
import importlib

from . import writers     # a registry in the bottom layer that imports nothing: the package's import stays light

__version__ = "0.1.0"

# public name -> module that defines it
_NAMES = {
    "GearDesignError": "errors", "CatalogError": "errors",
    "BasicRack": "gears.rack", "Mesh": "gears.mesh", "ShaperCutter": "gears.ring", "inv": "gears.involute", "inv_inverse": "gears.involute",
    "Geometry": "gears.geometry", "GEOMETRY_FIELDS": "gears.geometry", "pair_geometry": "gears.geometry",
    "x_sum_from_center_distance": "gears.geometry", "make_checks": "gears.checks", "GearPair": "gears.pair",
    "optimize_shifts": "shifts.optimize", "ShiftResult": "shifts.result", "OBJECTIVES": "shifts.objectives",
    "Objective": "shifts.objectives", "feasible_region": "shifts.region", "Region": "shifts.region",
    "shift_atlas": "shifts.atlas", "select_teeth": "shifts.teeth", "TeethSelection": "shifts.teeth",
    "sweep": "sensitivity.sweeps", "load_scene": "scene", "run_scene": "scene", "pair_report": "scene.html",
    "drive_report": "scene.html",
    "ShaftModel": "drives.shaft_beam", "ShaftLoad": "drives.shaft_beam", "analyse_shaft": "drives.shaft_beam",
    "ShaftNotch": "drives.din743", "Notch": "drives.din743", "din743_safety": "drives.din743",
    "shaft_safety": "drives.din743", "least_shaft_scale": "drives.din743", "plot_shaft": "drives.shaft_plot",
    "tooth_profile": "profiles.tooth", "ToothProfile": "profiles.tooth", "plot_mesh": "profiles.drawing",
    "plot_diagrams": "profiles.drawing", "export_profiles": "profiles.mesh",
    "pair_profiles": "profiles.mesh", "ring_profile": "profiles.ring", "RingProfile": "profiles.ring",
    "PlanetarySet": "gears.planetary", "optimize_planetary_shifts": "shifts.planetary",
    "planetary_region": "shifts.planetary", "select_planetary_teeth": "shifts.planetary_teeth",
    "Drive": "drives.drive", "GearStage": "drives.stages", "ChainStage": "drives.stages",
    "GivenStage": "drives.stages", "Shaft": "drives.stages", "DutyCycle": "drives.duty_cycle",
    "Load": "gears.strength", "Material": "gears.strength", "material": "gears.strength",
    "pair_strength": "gears.strength", "StrengthResult": "gears.strength", "StrengthOptions": "gears.strength",
    "LoadSpectrum": "gears.spectrum", "pair_life": "gears.strength", "LifeResult": "gears.strength",
    "tooth_measurements": "gears.measurement", "ToothMeasurements": "gears.measurement",
    "pair_backlash": "gears.backlash", "Backlash": "gears.backlash", "x_sum_for_backlash": "gears.backlash",
    "gost1643_jn_min": "gears.backlash", "flank_tolerances": "gears.tolerances", "FlankTolerances": "gears.tolerances",
    "data_block": "gears.data_block",
    "mesh_forces": "gears.forces", "pair_forces": "gears.forces", "planetary_forces": "gears.forces",
    "MeshForces": "gears.forces", "check_bearing": "drives.bearing", "select_bearing": "drives.bearing",
    "chain_pull": "drives.chain.pull", "tapered_axial_loads": "drives.bearing", "system_life": "drives.bearing",
    "reference_viscosity": "drives.bearing",
    "Lubricant": "gears.efficiency", "mesh_loss": "gears.efficiency", "stage_efficiency": "drives.efficiency",
    "BearingLoad": "drives.efficiency", "bearing_friction": "drives.bearing_friction",
    "SliderCrank": "mechanism.slider_crank", "IndicatorDiagram": "mechanism.pressure", "Engine": "mechanism.engine",
    "EngineTorque": "mechanism.engine", "engine_torque": "mechanism.engine", "joint_forces": "mechanism.kinetostatics",
    "virtual_power_torque": "mechanism.kinetostatics", "plot_torque": "mechanism.plot",
    "WormPair": "gears.worm.pair", "worm_geometry": "gears.worm.geometry", "select_worm": "gears.worm.series",
    "WormStage": "drives.stage_kinds.worm",
    "Shafting": "drives.shafting", "DriveShaft": "drives.shafting",
}
# modules reachable as attributes, under their short names (gd.chain.design, gd.key.select, ...)
_MODULES = {
    "catalogs": "catalogs", "involute": "gears.involute", "checks": "gears.checks", "chain": "drives.chain",
    "key": "drives.key", "sprocket": "drives.sprocket", "sweeps": "sensitivity.sweeps", "scene": "scene",
    "studies": "sensitivity.sweeps",    # the module's name before it was sweeps.py; kept for old scripts
    "gears": "gears", "shifts": "shifts", "drives": "drives", "sensitivity": "sensitivity", "profiles": "profiles",
    "motor": "drives.motor", "bearing": "drives.bearing", "forces": "gears.forces",
    "din743": "drives.din743", "shaft_beam": "drives.shaft_beam",
    "mechanism": "mechanism", "kinematics": "mechanism.kinematics",
}

__all__ = sorted(_NAMES) + sorted(_MODULES)


def _pair_report(pair, path, overwrite=False, **limits):
    """:func:`geardesign.scene.html.pair_report`, loaded on its first call (for ``GearPair.report``)."""
    return __getattr__("pair_report")(pair, path, overwrite=overwrite, **limits)


# the writer a lower object reaches by name: registered here, above every layer, so no layer imports upward
writers.register("pair_report", _pair_report)


def __getattr__(name):
    if name in _NAMES:
        value = getattr(importlib.import_module(f".{_NAMES[name]}", __name__), name)
    elif name in _MODULES:
        value = importlib.import_module(f".{_MODULES[name]}", __name__)
    else:
        raise AttributeError(f"module 'geardesign' has no attribute {name!r}")
    globals()[name] = value
    return value


def __dir__():
    return sorted(set(globals()) | set(__all__))
