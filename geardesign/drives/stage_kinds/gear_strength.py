"""A gear stage by the load it carries: its ISO 6336 strength checks at the torque and speed flowing
into it, and the module and face width of a stage given without them.

Checks (signed margins, >= 0 holds), from :func:`geardesign.gears.strength.pair_strength` with both
gears of the stage's ``material``, the load on the pinion (gear 1) with the stage's ``application_factor``
and ``life_h`` (None: endurance, Z_NT = Y_NT = 1) and the stage's ``strength`` options (accuracy grade, lubricant,
roughness, S_Hmin and S_Fmin, given factors; the defaults of :mod:`geardesign.gears.strength.defaults`):

- ``contact_strength``: min(S_H1, S_H2)/S_Hmin − 1;
- ``root_strength1``, ``root_strength2``: S_F1/S_Fmin − 1, S_F2/S_Fmin − 1.

With a ``spectrum`` (a :class:`~geardesign.drives.duty_cycle.DutyCycle` read at the stage's nominal load, or a
LoadSpectrum as it is) the damage checks of ISO 6336-6 join them (:data:`DAMAGE_CHECKS`: ``pitting_damage1``,
``pitting_damage2``, ``root_damage1``, ``root_damage2``, margin 1 − D, built by the check registry:
:func:`damage_checks`); ``single_load=False`` leaves the three above out. The sizing holds every one of them: the
damage checks are rated with the root checks, where they decide the answer.

Sizing (``GearStage(m=None)``): every module of the ISO 54 series (``catalogs/modules_iso54.csv``)
times face widths b = ψ_d·d1 (rounded up to whole mm) for ψ_d = b/d1 in :data:`WIDTH_TO_DIAMETER_RANGE`
by steps of :data:`WIDTH_TO_DIAMETER_STEP` (or the stage's own ``face_width_mm``) is checked, vectorised
over the grid and over several tooth pairs at once; the candidates that hold every strength check come
smallest module first, then narrowest. The range is a modelling choice, stated with where its ends come
from: b/d1 ≥ 0.2 is the lower end VDI 2736 Sheet 2 (2014) allows (as quoted by the FVA-Workbench
documentation, attribute "Ratio of facewidth to pinion diameter",
https://adoc.fva-service.de/help/8.0/en/attr/PMID_10677.htm); b/d1 ≤ 1.0 follows the rule that the width
stay below the pinion diameter, as the load distribution over a wider face suffers (GearCalc manual 12.7
"Face width", http://www.gearcalc.com/downloads/manual/manualse47.html). No width is narrower than
:data:`FACE_WIDTH_PITCHES_MIN` circular pitches, b >= 3·π·m: the lower end of the textbook range 3p <= b <= 5p
for spur gears (J. E. Shigley, Standard Handbook of Machine Design, 3rd ed., ch. 9 "Spur gears"; Budynas and
Nisbett, Shigley's Mechanical Engineering Design, ch. 14). Without it, a pinion of few teeth on a large module got
b = 0.2·d1, i.e. b/m = 0.2·z1 (19 teeth: b/m 3.8), a disc no reducer designer draws (issue 35).

The answer is that of every design checked in full, with less work, nothing assumed of how the
margins vary with m and b: a design is computed once however many ψ_d round to its width (small
modules: b = 1, 1, 2, 2, ... mm); contact first, on the whole grid (the root side is half of the
strength model's work); then the root checks only where they decide the answer, i.e. at the first
contact-holding designs in (m, b) order (a design whose contact fails is no candidate whatever its
root), and on the whole grid only when those do not settle the candidates asked for, or when no
design holds (the closest one is then chosen over every check).
"""
from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from ...gears.checks import make_checks
from ..stages import stage_material

__all__ = ["STRENGTH_CHECKS", "DAMAGE_CHECKS", "check_names", "damage_checks", "life_options", "load_checks", "safety_limits", "WIDTH_TO_DIAMETER_RANGE", "WIDTH_TO_DIAMETER_STEP", "FACE_WIDTH_PITCHES_MIN", "strength_margins",
           "strength_sizes", "strength_sizes_many", "widest_width"]

