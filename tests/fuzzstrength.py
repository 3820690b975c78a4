"""Generated cases for the load-capacity surfaces (ISO 6336): ``Load``, ``material``/``Material``,
``pair_strength`` (scalars and arrays, every option), ``GearPair.strength`` and its result, the
strength checks in every solver, region, atlas and tooth-count search, planetary sets with a load,
``pair_report`` with a load, the commands' load options and a drive's ``GearStage`` with a material.

Each target returns (description, call) like those of tests/fuzzcases.py, which registers them.
Valid extremes (a torque of 1e-6 or 1e9 N·m, 1e-6 or 1e5 rpm, modules 0.1 to 50, 5 to 300 teeth,
|x| up to 2, β up to 45°, a life of 1e-3 to 1e7 h) meet invalid input (NaN, inf, negative, wrong
types, empty, 0-d arrays). A call raises ``FailsChecks`` when an optimum (or a row marked feasible)
does not hold its strength checks on re-check, or a result's verdict disagrees with its own safety
factors; AssertionError (counted as a traceback) when a command breaks its one-line rule or a result
object its own form (a repr of more than 20 lines, JSON that is not JSON).
"""
from __future__ import annotations

import contextlib
import io
import json
import math
import os
import random
import re
import tempfile

import numpy as np

import geardesign as gd
from geardesign.cli import main as cli_main
from geardesign.gears.strength import Load, material, pair_strength
from geardesign.gears.strength import planetary_strength
from tests.fuzzcases import EXTREMES, HalfWritten
from tests.fuzzrecheck import FEASIBILITY_SLACK, FailsChecks, FeasibilityTol

# besides EXTREMES: numpy scalars and 0-d arrays, which a number's validator must take or refuse cleanly
_NUMPY = [np.array(100.0), np.array(float("nan")), np.float64("inf"), np.array([1.0]), np.int64(7), np.float32(1e38)]


# the chance of a bad value at each input of the case being generated: half the cases are all valid
# (valid extremes only), the others have a bad value here and there
_RATE = [0.0]


def _set_rate(rng) -> None:
    _RATE[0] = rng.choice([0.0, 0.0, 0.02, 0.06])


def _pick(rng: random.Random, valid, invalid=()):
    """A valid value (a list to choose from, or a function of rng), or now and then (at the case's rate)
    an invalid one: of ``invalid``, or an extreme of Python or numpy."""
    if rng.random() < _RATE[0]:
        return rng.choice(list(invalid)) if invalid and rng.random() < 0.5 else rng.choice(EXTREMES + _NUMPY)
    return valid(rng) if callable(valid) else rng.choice(valid)


_TORQUES = [100.0, 400.0, 1e-6, 1e-3, 5e3, 1e6, 1e9]
_SPEEDS = [1000.0, 1450.0, 1e-6, 0.5, 1e5, 3e4]
_LIVES = [None, None, 20000.0, 1e-3, 1.0, 1e7]
_NAMES = ["42CrMo4", "42CrMo4", "18CrNiMo7-6", "C45", "40Х", "16MnCr5", "42CrMo4-IF", "31CrMoV9"]
_BAD_NAMES = ["", "nope", " 42CrMo4", "42crmo4", "GG", "NV", ["42CrMo4"], 42]


def _load_spec(rng) -> dict:
    """The keywords of a Load: a torque or a power (or both, or neither, now and then) at a speed."""
    out = {}
    r = rng.random()
    if r < 0.65:
        out["torque_nm"] = _pick(rng, lambda g: g.choice(_TORQUES + [round(g.uniform(1, 3000), 2)]),
                                 [1.0000001e9, -1.0, 0.0])
    elif r < 0.99 or _RATE[0] == 0:
        out["power_kw"] = _pick(rng, lambda g: g.choice([15.0, 1e-6, 1e4, 1e6, round(g.uniform(0.1, 500), 2)]))
    else:
        out.update(torque_nm=100.0, power_kw=15.0)
    if rng.random() < 0.99 or _RATE[0] == 0:
        out["n_rpm"] = _pick(rng, lambda g: g.choice(_SPEEDS + [round(g.uniform(10, 6000), 1)]), [0.0, -1.0, 1e6])
    if rng.random() < 0.2:
        out["on_gear"] = _pick(rng, [1, 2, 2], [0, 3, 1.0])
    if rng.random() < 0.3:
        out["application_factor"] = _pick(rng, [1.0, 1.25, 2.0, 10.0], [0.5, 11.0])
    if rng.random() < 0.5:
        out["life_h"] = _pick(rng, _LIVES, [1e9, 0.0, -5.0])
    return out


def _material_spec(rng):
    """A material as given: a name, ("material", name, keywords) or ("Material", keywords)."""
    r = rng.random()
    if r < 0.75:
        return _pick(rng, _NAMES, _BAD_NAMES)
    if r < 0.9:
        # an ISO 6336-5 group at a hardness inside its line's range (the hardness then sometimes outside)
        group, hardness = rng.choice([("V_alloy", [200.0, 280.0, 360.0]), ("V_carbon", [135.0, 180.0]),
                                      ("Eh", [660.0, 700.0]), ("NT", [650.0, 700.0]), ("St", [120.0, 200.0])])
        kw = {"hardness": _pick(rng, hardness, [1e4, 0.0, 58.0])}
        if rng.random() < 0.3:
            kw["yield_mpa"] = _pick(rng, [700.0, 500.0, 1200.0], [0.0, -1.0])
        if rng.random() < 0.2:
            kw["quality"] = _pick(rng, ["MQ", "ML", "ME"], ["MX", ""])
        if rng.random() < 0.15:
            kw["E_mpa"] = _pick(rng, [206000.0, 210000.0], [1.0, 1e9])
        return ("material", group, kw)
    kw = dict(name="custom", kind=_pick(rng, ["V", "Eh", "NT"], ["x"]),
              E_mpa=_pick(rng, [206000.0, 170000.0, 1e3], [1e7]), nu=_pick(rng, [0.3, 0.28], [0.0, 0.5, 0.6]),
              hardness=_pick(rng, [280.0, 600.0]), hardness_scale=_pick(rng, ["HV", "HBW"], ["HB"]),
              sigma_Hlim_mpa=_pick(rng, [740.0, 1500.0, 1.0], [1e5]),
              sigma_Flim_mpa=_pick(rng, [300.0, 425.0, 1.0], [1e5]))
    if rng.random() < 0.3:
        kw["quality"] = _pick(rng, ["MQ", "ME"], ["zz"])
    if rng.random() < 0.2:
        kw["yield_mpa"] = _pick(rng, [700.0, None], [-1.0])
    return ("Material", kw)


