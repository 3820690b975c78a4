"""The drive's shafts analysed: the loads of its gears, sprockets and couplings on each shaft, bearing reactions,
DIN 743 safeties at the seats, the least standard seat diameter of a default shaft, bearings chosen for the life,
deflections and the mesh misalignment f_sh they cause, keys at the seats, and the gear stages' efficiencies.

:func:`analyse_shafting` is what :meth:`~geardesign.drives.drive.Drive.analyse` calls when the drive has a
:class:`~geardesign.drives.shafting.Shafting`; the layout rules are :mod:`geardesign.drives.shafting`'s.

Method, per shaft (docs/shafts_in_drive.md):

1. the elements' loads (:func:`element_loads`): a gear's mesh forces on the operating pitch circle
   (:func:`geardesign.gears.forces.pair_forces`) at its pitch point, its torque; a sprocket's chain pull
   F_t + 2 F_f along the line of centres (:func:`geardesign.drives.chain.pull.chain_pull`); a coupling's
   torque (an elastic coupling: its radial force neglected);
2. the reactions of the two bearings from statics (:func:`two_support_reactions`; they do not depend on the
   diameters); bearing A (the locating one) takes the axial force;
3. a default shaft's bearing-seat diameter d_b: the least bore of the bearing series at which every checked
   section reaches S_min after DIN 743 (:func:`geardesign.drives.din743.shaft_safety`; sections: a key seat
   under each keyed gear and hub, a press fit at each bearing, a shoulder at each step and gear body; a gear whose
   keyed rim would be too thin is cut on the shaft, :func:`cut_on_shaft`), then the least from there whose keys
   fit; then the bearing of the shaft's type (:meth:`~geardesign.drives.shafting.Shafting.type_of`) of the least
   bore >= d_b passing every check under both of the shaft's bearing loads (with "auto" a deep groove or
   cylindrical roller bearing before a tapered roller pair, whose axial loads come from the loads its radial loads
   induce, :func:`_pair_loads`; then the smallest outside diameter: :func:`_bearings`), the seat taking its bore; with ``Shafting(stiff=True)`` the default shafts of a pair are thickened until its f_sh is at most
   ISO 6336-1 eq. (44)'s (:func:`iso_f_sh_um`); a drawn shaft keeps its diameters and bearings, and is checked;
4. the beam's deflection (:func:`beam_deflections`, the beam of :func:`geardesign.drives.shaft_beam.analyse_shaft`)
   at each gear's face ends; the mesh
   misalignment of a pair f_sh = |Δδ| over its face width, δ the pinion's deflection relative to the wheel's
   along the tooth force plus the pinion body's torsional wind-up across the face r_w1·T·b/(2·G·J) (J of d_w1),
   each with its sign (:func:`mesh_misalignment_um`): at the nominal load; the strength chain takes
   f_sh·K_A·K_v, its value at F_m/b = K_A·K_v·F_t/b (ISO 6336-1:2006 7.6.2.2), and K_Hβ by method C from it.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from ..errors import GearDesignError
from .shaft_beam import E_STEEL_MPA
from .shafting import FILLET_MM, STEP_MM, default_positions, thicker_bores

__all__ = ["Element", "element_loads", "two_support_reactions", "shaft_deflections", "beam_deflections",
           "analyse_shafting", "iso_f_sh_um", "cut_on_shaft",
           "mesh_misalignment_um", "stage_efficiencies", "with_shaft_misalignment",
           "G_STEEL_MPA", "HUB_LENGTH_D"]

G_STEEL_MPA = 81_000.0     # shear modulus of steel, N/mm² (E/(2(1 + ν)), E = 210 000, ν = 0.3: 80 770)
HUB_LENGTH_D = 1.5         # a sprocket's or coupling's hub length over its seat diameter (its key's hub)
GEAR_HUB_D = 1.2           # a gear's hub: its face width, at least 1.2·d (Chernavsky's l_hub = (1.2 … 1.5)·d)
F_SH_MAX_UM = 1e4         # the largest f_sh the strength chain takes as a given factor (gears/strength/chain.py)
UNLOADED_NM = 1e-6         # a section whose moment, torque (N·m) and axial force (kN) are all below this carries nothing


@dataclass(frozen=True)
class Element:
    """One element on a shaft: ``name`` (its stage's name, or "coupling"), ``kind`` ("pinion", "wheel",
    "sprocket", "coupling"), ``side`` ("left", "right": overhung; "plane": between the bearings in gear plane
    ``plane``), ``width_mm`` (a gear's face width; None for a hub), forces (N) ``fy``, ``fz``, ``fx`` acting at
    ``y_mm`` off the axis, ``torque_nm`` put into the shaft (+: in), ``mass_kg``."""

    name: str
    kind: str
    side: str
    plane: int
    width_mm: float | None
    fy: float
    fz: float
    fx: float
    y_mm: float
    torque_nm: float
    mass_kg: float = 0.0
    root_mm: float | None = None      # a gear's root diameter d_f and module (whether it is cut on its shaft)
    m_mm: float | None = None


def two_support_reactions(x_mm, fy_n, fz_n, fx_n, y_mm, x_a_mm, x_b_mm) -> dict:
    """Reactions (N) of a shaft on two supports at x_a and x_b under forces (fy, fz) at x and axial forces fx
    acting at y off the axis (their couple −y·fx bends the shaft in the x-y plane): statics, Σ F = 0 and
    Σ M_A = 0 in each plane; the axial force taken at A.

    >>> r = two_support_reactions([100.0], [-1000.0], [0.0], [0.0], [0.0], 0.0, 200.0)
    >>> float(r["Ay"]), float(r["By"])
    (500.0, 500.0)
    """
    # plain floats: a drive's shaft carries a few loads, where numpy's cost per call was most of the time
    x, fy, fz, fx, y = (_floats(v) for v in (x_mm, fy_n, fz_n, fx_n, y_mm))
    if not len(x) == len(fy) == len(fz) == len(fx) == len(y):
        raise GearDesignError(f"x_mm, fy_n, fz_n, fx_n and y_mm must be of one length, got {len(x)}, {len(fy)}, "
                              f"{len(fz)}, {len(fx)} and {len(y)}")
    xa = float(x_a_mm)
    L = float(x_b_mm) - xa
    arm = [v - xa for v in x]
    couple = sum(-a * b for a, b in zip(y, fx))          # N·mm about z (x-y plane)
    By = -(sum(a * b for a, b in zip(fy, arm)) + couple) / L
    Bz = -sum(a * b for a, b in zip(fz, arm)) / L
    return {"Ay": -sum(fy) - By, "By": By, "Az": -sum(fz) - Bz, "Bz": Bz, "Ax": -sum(fx)}


def _rotation_senses(drive) -> list:
    """+1/−1 per shaft: shaft 0 positive about +x, a gear mesh reverses the sense, other stages keep it."""
    s = [1.0]
    for st in drive.stages:
        s.append(-s[-1] if getattr(st, "kind", "") == "gear" else s[-1])
    return s


def element_loads(drive, stages_out, T) -> dict:
    """{shaft k: [Element, ...]} of every shaft carrying a gear (the layout's shafts), from the analysed
    stages and the shafts' torques ``T`` (N·m)."""
    from ..gears.forces import pair_forces
    from .chain.pull import chain_pull
    from .stages import disc_mass_kg

    sense = _rotation_senses(drive)
    N = len(drive.stages)
    out: dict = {}
    gear_shafts = set()
    plane = 0
    for k, (st, res) in enumerate(zip(drive.stages, stages_out), start=1):
        if getattr(st, "kind", "") != "gear":
            continue
        pair, stage = res["pair"], res["stage"]
        b = float(stage.width_mm)
        f = pair_forces(pair, float(T[k - 1]))
        s = sense[k - 1]
        geo = pair.geometry()
        m1, m2 = float(disc_mass_kg(geo.da1, b)), float(disc_mass_kg(geo.da2, b))
        m_n = float(pair.m)
        out.setdefault(k - 1, []).append(Element(st.name, "pinion", "plane", plane, b, -f.F_r_n, -s * f.F_t_n,
                                                 f.F_a_n, f.r1_mm, -s * float(T[k - 1]), m1, float(geo.df1), m_n))
        out.setdefault(k, []).append(Element(st.name, "wheel", "plane", plane, b, f.F_r_n, s * f.F_t_n, -f.F_a_n,
                                             -f.r2_mm, sense[k] * float(T[k]), m2, float(geo.df2), m_n))
        gear_shafts.update((k - 1, k))
        plane += 1
    for k, (st, res) in enumerate(zip(drive.stages, stages_out), start=1):
        if getattr(st, "kind", "") != "chain":
            continue
        row = res["row"]
        p = chain_pull(float(T[k - 1]), float(row["pitch_mm"]), int(st.z1), float(res["flow"].n_in_rpm),
                       float(row["mass_kg_m"]), float(row["center_distance_mm"]))
        if k - 1 in gear_shafts:       # the driving sprocket takes power out at the right end
            out[k - 1].append(Element(st.name, "sprocket", "right", -1, None, p.shaft_load_n, 0.0, 0.0, 0.0,
                                      -sense[k - 1] * float(T[k - 1])))
        if k in gear_shafts:           # the driven sprocket brings it in at the left end
            out[k].append(Element(st.name, "sprocket", "left", -1, None, -p.shaft_load_n, 0.0, 0.0, 0.0,
                                  sense[k] * float(T[k])))
    for k in sorted(gear_shafts):     # what else brings power in or takes it out: a coupling, overhung
        els = out[k]
        total = sum(e.torque_nm for e in els)
        if abs(total) <= 1e-12 * max(abs(e.torque_nm) for e in els):
            continue
        incoming = -total * sense[k] > 0
        side = "left" if incoming else "right"
        if any(e.side == side for e in els):
            raise GearDesignError(f"shaft {k} needs a coupling at its {side} end, where a sprocket sits already")
        # a bought unit's (given stage's) shaft end, or the drive's input or output coupling
        j = k if incoming else k + 1
        name = drive.stages[j - 1].name if 1 <= j <= N and getattr(drive.stages[j - 1], "kind", "") == "given" \
            else "coupling"
        els.append(Element(name, "coupling", side, -1, None, 0.0, 0.0, 0.0, 0.0, -total))
    return out


# -- the shaft's geometry ------------------------------------------------------------------------------------

@dataclass
class _Geometry:
    """One shaft's model inputs: sections, bearing positions, element positions and hub lengths, the sections
    to check, and (default layout) the bearing-seat diameter it was built for."""

    sections: tuple
    supports: tuple
    x: dict            # element name -> x_mm
    hubs: dict         # element name -> (seat d, hub length)
    notches: list
    d_b: float | None
    given: bool


def cut_on_shaft(root_mm, m_mm, d_mm) -> bool:
    """True when a gear of root diameter d_f and module m on a seat of diameter d is cut on its shaft (a pinion
    shaft) rather than keyed: when the rim left over the keyway, (d_f − d)/2 − t_2 with the hub's keyway depth
    t_2 ≈ 0.05·d, would be thinner than 2.5·m (the rule of thumb for a keyed gear's rim in reducer design
    textbooks, e.g. Dunaev & Lelikov; a stated choice, see docs/shafts_in_drive.md).

    >>> cut_on_shaft(52.5, 3.0, 45.0), cut_on_shaft(52.5, 3.0, 20.0)
    (True, False)
    """
    return (root_mm - d_mm) / 2.0 - 0.05 * d_mm < 2.5 * m_mm


BODY_FILLET_D = 0.1     # the fillet at a gear body cut on its shaft, over the seat diameter


def _stepped(pieces) -> tuple:
    """Sections (length, d) from pieces (x0, x1, d), a later piece over an earlier one where it is thicker."""
    cuts = sorted({v for x0, x1, _ in pieces for v in (x0, x1)})
    out = []
    for a, b in zip(cuts, cuts[1:]):
        mid = 0.5 * (a + b)
        d = max(p[2] for p in pieces if p[0] <= mid <= p[1])
        if out and out[-1][1] == d:
            out[-1] = (out[-1][0] + b - a, d)
        else:
            out.append((b - a, d))
    return tuple(out)


def _default_geometry(sh, elements, planes, d_b) -> _Geometry:
    """The default shaft (module docstring of :mod:`geardesign.drives.shafting`) at bearing-seat diameter d_b; a
    gear whose keyed rim would be too thin (:func:`cut_on_shaft`) is cut on the shaft: its body, of its root
    diameter over its face width, is part of the shaft (no key; shoulders at its sides)."""
    from .din743 import Notch, ShaftNotch

    c = sh.clearance_mm
    offsets, span = planes
    left = [e for e in elements if e.side == "left"]
    right = [e for e in elements if e.side == "right"]
    x_a = max(sh.overhang_mm, c / 2.0 + 5.0) if left else c / 2.0
    x_b = x_a + span
    end = x_b + (max(sh.overhang_mm, c / 2.0 + 5.0) if right else c / 2.0)
    d_e, d_g = d_b - STEP_MM, d_b + STEP_MM
    pieces = [(0.0, x_a - c / 2.0, d_e if left else d_b), (x_a - c / 2.0, x_a + c / 2.0, d_b),
              (x_a + c / 2.0, x_b - c / 2.0, d_g), (x_b - c / 2.0, x_b + c / 2.0, d_b),
              (x_b + c / 2.0, end, d_e if right else d_b)]
    pieces = [p for p in pieces if p[1] > p[0]]
    x, hubs, notches, steps = {}, {}, [], [x_a + c / 2.0, x_b - c / 2.0]
    steps += ([x_a - c / 2.0] if left else []) + ([x_b + c / 2.0] if right else [])
    bodies = []
    for e in elements:
        if e.side == "plane":
            x[e.name] = x_a + offsets[e.plane]
            hubs[e.name] = (d_g, max(e.width_mm, GEAR_HUB_D * d_g))
            if e.root_mm is not None and cut_on_shaft(e.root_mm, e.m_mm, d_g):
                if d_g <= 0.98 * e.root_mm:     # (a root within 2 % of the seat: the seat's section, no step)
                    x0, x1 = x[e.name] - e.width_mm / 2.0, x[e.name] + e.width_mm / 2.0
                    pieces.append((x0, x1, e.root_mm))
                    bodies += [x0, x1]
                hubs[e.name] = None          # no key: the gear is the shaft
                continue
        else:
            x[e.name] = 0.0 if e.side == "left" else end
            hubs[e.name] = (d_e, HUB_LENGTH_D * d_e)
        notches.append(ShaftNotch(x[e.name], Notch("key"), f"key {e.name}"))
    for tag, xs in (("A", x_a), ("B", x_b)):
        notches.append(ShaftNotch(xs, Notch("press_fit"), f"bearing {tag}"))
    for xs in sorted(steps):
        notches.append(ShaftNotch(xs, Notch("shoulder", r_mm=FILLET_MM), f"shoulder at {xs:.4g}"))
    for xs in bodies:
        notches.append(ShaftNotch(xs, Notch("shoulder", r_mm=BODY_FILLET_D * d_g), f"gear body at {xs:.4g}"))
    return _Geometry(_stepped(pieces), (x_a, x_b), x, hubs, notches, d_b, False)


def _given_geometry(ds, elements) -> _Geometry:
    """A DriveShaft: its sections and supports, its elements where it puts them; the sections to check: a key seat
    under each element, a press fit at each bearing, a shoulder at each diameter step."""
    from .din743 import Notch, ShaftNotch
    from .shaft_beam import ShaftModel

    names = {e.name for e in elements}
    missing = sorted(names - set(ds.positions))
    if missing:
        raise GearDesignError(f"shaft {ds.at}: positions must place {', '.join(repr(m) for m in missing)} "
                              f"(the elements this shaft carries)")
    extra = sorted(set(ds.positions) - names)
    if extra:
        raise GearDesignError(f"shaft {ds.at}: positions name {', '.join(repr(m) for m in extra)}, which this "
                              f"shaft does not carry (it carries {', '.join(sorted(names))})")
    model = ShaftModel(ds.sections, ds.supports_mm)
    x, hubs, notches = {}, {}, []
    for e in elements:
        x[e.name] = ds.positions[e.name]
        d = float(model.diameter_at(x[e.name])[0])
        hub = ds.widths.get(e.name, max(e.width_mm, GEAR_HUB_D * d) if e.width_mm is not None else HUB_LENGTH_D * d)
        hubs[e.name] = (d, hub)
        notches.append(ShaftNotch(x[e.name], Notch("key"), f"key {e.name}"))
    for tag, xs in zip("AB", ds.supports_mm):
        notches.append(ShaftNotch(xs, Notch("press_fit"), f"bearing {tag}"))
    ends = model.section_ends_mm[1:-1]
    ds_ = [s[1] for s in model.sections]
    for i, xs in enumerate(ends):
        if ds_[i] != ds_[i + 1]:
            notches.append(ShaftNotch(float(xs), Notch("shoulder", r_mm=FILLET_MM), f"shoulder at {xs:.4g}"))
    return _Geometry(model.sections, model.supports_mm, x, hubs, notches, None, True)


def _model(geo: _Geometry, elements):
    from .shaft_beam import ShaftLoad, ShaftModel

    loads = [ShaftLoad(geo.x[e.name], fy_n=e.fy, fz_n=e.fz, fx_n=e.fx, y_mm=e.y_mm, torque_nm=e.torque_nm,
                       mass_kg=e.mass_kg, name=e.name) for e in elements]
    return ShaftModel(geo.sections, geo.supports, loads, axial_support=0)


def _safety(geo, elements, sh, mat):
    """(ShaftSafety, ShaftAnalysis) of a shaft geometry (coarse beam grid: the diagrams are exact at the nodes)."""
    from .din743 import shaft_safety
    from .shaft_beam import analyse_shaft

    a = analyse_shaft(_model(geo, elements), points=40)
    return shaft_safety(a, geo.notches, mat, peak_factor=sh.peak_factor, S_min=sh.S_min), a


def _least(table) -> float:
    return float(np.minimum(table["S_D"], table["S_F"]).min())


def _diagram(geo, elements) -> tuple:
    """(x, M, T, N): the bending moment, torque (N·m) and axial force (N) along a shaft. On two supports they do not
    depend on the diameters (statics), so a default shaft's sizing reads them once."""
    from .shaft_beam import analyse_shaft

    d = analyse_shaft(_model(geo, elements), points=10, shaft_mass=False).diagrams
    return tuple(d[c].to_numpy() for c in ("x_mm", "M_nm", "T_nm", "N_n"))


def _loads_at(diagram, x_mm) -> tuple:
    """(M, |T|, N) at x, the larger limit at a node, as :func:`~geardesign.drives.din743.shaft_safety` reads them."""
    x, M, T, N = diagram
    at = np.flatnonzero(x == x_mm)
    if at.size:
        return float(M[at].max()), float(np.abs(T[at]).max()), float(N[at][np.argmax(np.abs(N[at]))])
    return float(np.interp(x_mm, x, M)), abs(float(np.interp(x_mm, x, T))), float(np.interp(x_mm, x, N))


def _diameters_at(geo, x_mm) -> tuple:
    """(d left, d right) of the sections of ``geo`` at x."""
    ends = np.concatenate([[0.0], np.cumsum([s[0] for s in geo.sections])])
    ds = [s[1] for s in geo.sections]
    i_r = min(max(int(np.searchsorted(ends, x_mm, side="right")) - 1, 0), len(ds) - 1)
    i_l = min(max(int(np.searchsorted(ends, x_mm, side="left")) - 1, 0), len(ds) - 1)
    return ds[i_l], ds[i_r]


def _holds(sh, mat, geo, diagram) -> bool:
    """Every section of the default shaft ``geo`` to check reaches S_min (DIN 743, as shaft_safety takes them: a
    shoulder's d and D the two sides of its step, a key seat or press fit on the thinner side)."""
    from .din743 import din743_safety

    d_eff = max(s[1] for s in geo.sections)
    for sn in geo.notches:
        M, T, N = _loads_at(diagram, sn.x_mm)
        if M <= 0.0 and T <= 0.0 and N == 0.0:
            continue
        dl, dr = _diameters_at(geo, sn.x_mm)
        d, D = min(dl, dr), (max(dl, dr) if sn.notch.kind == "shoulder" else None)
        r = din743_safety(mat, sn.notch, d_mm=d, D_mm=D, d_eff_mm=d_eff, F_zdm=N, M_ba=M, T_m=T,
                          F_zdmax=sh.peak_factor * abs(N), M_bmax=sh.peak_factor * M, T_max=sh.peak_factor * T,
                          S_min=sh.S_min)
        if min(r.S_D, r.S_F) < sh.S_min:
            return False
    return True


def _keys_fit(geo, elements) -> bool:
    """Every keyed element's parallel key (:func:`geardesign.drives.key.select`, on its seat, in its hub: a gear's
    face width, at least 1.2·d; a sprocket's or coupling's 1.5·d) carries its torque."""
    from . import key as keys

    return all(keys.select(geo.hubs[e.name][0], abs(e.torque_nm), geo.hubs[e.name][1]).feasible
               for e in elements if geo.hubs[e.name] is not None and abs(e.torque_nm) > 0)


def _sized_geometry(sh, mat, elements, planes, bores, d_min):
    """The default shaft at the least catalog bore >= d_min whose sections all reach S_min (bisection: the safety
    rises as the shaft thickens; the thickest when none does), then the least from there whose keys hold."""
    cand = [d for d in bores if d >= d_min and d - STEP_MM >= 6.0]
    if not cand:
        raise GearDesignError(f"no bearing bore of series {', '.join(sh.series)} is >= {d_min:g} mm")
    diagram = _diagram(_default_geometry(sh, elements, planes, cand[-1]), elements)

    def ok(d):
        return _holds(sh, mat, _default_geometry(sh, elements, planes, d), diagram)

    lo, hi = 0, len(cand) - 1
    if not ok(cand[hi]):
        return _default_geometry(sh, elements, planes, cand[hi])
    while lo < hi:
        mid = (lo + hi) // 2
        lo, hi = (lo, mid) if ok(cand[mid]) else (mid + 1, hi)
    # the keys: the next bores up while one does not fit (a key's margins rise with d until its section's
    # shortest length outgrows a narrow hub: then no bore fits and the least safe one stays, its key failing)
    for d in cand[lo:]:
        geo = _default_geometry(sh, elements, planes, d)
        if _keys_fit(geo, elements):
            return geo
    return _default_geometry(sh, elements, planes, cand[lo])


# -- bearings --------------------------------------------------------------------------------------------------

@lru_cache(maxsize=16)
def _catalog(series: tuple):
    from .bearing import bearing_catalog

    return bearing_catalog(list(series))


def _pair_loads(rows, loads, ka_n):
    """Each catalog row's axial loads (Fa_A, Fa_B), N, as arrays, on a shaft's two bearings of that row under the
    radial loads of ``loads`` and the external axial force ``ka_n`` (> 0: toward bearing B): a tapered roller pair
    adjusted against each other (:func:`geardesign.drives.bearing.tapered_axial_loads`, SKF 17000/1 EN Table 7),
    each bearing its share with the loads its neighbour's radial load induces; any other bearing: A, the locating
    one, takes the whole axial force and B none."""
    from .bearing import tapered_axial_loads

    n = len(rows)
    fa_a, fa_b = np.full(n, abs(ka_n)), np.zeros(n)
    tr = (rows["bearing_type"] == "tapered_roller").to_numpy()
    if tr.any():
        Y = rows["Y"].to_numpy(dtype=float)[tr]
        fa_a[tr], fa_b[tr] = tapered_axial_loads(loads[0][0], loads[1][0], Y, Y, ka_n)
    return fa_a, fa_b


def _toward_b(sh, reactions, supports) -> float:
    """The external axial force on the shaft (N) as tapered_axial_loads takes it: > 0 toward the bearing that takes
    it, B. Face to face ("X") each bearing takes what points toward it, back to back ("O") the other one."""
    push = -float(reactions["Ax"]) * (1.0 if supports[1] >= supports[0] else -1.0)    # Σ F_x toward B's side
    return push if sh.arrangement == "X" else -push


def _bearings(sh, k, ds, reactions, n_rpm, bore, supports, grid=None):
    """(designations, [BearingCheck A, B]) of shaft k: the given ones, else chosen from the series of the shaft's
    bearing type (:meth:`~geardesign.drives.shafting.Shafting.type_of`) whose bore is >= ``bore`` (a drawn shaft:
    equal to its seat; a default one: a bore of ``grid``, the seat sizing's bores), both bearings alike, passing
    every check under both bearings' loads (a tapered pair's axial loads by :func:`_pair_loads`): the least bore
    first; at that bore, with "auto", a deep groove (or cylindrical roller) bearing before a tapered pair; then the
    smallest outside diameter. None holds: the one nearest to holding under the worse of its two loads."""
    from .bearing import _check_from_row, _evaluate, bearing_catalog, check_bearing, reliability_factor

    radial = [(max(math.hypot(reactions["Ay"], reactions["Az"]), 1e-9), abs(reactions["Ax"])),
              (max(math.hypot(reactions["By"], reactions["Bz"]), 1e-9), 0.0)]
    ka = _toward_b(sh, reactions, supports)
    if ds is not None and ds.bearings is not None:
        names = ds.bearings
        rows = bearing_catalog(tuple(dict.fromkeys(_catalog_series_of(names))))
        rows = rows.set_index("designation").loc[list(names)].reset_index()
        tapered = (rows["bearing_type"] == "tapered_roller").to_numpy()
        if tapered.any() and not tapered.all():
            raise GearDesignError(f"shaft {k}: bearings {names[0]!r} and {names[1]!r}: a tapered roller bearing is "
                                  f"mounted against another one (a pair adjusted against each other)")
        if tapered.all():
            fa = tapered_pair_axial(rows, radial, ka)
            loads = [(radial[0][0], fa[0]), (radial[1][0], fa[1])]
        else:
            loads = radial
        return names, [check_bearing(name, fr, fa, n_rpm=n_rpm, life_h=sh.life_h, reliability=sh.reliability)
                       for name, (fr, fa) in zip(names, loads)]
    series = sh.series_for(sh.type_of(k))
    rows = _catalog(series)
    keep = (rows["d_mm"] >= bore - 1e-9) & ((ds is None) | (rows["d_mm"] <= bore + 1e-9))
    if ds is None and grid is not None:
        keep &= rows["d_mm"].isin(grid)
    rows = rows[keep].reset_index(drop=True)
    if rows.empty:
        what = f"a bore of {bore:g} mm (the seat of shaft {ds.at} as given)" if ds is not None else f"a bore >= {bore:g} mm"
        raise GearDesignError(f"no bearing of series {', '.join(series)} has {what}: give the shaft's bearings "
                              f"or a seat of a catalog bore")
    a1 = reliability_factor(sh.reliability)
    fa_a, fa_b = _pair_loads(rows, radial, ka)
    ta, tb = (_evaluate(rows, fr, fa, n_rpm, sh.life_h, a1, None, None, "grease", None)
              for fr, fa in ((radial[0][0], fa_a), (radial[1][0], fa_b)))
    both = (ta["feasible"] & tb["feasible"]).to_numpy()
    if both.any():          # the least bore, at it radial before tapered (the series' order), the smallest D
        step = rows["bearing_type"].eq("tapered_roller").to_numpy()
        j = int(np.lexsort((np.arange(len(rows)), rows["D_mm"].to_numpy(), step, rows["d_mm"].to_numpy(), ~both))[0])
    else:                   # none: the one nearest to holding under the worse of its two loads
        worst = np.fmin(ta["min_margin"].to_numpy(), tb["min_margin"].to_numpy())
        j = int(np.argmax(np.where(np.isnan(worst), -np.inf, worst)))
    checks = [_check_from_row(t.iloc[j], fr, float(fa[j]), n_rpm, sh.life_h)     # row j was evaluated at its loads
              for t, fr, fa in ((ta, radial[0][0], fa_a), (tb, radial[1][0], fa_b))]
    name = checks[0].designation
    return (name, name), checks


def tapered_pair_axial(rows, radial, ka_n) -> tuple:
    """(Fa_A, Fa_B), N, of the two given tapered roller bearings ``rows`` (A then B) under the radial loads of
    ``radial`` [(Fr, ...), (Fr, ...)] and the external axial force ``ka_n`` toward B (SKF 17000/1 EN Table 7)."""
    from .bearing import tapered_axial_loads

    Y = rows["Y"].to_numpy(dtype=float)
    fa = tapered_axial_loads(radial[0][0], radial[1][0], Y[0], Y[1], ka_n)
    return float(fa[0]), float(fa[1])


def _types_of(checks) -> list:
    """The catalog bearing type of each BearingCheck (deep_groove_ball, tapered_roller, ...)."""
    from .bearing import SERIES

    return [SERIES[c.series][1] for c in checks]


def _catalog_series_of(names) -> list:
    """The catalog series holding each designation (an unknown one: refused by name, as check_bearing does)."""
    from .bearing import SERIES, bearing_catalog

    cat = bearing_catalog(tuple(SERIES))
    out = []
    for name in names:
        hit = cat.loc[cat["designation"] == name, "series"]
        if hit.empty:
            raise GearDesignError(f"designation {name!r} is in none of the bearing catalogs (series "
                                  f"{', '.join(SERIES)}); see geardesign.drives.bearing.bearing_catalog")
        out.append(str(hit.iloc[0]))
    return out


# -- the mesh misalignment -------------------------------------------------------------------------------------

def shaft_deflections(model, x_mm) -> tuple:
    """(reactions (2, supports) in N: the x-y and x-z planes, deflections (2, len(x)) in mm at ``x_mm``) of a
    :class:`~geardesign.drives.shaft_beam.ShaftModel`: :func:`beam_deflections` of its sections and loads.

    >>> from geardesign.drives.shaft_beam import ShaftLoad, ShaftModel, second_moment_mm4
    >>> R, w = shaft_deflections(ShaftModel([(200.0, 40.0)], [0.0, 200.0], [ShaftLoad(100.0, fy_n=-1000.0)]), [100.0])
    >>> R[0].round(9).tolist(), round(float(w[0, 0] / (-1000 * 200**3 / (48 * 210000 * second_moment_mm4(40)))), 12)
    ([500.0, 500.0], 1.0)
    """
    loads = model.loads
    return beam_deflections(model.sections, model.supports_mm, [ld.x_mm for ld in loads], [ld.fy_n for ld in loads],
                            [ld.fz_n for ld in loads],
                            [-ld.y_mm * ld.fx_n + 1000.0 * ld.mz_nm for ld in loads],
                            [-ld.z_mm * ld.fx_n + 1000.0 * ld.my_nm for ld in loads], x_mm, model.E_mpa)


SCALAR_BEAM_MAX = 4096     # sections + loads² up to which a two-support beam is solved in plain floats (its cost)


def _beam_two_supports(secs, a, b, xf, F, C, xq, E_mpa) -> tuple:
    """:func:`beam_deflections` of a shaft on two supports at a and b, in plain Python floats: the same nodes (every
    breakpoint's left and right limit), reactions by statics, moment and curvature at the nodes, the same exact
    segment-wise integration and constants from w = 0 at both supports (results within a few ulp of the array
    code). ``secs``: [(length, d, bore)]; ``xf``: load positions; ``F``, ``C``: the two planes' forces and couples
    (N, N·mm), a list per plane; ``xq``: query positions. Returns (R [(A, B) per plane], w [[...] per plane])."""
    from bisect import bisect_right

    ends = [0.0]
    for s in secs:
        ends.append(ends[-1] + s[0])
    last = len(secs) - 1
    brk = sorted(set(ends) | {a, b} | set(xf))
    nb = len(brk)
    # EI of each segment between breakpoints (every section end is one: a segment lies in one section)
    EI_sec = [E_mpa * (math.pi * (d ** 4 - di ** 4) / 64.0) for _, d, di in secs]
    EI, i = [], 0
    for x in brk[:-1]:
        while i < last and ends[i + 1] <= x:
            i += 1
        EI.append(EI_sec[i])
    EI_left, EI_right = [EI[0]] + EI, EI + [EI[-1]]      # a node's left limit: the segment before it
    ia, ib = brk.index(a), brk.index(b)
    R, out_w = [], []
    for Fp, Cp in zip(F, C):
        Rb = (sum(Cp) + sum(f * (x - a) for f, x in zip(Fp, xf))) / (a - b)
        Ra = -sum(Fp) - Rb
        R.append((Ra, Rb))
        # moment at the nodes: a force at xs acts on the nodes right of it (at xs itself its arm is 0), a couple on
        # the nodes right of it and on its own node's right limit (a zero force or couple adds nothing: left out)
        M = [0.0] * nb
        for xs, f in zip(xf + [a, b], Fp + [Ra, Rb]):
            if f != 0.0:
                for j in range(bisect_right(brk, xs), nb):
                    M[j] += f * (brk[j] - xs)
        cl, cr = [0.0] * nb, [0.0] * nb
        for xs, c in zip(xf, Cp):
            if c != 0.0:
                j0 = brk.index(xs)
                cr[j0] += c
                for j in range(j0 + 1, nb):
                    cl[j] += c
                    cr[j] += c
        kl = [(m - c) / e for m, c, e in zip(M, cl, EI_left)]      # curvature M/EI, left and right limits
        kr = [(m - c) / e for m, c, e in zip(M, cr, EI_right)]
        theta, w = [0.0] * nb, [0.0] * nb
        for j in range(nb - 1):
            h = brk[j + 1] - brk[j]
            k0, k1 = kr[j], kl[j + 1]
            theta[j + 1] = theta[j] + h * (k0 + k1) / 2.0
            w[j + 1] = w[j] + (theta[j] * h + h * h * (2.0 * k0 + k1) / 6.0)
        c1 = -(w[ib] - w[ia]) / (b - a)
        c0 = -w[ia] - c1 * a
        row = []
        for x in xq:
            j = bisect_right(brk, x) - 1
            if 0 <= j < nb - 1:         # inside segment j: from its right limit to the next node's left limit
                h, k0 = brk[j + 1] - brk[j], kr[j]
                dk = (kl[j + 1] - k0) / h if h > 0 else 0.0
            else:                       # beyond an end: that end's (left-limit) node, no change of curvature
                j = 0 if j < 0 else nb - 1
                k0, dk = kl[j], 0.0
            s = x - brk[j]
            row.append(w[j] + c0 + c1 * brk[j] + (theta[j] + c1) * s + k0 * s * s / 2.0 + dk * s ** 3 / 6.0)
        out_w.append(row)
    return R, out_w


def _floats(v) -> list:
    """A list of Python floats from a number, a list or an array."""
    if isinstance(v, (list, tuple)):
        return [float(u) for u in v]
    return np.asarray(v, dtype=float).ravel().tolist()


def beam_deflections(sections, supports_mm, x_mm, fy_n, fz_n, couple_xy_nmm, couple_xz_nmm, x_query_mm,
                     E_mpa=E_STEEL_MPA) -> tuple:
    """Reactions (2, supports) (N) and deflections (2, len(x_query)) (mm) in the x-y and x-z planes of a stepped
    shaft (``sections`` (length, d[, bore]) from x = 0) on its supports under forces (fy, fz) at x and couples
    (N·mm; an axial force's −y·F_x) there: the beam of :func:`~geardesign.drives.shaft_beam.analyse_shaft` (the
    same exact segment-wise integration, on the breakpoints alone: curvature is linear between them), on plain
    arrays, without its validation, tables and critical speeds (the drive's f_sh needs only these). On two
    supports the reactions come from statics and the two integration constants from w = 0 at both (no linear
    system); on more, the beam's own solve."""
    from .shaft_beam import _active, _integrate, _solve_plane, second_moment_mm4

    if len(supports_mm) == 2 and len(sections) + np.size(x_mm) ** 2 <= SCALAR_BEAM_MAX:
        # a drive's shaft: plain floats (the same method; numpy's cost per call on a dozen nodes was 90 % of the time)
        xf, fy, fz, cy, cz, xq = (_floats(v) for v in (x_mm, fy_n, fz_n, couple_xy_nmm, couple_xz_nmm, x_query_mm))
        R, w = _beam_two_supports([(float(s[0]), float(s[1]), float(s[2]) if len(s) > 2 else 0.0) for s in sections],
                                  float(supports_mm[0]), float(supports_mm[1]), xf, (fy, fz), (cy, cz), xq,
                                  float(E_mpa))
        return np.array(R), np.array(w).reshape((2,) + np.shape(x_query_mm))
    secs = np.asarray([tuple(s) + (0.0,) * (3 - len(s)) for s in sections], dtype=float)
    ends = np.concatenate([[0.0], np.cumsum(secs[:, 0])])
    xf = np.asarray(x_mm, dtype=float)
    sup = np.asarray(supports_mm, dtype=float)
    brk = np.unique(np.concatenate([ends, sup, xf]))
    x = np.concatenate([brk, brk])
    right = np.concatenate([np.zeros(brk.size, bool), np.ones(brk.size, bool)])
    order = np.lexsort((right, x))
    x, right = x[order], right[order]
    i = np.clip(np.searchsorted(ends, x, side="right") - 1, 0, len(secs) - 1)      # right-limit sections
    il = np.clip(np.searchsorted(ends, x, side="left") - 1, 0, len(secs) - 1)      # left-limit sections
    j = np.where(right, i, il)
    EI = E_mpa * second_moment_mm4(secs[j, 1], secs[j, 2])
    F = np.vstack([np.asarray(fy_n, dtype=float), np.asarray(fz_n, dtype=float)]).reshape(2, xf.size)
    C = np.vstack([np.asarray(couple_xy_nmm, dtype=float), np.asarray(couple_xz_nmm, dtype=float)]).reshape(2, xf.size)
    if sup.size == 2:       # statically determinate: the reactions by statics, the beam's constants by w = 0 at both
        a, b = sup
        Rb = (C.sum(axis=1) + F @ (xf - a)) / (a - b)
        R = np.column_stack([-F.sum(axis=1) - Rb, Rb])
        xs = np.concatenate([xf, sup])
        M = np.hstack([F, R]) @ (_active(x, right, xs) * (x[:, None] - xs[None, :])).T - C @ _active(x, right, xf).T
        kappa = M / EI
        theta, w = _integrate(kappa, x)
        ia, ib = np.searchsorted(x, sup, side="left")       # a support's left-limit node (w is continuous)
        c1 = -(w[:, ib] - w[:, ia]) / (b - a)
        c0 = -w[:, ia] - c1 * a
        w = w + c0[:, None] + c1[:, None] * x[None, :]
        theta = theta + c1[:, None]
    else:
        R, _, kappa, theta, w = _solve_plane(x, right, EI, sup, xf, F, xf, C)
    # the exact cubic of the segment holding each query point, both planes at once (shaft_beam._Plane.at)
    xq = np.asarray(x_query_mm, dtype=float)
    i = np.clip(np.searchsorted(x, xq, side="right") - 1, 0, x.size - 2)
    h = x[i + 1] - x[i]
    s = xq - x[i]
    k0, k1 = kappa[:, i], kappa[:, i + 1]
    dk = np.where(h > 0, (k1 - k0) / np.where(h > 0, h, 1.0), 0.0)
    return R, w[:, i] + theta[:, i] * s + k0 * s * s / 2.0 + dk * s ** 3 / 6.0


def mesh_misalignment_um(pinion_w, wheel_w, direction, r_w1_mm, torque1_nm, b_mm, d_w1_mm, twist_sign=1.0,
                         G_mpa=G_STEEL_MPA):
    """f_sh (µm) of a gear pair from its shafts: ``pinion_w``, ``wheel_w`` the deflections (wy, wz) (mm) of the two
    shafts at the two face ends, left then right (arrays (2, 2): end, plane); ``direction`` the unit tooth force on
    the pinion (y, z): δ = (w_pinion − w_wheel)·n at each end, their difference across the face Δδ_bend; and the
    pinion body's wind-up across the face, r_w1·T·b/(2·G·J), J = π·d_w1⁴/32 (the torque fed in at one side of the
    face and taken out evenly over it): its flank lags, along the tooth force, more at the side away from where the
    torque comes in (``twist_sign`` +1: it comes in from the left, −1: from the right). f_sh = |Δδ_bend + Δδ_twist|,
    the two signed as ISO 6336-1:2006 eq. (44) combines the pinion's bending and torsion.

    A pinion whose shafts do not bend: only the wind-up, T·b·r/(2GJ):

    >>> z = [[0.0, 0.0], [0.0, 0.0]]
    >>> f = mesh_misalignment_um(z, z, (0.0, 1.0), 30.0, 500.0, 60.0, 60.0)
    >>> round(f, 6) == round(1000 * 30 * 500e3 * 60 / (2 * 81000 * math.pi * 60**4 / 32), 6)
    True
    """
    pw, ww = np.asarray(pinion_w, dtype=float), np.asarray(wheel_w, dtype=float)
    n = np.asarray(direction, dtype=float)
    delta = (pw - ww) @ n
    J = math.pi * d_w1_mm ** 4 / 32.0
    twist = r_w1_mm * 1000.0 * abs(torque1_nm) * b_mm / (2.0 * G_mpa * J)
    return 1000.0 * abs(float(delta[1] - delta[0]) + float(twist_sign) * twist)


# -- the whole drive -------------------------------------------------------------------------------------------

def _gear_planes(drive, stages_out, elements) -> tuple:
    """(offsets from bearing A of the gear planes, span) of the default layout (:func:`default_positions`), where a
    drawn shaft carries a gear its plane where that shaft puts it (the default shafts beside it follow; the two
    gears of a pair in one plane) and the span at least the drawn shafts' spans."""
    sh = drive.shafting
    widths = [float(res["stage"].width_mm) for st, res in zip(drive.stages, stages_out)
              if getattr(st, "kind", "") == "gear"]
    offsets, span = default_positions(widths, sh.clearance_mm, sh.gear_gap_mm)
    drawn: dict = {}
    for ds in sh.layout:
        for e in elements.get(ds.at, ()):
            if e.side != "plane" or e.name not in ds.positions:
                continue
            off = ds.positions[e.name] - ds.supports_mm[0]
            if e.plane in drawn and abs(drawn[e.plane][0] - off) > 1e-6:
                raise GearDesignError(f"stage '{e.name}': its two gears must be in one plane, {drawn[e.plane][0]:g} mm "
                                      f"from bearing A on shaft {drawn[e.plane][1]} but {off:g} mm on shaft {ds.at}")
            drawn[e.plane] = (off, ds.at)
        span = max(span, ds.supports_mm[1] - ds.supports_mm[0])
    offsets = [drawn[p][0] if p in drawn else o for p, o in enumerate(offsets)]
    return offsets, span


def _seat_bores(sh, k) -> list:
    """The bores a default shaft k's bearing seat is sized over: those of its bearing type's series ("auto": of
    its deep groove and cylindrical roller series, the first it tries, when it has them)."""
    series = sh.series_for(sh.type_of(k))
    cat = _catalog(series)
    first = cat[cat["bearing_type"] != "tapered_roller"]
    return sorted(set(float(v) for v in (first if len(first) else cat)["d_mm"]))


def _placed(sh, k, els, planes, bores, n_rpm, d_min):
    """(geometry, model, bearing designations, BearingChecks, material) of shaft k: a drawn one as drawn, a default
    one at the least bore >= d_min holding DIN 743 and its keys, then on the bearings chosen for it (their bore
    the seat: a thicker shaft where the life needs a larger bearing)."""
    from .din743 import _material

    ds = sh.given(k)
    mat = sh._material if ds is None or ds.material is None else _material(ds.material)
    geo = _given_geometry(ds, els) if ds is not None else _sized_geometry(sh, mat, els, planes, bores, d_min)
    model = _model(geo, els)
    r = two_support_reactions([geo.x[e.name] for e in els], [e.fy for e in els], [e.fz for e in els],
                              [e.fx for e in els], [e.y_mm for e in els], *geo.supports)
    seat = geo.d_b if geo.d_b is not None else float(model.diameter_at(geo.supports[0])[0])
    names, checks = _bearings(sh, k, ds, r, n_rpm, seat, geo.supports, bores)
    if ds is None and checks[0].d_mm > geo.d_b:      # the bearing's bore is the seat: a thicker shaft
        geo = _default_geometry(sh, els, planes, checks[0].d_mm)
        model = _model(geo, els)
    return geo, model, names, checks, mat


def _mesh_f_sh(drive, stages_out, T, elements, placed) -> dict:
    """{stage name: f_sh at the nominal load, µm} of every gear pair whose two shafts are placed."""
    out = {}
    for k, (st, res) in enumerate(zip(drive.stages, stages_out), start=1):
        if getattr(st, "kind", "") != "gear" or k - 1 not in placed or k not in placed:
            continue
        b = float(res["stage"].width_mm)
        (gp, mp), (gw, mw) = placed[k - 1][:2], placed[k][:2]
        xp, xw = gp.x[st.name], gw.x[st.name]
        wp = shaft_deflections(mp, np.clip([xp - b / 2.0, xp + b / 2.0], 0.0, mp.length_mm))[1].T
        ww = shaft_deflections(mw, np.clip([xw - b / 2.0, xw + b / 2.0], 0.0, mw.length_mm))[1].T
        pin = next(e for e in elements[k - 1] if e.name == st.name)
        F = math.hypot(pin.fy, pin.fz)
        geo_p = res["pair"].geometry()
        # where the pinion's torque comes from: the elements bringing torque into its shaft (opposite sign)
        src = [gp.x[e.name] for e in elements[k - 1] if e.torque_nm * pin.torque_nm < 0]
        sign = 1.0 if (sum(src) / len(src) if src else 0.0) < xp else -1.0
        out[st.name] = mesh_misalignment_um(wp, ww, (pin.fy / F, pin.fz / F), float(geo_p.dw1) / 2.0,
                                            float(T[k - 1]), b, float(geo_p.dw1), sign)
    return out


NU_PAIR_MOUNTING = "NU pair, both non-locating (axial location not modelled)"


def _f_sh_from_shafts(strength, nominal_um: float, value_um: float):
    """``strength`` (a StrengthResult whose chain took f_sh as a given factor) with that f_sh said to be the
    shafts' (its note and its factor-table row), not a value the user gave."""
    from ..gears.strength.result import from_chain

    text = (f"f_sh {value_um:.4g} µm from the shafts' deflection ({nominal_um:.4g} µm at the nominal load × K_A·K_v; "
            f"docs/shafts_in_drive.md), not ISO 6336-1 eq. (44)")
    chain = dict(strength._chain, given_source={**(strength._chain.get("given_source") or {}), "f_sh": text})
    return from_chain(chain, strength.title, strength.case)


def iso_f_sh_um(stage, pair, torque1_nm) -> float:
    """ISO 6336-1:2006 eq. (44)'s f_sh (µm) of a gear stage at the nominal load (F_m/b = F_t/b, F_t on the
    reference circle), with the stage's ``shaft`` strength option if it gives one: the misalignment the strength
    chain assumes when the shafts are not known (the default shafts are made at least this stiff)."""
    from ..gears.strength.factors import shaft_misalignment

    b = float(stage.width_mm)
    d1 = float(pair.geometry().d1)
    shaft = dict((stage.strength or {}).get("shaft") or {})
    return float(shaft_misalignment(2000.0 * torque1_nm / d1 / b, b, d1, **shaft))


def analyse_shafting(drive, stages_out, n, T, least_bore=None) -> dict:
    """Every shaft of the drive that carries a gear: its geometry (drawn, or the default one sized by DIN 743, its
    keys, its bearings' life and, with ``Shafting(stiff=True)``, its stiffness), bearing reactions and bearings,
    safeties, deflections; each gear stage's nominal f_sh; the keys at the seats.

    Stiffness (default shafts): while a gear pair's f_sh from its shafts exceeds ISO 6336-1 eq. (44)'s estimate
    (:func:`iso_f_sh_um`, what the gear's strength, and a stage sized by its load, assumed), each default shaft of
    that pair goes to the next bearing bore (a drawn shaft stays as drawn); the table ``shafts`` says which shafts
    were thickened so.

    Returns dict(shafts, bearings, sections, seat_keys, gear_deflections: DataFrames; rows: the checks table's rows (item, check,
    margin); f_sh {stage name: µm at the nominal load}; bearing_loads {shaft k: [(designation, Fr, Fa), ...]};
    analyses {shaft k: ShaftAnalysis}; elements {shaft k: [Element]})."""
    import pandas as pd

    from . import key as keys

    sh = drive.shafting
    elements = element_loads(drive, stages_out, T)
    for ds in sh.layout:
        if ds.at not in elements:
            raise GearDesignError(f"layout: shaft {ds.at} carries no gear of the drive (the shafts on bearings are "
                                  f"{', '.join(map(str, sorted(elements))) or 'none'})")
    planes = _gear_planes(drive, stages_out, elements)
    grids = {k: _seat_bores(sh, k) for k in elements}
    least_bore = thicker_bores(sh.min_bore_mm, least_bore or {})
    placed = {k: _placed(sh, k, elements[k], planes, grids[k], float(n[k]), _at_least(grids[k], least_bore.get(k)))
              for k in sorted(elements)}
    stiffened = {k for k, d in least_bore.items() if k in grids and sh.given(k) is None and d > grids[k][0]}
    if sh.stiff is True:
        limits = {st.name: iso_f_sh_um(res["stage"], res["pair"], float(T[k - 1]))
                  for k, (st, res) in enumerate(zip(drive.stages, stages_out), start=1)
                  if getattr(st, "kind", "") == "gear"}
        for _ in range(max(len(g) for g in grids.values())):
            f_sh = _mesh_f_sh(drive, stages_out, T, elements, placed)
            grow = set()
            for k, st in enumerate(drive.stages, start=1):
                if st.name in f_sh and f_sh[st.name] > limits[st.name]:
                    grow |= {j for j in (k - 1, k) if placed[j][0].d_b is not None and placed[j][0].d_b < grids[j][-1]}
            if not grow:
                break
            for j in grow:
                d_next = next(d for d in grids[j] if d > placed[j][0].d_b)
                placed[j] = _placed(sh, j, elements[j], planes, grids[j], float(n[j]), d_next)
            stiffened |= grow
    shaft_rows, bearing_rows, section_rows, key_rows, rows, deflection_rows = [], [], [], [], [], []
    analyses, bearing_loads = {}, {}
    for k in sorted(elements):
        els = elements[k]
        geo, model, names, checks, mat = placed[k]
        name = f"shaft {k}"
        safety, analysis = _safety(geo, els, sh, mat)
        analyses[k] = analysis
        d_seat = [float(v) for v in model.diameter_at(list(geo.supports))[0]]
        kinds = _types_of(checks)
        # an NU bearing has no ribs on its inner ring: it locates nothing (SKF 17000 C.3 calls it non-locating), so a
        # shaft on two of them is not "locating A"; its axial location (an NJ, NUP or ball bearing) is not modelled
        mounting = (f"tapered pair ({sh.arrangement})" if set(kinds) == {"tapered_roller"} else
                    NU_PAIR_MOUNTING if set(kinds) == {"cylindrical_roller"} else "locating A, floating B")
        for tag, chk, d_s, kind in zip("AB", checks, d_seat, kinds):
            item = f"bearing {k}{tag} {chk.designation}"     # the checks table names the bearing chosen
            bearing_rows.append(dict(name=item, shaft=k, x_mm=geo.supports["AB".index(tag)],
                                     designation=chk.designation, bearing_type=kind, mounting=mounting,
                                     seat_d_mm=d_s, bore_mm=chk.d_mm, D_mm=chk.D_mm,
                                     B_mm=chk.B_mm, F_r_n=chk.F_r_n, F_a_n=chk.F_a_n, n_rpm=chk.n_rpm, P_n=chk.P_n,
                                     L10h=chk.L10h, life_h=sh.life_h, s0=chk.s0, ok=chk.ok))
            fit = chk.d_mm - d_s
            if abs(fit) > 1e-9:       # a given bearing whose bore is not the seat's diameter
                rows.append((item, "bore_fits_seat", -abs(fit) / d_s))
            for c in ("life", "static_safety", "speed", "axial_load"):
                v = chk.margins.get(c)
                if v is not None and math.isfinite(v):
                    rows.append((item, c, float(v)))
        bearing_loads[k] = [(chk.designation, chk.F_r_n, chk.F_a_n) for chk in checks]
        for _, srow in safety.table.iterrows():
            if max(abs(srow["M_nm"]), abs(srow["T_nm"]), abs(srow["N_n"]) / 1000.0) < UNLOADED_NM:
                continue          # a section that carries nothing (beyond the last element): nothing to check
            s = min(srow["S_D"], srow["S_F"])
            section_rows.append(dict(shaft=k, section=srow["name"], x_mm=srow["x_mm"], notch=srow["notch"],
                                     d_mm=srow["d_mm"], M_nm=srow["M_nm"], T_nm=srow["T_nm"], S_D=srow["S_D"],
                                     S_F=srow["S_F"], ok=bool(srow["ok"])))
            rows.append((name, f"safety {srow['name']}", s / sh.S_min - 1.0))
        for e in els:
            if geo.hubs[e.name] is None:      # cut on its shaft: no key
                continue
            d, hub = geo.hubs[e.name]
            torque = abs(e.torque_nm)
            sel = keys.select(d, torque, hub)
            key_rows.append(dict(name=f"key {k} {e.name}", shaft=k, element=e.name, d_mm=d, hub_length_mm=hub,
                                 torque_nm=torque, b_mm=sel.b_mm, h_mm=sel.h_mm, length_mm=sel.length_mm,
                                 n_keys=sel.n_keys, margin_crush=sel.margin_crush, margin_shear=sel.margin_shear,
                                 feasible=sel.feasible))
            rows += [(f"key {k} {e.name}", "crushing", sel.margin_crush), (f"key {k} {e.name}", "shear",
                                                                            sel.margin_shear)]
        el = analysis.elements
        gears = el["name"].isin([e.name for e in els if e.width_mm is not None])
        for _, g in el.loc[gears].iterrows():
            kind = next(e.kind for e in els if e.name == g["name"])
            deflection_rows.append(dict(shaft=k, gear=f"{g['name']} {kind}", x_mm=g["x_mm"], w_mm=g["w_mm"],
                                        wy_mm=g["wy_mm"], wz_mm=g["wz_mm"], slope_rad=g["th_rad"]))
        shaft_rows.append(dict(shaft=k, layout="given" if geo.given else "default",
                               material=mat.get("material", "given"), length_mm=model.length_mm,
                               span_mm=geo.supports[1] - geo.supports[0],
                               d_end_mm=None if geo.d_b is None else geo.d_b - STEP_MM,
                               d_bearing_mm=d_seat[0], d_gear_mm=None if geo.d_b is None else geo.d_b + STEP_MM,
                               stiffened=k in stiffened, bearings="/".join(names), bearing_type=kinds[0],
                               mounting=mounting, least_safety=_least(safety.table),
                               max_deflection_mm=analysis.max_deflection_mm,
                               gear_deflection_mm=float(el.loc[gears, "w_mm"].max()),
                               gear_slope_rad=float(el.loc[gears, "th_rad"].max()),
                               critical_speed_rpm=analysis.critical_speed_rpm, mass_kg=analysis.mass_kg))
    return dict(shafts=pd.DataFrame(shaft_rows), bearings=pd.DataFrame(bearing_rows),
                sections=pd.DataFrame(section_rows), seat_keys=pd.DataFrame(key_rows),
                gear_deflections=pd.DataFrame(deflection_rows), rows=rows,
                f_sh=_mesh_f_sh(drive, stages_out, T, elements, placed), bearing_loads=bearing_loads,
                analyses=analyses, elements=elements,
                seat_bores={k: (None if sh.given(k) is not None else placed[k][0].d_b) for k in placed},
                bore_grids=grids)


def _at_least(bores: list, d_mm) -> float:
    """The least of ``bores`` >= d_mm (the first without one; the largest where none is)."""
    if d_mm is None:
        return bores[0]
    return next((d for d in bores if d >= d_mm - 1e-9), bores[-1])


STIFFEN_ROUNDS = 2   # bore steps a gear pair's default shafts may take for its K_Hβ (stiffened_for_gears)


def stiffened_for_gears(drive, kinds, stages_out, stage_rows, shafting, n, T, objective) -> tuple:
    """The gear stages with K_Hβ from their shafts (:func:`with_shaft_misalignment`), a gear stage that fails
    there with K_Hβ above the ISO 6336-1 default's having its default shafts thickened a bore step at a time (the
    next bore of the bearing series; a drawn shaft stays as drawn) until it holds, at most :data:`STIFFEN_ROUNDS`
    steps: the deflection that tilts the mesh falls as d⁴, while a larger gear on the same shafts tilts it as much
    (F_t/b and f_sh fall together) — an engineer stiffens the shaft. The thickened shafts are kept only if every
    stage that failed so then holds; else the shafts as DIN 743, the keys and the bearings sized them (the stage
    fails, named). Returns (stages, check rows, the f_sh table, the shafting)."""
    first = with_shaft_misalignment(drive, kinds, stages_out, stage_rows, shafting["f_sh"], objective)
    least, now, shafts = {}, first, shafting
    for _ in range(STIFFEN_ROUNDS if drive.shafting.stiff == "gears" else 0):
        failing = _shaft_failures(now[1], now[2])
        if not failing:
            break
        grow = {}
        for k, st in enumerate(drive.stages, start=1):
            if st.name not in failing:
                continue
            for j in (k - 1, k):
                d = shafts["seat_bores"].get(j)
                nxt = None if d is None else next((b for b in shafts["bore_grids"][j] if b > d + 1e-9), None)
                if nxt is not None:
                    grow[j] = max(grow.get(j, 0.0), nxt)
        if not grow:
            break
        least = thicker_bores(least, grow)
        shafts = analyse_shafting(drive, stages_out, n, T, least_bore=least)
        shafts["efficiency"] = shafting.get("efficiency")
        now = with_shaft_misalignment(drive, kinds, stages_out, stage_rows, shafts["f_sh"], objective)
    if least and not _shaft_failures(now[1], now[2]) and _shaft_failures(first[1], first[2]):
        return (*now, shafts)
    return (*first, shafting)


def _shaft_failures(rows, table) -> set:
    """The gear stages that fail a check with K_Hβ from their shafts above the ISO 6336-1 default's."""
    worse = {r["stage"] for _, r in table.iterrows() if r["source"] == "shafts" and r["K_Hbeta"] > r["K_Hbeta_default"]}
    return {item for item, _, margin in rows if item in worse and margin < 0}


# -- efficiencies and K_Hβ ----------------------------------------------------------------------------------------

def _bearings_of_stages(drive, bearing_loads) -> dict:
    """{stage index k (1-based): [(designation, shaft 1|2, Fr, Fa), ...]}: each shaft's bearings charged once, to
    the gear stage whose wheel it carries, else (the input shaft, a shaft a chain drives) to the one whose pinion
    it carries."""
    out: dict = {}
    gear = [getattr(st, "kind", "") == "gear" for st in drive.stages]
    for k, rows in bearing_loads.items():
        if k >= 1 and gear[k - 1]:
            out.setdefault(k, []).extend((d, 2, fr, fa) for d, fr, fa in rows)
        elif k < len(gear) and gear[k]:
            out.setdefault(k + 1, []).extend((d, 1, fr, fa) for d, fr, fa in rows)
    return out


def stage_efficiencies(drive, stages_out, n, T, shafting) -> tuple:
    """(η of every stage as the power flow takes it, the efficiency table): a gear stage whose efficiency was not
    given, with the Shafting's lubricant, by :func:`geardesign.drives.efficiency.stage_efficiency` (mesh loss,
    the given no-load loss, the SKF friction of its bearings of series 62/63: others' friction is not modelled,
    the table says so); every other stage its own efficiency."""
    import pandas as pd

    from ..gears.pair import GearPair
    from ..gears.strength import Load
    from .bearing_friction import SKF_CONSTANTS
    from .efficiency import BearingLoad, stage_efficiency

    sh = drive.shafting
    charged = _bearings_of_stages(drive, shafting["bearing_loads"])
    eta, rows = [], []
    for k, (st, res) in enumerate(zip(drive.stages, stages_out), start=1):
        p_in = float(T[k - 1]) * float(n[k - 1]) * math.pi / 30.0
        compute = getattr(st, "kind", "") == "gear" and not st.efficiency_given and sh.lubricant is not None
        if not compute:
            eta.append(st.efficiency)
            rows.append(dict(stage=st.name, source="given" if getattr(st, "efficiency_given", True) else "default",
                             efficiency=st.efficiency, power_in_w=p_in, mesh_loss_w=math.nan,
                             bearing_loss_w=math.nan, no_load_loss_w=math.nan, loss_w=(1.0 - st.efficiency) * p_in,
                             note=""))
            continue
        pair, stage = res["pair"], res["stage"]
        pair = GearPair(pair.m, pair.z1, pair.z2, pair.x1, pair.x2, beta_deg=pair.beta_deg,
                        face_width_mm=stage.width_mm)
        mine = charged.get(k, [])
        modelled = [BearingLoad(d, s, fr, fa) for d, s, fr, fa in mine if d[:2] in SKF_CONSTANTS]
        left_out = [d for d, *_ in mine if d[:2] not in SKF_CONSTANTS]
        r = stage_efficiency(pair, Load(torque_nm=float(T[k - 1]), n_rpm=float(n[k - 1])), sh.lubricant,
                             sh.oil_temperature_c, sh.Ra_um, bearings=modelled, no_load_loss_w=sh.no_load_loss_w,
                             lubrication=sh.lubrication)
        eta.append(r.efficiency)
        rows.append(dict(stage=st.name, source="computed", efficiency=r.efficiency, power_in_w=r.power_in_w,
                         mesh_loss_w=r.mesh_loss_w, bearing_loss_w=r.bearing_loss_w, no_load_loss_w=r.no_load_loss_w,
                         loss_w=r.loss_w, note=("friction not modelled for " + ", ".join(left_out)) if left_out else ""))
    return np.array(eta), pd.DataFrame(rows)


def _factor(result, symbol: str) -> float:
    f = result.factors
    return float(f.loc[(f["symbol"] == symbol) & (f["gear"] == 0), "value"].iloc[0])


def with_shaft_misalignment(drive, kinds, stages_out, stage_rows, f_sh: dict, objective: str) -> tuple:
    """The gear stages with a material analysed again with f_sh from their shafts: the chain's f_sh given as
    f_sh,nominal·K_A·K_v (its load level F_m/b), K_Hβ by method C from it (unless the stage's strength options give
    f_sh, K_Hbeta or K_Fbeta themselves: the user's value wins). Returns (stages, check rows, the table of f_sh and
    K_Hβ with the ISO 6336-1 default beside the shafts')."""
    import pandas as pd
    from dataclasses import replace

    stages_out = list(stages_out)
    rows_by_stage: dict = {}
    for item, check, margin in stage_rows:
        rows_by_stage.setdefault(item, []).append((item, check, margin))
    table = []
    for i, (kind, st) in enumerate(zip(kinds, drive.stages)):
        res = stages_out[i]
        if st.name not in f_sh or res.get("strength") is None:
            continue
        stage = res["stage"]
        factors = dict((stage.strength or {}).get("factors") or {})
        before = _factor(res["strength"], "K_Hbeta")
        K_v = _factor(res["strength"], "K_v")
        value = f_sh[st.name] * stage.application_factor * K_v
        own = any(k in factors for k in ("f_sh", "K_Hbeta"))
        if not own and value > F_SH_MAX_UM:
            # shafts that tilt the mesh by more than the chain takes (10 mm, far past any gear): the stage fails by
            # this check's name (an error stopped the analysis; K_Hβ stays the default's, the table says so)
            rows_by_stage.setdefault(st.name, []).append((st.name, "shaft_misalignment", 1.0 - value / F_SH_MAX_UM))
            table.append(dict(stage=st.name, f_sh_nominal_um=f_sh[st.name], K_A=stage.application_factor, K_v=K_v,
                              f_sh_um=value, K_Hbeta_default=before, K_Hbeta=before,
                              source=f"default (f_sh above {F_SH_MAX_UM:g} µm)"))
            continue
        if not own:
            factors["f_sh"] = value
            new = replace(stage, strength={**(stage.strength or {}), "factors": factors})
            out = kind.analyse(new, res["flow"], objective)
            if out.get("strength") is not None:   # the f_sh is the shafts', not the user's: its note and row say so
                out["strength"] = _f_sh_from_shafts(out["strength"], f_sh[st.name], value)
            rows_by_stage[st.name] = [(st.name, k, v) for k, v in out.pop("margins").items()]
            out.pop("size", None)
            out.pop("mass", None)
            stages_out[i] = dict(out, flow=res["flow"])
        after = _factor(stages_out[i]["strength"], "K_Hbeta")
        table.append(dict(stage=st.name, f_sh_nominal_um=f_sh[st.name], K_A=stage.application_factor, K_v=K_v,
                          f_sh_um=value, K_Hbeta_default=before, K_Hbeta=after,
                          source="given by the user" if own else "shafts"))
    rows = [r for st in drive.stages for r in rows_by_stage.get(st.name, [])]
    return stages_out, rows, pd.DataFrame(table)