STRENGTH_CHECKS = ("contact_strength", "root_strength1", "root_strength2")
DAMAGE_CHECKS = ("pitting_damage1", "pitting_damage2", "root_damage1", "root_damage2")
WIDTH_TO_DIAMETER_RANGE = (0.2, 1.0)
WIDTH_TO_DIAMETER_STEP = 0.05
FACE_WIDTH_PITCHES_MIN = 3.0      # b >= 3 circular pitches (π·m each)


def strength_margins(stage, m, face_width_mm, z1, z2, x1, x2, torque_nm, speed_rpm, root: bool = True) -> dict:
    """{check: margin array} of the stage's load checks for its pairs (m, b broadcast) carrying ``torque_nm`` on
    the pinion at ``speed_rpm`` (with the stage's life, application factor and strength options): the checks the
    check registry builds for that load case (:func:`load_checks`; the built-in :data:`STRENGTH_CHECKS`, and any
    load model registered there; with a ``spectrum``, the damage checks :data:`DAMAGE_CHECKS` of
    :func:`damage_checks`), evaluated on the arrays in one call each; ``root=False``: ``contact_strength``
    alone (the strength model skips the root side; the damage checks rate both sides together, so they are left
    out). A torque and speed per design (arrays broadcast with the designs) check many flows in one call
    (:meth:`~geardesign.gears.strength.Load.per_design`; the damage checks one call per distinct flow)."""
    arrays = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (m, face_width_mm, z1, z2, x1, x2,
                                                                       torque_nm, speed_rpm)))
    designs, (T, N) = arrays[:6], arrays[6:]
    out = {}
    if stage.single_load:
        if np.ndim(torque_nm) or np.ndim(speed_rpm):
            from ...gears.strength import Load

            load = Load.per_design(T, N, stage.application_factor, stage.life_h)
            checks = _built_checks(_strength_options(stage), stage.material, stage.checks_key(), load, root)
        else:
            checks = load_checks(stage, float(torque_nm), float(speed_rpm), root)
        out.update(_evaluated(stage, checks, *designs))
    if root and stage.spectrum is not None:
        out.update(_damage_margins(stage, designs, T, N))
    return out


def _evaluated(stage, checks, M, B, Z1, Z2, X1, X2) -> dict:
    """{check: margin array} of ``checks`` on the designs (arrays of one shape)."""
    from ...gears.geometry import mesh_geometry
    from ...gears.mesh import Mesh

    mesh = Mesh(20, 60, None, True, stage.beta_deg).unchecked(Z1, Z2)
    if all(c.costly for c in checks):   # the chain computes the geometry it needs itself
        geo = {"_mesh": mesh, "_m": M, "_z1": Z1, "_z2": Z2, "_x1": X1, "_x2": X2}
    else:                               # a load model reading geometry fields: give it them all
        with np.errstate(all="ignore"):
            geo = mesh_geometry(mesh, M, X1, X2, full=False)
    geo["_face_width_mm"] = B           # a width per design (the sizing grid), read by the load checks
    return {c.name: np.asarray(c.margin(geo), dtype=float) for c in checks}


def _damage_margins(stage, designs, T, N) -> dict:
    """The damage checks' margins of the designs, each at its own flow (T, N arrays of the designs' shape): one
    evaluation per distinct flow (a duty cycle's bins follow the flow; a LoadSpectrum's do not)."""
    from ..duty_cycle import DutyCycle

    if not isinstance(stage.spectrum, DutyCycle) or (np.all(T == T.flat[0]) and np.all(N == N.flat[0])):
        return _evaluated(stage, damage_checks(stage, float(T.flat[0]), float(N.flat[0])), *designs)
    out = {k: np.full(T.shape, np.nan) for k in DAMAGE_CHECKS}
    flows, inverse = np.unique(np.stack([T.ravel(), N.ravel()]), axis=1, return_inverse=True)
    inverse = inverse.reshape(T.shape)
    for j, (t, n) in enumerate(flows.T):
        sel = inverse == j
        for k, v in _evaluated(stage, damage_checks(stage, float(t), float(n)), *(a[sel] for a in designs)).items():
            out[k][sel] = v
    return out


