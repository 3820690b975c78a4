"""The defaults and input ranges of the strength model, each in one place with where it comes from."""
from __future__ import annotations

__all__ = ["S_HMIN", "S_FMIN", "MIN_SAFETY_SOURCE", "NU40_MM2_S", "RZ_FLANK_UM", "RZ_ROOT_UM", "ACCURACY_GRADE", "TRANSVERSE_DEVIATION",
           "NU40_RANGE", "RZ_RANGE_UM", "K_GAMMA_RANGE", "FACE_WIDTH_RANGE_MM", "FACTOR_RANGE"]

# Minimum safety factors. ISO 6336-1:2019 (4.1.7, 4.1.8) leaves S_Hmin and S_Fmin to agreement between
# supplier and purchaser and names no numbers; these are the lower ends of the values commonly used for
# industrial gears (the bending minimum higher, as a tooth breakage ends the gear's life). Set your own.
S_HMIN = 1.0
S_FMIN = 1.4
MIN_SAFETY_SOURCE = ("to be agreed (ISO 6336-1:2019 4.1.7-4.1.8 gives no value); geardesign defaults "
                     "S_Hmin = 1.0, S_Fmin = 1.4, the lower ends of common industrial practice")

NU40_MM2_S = 220.0       # ISO VG 220, a common industrial gear oil (ISO 3448 grade)
RZ_FLANK_UM = 6.0        # ground or finely hobbed flank, about Ra 1 µm (ISO/TR 6336-30 example 1 uses Rz = 6 µm)
RZ_ROOT_UM = 10.0        # hobbed root fillet
# the deviation of K_Hα, K_Fα: f_pb (the chain's validated figures) or "larger" of f_pb and f_fα, which ISO 6336-1:2006
# 8.3.2 prescribes as we could read it (second hand) and KISSsoft uses; the 2019 text was not at hand. See
# factors.transverse_deviation and docs/strength.md "Questions from the audit".
TRANSVERSE_DEVIATION = "f_pb"
ACCURACY_GRADE = 7       # ISO 1328-1:1995 grade of ordinary industrial gearing

NU40_RANGE = (1.0, 10_000.0)       # mm²/s: from thin spindle oils to the heaviest open-gear compounds
RZ_RANGE_UM = (0.01, 100.0)
RZ_ROOT_MAX_UM = 40.0              # the end of the Y_RrelT curves (ISO 6336-3:2019 clause 14)
K_GAMMA_RANGE = (1.0, 3.0)         # mesh load factor of planetary sets (ISO 6336-1:2019 6.4: 1.0 to about 1.6)
# a loaded face width: at least a micrometre (closed below; a subnormal width made the line load F_t/b infinite:
# NaN damage and lives, fuzz), as the mesh loss of gears/efficiency.py
FACE_WIDTH_RANGE_MM = (1e-3, 1e5)
FACTOR_RANGE = (0.01, 100.0)       # a given factor outside this is a typo, not a measurement
EPS_BETA_MAX = 50.0      # the overlap ratio up to which the helix factors are taken (far beyond any gear)
