"""Roller-chain drive design from standard catalogs.

:func:`design` enumerates every candidate — each catalog row (a chain with its strand count)
times each small-sprocket tooth count — evaluates all checks in one vectorised pass and ranks
the candidates for an objective. It is a recipe of small steps (validate the inputs, build the
candidate table, evaluate every margin, rank, wrap the result in a :class:`ChainDesign`), each
working on numpy arrays. Every check is a signed dimensionless margin (>= 0 holds):

- hinge pressure ``1 - p/[p]`` with p = F_t·K_e / (A·m_eff) (hinge-pressure method);
- breaking-load safety ``s/[s] - 1`` with s = Q / (K_d·F_t + F_v + F_f);
- speed ``1 - n1/n1_max`` and impacts per second ``1 - w/[w]`` (hinge-pressure method);
- rated power ``P_rated/P_design - 1`` (power-rating method, ISO 606 / ANSI chains).

Units at the interface: torque N·m, power kW, speed rpm, lengths mm, forces N, pressure MPa.
Inside, powers are in W and chain speeds in m/s.

formulas (one function per formula) -> inputs (ranges, validation) -> tables (the catalogs as arrays)
-> candidates (rows × teeth, their layout) -> checks (every margin) -> design.
"""
from .inputs import (CENTER_DISTANCE_MAX_MM, CENTER_DISTANCE_MIN_MM, CENTER_DISTANCE_PITCHES_MAX, FACTOR_NAMES, FACTOR_RANGE, K_E_RANGE,
                         METHODS, N1_RANGE_RPM, OBJECTIVES, POWER_RANGE_KW, RATIO_RANGE, SAFETY_FACTOR_RANGE,
                         SAG_FACTOR_RANGE, STRANDS_RANGE, TORQUE_RANGE_NM, Z1_RANGE, Z2_MAX_LIMIT, Conditions)
from .design import ChainDesign, design
from .pull import ChainPull, chain_pull
from .formulas import (G, HP_TO_KW, IN_MM, allowable_pressure_mpa, hinge_pressure_mpa, pitch_estimate_mm,
                       rated_power_link_plate_kw, rated_power_roller_bushing_kw, recommended_z1, safety_factor)

__all__ = ["Conditions", "ChainDesign", "design", "ChainPull", "chain_pull", "recommended_z1", "pitch_estimate_mm", "hinge_pressure_mpa",
           "safety_factor", "rated_power_link_plate_kw", "rated_power_roller_bushing_kw", "allowable_pressure_mpa",
           "OBJECTIVES", "METHODS", "FACTOR_NAMES", "TORQUE_RANGE_NM", "POWER_RANGE_KW", "N1_RANGE_RPM", "RATIO_RANGE",
           "K_E_RANGE", "FACTOR_RANGE", "SAFETY_FACTOR_RANGE", "SAG_FACTOR_RANGE", "Z1_RANGE", "STRANDS_RANGE",
           "CENTER_DISTANCE_MAX_MM", "CENTER_DISTANCE_MIN_MM", "CENTER_DISTANCE_PITCHES_MAX", "Z2_MAX_LIMIT", "HP_TO_KW", "IN_MM", "G"]