def _make_material(spec):
    if isinstance(spec, tuple) and spec and spec[0] == "material":
        return material(spec[1], **spec[2])
    if isinstance(spec, tuple) and spec and spec[0] == "Material":
        return gd.Material(**spec[1])
    return spec


def _options(rng) -> dict:
    """Some of pair_strength's options, each now and then bad."""
    opts = {}
    table = {     # name: (valid, invalid)
        "accuracy_grade": ([7, 1, 5, 12, 6.0], [0, 13, 7.5, "7"]),
        "nu40": ([220.0, 1.0, 10000.0, 68.0], [0.0, 1e5]),
        "Rz_flank_um": ([6.0, 0.01, 100.0, 1.0], [0.0]),
        "Rz_root_um": ([10.0, 0.01, 40.0, 3.2], [41.0]),
        "root_method": (["B", "C", "C"], ["b", "X", ""]),
        "factors": ([{"K_v": 1.1}, {"K_Hbeta": 1.16}, {"Z_NT1": 1.3, "Y_NT2": 0.9}, {"f_pb": 0.0}, {"C_a": 1e4}, {},
                     {"Y_F1": 2.5, "Y_F2": 2.2}, {"K_Halpha": 5.0, "K_Falpha": 5.0}, {"K_Hbeta": 0.01}],
                    [{"bogus": 1.0}, [("K_v", 1.0)], {"K_v": float("nan")}, {"K_v": -1.0}]),
        "K_gamma": ([1.0, 1.1, 3.0], [0.99, 3.01]),
        "cycles_per_rev": ([(1, 1), (2, 1), (1, 3), (1000, 1)], [(0, 1), (1,), (1, 1, 1), 3, (1.5, 1)]),
        "rim_mm": ([(None, None), (30.0, None), (None, 30.0), (1e6, 1e6)], [(1.0, 1.0), (-5.0, None), (0.0, 0.0)]),
        "face_width2_mm": ([None, 20.0, 60.0, 1e-6, 1e5], [0.0]),
        "S_Hmin": ([1.0, 1.3, 0.5, 3.0], [0.0]),
        "S_Fmin": ([1.4, 2.0, 1.0], [0.0]),
        "pitting_permitted": ([False, True], [1, "yes"]),
        "optimum_life": ([False, True], [None]),
        "tip_relief_um": ([None, 0.0, 20.0], [-1.0]),
        "bore_ratio": ([(0.0, 0.0), (0.5, 0.5), (0.99, 0.0)], [(1.0, 0.0)]),
    }
    for name, (valid, invalid) in table.items():
        if rng.random() < 0.18:
            opts[name] = _pick(rng, valid, invalid)
    return opts


def _geometry_spec(rng) -> dict:
    """A pair from the valid extremes (modules 0.1 to 50, 5 to 300 teeth, |x| up to 2, β up to 45°)."""
    z1 = _pick(rng, lambda g: g.choice([g.randint(5, 60), g.randint(12, 40), 5, 300]))
    z2 = _pick(rng, lambda g: g.choice([g.randint(20, 300), g.randint(40, 120), 300]))
    out = dict(m=_pick(rng, lambda g: g.choice([4.0, 2.0, 0.1, 50.0, round(g.uniform(0.1, 50), 3)])), z1=z1, z2=z2,
               x1=_pick(rng, lambda g: g.choice([0.0, 0.3, round(g.uniform(-0.5, 1), 3), round(g.uniform(-2, 2), 3)])),
               x2=_pick(rng, lambda g: g.choice([0.0, 0.1, round(g.uniform(-0.5, 1), 3), round(g.uniform(-2, 2), 3)])))
    if rng.random() < 0.4:
        out["beta_deg"] = _pick(rng, lambda g: g.choice([15.0, 30.0, 45.0, round(g.uniform(0, 45), 2)]), [46.0, -1.0])
    if rng.random() < 0.2 and isinstance(z1, int) and isinstance(z2, int):
        out["internal"], out["z2"] = True, z1 + rng.randint(8, 120)
    return out


def _width(rng, m):
    scale = m if type(m) is float and 0 < m < 100 else 4.0
    return _pick(rng, lambda g: g.choice([round(10 * scale, 3), round(g.uniform(3, 25) * scale, 3), 1e-3, 1e4]),
                 [0.0, -1.0])


def _judge_result(r) -> None:
    """A StrengthResult: short repr, a frame, JSON that is JSON, a verdict that follows its safeties."""
    lines = repr(r).count("\n") + 1
    if lines > 20:
        raise AssertionError(f"repr of {lines} lines")
    r.to_frame()
    r.factors
    json.loads(r.to_json(), parse_constant=lambda c: (_ for _ in ()).throw(ValueError(f"JSON with {c}")))
    s = [r.S_H1, r.S_H2, r.S_F1, r.S_F2]
    if all(math.isfinite(v) for v in s):
        holds = min(r.S_H1, r.S_H2) >= r.S_Hmin and min(r.S_F1, r.S_F2) >= r.S_Fmin
        if bool(r.ok) != holds:
            raise FailsChecks(f"ok={r.ok} but S_H {min(s[:2]):.6g} / {r.S_Hmin}, S_F {min(s[2:]):.6g} / {r.S_Fmin}")