def life_options(options: dict) -> dict:
    """A stage's strength options as the damage checks and the life take them: without S_Hmin and S_Fmin (the
    single-load checks' limits; the damage checks' limit is D <= 1, the life's S is computed)."""
    return {k: v for k, v in options.items() if k not in ("S_Hmin", "S_Fmin")}


def check_names(stage) -> tuple:
    """The load checks a stage is sized by: :data:`STRENGTH_CHECKS` (``single_load``) and, with a spectrum,
    :data:`DAMAGE_CHECKS`."""
    return (STRENGTH_CHECKS if stage.single_load else ()) + (DAMAGE_CHECKS if stage.spectrum is not None else ())


def damage_checks(stage, torque_nm: float, speed_rpm: float) -> tuple:
    """The damage checks (ISO 6336-6, :mod:`geardesign.gears.checks.damage`) of a stage with a ``spectrum`` at the
    nominal ``torque_nm`` (N·m) on its pinion and ``speed_rpm`` (rpm), as the check registry builds them: the
    stage's spectrum at that load (:meth:`~geardesign.drives.stages.GearStage.spectrum_at`) over its ``life_h``,
    with its material, strength options, ``sn_curve`` and ``mean_stress_factor``."""
    from ..duty_cycle import DutyCycle

    relative = isinstance(stage.spectrum, DutyCycle)
    return _damage_checks(stage.spectrum, stage.material, stage.life_h, _strength_options(stage), stage.sn_curve,
                          stage.mean_stress_factor, float(torque_nm) if relative else None,
                          float(speed_rpm) if relative else None)


@lru_cache(maxsize=256)
def _damage_checks(spectrum, material, life_h, options: tuple, sn_curve, mean_stress_factor, torque_nm,
                   speed_rpm) -> tuple:
    spec = spectrum if torque_nm is None else spectrum.at(torque_nm, speed_rpm, life_h)
    opts = life_options(_thawed(options))
    built = make_checks(spectrum=spec, material=stage_material(material), strength=opts or None, life_h=life_h,
                        sn_curve=sn_curve, mean_stress_factor=mean_stress_factor)
    return tuple(c for c in built if c.name in DAMAGE_CHECKS)


def _strength_options(stage) -> tuple:
    """The stage's strength options as a hashable key (a dict value, the given factors, as its sorted items)."""
    return tuple(sorted((k, ("dict", tuple(sorted(v.items()))) if isinstance(v, dict) else v)
                        for k, v in (stage.strength or {}).items()))


def safety_limits(options: dict) -> dict:
    """The S_Hmin, S_Fmin among a stage's strength options, as make_checks' limits: the checks' limits, and (left in
    the options too) the chain's (its permissible stresses and the result's S_min)."""
    return {k: options[k] for k in ("S_Hmin", "S_Fmin") if k in options}


def _thawed(options: tuple) -> dict:
    return {k: dict(v[1]) if isinstance(v, tuple) and len(v) == 2 and v[0] == "dict" else v for k, v in options}


def load_checks(stage, torque_nm: float, speed_rpm: float, root: bool = True) -> tuple:
    """The checks of a gear stage's load case at one flow: what :func:`~geardesign.gears.checks.make_checks`
    builds from the stage's load context (its ``costly`` checks: the strength chain, and any load model
    registered with the check registry), the route every pair, region and search takes (docs/extending.md)."""
    return _load_checks(stage.material, stage.life_h, stage.application_factor, _strength_options(stage),
                        stage.checks_key(), torque_nm, speed_rpm, root)


@lru_cache(maxsize=256)
def _load_checks(material, life_h, application_factor, options: tuple, checks: tuple, torque_nm, speed_rpm,
                 root) -> tuple:
    from ...gears.strength import Load

    load = Load(torque_nm=torque_nm, n_rpm=speed_rpm, life_h=life_h, application_factor=application_factor)
    return _built_checks(options, material, checks, load, root)


