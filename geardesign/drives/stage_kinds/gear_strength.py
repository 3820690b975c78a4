"""A gear stage by the load it carries: its ISO 6336 strength checks at the torque and speed flowing
into it, and the module and face width of a stage given without them.

Checks (signed margins, >= 0 holds), from :func:`geardesign.gears.strength.pair_strength` with both
gears of the stage's ``material``, the load on the pinion (gear 1) with the stage's ``application_factor``
and ``life_h`` (None: endurance, Z_NT = Y_NT = 1) and the strength model's defaults (accuracy grade, lubricant, roughness, S_Hmin and
S_Fmin, :mod:`geardesign.gears.strength.defaults`):

- ``contact_strength``: min(S_H1, S_H2)/S_Hmin − 1;
- ``root_strength1``, ``root_strength2``: S_F1/S_Fmin − 1, S_F2/S_Fmin − 1.

Sizing (``GearStage(m=None)``): every module of the ISO 54 series (``catalogs/modules_iso54.csv``)
times face widths b = ψ_d·d1 (rounded up to whole mm) for ψ_d = b/d1 in :data:`WIDTH_TO_DIAMETER_RANGE`
by steps of :data:`WIDTH_TO_DIAMETER_STEP` (or the stage's own ``face_width_mm``) is checked in one
vectorised call; the candidates that hold every strength check come smallest module first, then
narrowest. The range is a modelling choice, stated with where its ends come from: b/d1 ≥ 0.2 is the
lower end VDI 2736 Sheet 2 (2014) allows (as quoted by the FVA-Workbench documentation, attribute
"Ratio of facewidth to pinion diameter", https://adoc.fva-service.de/help/8.0/en/attr/PMID_10677.htm);
b/d1 ≤ 1.0 follows the rule that the width stay below the pinion diameter, as the load distribution
over a wider face suffers (GearCalc manual 12.7 "Face width",
http://www.gearcalc.com/downloads/manual/manualse47.html).
"""
from __future__ import annotations

import math

import numpy as np

from ..stages import stage_material

__all__ = ["STRENGTH_CHECKS", "WIDTH_TO_DIAMETER_RANGE", "WIDTH_TO_DIAMETER_STEP", "strength_margins",
           "strength_sizes", "strength_sizes_many"]

STRENGTH_CHECKS = ("contact_strength", "root_strength1", "root_strength2")
WIDTH_TO_DIAMETER_RANGE = (0.2, 1.0)
WIDTH_TO_DIAMETER_STEP = 0.05


def strength_margins(stage, m, face_width_mm, z1, z2, x1, x2, torque_nm: float, speed_rpm: float) -> dict:
    """{check: margin array} of :data:`STRENGTH_CHECKS` for the stage's pairs (m, b broadcast) carrying
    ``torque_nm`` on the pinion at ``speed_rpm`` (with the stage's life and application factor)."""
    from ...gears.strength import pair_strength   # here: the materials catalog loads pandas

    out = pair_strength(m, z1, z2, x1, x2, load=stage.load(torque_nm, speed_rpm),
                        material1=stage_material(stage.material), face_width_mm=face_width_mm, beta_deg=stage.beta_deg)
    return {"contact_strength": np.minimum(out["S_H1"], out["S_H2"]) / out["S_Hmin"] - 1.0,
            "root_strength1": out["S_F1"] / out["S_Fmin"] - 1.0,
            "root_strength2": out["S_F2"] / out["S_Fmin"] - 1.0}


def _widths(stage, modules: np.ndarray, z1: int) -> tuple:
    """(m, b) grids: every module times the stage's face width, or the ψ_d range's widths."""
    if stage.face_width_mm is not None:
        return modules[:, None], np.full((modules.size, 1), stage.face_width_mm)
    lo, hi = WIDTH_TO_DIAMETER_RANGE
    psi = np.arange(lo, hi + 1e-9, WIDTH_TO_DIAMETER_STEP)
    d1 = modules[:, None] * z1 / math.cos(math.radians(stage.beta_deg))
    return np.broadcast_to(modules[:, None], (modules.size, psi.size)), np.ceil(psi[None, :] * d1 - 1e-9)


def strength_sizes(stage, torque_nm: float, speed_rpm: float, z1: int, z2: int, x1: float, x2: float,
                   modules: np.ndarray, tol: float) -> tuple:
    """(candidates, best): the (m, b) that hold every strength check at shifts x1, x2, smallest module
    first, then narrowest; and (m, b, {check: margin}) of the first candidate, or when none holds, of
    the (m, b) closest to holding."""
    return strength_sizes_many(stage, torque_nm, speed_rpm, [(z1, z2, x1, x2)], modules, tol)[0]


def strength_sizes_many(stage, torque_nm: float, speed_rpm: float, pairs, modules: np.ndarray, tol: float) -> list:
    """:func:`strength_sizes` of several tooth pairs ``pairs`` [(z1, z2, x1, x2), ...] at one load, in one
    vectorised call (its fixed cost shared)."""
    modules = np.asarray(modules, dtype=float)
    grids = [_widths(stage, modules, z1) for z1, _, _, _ in pairs]
    M = np.stack([np.broadcast_to(m, grids[0][0].shape) for m, _ in grids])
    B = np.stack([np.broadcast_to(b, grids[0][0].shape) for _, b in grids])
    z1, z2 = (np.array([p[i] for p in pairs], dtype=np.int64)[:, None, None] for i in (0, 1))
    x1, x2 = (np.array([p[i] for p in pairs], dtype=float)[:, None, None] for i in (2, 3))
    margins = strength_margins(stage, M, B, z1, z2, x1, x2, torque_nm, speed_rpm)
    margins = {k: np.broadcast_to(v, M.shape) for k, v in margins.items()}
    return [_first_size(M[i], B[i], {k: v[i] for k, v in margins.items()}, tol) for i in range(len(pairs))]


def _first_size(M: np.ndarray, B: np.ndarray, margins: dict, tol: float) -> tuple:
    """(candidates, best) of one pair's (m, b) grid and its margins, as :func:`strength_sizes` returns."""
    worst = np.minimum.reduce([margins[k] for k in STRENGTH_CHECKS])
    worst = np.where(np.isnan(worst), -np.inf, worst)
    ok = worst >= -tol
    order = np.lexsort((B[ok], M[ok]))
    cands = [(float(m), float(b)) for m, b in zip(M[ok][order], B[ok][order])]
    if cands:
        i = tuple(np.argwhere(ok)[order[0]])
    else:
        i = np.unravel_index(np.argmax(worst), M.shape)
    return cands, (float(M[i]), float(B[i]), {k: float(v[i]) for k, v in margins.items()})