# --- the targets -------------------------------------------------------------------------------------

def _strength_pair(rng):
    """GearPair(...).strength(load, material, **options) and its result's forms; or a load or a
    material alone."""
    _set_rate(rng)
    geo, load, mat, opts = _geometry_spec(rng), _load_spec(rng), _material_spec(rng), _options(rng)
    geo["face_width_mm"] = _width(rng, geo["m"]) if rng.random() < 0.9 else None
    mat2 = _material_spec(rng) if rng.random() < 0.2 else None
    if mat2 is not None:
        opts["material2"] = mat2

    def call():
        pair = gd.GearPair(**geo)
        extra = {k: (_make_material(v) if k == "material2" else v) for k, v in opts.items()}
        r = pair.strength(Load(**load), _make_material(mat), **extra)
        _judge_result(r)
        return r
    return f"GearPair(**{geo}).strength(Load(**{load}), {mat}, **{opts})", call


def _pair_strength(rng):
    """pair_strength on arrays (broadcast, mismatched, large, empty) and scalars."""
    _set_rate(rng)
    geo = _geometry_spec(rng)
    n = rng.choice([1, 3, 7, 50, 0, 10**6])
    shape = rng.choice(["x1", "x1", "m", "z2", "mismatch", "scalar", "width"])
    a = dict(geo)
    if shape == "x1" or shape == "mismatch":
        a["x1"] = np.linspace(-0.5, 1.0, n) if n < 10**6 else np.zeros(n)
    if shape == "mismatch":
        a["x2"] = np.zeros(n + 1)
    if shape == "m":
        a["m"] = np.array([0.1, 1.0, 4.0, 50.0])
    if shape == "z2" and not a.get("internal"):
        a["z2"] = np.arange(20, 20 + max(n, 1))
    width = _width(rng, geo["m"] if not isinstance(a["m"], np.ndarray) else 4.0)
    if shape == "width":
        width = np.array([5.0, 40.0, 400.0])
    load, mat, opts = _load_spec(rng), _material_spec(rng), _options(rng)
    what = {k: (f"array{np.shape(v)}" if isinstance(v, np.ndarray) else v) for k, v in a.items()}

    def call():
        # without geometry= every design is validated: a NaN in any array is one passed off as a result,
        # but for the load cycles N_L, NaN by design (not applicable) when no life is given
        # the options one way (findings36): the StrengthOptions' fields in options=, the rest as keywords
        from dataclasses import fields as _fields
        from geardesign.gears.strength.options import StrengthOptions
        names = {f.name for f in _fields(StrengthOptions)}
        grouped = {k: v for k, v in opts.items() if k in names}
        rest = {k: v for k, v in opts.items() if k not in names}
        if grouped:
            rest["options"] = StrengthOptions(**grouped)
        out = pair_strength(load=Load(**load), material1=_make_material(mat), face_width_mm=width, **a, **rest)
        return {k: v for k, v in out.items() if not (k in ("N_L1", "N_L2") and load.get("life_h") is None)}
    shown = width if np.ndim(width) == 0 else "array"
    return f"pair_strength(**{what}, width={shown}, Load(**{load}), {mat}, **{opts})", call


def _case(rng) -> dict:
    """A checks dict with a load case (sometimes broken)."""
    case = {"load": ("Load", _load_spec(rng)), "material": _material_spec(rng),
            "face_width_mm": _pick(rng, [40.0, 20.0, 80.0, 1e-3, 1e4], [0.0, -1.0])}
    if rng.random() < 0.2:
        case["material2"] = _material_spec(rng)
    if rng.random() < 0.3:
        case["strength"] = _pick(rng, [{"accuracy_grade": 6}, {"root_method": "C"}, {"K_gamma": 1.2},
                                       {"factors": {"K_Hbeta": 1.16}}, {"nu40": 68.0}, {"cycles_per_rev": (2, 1)}],
                                 [{"bogus": 1}, [], {"S_Hmin": 1.2}])
    if rng.random() < 0.2:
        case["S_Hmin"] = _pick(rng, [1.0, 1.2, 0.5, 5.0], [0.0])
    if rng.random() < 0.2:
        case["S_Fmin"] = _pick(rng, [1.4, 2.0, 5.0], [0.0])
    if rng.random() < 0.3 * (_RATE[0] > 0):
        del case[rng.choice(["load", "material", "face_width_mm"])]
    if rng.random() < 0.15:
        case["eps_alpha_min"] = _pick(rng, [1.1, None])
    return case


def _built(case):
    out = dict(case)
    if isinstance(out.get("load"), tuple):
        out["load"] = Load(**out["load"][1])
    for k in ("material", "material2", "planet_material", "ring_material"):
        if k in out:
            out[k] = _make_material(out[k])
    return out


def _recheck_strength(m, z1, z2, x1, x2, checks, what, margins=None, **kind) -> None:
    """The design rebuilt as a GearPair must hold the checks (strength among them) its solver held."""
    try:
        pair = gd.GearPair(m, int(z1), int(z2), float(x1), float(x2), **kind)
        table = pair.checks(jamming=False, **checks)
    except gd.GearDesignError as exc:
        raise FailsChecks(f"{what} ({z1}/{z2} at x = {x1:.6g}, {x2:.6g}) refused on re-check: {exc}"[:300]) from None
    rows = table[table["check"].isin(list(margins))] if margins is not None else table
    rows = rows[rows["margin"].notna()]
    if not len(rows):
        return
    worst = rows["margin"].min()
    if worst < -FEASIBILITY_SLACK:
        bad = rows.loc[rows["margin"].idxmin()]
        raise FailsChecks(f"{what} ({z1}/{z2} at x = {x1:.6g}, {x2:.6g}): {bad['check']} margin {bad['margin']:.3g}")
    if not rows["ok"].all():
        raise FeasibilityTol(f"{what}: ok False at margin {worst:.3g}")