def _built_checks(options: tuple, material, checks: tuple, load, root: bool) -> tuple:
    """What the check registry adds to a stage's geometric checks for ``load`` (the load case's checks)."""
    opts = _thawed(options)
    limits = safety_limits(opts)
    if not root:
        opts["root"] = False
        limits["S_Fmin"] = None
    built = make_checks(**dict(checks), load=load, material=stage_material(material), strength=opts or None, **limits)
    plain = _plain_names(checks)
    return tuple(c for c in built if c.name not in plain)   # what the load case adds: every registered load model


@lru_cache(maxsize=64)
def _plain_names(checks: tuple) -> frozenset:
    """The names of a stage's geometric checks (built once per checks key: a search builds load cases per call)."""
    from ...gears.checks import make_checks

    return frozenset(c.name for c in make_checks(**dict(checks)))


def _widths(stage, modules: np.ndarray, z1: int) -> tuple:
    """(m, b) grids: every module times the stage's face width, or the ψ_d range's widths."""
    if stage.face_width_mm is not None:
        return modules[:, None], np.full((modules.size, 1), stage.face_width_mm)
    lo, hi = WIDTH_TO_DIAMETER_RANGE
    psi = np.arange(lo, hi + 1e-9, WIDTH_TO_DIAMETER_STEP)
    d1 = modules[:, None] * z1 / math.cos(math.radians(stage.beta_deg))
    least = np.ceil(FACE_WIDTH_PITCHES_MIN * math.pi * modules[:, None] - 1e-9)
    return (np.broadcast_to(modules[:, None], (modules.size, psi.size)),
            np.maximum(np.ceil(psi[None, :] * d1 - 1e-9), least))


def widest_width(stage, z1: int, m: float = 1.0) -> float:
    """The widest face width the sizing tries at module ``m`` [mm] (the stage's own when it has one)."""
    return float(_widths(stage, np.array([float(m)]), z1)[1].max())


def strength_sizes(stage, torque_nm: float, speed_rpm: float, z1: int, z2: int, x1: float, x2: float,
                   modules: np.ndarray, tol: float, tries: int = 1) -> tuple:
    """(candidates, best): the first ``tries`` (m, b) that hold every strength check at shifts x1, x2,
    smallest module first, then narrowest; and (m, b, {check: margin}) of the first candidate, or when
    none holds, of the (m, b) closest to holding."""
    return strength_sizes_many(stage, torque_nm, speed_rpm, [(z1, z2, x1, x2)], modules, tol, tries)[0]


def strength_sizes_many(stage, torque_nm: float, speed_rpm: float, pairs, modules: np.ndarray, tol: float,
                        tries: int = 1) -> list:
    """:func:`strength_sizes` of several tooth pairs ``pairs`` [(z1, z2, x1, x2), ...] at one load, each
    strength call vectorised over them all (its fixed cost shared): the contact margin on every pair's
    whole grid, the root margins where they decide the candidates (:func:`_root_margins`)."""
    grid, first, same = _grid(stage, np.asarray(modules, dtype=float), pairs)
    load = (stage, torque_nm, speed_rpm, grid)
    order = np.lexsort((grid["b"], grid["m"]), axis=1)
    if "contact_strength" in check_names(stage):
        contact = np.take_along_axis(_margins_at(*load, first, root=False)["contact_strength"], same, axis=1)
        margins = {"contact_strength": contact}
    else:       # sized by the spectrum alone: no single-load screen, every design is a candidate until checked
        contact, margins = np.zeros(grid["m"].shape), {}
    margins.update(_root_margins(load, first, same, contact, order, tol, tries))
    return [_first_size(grid["m"][i], grid["b"][i], {k: v[i] for k, v in margins.items()}, order[i], tol, tries)
            for i in range(len(pairs))]


