"""Design checks of a gear pair as named constraints with signed, dimensionless margins.

Every check maps a geometry (the dict of :func:`geardesign.gears.geometry.mesh_geometry`, arrays or,
on the optimisers' single-design path, Python floats) to

* ``value`` — the checked quantity, ``limit`` — its bound (a parameter of the check),
* ``margin`` — signed and dimensionless, >= 0 where the check holds (lengths are divided
  by the module, so margins of different checks compare),
* ``gradient`` — ∂margin/∂x1 and ∂margin/∂x2, analytic (checked against finite differences
  in the tests), for the optimisers of :mod:`geardesign.shifts.optimize`.

The modules: :mod:`.base` (the base class, the options and the registry every consumer reads:
:func:`make_checks`, the CLI's limit options, the scene schema, the plots' colours, the sweeps),
:mod:`.external` (an external pair and a ring pair's pinion), :mod:`.ring` (a ring pair's own
checks), :mod:`.strength` (ISO 6336 contact and root safety, built when a load is given). A problem models only the checks asked for: build the list with :func:`make_checks`.
"""
from .base import (CONTEXT_KEYWORDS, FEASIBILITY_TOL, UNDEFINED, Check, Option, check_colour, evaluate, make_checks,
                   margins, option, options, register, register_context, registered, registry_version, resolve_checks,
                   unregister)
from .external import (DEFAULT_EPS_ALPHA_MIN, DEFAULT_SA_MIN, EPS_ALPHA_MIN_RANGE, EPS_GAMMA_MIN_RANGE, SA_MIN_RANGE,
                       CenterDistance, ContactRatio, CustomCheck, Interference, Jamming, TipThickness,
                       TotalContactRatio, Undercut)
from .gradients import sliding_root_gradient
from .strength import ContactStrength, RootStrength, StrengthSpec
from .ring import (TOOTH_DIFFERENCE_RANGE, CutterInterference, CutterTrimming, RadialAssembly, RingInterference,
                   RingTip, TipInterference, ToothDifference)

__all__ = [
    "Check", "Option", "Undercut", "Interference", "TipThickness", "ContactRatio", "TotalContactRatio", "Jamming",
    "RingInterference", "RingTip", "TipInterference", "RadialAssembly", "CutterTrimming", "CutterInterference",
    "ToothDifference", "CenterDistance", "CustomCheck", "ContactStrength", "RootStrength", "StrengthSpec", "make_checks", "resolve_checks", "evaluate", "margins",
    "register", "unregister", "registered", "registry_version", "options", "option", "check_colour", "sliding_root_gradient",
    "DEFAULT_EPS_ALPHA_MIN", "DEFAULT_SA_MIN", "EPS_ALPHA_MIN_RANGE", "SA_MIN_RANGE", "EPS_GAMMA_MIN_RANGE",
    "TOOTH_DIFFERENCE_RANGE", "FEASIBILITY_TOL", "UNDEFINED", "CONTEXT_KEYWORDS", "register_context",
]

# the worm pair's checks register themselves (pair kind "worm"): imported here so that the registry, and every
# consumer of it (options, CLI, scene schema), is the same whichever module a program imports first
from ..worm import checks as _worm_checks  # noqa: E402,F401