def _strength_solvers(rng):
    """optimize_shifts (exact, convex, grid; the strength objectives), feasible_region, shift_atlas and
    select_teeth with a load case; every optimum and row marked feasible re-checked."""
    _set_rate(rng)
    kind = rng.choice(["optimize"] * 5 + ["region", "atlas", "teeth"])
    z1, z2 = rng.choice([(20, 60), (17, 26), (12, 31), (25, 40), (5, 300), (30, 90)])
    m = _pick(rng, [4.0, 2.0, 8.0, 0.5, 20.0])
    case = _case(rng)
    geo = {}
    if rng.random() < 0.3:
        geo["beta_deg"] = _pick(rng, [15.0, 30.0, 45.0])
    if kind == "optimize":
        kw = dict(method=_pick(rng, ["exact", "exact", "exact", "grid", "convex"], ["simplex"]),
                  objective=_pick(rng, [None, "balanced_root_strength", "max_min_safety", "max_min_safety",
                                        "max_x_sum", "balanced_sliding"], ["min_safety"]))
        if kw["objective"] == "balanced_root_strength" or rng.random() < 0.2:
            half = (z1 + z2) / 2 * (m if type(m) is float else 4.0)
            kw["a_w"] = _pick(rng, lambda g: round(half * g.uniform(0.99, 1.06), 4))
        if kw["method"] == "grid" and rng.random() < 0.5:
            kw["grid_n"] = rng.choice([11, 41])
    elif kind == "region":
        kw = dict(n=rng.choice([None, 21, 41]))
    elif kind == "atlas":
        z1, z2 = rng.choice([range(17, 19), [20]]), rng.choice([[60], range(40, 42)])
        kw = dict(objective=rng.choice(["max_x_sum", "max_min_safety", "balanced_root_strength"]))
    else:
        kw = dict(ratio=_pick(rng, [3.0, 2.5, 1.7]), z1_range=(rng.randint(17, 22),) * 2, objective=rng.choice(
            [None, "max_min_safety", "max_x_sum"]))
    desc = f"{kind}({z1}, {z2}, m={m}, checks={case}, **{kw}, **{geo})"

    def call():
        checks = _built(case)
        if kind == "optimize":
            r = gd.optimize_shifts(z1, z2, m=m, checks=checks, **kw, **geo)
            if r.success:
                _recheck_strength(m, r.z1, r.z2, r.x1, r.x2, checks, "optimum", r.margins, **geo)
            return r
        if kind == "region":
            return gd.feasible_region(z1, z2, m=m, checks=checks, **kw, **geo)
        if kind == "atlas":
            df = gd.shift_atlas(z1, z2, checks=checks, **kw, **geo)
            names = [c[len("margin_"):] for c in df.columns if c.startswith("margin_")]
            for row in df[df["feasible"]].head(3).itertuples():
                _recheck_strength(1.0, row.z1, row.z2, row.x1, row.x2, checks, "atlas row", names, **geo)
            return df
        sel = gd.select_teeth(m=m, checks=checks, **kw, **geo)
        names = [c[len("margin_"):] for c in sel.table.columns if c.startswith("margin_")]
        for _, row in sel.feasible.head(3).iterrows():
            _recheck_strength(float(row["module_mm"]), row["z1"], row["z2"], row["x1"], row["x2"], checks,
                              "row marked feasible", names, **geo)
        return sel
    return desc, call


def _strength_planetary(rng):
    """Planetary sets with a load on the sun: the optimiser, the region, the set's checks and
    planetary_strength."""
    _set_rate(rng)
    z_s, z_p, n = rng.choice([(21, 43, 3), (20, 31, 3), (15, 30, 4), (24, 24, 4), (12, 60, 3)])
    z_r = z_s + 2 * z_p
    m = _pick(rng, [1.75, 2.0, 1.0, 5.0])
    case = _case(rng)
    case.pop("material2", None)
    if isinstance(case.get("load"), tuple) and _RATE[0] == 0:
        case["load"][1].pop("on_gear", None)     # a set's load is on the sun
    for k in ("planet_material", "ring_material"):
        if rng.random() < 0.25:
            case[k] = _material_spec(rng)
    if rng.random() < 0.3:
        case["strength"] = _pick(rng, [{"K_gamma": 1.1}, {"K_gamma": 3.0}, {"K_gamma": 1.2, "accuracy_grade": 5}],
                                 [{"K_gamma": 0.5}, {"K_gamma": float("nan")}])
    kind = rng.choice(["optimize", "optimize", "region", "set", "direct"])
    method = _pick(rng, ["exact", "exact", "grid"])
    xs = (round(rng.uniform(-0.3, 1.0), 3), round(rng.uniform(-0.3, 1.2), 3))

    def call():
        checks = _built(case)
        if kind == "optimize":
            r = gd.optimize_planetary_shifts(z_s, z_p, z_r, n, m=m, checks=checks, method=method)
            if r.success:
                s = gd.PlanetarySet(m, z_s, z_p, z_r, n, r.x_sun, r.x_planet, r.x_ring)
                _judge_set(s.checks(checks), "optimum")
            return r
        if kind == "region":
            return gd.planetary_region(z_s, z_p, z_r, n, m, checks=checks, n=21)
        s = gd.PlanetarySet.coaxial(m, z_s, z_p, z_r, n, *xs)
        if kind == "set":
            return s.checks(checks)
        opts = dict(checks.get("strength") or {}) if isinstance(checks.get("strength"), dict) else {}
        res = planetary_strength(s, checks.get("load"), checks.get("material"), face_width_mm=checks.get(
            "face_width_mm"), planet_material=checks.get("planet_material"), ring_material=checks.get("ring_material"),
            **opts)
        for r in res.values():
            _judge_result(r)
        return res
    return f"planetary {kind}({z_s}/{z_p}/{z_r} x{n}, m={m}, {method}, x={xs}, checks={case})", call