def _grid(stage, modules: np.ndarray, pairs) -> tuple:
    """(grid, first, same) of the pairs' designs, pairs × flat (m, b) grid: ``grid`` {m, b, z1, z2, x1, x2}
    as arrays of that shape; ``first`` True at the first design of each run of equal widths along a
    module's widths; ``same`` the index of that first design (the margins of a design are those of it)."""
    mb = [_widths(stage, modules, z1) for z1, _, _, _ in pairs]
    shape = mb[0][1].shape
    grid = {"m": np.stack([np.broadcast_to(m, shape).ravel() for m, _ in mb]),
            "b": np.stack([np.broadcast_to(b, shape).ravel() for _, b in mb])}
    for i, name in enumerate(("z1", "z2", "x1", "x2")):
        col = np.array([p[i] for p in pairs], dtype=np.int64 if i < 2 else float)
        grid[name] = np.broadcast_to(col[:, None], grid["m"].shape)
    pos = np.arange(grid["b"].shape[1])
    first = np.ones(grid["b"].shape, dtype=bool)
    first[:, 1:] = (grid["b"][:, 1:] != grid["b"][:, :-1]) | (pos[1:] % shape[1] == 0)
    return grid, first, np.maximum.accumulate(np.where(first, pos, 0), axis=1)


def _margins_at(stage, torque_nm, speed_rpm, grid: dict, pick: np.ndarray, root: bool = True) -> dict:
    """{check: margins} of the designs ``pick`` (pairs × flat grid; NaN elsewhere), in one call."""
    names = check_names(stage) if root else STRENGTH_CHECKS[:1]
    out = {k: np.full(pick.shape, np.nan) for k in names}
    if pick.any():
        at = {k: v[pick] for k, v in grid.items()}
        got = strength_margins(stage, at["m"], at["b"], at["z1"], at["z2"], at["x1"], at["x2"], torque_nm, speed_rpm,
                               root=root)
        for k in names:
            out[k][pick] = got[k]
    return out


def _root_margins(load: tuple, first, same, contact: np.ndarray, order: np.ndarray, tol: float, tries: int) -> dict:
    """The root margins, and the damage margins of a stage with a spectrum (NaN where not computed), of the designs
    that decide each pair's sizing (pairs × flat grid). Round one: each pair's first ``tries`` contact-holding designs in (m, b) order (every
    design when none holds contact). A candidate must hold contact, so a pair is settled when ``tries``
    of the designs known hold every check (those known are a leading run of the contact-holding ones in
    that order), or when every contact-holding design is known and one holds. Round two: every design
    of the others (when none holds, the closest design is chosen over the whole grid). A design equal
    to an earlier one of the run (``same``) comes right after it in the order, so computing the firsts
    (``first``) of the designs asked for covers them all."""
    ok_c = contact >= -tol                                   # NaN: no such design, never a candidate
    want = np.zeros(contact.shape, dtype=bool)
    for i, o in enumerate(order):
        holders = o[ok_c[i, o]]
        want[i, holders[:tries] if holders.size else o] = True
    at = _margins_at(*load, want & first)
    roots = {k: np.take_along_axis(at[k], same, axis=1) for k in check_names(load[0]) if k != "contact_strength"}
    known = np.take_along_axis(want & first, same, axis=1)
    held = (ok_c & (np.minimum.reduce(list(roots.values())) >= -tol)).sum(axis=1)
    unsettled = ((held < tries) & (ok_c & ~known).any(axis=1)) | (held == 0)
    more = unsettled[:, None] & ~known
    if more.any():
        at = _margins_at(*load, more & first)
        for k in roots:
            roots[k] = np.where(more, np.take_along_axis(at[k], same, axis=1), roots[k])
    return roots


def _first_size(M: np.ndarray, B: np.ndarray, margins: dict, order: np.ndarray, tol: float, tries: int) -> tuple:
    """(candidates, best) of one pair's flat (m, b) grid, its margins (root NaN where unchecked) and its
    (m, b) order, as :func:`strength_sizes` returns."""
    worst = np.minimum.reduce(list(margins.values()))
    worst = np.where(np.isnan(worst), -np.inf, worst)
    ok = worst[order] >= -tol
    first = order[ok][:tries]
    i = first[0] if first.size else int(np.argmax(worst))
    return ([(float(M[j]), float(B[j])) for j in first],
            (float(M[i]), float(B[i]), {k: float(v[i]) for k, v in margins.items()}))