def _set_spectrum_spec(rng, sizes, m, width) -> dict:
    """The keywords of one LoadSpectrum.from_bins on the sun of a set: 1 to 8 bins of random sign whose torques span
    zero damage to worn out (a planet's line load w from 0.001 to 1e4 N/mm, within two decades in one spectrum:
    T_sun = w·N·d_s·b/2000), odd speeds,
    hours, cycles or time shares; now and then (at the case's rate) a bad value."""
    n = rng.randint(1, 8)
    z_s, n_pl = (sizes[0], sizes[3]) if all(type(v) is int and 0 < v < 1e4 for v in (sizes[0], sizes[3])) else (20, 3)
    scale = n_pl * float(m if type(m) in (int, float) and 0 < m < 1e3 else 2.0) * z_s * float(
        width if type(width) is float and 0 < width < 1e5 else 25.0) / 2000.0
    signs = rng.choice(["+", "+", "-", "mixed", "mixed", "mixed"])
    top = rng.uniform(-1, 4)       # the case's severity: its largest line load 10^top N/mm, the others up to 100x less

    def torque(g):
        t = scale * 10.0 ** g.uniform(top - 2, top)
        t = round(t, 6) if g.random() < 0.8 else t
        sign = 1 if signs == "+" else -1 if signs == "-" else g.choice([1, -1])
        return 0.0 if g.random() < 0.04 else sign * t
    kw = dict(torque_nm=_pick(rng, lambda g: [torque(g) for _ in range(n)], [[float("nan")] * n, [], [1e10] * n]),
              n_rpm=_pick(rng, lambda g: g.choice([1450.0, round(g.uniform(0.5, 2e4), 3), 1e-3, 7777.7,
                                                   [round(g.uniform(1, 9000), 2) for _ in range(n)]]),
                          [0.0, -1.0, [1.0] * (n + 1)]))
    how = rng.choice(["time_h", "time_h", "share", "cycles"])
    if how == "time_h":
        kw["time_h"] = _pick(rng, lambda g: [g.choice([0.0] * (g.random() < 0.1) + [1e-3, round(10 ** g.uniform(-1, 5), 3), round(10 ** g.uniform(-1, 5), 3)])
                                             for _ in range(n)], [[-1.0] * n, [1e10] * n])
    elif how == "share":
        w = [rng.random() + 1e-3 for _ in range(n)]
        kw["share"] = _pick(rng, [[v / sum(w) for v in w], [1.0 / n] * n], [[0.5] * (n + 1), [2.0] + [0.0] * (n - 1)])
        kw["duration_h"] = _pick(rng, [2e4, 1.0, 1e6, 333.3], [0.0, -1.0])
    else:
        kw["cycles"] = _pick(rng, lambda g: [g.choice([0.0] * (g.random() < 0.1) + [1e3, 1e7, 3.3e9, round(10 ** g.uniform(2, 10))]) for _ in range(n)], [[1e30] * n])
    if rng.random() < 0.01:
        kw["on_gear"] = 2      # a set's spectrum is on the sun: refused
    return kw


def _recheck_planetary_life(pset, table, checks) -> None:
    """The set's damage checks against planetary_life's bin-by-bin sums (the independent reference), each load case:
    the sun's and ring's mesh checks D_<mode>_sun/ring, the planet's set check (a reversing case among them) or its
    two mesh checks' larger (one-sided) D_<mode>_planet, rel 1e-12."""
    from geardesign.gears.strength.planetary_meshes import planetary_life

    spectra = checks["spectrum"] if isinstance(checks["spectrum"], (list, tuple)) else [checks["spectrum"]]
    reversing = any(s.reverses for s in spectra)
    value = dict(zip(table["check"], table["value"]))
    opts = dict(checks.get("strength") or {})
    for k, spec in enumerate(spectra, start=1):
        case = "" if k == 1 else f"case{k}_"
        try:
            ref = planetary_life(pset, spec, checks["material"], face_width_mm=checks["face_width_mm"],
                                 mean_stress_factor=checks.get("mean_stress_factor"), life_h=checks.get("life_h"),
                                 planet_material=checks.get("planet_material"),
                                 ring_material=checks.get("ring_material"), sn_curve=checks.get("sn_curve") or "iso",
                                 **opts)
        except gd.GearDesignError as exc:
            # a mesh the chain cannot rate (a shift past its range): the set's checks must call it undefined
            if not any(math.isnan(float(v)) for n, v in value.items() if "_damage_" in n and case in n):
                raise FailsChecks(f"case {k}: planetary_life refuses ({exc}) but the set's checks rate it") from None
            continue
        for mode, kind in (("H", "pitting_damage"), ("F", "root_damage")):
            got = {"sun": value[f"sun-planet:{case}{kind}_sun"], "ring": value[f"planet-ring:{case}{kind}_ring"],
                   "planet": value[f"set:{case}{kind}_planet"] if reversing else max(
                       value[f"sun-planet:{case}{kind}_planet"], value[f"planet-ring:{case}{kind}_planet"])}
            for gear, v in got.items():
                want = ref[f"D_{mode}_{gear}"]
                if not math.isclose(float(v), want, rel_tol=1e-12, abs_tol=1e-300):
                    raise FailsChecks(f"case {k} D_{mode}_{gear}: the set's check {float(v)!r}, planetary_life "
                                      f"{want!r}")


def _planetary_spectrum(rng):
    """Planetary sets under load spectra on the sun (issue 38): reversing or one-sided bins, several load cases, Y_M,
    a required life, materials, damage_max; the set's checks (re-checked against planetary_life), the optimiser
    (max_life, max_x_sum, max_min_safety; with and without a load) and the region. An optimum must hold its checks,
    max_life's fun must be −ln of the largest damage there."""
    from tests.fuzzcases import _planetary_sizes

    _set_rate(rng)
    sizes = _planetary_sizes(rng) if rng.random() < 0.5 else rng.choice(
        [(20, 31, 82, 3), (21, 43, 108, 3), (15, 30, 75, 3), (24, 24, 72, 4), (12, 60, 132, 3), (19, 17, 56, 3),
         (30, 15, 60, 5)])
    m = _pick(rng, [2.0, 1.75, 1.0, 3.0, 5.0, 0.5, 12.0])
    width = _pick(rng, lambda g: round(float(m if type(m) is float else 2.0) * g.choice([8.0, 12.5, 20.0,
                                                                                           g.uniform(2, 40)]), 3),
                  [0.0, -1.0])
    n_cases = rng.choice([1, 1, 1, 2, 3])
    spectra = [_set_spectrum_spec(rng, sizes, m, width) for _ in range(n_cases)]
    case = {"material": _material_spec(rng), "face_width_mm": width}
    ym = rng.random()
    if ym < 0.92:
        case["mean_stress_factor"] = _pick(rng, lambda g: g.choice([0.7, 1.0, 0.3, round(g.uniform(0.3, 1.0), 4),
                                                                    (0.7, 0.8)]), [0.29, 1.01, (0.7,), "0.7"])
    if rng.random() < 0.5:
        case["life_h"] = _pick(rng, [2e4, 1.0, 1e7, 1e-3, 5e5], [0.0, -1.0, 1e8])
    for k in ("planet_material", "ring_material"):
        if rng.random() < 0.25:
            case[k] = _material_spec(rng)
    if rng.random() < 0.4:
        case["damage_max"] = _pick(rng, lambda g: g.choice([1.0, 0.5, 10.0, 1e-6, round(g.uniform(0.01, 10), 4)]),
                                   [0.0, 11.0, -1.0])
    if rng.random() < 0.15:
        case["sn_curve"] = _pick(rng, ["iso", "original", "elementary", "haibach"], ["nope"])
    if rng.random() < 0.15:
        case["strength"] = _pick(rng, [{"K_gamma": 1.1}, {"accuracy_grade": 6}], [{"K_gamma": 0.5}, {"bogus": 1}])
    kind = rng.choice(["set", "set", "optimize", "optimize", "optimize", "region", "cli"])
    objective = _pick(rng, ["max_life", "max_life", "max_x_sum", "max_min_safety"], ["min_life"])
    if kind in ("optimize", "region") and (objective == "max_min_safety" or rng.random() < 0.3):
        plain = all(type(v) is int and 0 < v < 1e4 for v in sizes) and type(m) is float and type(width) is float
        scale = sizes[3] * m * sizes[0] * width / 2000.0 if plain else 100.0     # T_sun at 1 N/mm
        case["load"] = ("Load", {"torque_nm": _pick(rng, lambda g: round(scale * 10 ** g.uniform(-1, 3), 4), [-1.0]),
                                 "n_rpm": _pick(rng, [1450.0, 100.0, 1e4])})
    geo = {}
    if rng.random() < 0.2:
        geo["beta_deg"] = _pick(rng, [10.0, 20.0, 30.0])
    if rng.random() < 0.15:
        geo["arrangement"] = _pick(rng, ["carrier_fixed", "carrier_fixed", "sun_fixed"])
    method = _pick(rng, ["exact", "exact", "grid"])
    xs = (round(rng.uniform(-0.4, 1.0), 3), round(rng.uniform(-0.4, 1.0), 3))
    n_region = rng.choice([11, 15, 21])
    rng_cli = random.Random(rng.random())

    def call():
        built = [gd.LoadSpectrum.from_bins(**s) for s in spectra]
        if kind == "cli":
            return _planetary_spectrum_cli(sizes, m, case, geo, built[0], objective, method, xs, rng_cli)
        checks = _built({**case, "spectrum": built if n_cases > 1 else built[0]})
        if kind == "set":
            s = gd.PlanetarySet.coaxial(m, *sizes, *xs, **geo)
            table = s.checks(checks)
            margin = table["margin"].to_numpy(dtype=float)
            # −inf is a check undefined for the design (its label says so, it fails); anything else must be finite
            undefined = (margin == -np.inf) & table["label"].str.contains("undefined for this design").to_numpy()
            if not (np.isfinite(margin) | undefined).all():
                return float("nan")
            _recheck_planetary_life(s, table, checks)
            return table
        if kind == "region":
            return gd.planetary_region(*sizes, m, checks=checks, n=n_region, method=method, **geo)
        r = gd.optimize_planetary_shifts(*sizes, m, checks=checks, objective=objective, method=method, **geo)
        if r.success:
            s = gd.PlanetarySet(m, *sizes, r.x_sun, r.x_planet, r.x_ring, **geo)
            table = s.checks(checks)
            _judge_set(table, "optimum")
            _recheck_planetary_life(gd.PlanetarySet.coaxial(m, *sizes, r.x_sun, r.x_planet, **geo), table, checks)
            if objective == "max_life":
                damage = table.loc[table["check"].str.contains("_damage_"), "value"].astype(float)
                want = -math.log(max(float(damage.max()), 1e-300))
                if not math.isclose(r.fun, want, rel_tol=1e-9, abs_tol=1e-9):
                    raise FailsChecks(f"max_life's fun {r.fun!r} is not -ln of the largest damage there ({want!r})")
        return r
    shown = [{k: (v if not isinstance(v, list) or len(v) < 9 else f"{len(v)} values") for k, v in s.items()}
             for s in spectra]
    return (f"planetary_spectrum {kind}({sizes}, m={m}, {objective}, {method}, x={xs}, n={n_region}, {geo}, "
            f"checks={case}, spectra={shown})", call)


def _planetary_spectrum_cli(sizes, m, case, geo, spectrum, objective, method, xs, rng) -> int:
    """``geardesign planetary ... --spectrum CSV`` with the case's bins written as a CSV (torque_nm, n_rpm, time_h):
    exit 0 or 1 with a result and no NaN printed, or exit 2 with one stderr line; nothing left beside the CSV."""
    names = {k: (v if isinstance(v, str) else "42CrMo4") for k, v in case.items() if "material" in k}
    argv = ["planetary", "--module", str(m), "--planets", str(sizes[3]), "--z-sun", str(sizes[0]),
            "--z-planet", str(sizes[1]), "--z-ring", str(sizes[2]), "--material", names["material"],
            "--face-width", str(case["face_width_mm"]), "--method", str(method)]
    for k in ("planet_material", "ring_material"):
        if k in names:
            argv += ["--" + k.replace("_", "-"), names[k]]
    ym = case.get("mean_stress_factor")
    if ym is not None:
        argv += ["--mean-stress-factor", str(ym[0] if isinstance(ym, tuple) and ym else ym)]
    for key, flag in (("life_h", "--life-h"), ("damage_max", "--damage-max"), ("sn_curve", "--sn-curve")):
        if case.get(key) is not None:
            argv += [flag, str(case[key])]
    if geo.get("beta_deg"):
        argv += ["--beta", str(geo["beta_deg"])]
    if geo.get("arrangement"):
        argv += ["--arrangement", str(geo["arrangement"])]
    if rng.random() < 0.4:
        argv += ["--x-sun", str(xs[0]), "--x-planet", str(xs[1])]
    elif rng.random() < 0.7:
        argv += ["--objective", str(objective)]
    if rng.random() < 0.3:
        argv.append("--json")
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "sun.csv")
        with open(path, "w", encoding="utf-8") as fh:
            fh.write("torque_nm,n_rpm,time_h\n" + "".join(f"{t!r},{n!r},{h!r}\n" for t, n, h in zip(
                spectrum.torque_nm.tolist(), spectrum.n_rpm.tolist(), spectrum.time_h.tolist())))
        out, err = io.StringIO(), io.StringIO()
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            try:
                code = cli_main(argv + ["--spectrum", path])
            except SystemExit as exc:
                code = exc.code
        if os.listdir(tmp) != ["sun.csv"]:
            raise HalfWritten(f"exit {code} and left {os.listdir(tmp)}")
    lines = err.getvalue().strip().splitlines()
    if "Traceback" in err.getvalue():
        raise AssertionError(f"traceback printed: {lines[-1][:200]!r}")
    if code == 2 and len(lines) != 1:
        raise AssertionError(f"exit 2 with {len(lines)} stderr lines: {err.getvalue()[:300]!r}")
    if code not in (0, 1, 2):
        raise AssertionError(f"exit {code}: {err.getvalue()[:200]!r}")
    if code == 2:
        raise gd.GearDesignError(lines[0])        # counted as the clean refusal it is
    # a check undefined for the design fails with margin −inf (its table row: "-inf False", the value blank), as
    # PlanetarySet.checks() has it; any other NaN or infinity printed is one passed off as a result
    text = re.sub(r"\s-inf\s+False\s", " ", out.getvalue())
    words = text.replace("|", " ").replace('"', " ").split()
    if any(w.strip(",;:()%[]{}").lower() in ("nan", "-nan", "inf", "-inf", "infinity", "-infinity") for w in words):
        return float("nan")
    return code


def _judge_set(table, what) -> None:
    rows = table[table["margin"].notna()]
    if len(rows) and rows["margin"].min() < -FEASIBILITY_SLACK:
        bad = rows.loc[rows["margin"].idxmin()]
        raise FailsChecks(f"{what}: {bad['check']} margin {bad['margin']:.3g} on re-check")
    if len(rows) and not rows["ok"].all():
        raise FeasibilityTol(f"{what}: ok False on re-check")


def _num(rng, valid, invalid=()):
    v = _pick(rng, valid, invalid)
    return v if isinstance(v, str) else repr(float(v)) if isinstance(v, (int, float)) and not isinstance(
        v, bool) and abs(v) < 1e300 else str(v)


def _cli_load_args(rng, planetary=False) -> list:
    args = []
    if rng.random() < 0.8:
        args += ["--torque", _num(rng, _TORQUES, [-1.0, 0.0])]
    elif rng.random() < 0.8:
        args += ["--power", _num(rng, [15.0, 1e-6, 1e6])]
    if rng.random() < 0.9:
        args += ["--speed", _num(rng, _SPEEDS)]
    if rng.random() < 0.9:
        args += ["--material", str(_pick(rng, _NAMES, _BAD_NAMES))]
    if rng.random() < 0.3:
        args += ["--life-h", _num(rng, [20000.0, 1e-3, 1e7], [-1.0])]
    if rng.random() < 0.2:
        args += ["--application-factor", _num(rng, [1.25, 10.0], [0.0])]
    if planetary:
        for flag in ("--planet-material", "--ring-material"):
            if rng.random() < 0.2:
                args += [flag, str(_pick(rng, _NAMES, _BAD_NAMES))]
        if rng.random() < 0.3:
            args += ["--k-gamma", _num(rng, [1.1, 3.0], [0.5])]
        if rng.random() < 0.85:
            args += ["--face-width", _num(rng, [25.0, 1e-3, 1e4], [0.0])]
    else:
        if rng.random() < 0.2:
            args += ["--material2", str(_pick(rng, _NAMES, _BAD_NAMES))]
        if rng.random() < 0.85:
            args += ["--strength-width", _num(rng, [40.0, 20.0, 1e-3, 1e4], [0.0])]
    return args


def _strength_cli(rng):
    """The commands with a load (pair, shift, teeth, atlas, planetary) and the pair's report with a
    load: exit 0/1 with a result, or exit 2 with one line; no file left by a refused report."""
    _set_rate(rng)
    cmd = rng.choice(["pair", "pair", "shift", "shift", "teeth", "atlas", "planetary", "report", "report"])
    if cmd in ("pair", "report"):
        argv = ["pair", "--module", _num(rng, [4.0, 0.1, 50.0]), "--z1", str(_pick(rng, [20, 5, 300])),
                "--z2", str(rng.choice([60, 300, 40])), "--x1", _num(rng, [0.3, 0.8, -0.2]),
                "--x2", _num(rng, [0.1, 0.0])]
    elif cmd == "shift":
        argv = ["shift", "--z1", str(rng.choice([20, 17, 12])), "--z2", str(rng.choice([60, 26, 31])), "--module", "4"]
        argv += rng.choice([[], ["--method", "grid"], ["--objective", "max_min_safety"],
                            ["--objective", "balanced_root_strength", "--center-distance", "162"]])
    elif cmd == "teeth":
        argv = ["teeth", "--ratio", str(rng.choice([3, 2.5])), "--module", "4", "--z1-min", "20", "--z1-max", "21"]
    elif cmd == "atlas":
        argv = ["atlas", "--z1", "20", "--z2", rng.choice(["60", "40:41"])]
    else:
        argv = ["planetary", "--module", "1.75", "--planets", "3", "--z-sun", "21", "--z-planet", "43",
                "--z-ring", "108"]
    argv += _cli_load_args(rng, planetary=cmd == "planetary")

    def call():
        with tempfile.TemporaryDirectory() as tmp:
            args = list(argv) + (["--report", os.path.join(tmp, "pair.html")] if cmd == "report" else [])
            out, err = io.StringIO(), io.StringIO()
            with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
                try:
                    code = cli_main(args)
                except SystemExit as exc:
                    code = exc.code
            left = os.listdir(tmp)
            if (code == 2 and left) or any(n.startswith(".") for n in left):
                raise HalfWritten(f"exit {code} and left {left}")
            lines = err.getvalue().strip().splitlines()
            if "Traceback" in err.getvalue():
                raise AssertionError(f"traceback printed: {lines[-1][:200]!r}")
            if code == 2 and len(lines) != 1 and not err.getvalue().startswith("usage:"):
                raise AssertionError(f"exit 2 with {len(lines)} stderr lines: {err.getvalue()[:300]!r}")
            if code not in (0, 1, 2):
                raise AssertionError(f"exit {code}")
            words = out.getvalue().replace("|", " ").split()
            if code in (0, 1) and any(w.strip(",;()%").lower() in ("nan", "inf", "-inf") for w in words):
                return float("nan")
            return code
    return f"geardesign {' '.join(argv)}" + (" --report <tmp>/pair.html" if cmd == "report" else ""), call


def _strength_drive(rng):
    """A small drive whose gear stage has a material: given (analyse) or free (optimize)."""
    _set_rate(rng)
    power = _pick(rng, [4.0, 2.0, 0.01, 75.0, 1e4])
    n_in = _pick(rng, [1410.0, 950.0, 0.1, 1e5], [1e-3])
    mat = _material_spec(rng)
    free = rng.random() < 0.35
    stage = dict(material=mat, m=None) if free else dict(
        m=_pick(rng, [3.0, 2.0, 0.5, 10.0]), z1=rng.choice([20, 17, 24]), z2=rng.choice([60, 51, 70]),
        face_width_mm=_pick(rng, [30.0, 60.0, None, 1e-3]), material=mat)
    ratio = round(rng.uniform(2, 4.5), 2)

    def call():
        s = dict(stage)
        s["material"] = _make_material(s["material"])
        drive = gd.Drive(power_kw=power, n_in_rpm=n_in, stages=[gd.GearStage(**s)])
        return drive.optimize(total_ratio=ratio, top=3) if free else drive.analyse()
    return f"Drive({power} kW, {n_in} rpm, GearStage(**{stage})).{'optimize' if free else 'analyse'}(u={ratio})", call


def _strength_report(rng):
    """gd.pair_report(pair, path, load=..., material=...): a whole HTML file with the strength section, or
    a clean refusal that leaves the folder as it was."""
    _set_rate(rng)
    geo, case = _geometry_spec(rng), _case(rng)
    case.pop("eps_alpha_min", None)
    existing, overwrite = rng.random() < 0.2, rng.random() < 0.5

    def call():
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "pair.html")
            if existing:
                with open(path, "w") as fh:
                    fh.write("precious")
            try:
                out = gd.pair_report(gd.GearPair(**geo), path, overwrite=overwrite, **_built(case))
            except gd.GearDesignError:
                if sorted(os.listdir(tmp)) != (["pair.html"] if existing else []):
                    raise HalfWritten(f"a refused report changed the folder: {os.listdir(tmp)}") from None
                raise
            finally:
                if any(n.startswith(".") for n in os.listdir(tmp)):
                    raise HalfWritten(f"temporary files left behind: {os.listdir(tmp)}")
            with open(out, encoding="utf-8") as fh:
                text = fh.read()
            if not text.rstrip().endswith("</html>"):
                raise HalfWritten("the report does not end with </html>")
            if re.search(r">\s*(nan|NaN|inf)\s*<", text):
                return float("nan")       # a NaN or inf printed as a figure
            return len(text)
    return f"pair_report(GearPair(**{geo}), overwrite={overwrite}, existing={existing}, **{case})", call


STRENGTH = {"strength_pair": _strength_pair, "pair_strength": _pair_strength, "strength_solvers": _strength_solvers,
            "strength_planetary": _strength_planetary, "strength_cli": _strength_cli, "strength_drive": _strength_drive,
            "strength_report": _strength_report,
            "planetary_spectrum": _planetary_spectrum}
