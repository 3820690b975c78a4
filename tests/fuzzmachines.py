"""Generated cases for the machine-element surfaces: the slider-crank and engine (``SliderCrank``,
``IndicatorDiagram``, ``Engine``, ``engine_torque``, ``joint_forces``), load spectra and service life
(``LoadSpectrum`` from bins, CSV and a curve, ``GearPair.life``, ``pair_life``, the damage checks of
``optimize_shifts``), worm pairs (``WormPair``, ``worm_geometry``, ``select_worm``,
``WormPair.from_center_distance``, ``optimize_x2``), rolling bearings (``check_bearing``,
``select_bearing``, ``tapered_axial_loads``), shafts (``analyse_shaft``, ``shaft_safety``),
``stage_efficiency`` and the commands ``engine``, ``worm``, ``bearing``, ``shaft``, ``pair --spectrum``
and ``shift --spectrum``.

Each target returns (description, call) like those of tests/fuzzcases.py, which registers them. Half
the cases are valid (valid extremes among them), the others have a bad value here and there: NaN,
inf, negative, zero, huge, empty, wrong types, numpy scalars and arrays; files missing, malformed,
existing without ``--overwrite``, or in a folder that does not exist.
"""
from __future__ import annotations

import contextlib
import io
import os
import random
import tempfile

import numpy as np

import geardesign as gd
from geardesign.cli import main as cli_main
from tests.fuzzcases import EXTREMES, HalfWritten

_NUMPY = [np.array(100.0), np.array(float("nan")), np.float64("inf"), np.array([1.0]), np.int64(7), np.float32(1e38),
          np.array([]), np.array([1.0, float("nan")])]
_RATE = [0.0]


def _set_rate(rng) -> None:
    _RATE[0] = rng.choice([0.0, 0.0, 0.05, 0.12])


def _pick(rng: random.Random, valid, invalid=()):
    """A valid value (a list to choose from, or a function of rng), or now and then (at the case's rate) an
    invalid one: of ``invalid``, or an extreme of Python or numpy."""
    if rng.random() < _RATE[0]:
        return rng.choice(list(invalid)) if invalid and rng.random() < 0.5 else rng.choice(EXTREMES + _NUMPY)
    return valid(rng) if callable(valid) else rng.choice(valid)


# fields where +inf is an answer, not a fault: an infinite life (no damage), the safety of an unloaded
# section, a bearing's e where the axial load never counts (to_dict shows None for it)
_INF_OK = ("life", "life_h", "life_inf", "L10", "Lnm", "S_D", "S_F", "s0", "e", "least_safety", "safety")


def _inf_allowed(name: str, inf_ok) -> bool:
    return name in inf_ok or name.startswith(tuple(n for n in inf_ok if len(n) > 2))


def _judged(result, inf_ok=_INF_OK):
    """``result`` when every number in it is finite (or +inf where ``inf_ok`` names the field); else a dict
    naming the bad value with a NaN in it, which run_case counts as nan_result."""
    import math
    from dataclasses import fields, is_dataclass

    def walk(obj, path, depth):
        if depth > 6 or isinstance(obj, (bool, str, type(None), np.bool_)):
            return None
        if isinstance(obj, (float, np.floating)):
            v = float(obj)
            if math.isnan(v) or (math.isinf(v) and not (v > 0 and path and _inf_allowed(path[-1], inf_ok))):
                return "/".join(path) + f" = {v}"
            return None
        if isinstance(obj, np.ndarray) and obj.dtype.kind in "fc":
            inf_allowed = bool(path) and _inf_allowed(path[-1], inf_ok)
            bad = np.isnan(obj) | (np.isinf(obj) & ~((obj > 0) & inf_allowed))
            return "/".join(path) + " array" if bad.any() else None
        if isinstance(obj, dict):
            items = obj.items()
        elif isinstance(obj, (list, tuple)):
            items = ((str(i), v) for i, v in enumerate(obj))
        elif is_dataclass(obj):
            items = ((f.name, getattr(obj, f.name)) for f in fields(obj)
                     if f.name not in ("table", "candidates", "_chain", "skipped", "blocking"))
        else:
            return None
        for k, v in items:
            w = walk(v, path + [str(k)], depth + 1)
            if w:
                return w
        return None
    from geardesign.drives.bearing import BearingCheck
    if isinstance(result, BearingCheck):     # its margins' NaN is "not checked" (no life asked): to_dict's None
        result = result.to_dict()
    where = walk(result, [], 0)
    return {f"not finite at {where}": float("nan")} if where else "finite"


def _judging(target):
    """``target`` with its call's result judged by :func:`_judged`."""
    def make(rng):
        desc, call = target(rng)
        return desc, lambda: _judged(call())
    return make


# --- the slider-crank and the engine --------------------------------------------------------

def _mech_spec(rng) -> dict:
    r = _pick(rng, [70.0, 45.0, 0.5, 1e3, 1e-3], [0.0, -5.0])
    rf = r if isinstance(r, float) and 0 < r < 1e4 else 70.0
    spec = dict(crank_radius_mm=r,
                rod_length_mm=_pick(rng, lambda g: rf * g.choice([3.5, 1.01, 1.0000001, 20.0]), [rf, rf * 0.5]),
                rod_cg_mm=_pick(rng, [75.0, 0.0, 45.0], [-1.0, 1e9]),
                piston_mass_kg=_pick(rng, [2.5, 0.0, 0.6, 1e3], [-1.0]),
                rod_mass_kg=_pick(rng, [4.7, 0.0, 0.7], [-1.0]),
                rod_inertia_kg_m2=_pick(rng, [0.0617, 0.0, 0.003], [-1.0]),
                crank_mass_kg=_pick(rng, [10.5, 0.0], [-1.0]),
                crank_cg_mm=_pick(rng, lambda g: round(rf * g.choice([0.35, 0.0, -0.3, 10.0]), 6), [1e9, 11 * rf]),
                cylinder_bore_mm=_pick(rng, [100.0, 86.0, 1.0, 2e3], [0.0, -1.0, None]))
    if rng.random() < 0.2:
        spec["offset_mm"] = _pick(rng, [0.0, 5.0, -5.0, 0.99 * rf], [1e9, rf * 10])
    if isinstance(spec["rod_cg_mm"], float) and isinstance(spec["rod_length_mm"], float) \
            and spec["rod_cg_mm"] > spec["rod_length_mm"] and rng.random() < 0.9:
        spec["rod_cg_mm"] = 0.0
    return spec


def _diagram(rng, spec):
    r = spec.get("crank_radius_mm")
    l_ = spec.get("rod_length_mm")
    kind = rng.choice(["otto", "otto", "table", "csv"])
    if kind == "otto":
        kw = dict(compression_ratio=_pick(rng, [6.0, 10.0, 1.5, 25.0], [1.0, 0.5, -3.0]),
                  peak_pressure_mpa=_pick(rng, [3.2, 7.0, 0.2, 30.0], [0.0, -1.0, 1e9]))
        if rng.random() < 0.3:
            kw["points"] = _pick(rng, [8, 360, 1440, 20000], [7, 0, 1.5, 10**7])
        if rng.random() < 0.3:
            kw["strokes"] = _pick(rng, [2, 4], [3, 0, "4"])
        if rng.random() < 0.2:
            kw["polytropic_compression"] = _pick(rng, [1.35, 1.0, 1.4], [0.0, -1.0, 100.0])
        return f"IndicatorDiagram.otto({r}, {l_}, **{kw})", lambda: gd.IndicatorDiagram.otto(r, l_, **kw)
    n = _pick(rng, [4, 16, 2], [1, 0])
    n = n if isinstance(n, int) and 0 <= n < 10**6 and not isinstance(n, bool) else 4
    strokes = _pick(rng, [4, 2], [3, 1, None])
    cyc = 720 if isinstance(strokes, int) and strokes == 4 else 360
    phi = [cyc * i / max(n, 1) for i in range(n)]
    p = [_pick(rng, lambda g: round(g.uniform(0.05, 8), 3), [-0.1, 0.0, 1e6]) for _ in range(n)]
    if rng.random() < 0.1:
        phi = list(reversed(phi))
    if kind == "table":
        return (f"IndicatorDiagram({phi}, {p}, {strokes})", lambda: gd.IndicatorDiagram(phi, p, strokes))
    text = rng.choice(["crank_angle_deg,pressure_mpa\n" + "".join(f"{a},{b}\n" for a, b in zip(phi, p)),
                       "crank_angle_deg,pressure_mpa\n", "", "angle,p\n0,1\n", "crank_angle_deg,pressure_mpa\n0,x\n",
                       "crank_angle_deg,pressure_mpa\n0,1,2\n360\n", "\ufeffcrank_angle_deg,pressure_mpa\n0,1\n1,2\n",
                       "crank_angle_deg,pressure_mpa\n0,nan\n10,1\n", "\x00\xff\xfe"])

    def make():
        path = _TMP[0] + "/diagram.csv" if rng.random() < 0.9 else "/nonexistent/diagram.csv"
        if path.startswith(_TMP[0]):
            with open(path, "w", encoding="utf-8", errors="surrogateescape") as fh:
                fh.write(text)
        return gd.IndicatorDiagram.from_csv(path, strokes=strokes)
    return f"IndicatorDiagram.from_csv({text[:80]!r}, strokes={strokes})", make


_TMP = [""]


def _in_tmp(call):
    """Run ``call`` with _TMP[0] a fresh temporary folder, removed afterwards."""
    def run():
        with tempfile.TemporaryDirectory() as tmp:
            _TMP[0] = tmp
            return call()
    return run


def _engine(rng):
    _set_rate(rng)
    spec = _mech_spec(rng)
    ddesc, dmake = _diagram(rng, spec)
    kw = dict(n_rpm=_pick(rng, [1700.0, 3000.0, 1e-3, 1e4], [0.0, -1.0, 1e9]))
    n = _pick(rng, [1, 2, 4, 6, 12], [0, -1, 1.5, 10**6])
    kw["cylinders"] = n
    ni = n if isinstance(n, int) and not isinstance(n, bool) and 1 <= n <= 24 else 2
    mode = rng.random()
    if mode < 0.25:
        kw["phases_deg"] = _pick(rng, lambda g: tuple(sorted(g.uniform(0, 359) for _ in range(ni))),
                                 [(0, 720), (-1,) * ni, (0,) * (ni + 1), ()])
    elif mode < 0.45:
        kw["throws_deg"] = _pick(rng, lambda g: tuple(g.choice([0, 180, 90, 270]) for _ in range(ni)),
                                 [(float("nan"),) * ni, (0,) * (ni + 1)])
        kw["firing_order"] = _pick(rng, lambda g: tuple(g.sample(range(1, ni + 1), ni)),
                                   [(1,) * ni, tuple(range(0, ni)), (1, 1e9)])
    elif mode < 0.55:
        kw["firing_order"] = _pick(rng, lambda g: tuple(g.sample(range(1, ni + 1), ni)), [(1,) * ni, (0,)])
    if rng.random() < 0.3:
        kw["mechanical_efficiency"] = _pick(rng, [0.8, 1.0, 1e-6], [0.0, 1.5])
    if rng.random() < 0.3:
        kw["flywheel_inertia_kg_m2"] = _pick(rng, [1.0, 1e-6, 1e4], [0.0, -1.0])
    if rng.random() < 0.15:
        kw["axis_tilts_deg"] = _pick(rng, lambda g: tuple(g.uniform(-180, 180) for _ in range(ni)), [(200.0,) * ni])
    if rng.random() < 0.1:
        kw["gravity_m_s2"] = _pick(rng, [0.0, 9.81], [-1.0, 1e3])
    points = _pick(rng, [720, 36, 8, 7200], [0, 2, -5, 10**8, 2.5])
    how = rng.choice(["analyse", "analyse", "engine_torque", "curve", "summary"])

    def call():
        eng = gd.Engine(gd.SliderCrank(**spec), dmake(), **kw)
        if how == "engine_torque":
            return gd.engine_torque(eng, points=points)
        if how == "curve":
            return eng.torque_curve(points)
        res = eng.analyse(points)
        if how == "summary":
            res.summary(), res.to_dict(), res.table
        return res
    return f"Engine(SliderCrank(**{spec}), {ddesc}, **{kw}).{how}({points})", _in_tmp(call)


def _joint_forces(rng):
    _set_rate(rng)
    spec = _mech_spec(rng)
    phi = _pick(rng, lambda g: g.choice([[0.0, 90.0, 300.0], list(np.linspace(0, 720, 37)), 45.0, [1e6]]),
                [[], [float("nan")], "90", [[1, 2], [3]]])
    kw = dict(n_rpm=_pick(rng, [1700.0, 1e-3, 1e4], [0.0, -1.0, 1e9]),
              gas_force_n=_pick(rng, [0.0, 1e4, -500.0, 1e7], [[1.0, 2.0, 3.0, 4.0, 5.0]]))
    if rng.random() < 0.3:
        kw["gravity_m_s2"] = _pick(rng, [0.0, 9.81], [-1.0])
    if rng.random() < 0.3:
        kw["axis_tilt_deg"] = _pick(rng, [0.0, 45.0, -180.0], [400.0])
    fn = rng.choice(["joint_forces", "virtual_power_torque"])

    def call():
        mech = gd.SliderCrank(**spec)
        return getattr(gd, fn)(mech, phi, **kw)
    return f"{fn}(SliderCrank(**{spec}), {phi}, **{kw})", call


# --- spectra and service life ---------------------------------------------------------------

def _bins(rng, n):
    sign = rng.choice([1, 1, 1, -1])        # a quarter of the spectra reverse (they need a mean stress factor)
    return [_pick(rng, lambda g: round(g.choice([1, sign]) * g.uniform(1, 3000), 1), [0.0]) for _ in range(n)]


def _spectrum(rng):
    """A LoadSpectrum from bins, a CSV file or a curve, or a bad one."""
    n = rng.choice([1, 3, 8])
    kind = rng.choice(["bins", "bins", "csv", "curve"])
    if kind == "bins":
        which = _pick(rng, ["time_h", "cycles", "share"], ["both", "none"])
        which = which if isinstance(which, str) else "none"
        kw = dict(torque_nm=_pick(rng, lambda g: _bins(g, n), [[], [float("nan")] * n, "abc"]),
                  n_rpm=_pick(rng, lambda g: g.choice([1000.0, 1e-3, 1e4, [1450.0] * n]), [[1.0] * (n + 1), 0.0]))
        if which in ("time_h", "both"):
            kw["time_h"] = _pick(rng, lambda g: [g.choice([1e-3, 100.0, 2e4, 1e6]) for _ in range(n)], [[-1.0] * n])
        if which in ("cycles", "both"):
            kw["cycles"] = _pick(rng, lambda g: [g.choice([1.0, 1e6, 1e9, 0.0]) for _ in range(n)], [[1e19] * n])
        if which == "share":
            kw["share"] = _pick(rng, lambda g: [1.0 / n] * n, [[0.5] * n, [2.0] + [0.0] * (n - 1)])
            kw["duration_h"] = _pick(rng, [2e4, 1.0, 1e6], [0.0, -1.0, None])
        if rng.random() < 0.2:
            kw["on_gear"] = _pick(rng, [1, 2], [0, 3, 1.5])
        return f"LoadSpectrum.from_bins(**{kw})", lambda: gd.LoadSpectrum.from_bins(**kw)
    if kind == "csv":
        rows = [(t, rng.choice([100.0, 5000.0, 1e-3])) for t in _bins(rng, n)]
        text = rng.choice([
            "torque_nm,time_h\n" + "".join(f"{t},{h}\n" for t, h in rows),
            "torque_nm,time_h,n_rpm\n" + "".join(f"{t},{h},1450\n" for t, h in rows),
            "torque_nm,cycles\n" + "".join(f"{t},{h * 1e4}\n" for t, h in rows),
            "torque_nm,time_h\n" + "".join(f"{t},{h}\n" for t, h in rows) + "1,\n",
            "torque_nm,time_h\nnan,1\n", "torque_nm,time_h\ninf,1\n", "torque_nm,time_h\n1,-5\n", "", "\n\n",
            "torque_nm\n100\n", "torque_nm,time_h,bogus\n1,2,3\n", "torque_nm,time_h\n1,2,3\n", "\x80\x81\n",
            "torque_nm;time_h\n1;2\n", "torque_nm,time_h\n" + "1e308,1e308\n" * 2, "torque_nm,time_h\n0,0\n",
            "torque_nm,time_h,time_h\n1,2,3\n", '"torque_nm","time_h"\n"1","2"\n', "torque_nm,time_h\n1,1e-300\n"])
        kw = {}
        if "n_rpm" not in text.split("\n")[0] or rng.random() < 0.2:
            kw["n_rpm"] = _pick(rng, [1450.0, 1e-3, 1e4], [0.0, float("nan"), "x", [1, 2]])
        if rng.random() < 0.2:
            kw["duration_h"] = _pick(rng, [1e4, 1.0], [0.0, -1.0])
        missing = rng.random() < 0.05

        def make():
            with tempfile.TemporaryDirectory() as tmp:
                path = os.path.join(tmp, "no_such" if missing else "spec.csv")
                if not missing:
                    with open(path, "w", encoding="utf-8", errors="surrogateescape") as fh:
                        fh.write(text)
                return gd.LoadSpectrum.from_csv(path, **kw)
        return f"LoadSpectrum.from_csv({text[:100]!r}, **{kw})", make
    pts = rng.choice([721, 361, 50, 2])
    span = rng.choice([720.0, 360.0, 720.0, 360.0, 100.0])
    kw = dict(n_rpm=_pick(rng, [1700.0, 1e-3, 1e4], [0.0]),
              teeth=_pick(rng, [(17, 26), (20, 60), (13, 13), (101, 103)], [(0, 26), (17,), (17.5, 26), "x"]))
    if rng.random() < 0.3:
        kw["levels"] = _pick(rng, [1, 24, 10000], [0, -1, 1e9])
    if rng.random() < 0.2:
        kw["on_gear"] = _pick(rng, [1, 2], [3])
    use_time = rng.random() < 0.3
    amp = _pick(rng, [500.0, 0.0, 1e6, 1e-9], [float("nan")])

    def make():
        phi = np.linspace(0, span, pts)
        with np.errstate(invalid="ignore"):      # inf·0 makes a NaN for the curve to refuse
            T = 300 + amp * np.exp(-((phi - 20) / 15) ** 2) if isinstance(amp, float) else amp
        if use_time:
            return gd.LoadSpectrum.from_curve(T, time_s=phi / 1e4, **kw)
        return gd.LoadSpectrum.from_curve(T, angle_deg=phi, **kw)
    return f"LoadSpectrum.from_curve({pts} points over {span} deg, amp {amp}, time={use_time}, **{kw})", make


def _spectrum_target(rng):
    _set_rate(rng)
    desc, make = _spectrum(rng)

    def call():
        s = make()
        p = rng.choice([6.61, 1.0, 17.0, 50.0])
        return s, s.equivalent_torque(p), repr(s), s.to_frame()
    return desc, call


def _pair_life(rng):
    _set_rate(rng)
    desc, make = _spectrum(rng)
    m = _pick(rng, [4.0, 2.0, 0.5, 20.0], [0.0, -1.0])
    z1, z2 = _pick(rng, [20, 17, 31, 8], [2, 0]), _pick(rng, [60, 26, 80, 200], [1, -3])
    b = _pick(rng, [40.0, 5.0, 400.0], [0.0, -1.0, 1e9])
    kw = {}
    if rng.random() < 0.4:
        kw["life_h"] = _pick(rng, [None, 2e4, 1e-3, 1e7], [0.0, -1.0, 1e30])
    if rng.random() < 0.3:
        kw["sn_curve"] = _pick(rng, ["iso", "original", "elementary", "haibach"], ["", "nope"])
    if rng.random() < 0.6:
        kw["mean_stress_factor"] = _pick(rng, [0.7, 1.0], [0.0, 2.0, -1.0])
    mat = _pick(rng, ["42CrMo4", "18CrNiMo7-6", "C45", "16MnCr5"], ["", "nope", 42])
    how = rng.choice(["life", "life", "pair_life"])

    def call():
        s = make()
        if how == "life":
            r = gd.GearPair(m, z1, z2, 0.3, 0.1, face_width_mm=b).life(s, mat, **kw)
            repr(r), r.to_dict()
            return r
        return gd.pair_life(m, z1, z2, 0.3, 0.1, spectrum=s, material1=mat, face_width_mm=b, **kw)
    return f"{how}(m {m}, {z1}/{z2}, b {b}, {mat}, **{kw}) of {desc}", call


def _damage_optimize(rng):
    _set_rate(rng)
    desc, make = _spectrum(rng)
    z1, z2 = rng.choice([(20, 60), (17, 26), (13, 40)])
    case = {"material": _pick(rng, ["42CrMo4", "18CrNiMo7-6"], ["nope", None]),
            "face_width_mm": _pick(rng, [40.0, 10.0, 200.0], [0.0, -1.0])}
    if rng.random() < 0.3:
        case["life_h"] = _pick(rng, [2e4, 1.0, 1e6], [0.0, -1.0])
    if rng.random() < 0.2:
        case["damage_max"] = _pick(rng, [1.0, 0.5, 10.0], [0.0, -1.0, 11.0])
    if rng.random() < 0.6:
        case["mean_stress_factor"] = _pick(rng, [0.7, 1.0], [0.0, 2.0])
    if rng.random() < 0.1:
        case["bogus"] = 1
    kw = dict(m=_pick(rng, [4.0, 2.0, 8.0], [0.0]), objective=rng.choice(["max_x_sum", "balanced_sliding", None]),
              method=rng.choice(["exact", "exact", "grid"]))

    def call():
        s = make() if rng.random() < 0.95 else "not a spectrum"
        return gd.optimize_shifts(z1, z2, checks={"spectrum": s, **case}, **kw)
    return f"optimize_shifts({z1}, {z2}, checks=spectrum {desc} + {case}, **{kw})", call


# --- worm pairs -----------------------------------------------------------------------------

def _worm_args(rng) -> dict:
    return dict(m_x=_pick(rng, [3.0, 4.0, 8.0, 1.0, 0.1, 25.0], [0.0, -1.0, 1e9]),
                z1=_pick(rng, [1, 2, 4, 10], [0, 11, 2.5]),
                z2=_pick(rng, [30, 40, 16, 80, 1000], [0, 1, -5]),
                q=_pick(rng, [10.0, 44 / 3, 8.0, 2.51, 25.0], [2.5, 0.0, -1.0, 1e9]))


def _worm_kw(rng) -> dict:
    kw = {}
    if rng.random() < 0.3:
        kw["flank_form"] = _pick(rng, ["ZA", "ZN", "ZI", "ZK"], ["za", "", "ZX"])
    if rng.random() < 0.15:
        kw["rack"] = dict(alpha_deg=rng.choice([15.0, 20.0, 25.0]), ha=rng.choice([0.8, 1.0, 1.2]),
                                  c=rng.choice([0.2, 0.25]), rho_f=rng.choice([0.2, 0.3]))
    if rng.random() < 0.2:
        kw["worm_length_mm"] = _pick(rng, [10.0, 100.0, 1e3], [0.0, -1.0])
    if rng.random() < 0.2:
        kw["face_width_mm"] = _pick(rng, [5.0, 30.0, 1e3], [0.0, -1.0])
    return kw


def _worm(rng):
    _set_rate(rng)
    a = _worm_args(rng)
    kw = _worm_kw(rng)
    if "rack" in kw:
        try:
            kw["rack"] = gd.BasicRack(**kw["rack"])
        except gd.GearDesignError:
            del kw["rack"]
    how = rng.choice(["pair", "pair", "center", "x2", "limits", "measure", "geometry"])
    limits = {}
    if rng.random() < 0.3:
        limits = rng.choice([{"eps_alpha_min": _pick(rng, [1.0, 1.5, 3.0], [-1.0, None])},
                             {"sa_min": _pick(rng, [0.2, 0.4, 5.0], [-1.0])}, {"undercut": False},
                             {"bogus": 1}])
    x2 = _pick(rng, [0.0, 0.5, -0.5, 1.0, -1.0], [5.0, -5.0])
    obj = _pick(rng, ["min_abs_x2", "max_margin"], ["", "x"])
    if how == "center":
        mx = a["m_x"] if isinstance(a["m_x"], float) and 0 < a["m_x"] < 1e4 else 3.0
        z2 = a["z2"] if isinstance(a["z2"], int) and 0 < a["z2"] < 1e4 else 30
        q = a["q"] if isinstance(a["q"], float) and 0 < a["q"] < 1e4 else 10.0
        cd = _pick(rng, lambda g: mx * (q + z2) / 2 + mx * g.uniform(-1, 1), [0.0, -1.0, 1e300])
        return (f"WormPair.from_center_distance({cd}, **{a}, **{kw}).checks({limits})",
                lambda: gd.WormPair.from_center_distance(cd, **a, **kw).checks(**limits))
    if how == "geometry":
        arr = rng.random() < 0.5
        args = {k: (np.array([v, v]) if arr and k in ("m_x", "q") and isinstance(v, float) else v) for k, v in a.items()}
        return (f"worm_geometry(**{args}, x2={x2}, **{kw})",
                lambda: gd.worm_geometry(**args, x2=x2, **kw))

    def call():
        p = gd.WormPair(**a, x2=x2, **kw)
        if how == "pair":
            return p.geometry(), p.checks(**limits), p.ok(**limits), p.geometry().summary()
        if how == "x2":
            r = p.optimize_x2(obj, **limits)
            if r.success:
                p2 = r.pair()
                failing = [c for c, v in p2.checks(**limits).items() if not v.get("ok", True)] \
                    if isinstance(p2.checks(**limits), dict) else []
                if failing:
                    raise AssertionError(f"optimize_x2's x2 {r.x2} fails {failing}")
            return r
        if how == "limits":
            lo, hi = p.x2_limits(**limits)
            return "no x2 holds every check" if np.isnan(lo) and np.isnan(hi) else (lo, hi)   # documented
        return p.measurements()
    return f"WormPair(**{a}, x2={x2}, **{kw}).{how}({obj}, {limits})", call


def _select_worm(rng):
    _set_rate(rng)
    kw = {}
    ratio = _pick(rng, [12.5, 20.0, 40.0, 1.0, 100.0, None], [0.0, -1.0, 1e9])
    a = _pick(rng, [125.0, 100.0, None, 40.0, 500.0], [0.0, -1.0])
    if a is None or rng.random() < 0.5:
        kw["m_x"] = _pick(rng, [4.0, [3.15, 4.0], 6.3], [0.0, [], [-1.0]])
    if rng.random() < 0.4:
        kw["z1"] = _pick(rng, [1, 2, (2, 4), (1, 2, 3, 4)], [0, (), (11,)])
    if rng.random() < 0.3:
        kw["q"] = _pick(rng, [10.0, (8.0, 12.5)], [0.0, 1.0, ()])
    if rng.random() < 0.2:
        kw["ratio_tol"] = _pick(rng, [0.05, 0.0, 0.5], [-1.0, 10.0])
    if rng.random() < 0.2:
        kw["objective"] = _pick(rng, ["min_abs_x2", "max_margin"], ["bogus"])

    def call():
        s = gd.select_worm(ratio, a, **kw)
        s.table, repr(s)
        if s.found:
            s.pair().checks()
        return s
    return f"select_worm({ratio}, {a}, **{kw})", call


# --- bearings, shafts, efficiency -------------------------------------------------------------

_DESIGNATIONS = ["6208", "6308", "7310B", "NU210EA", "30206", "32210", "6200", "NU330EA"]


def _bearing(rng):
    _set_rate(rng)
    kw = dict(F_r_n=_pick(rng, [3200.0, 0.0, 1e-3, 1e6], [-1.0, 1e30]),
              F_a_n=_pick(rng, [1800.0, 0.0, 1e5], [-1.0]),
              n_rpm=_pick(rng, [650.0, 1e-3, 3e4, 1e5], [0.0, -1.0, None]))
    if rng.random() < 0.5:
        kw["life_h"] = _pick(rng, [1e4, 1e-3, 1e6, None], [0.0, -1.0])
    if rng.random() < 0.3:
        kw["reliability"] = _pick(rng, [90, 95, 99, 99.0], [50, 100, 89.5])
    if rng.random() < 0.3:
        kw["kappa"], kw["e_c"] = _pick(rng, [2.0, 0.1, 4.0], [0.0, -1.0]), _pick(rng, [0.5, 0.0, 1.0], [2.0, -1.0])
    if rng.random() < 0.2:
        kw["lubrication"] = _pick(rng, ["grease", "oil"], ["water", ""])
    if rng.random() < 0.2:
        kw["s0_min"] = _pick(rng, [1.0, 2.0, 0.5], [0.0, -1.0])
    how = rng.choice(["check", "select", "tapered"])
    if how == "check":
        d = _pick(rng, _DESIGNATIONS, ["", "bogus", " 6208", 6208])
        return f"check_bearing({d!r}, **{kw})", lambda: gd.check_bearing(d, **kw)
    if how == "select":
        series = _pick(rng, ["62", ["62", "63"], "302", ["NU2", "72B"], ("323",)], ["", [], "99", ["62", 62]])
        bore = _pick(rng, [40.0, 5.0, 120.0, 1e3], [0.0, -1.0])
        kw.setdefault("life_h", _pick(rng, [2e4, 1e-3], [None]))
        return f"select_bearing({series!r}, {bore}, **{kw})", lambda: gd.select_bearing(series, bore, **kw)
    args = [_pick(rng, [5980.0, 4000.0, 0.0, 1e6], [-1.0, [1.0, 2.0]]), _pick(rng, [4180.0, 2500.0, 0.0], [-1.0]),
            _pick(rng, [2.06, 1.6, 0.5, 10.0], [0.0, -1.0]), _pick(rng, [2.07, 1.6], [0.0])]
    ka = _pick(rng, [0.0, 1200.0, -1200.0, 1e6], [[1.0, 2.0, 3.0]])
    return f"tapered_axial_loads(*{args}, {ka})", lambda: gd.tapered_axial_loads(*args, ka)


def _shaft_model(rng):
    n = rng.choice([1, 3, 5])
    sections = _pick(rng, lambda g: [(g.choice([40.0, 110.0, 1.0]), g.choice([35.0, 48.0, 32.0, 1.0]))
                                     for _ in range(n)],
                     [[], [(40, 0)], [(0, 30)], [(-1, 30)], [(40, 30, 35)], [(40, 30, 40)], "40x30", [(40,)]])
    L = sum(s[0] for s in sections) if isinstance(sections, list) and all(
        isinstance(s, tuple) and len(s) >= 2 and isinstance(s[0], float) for s in sections) and sections else 100.0
    supports = _pick(rng, lambda g: sorted(g.sample([0.0, 0.1 * L, 0.5 * L, 0.9 * L, L], g.choice([2, 2, 3]))),
                     [[0.0], [0.0, 0.0], [0.0, 2 * L], [-1.0, L], []])
    loads = [dict(x_mm=_pick(rng, lambda g: g.uniform(0, L), [-1.0, 2 * L]),
                  fy_n=_pick(rng, [0.0, -1000.0, 1e6], []), fz_n=_pick(rng, [0.0, 2000.0], []),
                  fx_n=_pick(rng, [0.0, 500.0], []), y_mm=_pick(rng, [0.0, 70.0], []),
                  torque_nm=_pick(rng, [0.0, 120.0, -120.0], []), mass_kg=_pick(rng, [0.0, 1.5], [-1.0]))
             for _ in range(rng.choice([0, 1, 2, 3]))]
    torque = sum(ld["torque_nm"] for ld in loads if isinstance(ld["torque_nm"], float))
    if loads and torque and rng.random() < 0.9:        # the output torque where the shaft leaves it
        loads.append(dict(x_mm=L, torque_nm=-torque))
    axial = _pick(rng, [0, 1], [5, -1, 1.5]) if rng.random() < 0.2 else 0
    return sections, supports, loads, axial


def _shaft(rng):
    _set_rate(rng)
    sections, supports, loads, axial = _shaft_model(rng)
    points = _pick(rng, [201, 3, 10001], [0, 1, 10**8]) if rng.random() < 0.2 else None
    safety = rng.random() < 0.5
    L = 100.0
    notches = [(_pick(rng, lambda g: g.uniform(0, L), [-1.0, 1e9]),
                _pick(rng, ["key", "shoulder", "smooth", "press_fit", "groove"], ["bogus", ""]),
                _pick(rng, [1.0, 1.6, 0.1], [0.0, -1.0])) for _ in range(rng.choice([1, 2, 3]))]
    kw = {}
    if rng.random() < 0.3:
        kw["peak_factor"] = _pick(rng, [1.0, 2.0, 10.0], [0.0, -1.0])
    if rng.random() < 0.3:
        kw["torque_amplitude"] = _pick(rng, [0.0, 0.5, 1.0], [-1.0, 5.0])
    if rng.random() < 0.2:
        kw["Rz_um"] = _pick(rng, [6.3, 0.1, 100.0], [0.0, -1.0])
    if rng.random() < 0.2:
        kw["load_case"] = _pick(rng, [1, 2], [3, 0])
    mat = _pick(rng, ["C45", "42CrMo4", "34CrNiMo6"], ["", "nope"])

    def call():
        model = gd.ShaftModel(sections=sections, supports_mm=supports, loads=[gd.ShaftLoad(**ld) for ld in loads],
                              axial_support=axial)
        a = gd.analyse_shaft(model) if points is None else gd.analyse_shaft(model, points=points)
        if not safety:
            a.reactions, a.elements, a.to_dict(), a.deflection_at([0.0, model.length_mm])
            return a
        ns = []
        for x, kind, r in notches:
            named = kind if isinstance(kind, str) else ""
            t = 2 * r if isinstance(r, float) else r
            notch = (gd.Notch(kind, r_mm=r) if named == "shoulder" else gd.Notch(kind, r_mm=r, t_mm=t)
                     if named == "groove" else gd.Notch(kind))
            ns.append(gd.ShaftNotch(min(x, model.length_mm) if isinstance(x, float) else x, notch))
        s = gd.shaft_safety(a, ns, mat, **kw)
        s.table, s.to_dict()
        return s
    return (f"analyse_shaft(ShaftModel({sections}, {supports}, {loads}, axial {axial}), points={points})"
            + (f" + shaft_safety({notches}, {mat}, **{kw})" if safety else "")), call


def _stage_efficiency(rng):
    _set_rate(rng)
    pair = dict(m=_pick(rng, [3.0, 1.0, 10.0]), z1=_pick(rng, [21, 17, 40]), z2=_pick(rng, [64, 26, 100]),
                x1=0.3, x2=0.2, beta_deg=_pick(rng, [0.0, 12.0, 30.0]),
                face_width_mm=_pick(rng, [40.0, 5.0, 300.0], [0.0, -1.0, None]))
    load = dict(power_kw=_pick(rng, [15.0, 1e-3, 1e3], [0.0, -1.0]), n_rpm=_pick(rng, [1450.0, 1.0, 1e4], [0.0]))
    oil = _pick(rng, [(100.0, 11.1), (32.0, 5.4), (680.0, 40.0)], [(0.0, 11.1), (-1.0, 5.4), (100.0, 200.0),
                                                                    (100.0, 0.0), (float("nan"), 5.0)])
    oil = oil if isinstance(oil, tuple) else (oil, 10.0)
    temp = _pick(rng, [60.0, 20.0, 120.0, -20.0], [-300.0, 1e4])
    kw = dict(Ra_um=_pick(rng, [0.5, 0.1, 3.0], [0.0, -1.0]))
    if rng.random() < 0.4:
        kw["bearings"] = _pick(rng, lambda g: [("6307", 1, g.choice([1700.0, 1.0, 1e5])), ("6310", 2, 1700.0)],
                               [[("bogus", 1, 100.0)], [("6307", 3, 1.0)], [("6307", 1, -1.0)], "6307"])
    if rng.random() < 0.2:
        kw["no_load_loss_w"] = _pick(rng, [0.0, 100.0], [-1.0])
    if rng.random() < 0.2:
        kw["lubrication"] = _pick(rng, ["oil_bath", "oil_jet", "grease", "oil_air"], ["", "water"])
    if rng.random() < 0.2:
        kw["method"] = _pick(rng, ["integrated", "ohlendorf"], ["x"])

    def call():
        b = kw.get("bearings")
        kws = dict(kw)
        if isinstance(b, list):
            kws["bearings"] = [gd.BearingLoad(*t) if isinstance(t, tuple) else t for t in b]
        r = gd.stage_efficiency(gd.GearPair(**pair), gd.Load(**load), gd.Lubricant(*oil), temp, **kws)
        r.table, r.to_dict()
        return r
    return f"stage_efficiency(GearPair(**{pair}), Load(**{load}), Lubricant{oil}, {temp}, **{kw})", call


# --- the commands ---------------------------------------------------------------------------

_ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def _num(rng, valid, invalid=()):
    return str(_pick(rng, valid, list(invalid) + ["nan", "inf", "-inf", "-1", "0", "1e400", "", "abc", "0x10"]))


_ENGINE_TOML = """[engine]
n_rpm = {n}
cylinders = {cyl}
{extra}
[engine.mechanism]
crank_radius_mm = {r}
rod_length_mm = {l}
rod_cg_mm = 75
piston_mass_kg = 2.5
rod_mass_kg = 4.7
rod_inertia_kg_m2 = 0.0617
cylinder_bore_mm = {bore}

[engine.pressure]
{pressure}
"""
_PRESSURES = ['kind = "otto"\ncompression_ratio = {eps}\npeak_pressure_mpa = {p}',
              'kind = "table"\ncrank_angle_deg = [0, 180, 360, 540]\npressure_mpa = [0.1, 0.1, {p}, 0.3]',
              'kind = "csv"\ncsv = "diagram.csv"', 'kind = "csv"\ncsv = "missing.csv"', 'kind = "bogus"',
              'kind = "table"\ncrank_angle_deg = []\npressure_mpa = []', 'kind = "otto"']
_DIAGRAM_CSVS = ["crank_angle_deg,pressure_mpa\n0,0.1\n180,0.1\n360,3.0\n540,0.3\n", "", "a,b\n1,2\n",
                 "crank_angle_deg,pressure_mpa\n0,nan\n", "crank_angle_deg,pressure_mpa\n0,1\n0,2\n", "\x80\x81"]


def _cli_machines(rng):
    _set_rate(rng)
    cmd = rng.choice(["engine", "worm", "worm", "bearing", "bearing", "shaft", "shaft", "pair_spectrum",
                      "shift_spectrum"])
    files = {}
    wanted = []
    if cmd == "engine":
        pressure = rng.choice(_PRESSURES).format(eps=_num(rng, [6.0, 10]), p=_num(rng, [3.2, 7.0]))
        extra = rng.choice(["", "", "mechanical_efficiency = " + _num(rng, [0.8, 1]),
                            "flywheel_inertia_kg_m2 = " + _num(rng, [1.0, 0.1]), "phases_deg = [0, 540]",
                            "points = " + _num(rng, [720, 36]), "strokes = " + _num(rng, [2, 4]),
                            'firing_order = [1, 2]', "throws_deg = [0, 180]\nfiring_order = [1, 2]"])
        text = rng.choice([_ENGINE_TOML.format(
            r=_num(rng, [70, 45.0]), l=_num(rng, [250, 150.0]), bore=_num(rng, [100, 86]), n=_num(rng, [1700, 3000]),
            cyl=_num(rng, [1, 2, 2, 4]), extra=extra, pressure=pressure)] * 6 +
            ["[engine\n", "", "[engine]\n", "[other]\nx = 1\n", '[engine]\nn_rpm = "70"\n', "\x00\x01"])
        files["scene.toml"] = text
        files["diagram.csv"] = rng.choice(_DIAGRAM_CSVS)
        args = ["engine", "{tmp}/scene.toml" if rng.random() < 0.95 else "{tmp}/missing.toml"]
        if rng.random() < 0.3:
            args += ["--points", _num(rng, ["720", "36", "2"], ["1", "1e9", "10000000000"])]
    elif cmd == "worm":
        if rng.random() < 0.7:
            args = ["worm", "--module", _num(rng, [3, 4, 8]), "--z1", _num(rng, [1, 2, 4], ["11", "2.5"]),
                    "--z2", _num(rng, [30, 40]), "--q", _num(rng, [10, 14.667])]
            if rng.random() < 0.3:
                args += ["--x2", _num(rng, [0, 0.5, -0.5], ["5"])]
            if rng.random() < 0.2:
                args += ["--center-distance", _num(rng, [67, 100], ["1e300"])]
            if rng.random() < 0.2:
                args += ["--optimize-x2", rng.choice(["min_abs_x2", "max_margin", "bogus", ""])]
            if rng.random() < 0.2:
                args += ["--flank-form", rng.choice(["ZA", "ZN", "ZI", "ZK", "za", ""])]
            if rng.random() < 0.2:
                args += ["--measurements"]
            if rng.random() < 0.15:
                args += [rng.choice(["--worm-length", "--face-width", "--eps-alpha-min", "--sa-min", "--ha", "--c",
                                     "--alpha-deg", "--rho-f", "--x2-abs-max"]), _num(rng, [1.0, 20.0, 50.0])]
        else:
            args = ["worm", "--ratio", _num(rng, [12.5, 20, 40], ["1e9"])]
            if rng.random() < 0.6:
                args += ["--center-distance", _num(rng, [125, 100, 40])]
            if rng.random() < 0.3:
                args += ["--top", _num(rng, ["3", "0"], ["-1", "1.5"])]
    elif cmd == "bearing":
        args = ["bearing", "--fr", _num(rng, [3200, 0, 1e5]), "--speed", _num(rng, [650, 3000])]
        if rng.random() < 0.5:
            args += ["--designation", rng.choice(_DESIGNATIONS + ["bogus", "", " "])]
        else:
            args += ["--bore", _num(rng, [40, 20, 100]), "--life-h", _num(rng, [2e4, 1000])]
            if rng.random() < 0.5:
                args += ["--series", rng.choice(["62", "62,63", "302", "", ",", "99", "62,,63"])]
            if rng.random() < 0.2:
                args += ["--type", rng.choice(["deep_groove", "tapered", "bogus"])]
            if rng.random() < 0.2:
                args += ["--top", _num(rng, ["3", "0"], ["-1"])]
        for opt, v in (("--fa", [1800, 0]), ("--reliability", [90, 99]), ("--kappa", [2.0]), ("--ec", [0.5]),
                       ("--s0-min", [1.0, 2.0])):
            if rng.random() < 0.2:
                args += [opt, _num(rng, v)]
        if rng.random() < 0.1:
            args += ["--lubrication", rng.choice(["oil", "grease", "x"])]
    elif cmd == "shaft":
        if rng.random() < 0.75:
            args = ["shaft", "--sections", rng.choice(["40x35,40x40,110x48,40x40,50x32", "40x35,120x45,40x35",
                                                       _num(rng, ["100x30"]), "", "40x", "x", "40x35x40", "40x35,",
                                                       "nanx30", "1e400x30", "40x35x20", "0x30,40x30"]),
                    "--supports", rng.choice(["20,210", "20,140", "0,200", "", "20", "20,20", "-5,210", "nan,100",
                                              "20,1e9", "20,,210"])]
            for _ in range(rng.choice([0, 1, 2])):
                args += ["--load", rng.choice(["x=110,fy=-1000,fz=3000,torque=120", "x=280,torque=-120",
                                               "x=" + _num(rng, ["110", "50"]) + ",fy=" + _num(rng, ["-1000"]),
                                               "", "x", "x=1,bogus=2", "fy=1", "x=110,mass=-1", "x=110,name=",
                                               "x=110,fy=1,fy=2", "x=110=3"])]
            for _ in range(rng.choice([0, 1, 2])):
                args += ["--notch", rng.choice(["x=110,kind=key", "x=80,kind=shoulder,r=1.6", "x=40,kind=smooth",
                                                "x=110,kind=given,beta_sigma=2,beta_tau=1.5", "x=110,kind=bogus",
                                                "kind=key", "x=" + _num(rng, ["80"]) + ",kind=shoulder,r=" +
                                                _num(rng, ["1.6"]), "x=110,kind=key,keys=3", "x=110,kind=groove,r=1,t=0"])]
        else:
            files["shaft.toml"] = rng.choice([
                '[shaft]\nsections = [[40, 35], [110, 48], [40, 35]]\nsupports = [20, 170]\nmaterial = "C45"\n'
                '[[shaft.load]]\nx = 95\nfy = -1000\ntorque = 120\n[[shaft.notch]]\nx = 95\nkind = "key"\n',
                '[shaft]\nsections = [[40, 35]]\nsupports = [0, 40]\n', '[shaft\n', '', '[shaft]\n',
                '[shaft]\nsections = "x"\nsupports = [0, 40]\n', '[shaft]\nsections = [[40, nan]]\nsupports = [0, 40]\n',
                '[shaft]\nsections = [[40, 35]]\nsupports = [0, 40]\n[[shaft.load]]\nx = "a"\n',
                '[shaft]\nsections = [[40, 35]]\nsupports = [0, 40]\nbogus = 1\n',
                '[shaft]\nsections = [[40, 35]]\nsupports = [0, 40]\n[[shaft.load]]\nx = 20\nfy = inf\n',
                '[shaft]\nsections = [[40, 35]]\nsupports = [0, 40]\nshaft = 3\n[shaft.load]\nx = 1\n',
                '[shaft]\nsections = [[40, 35, 50]]\nsupports = [0, 40]\n', 'shaft = 1\n'])
            args = ["shaft", "{tmp}/shaft.toml" if rng.random() < 0.95 else "{tmp}/missing.toml"]
        for opt, v in (("--rz", [6.3, 1.0]), ("--peak-factor", [1.0, 2.0]), ("--torque-amplitude", [0.0, 0.5]),
                       ("--s-min", [1.2, 2.0]), ("--axial-support", ["0", "1"]), ("--material", ["C45", "42CrMo4"])):
            if rng.random() < 0.1:
                args += [opt, _num(rng, v, ["bogus", "5"])]
        if rng.random() < 0.2:
            args += ["--least"]
        if rng.random() < 0.3:
            kind = rng.choice(["fresh", "fresh", "existing", "missing_folder", "folder"])
            path = {"fresh": "{tmp}/plot.png", "existing": "{tmp}/old.png", "missing_folder": "{tmp}/no/plot.png",
                    "folder": "{tmp}"}[kind]
            if kind == "existing":
                files["old.png"] = "precious"
            args += ["--plot", path]
            wanted.append(path)
            if rng.random() < 0.3:
                args += ["--overwrite"]
    else:
        files["spec.csv"] = rng.choice(["torque_nm,time_h\n120,2000\n90,8000\n60,10000\n",
                                        "torque_nm,time_h,n_rpm\n120,2000,1000\n-90,8000,1000\n",
                                        "torque_nm,cycles\n500,9e6\n1000,1e6\n", "", "torque_nm,time_h\nnan,1\n",
                                        "torque_nm,time_h\n1,-1\n", "x,y\n1,2\n", "torque_nm,time_h\n1e300,1e300\n",
                                        "torque_nm,time_h\n1,2\n\n3,4\n", "\x80\x81"])
        spec = "{tmp}/spec.csv" if rng.random() < 0.9 else rng.choice(["{tmp}/missing.csv", "{tmp}", ""])
        if cmd == "pair_spectrum":
            args = ["pair", "--module", _num(rng, [4, 2]), "--z1", _num(rng, [20, 17]), "--z2", _num(rng, [60, 26]),
                    "--x1", "0.3", "--x2", "0.1", "--spectrum", spec]
        else:
            args = ["shift", "--z1", _num(rng, [20, 17]), "--z2", _num(rng, [60, 26]), "--module", _num(rng, [4, 2]),
                    "--spectrum", spec]
        for opt, v in (("--material", ["42CrMo4", "C45"]), ("--face-width", [40, 20]), ("--speed", [1000, 1450]),
                       ("--life-h", [2e4, 1000]), ("--sn-curve", ["iso", "haibach"])):
            if rng.random() < (0.8 if opt in ("--material", "--face-width", "--speed") else 0.25):
                args += [opt, _num(rng, v, ["bogus"])]
        if rng.random() < 0.2:
            args += ["--json"]
    if cmd in ("worm", "bearing", "shaft", "engine") and rng.random() < 0.2:
        args += ["--json"]
    if cmd == "engine" and rng.random() < 0.4:
        for flag, sfx in rng.sample([("--csv", ".csv"), ("--plot", ".png")], rng.randint(1, 2)):
            kind = rng.choice(["fresh", "fresh", "existing", "missing_folder"])
            path = {"fresh": "{tmp}/out", "existing": "{tmp}/old", "missing_folder": "{tmp}/no/out"}[kind] + sfx
            if kind == "existing":
                files["old" + sfx] = "precious"
            args += [flag, path]
            wanted.append(path)
        if rng.random() < 0.3:
            args += ["--overwrite"]

    def call():
        with tempfile.TemporaryDirectory() as tmp:
            for name, text in files.items():
                with open(os.path.join(tmp, name), "w", encoding="utf-8", errors="surrogateescape") as fh:
                    fh.write(text)
            argv = [a.replace("{tmp}", tmp) for a in args]
            want = [w.replace("{tmp}", tmp) for w in wanted]
            before = {p: _stamp(p) for p in want}
            listing = sorted(os.listdir(tmp))
            out, err = io.StringIO(), io.StringIO()
            with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
                try:
                    code = cli_main(argv)
                except SystemExit as exc:
                    code = exc.code
            lines = err.getvalue().strip().splitlines()
            if "Traceback" in err.getvalue() or code not in (0, 1, 2):
                raise AssertionError(f"exit {code}: {err.getvalue()[-300:]!r}")
            if code == 2 and len(lines) != 1:
                raise AssertionError(f"exit 2 with {len(lines)} stderr lines: {err.getvalue()[:300]!r}")
            left = [n for n in os.listdir(tmp) if n.startswith(".")]
            if left:
                raise HalfWritten(f"temporary files left behind: {left}")
            if code == 2 and sorted(os.listdir(tmp)) != listing:
                raise HalfWritten(f"exit 2 but the folder changed: {sorted(os.listdir(tmp))}")
            changed = [p for p in want if _stamp(p) != before[p]]
            if code == 2 and changed:
                raise HalfWritten(f"exit 2 but wrote {changed}")
            if "--overwrite" not in argv and any(before[p] == hash(b"precious") and p in changed for p in want):
                raise HalfWritten("an existing file was overwritten without --overwrite")
            if code == 2:           # a clean refusal: counted as one
                raise gd.GearDesignError(lines[0])
            text = out.getvalue()
            # NaN only: an infinite life is an answer, and worm's ranking shows -inf for a wheel that does not exist
            if code in (0, 1) and any(w in ("nan", "NaN") for w in text.replace(",", " ").split()):
                return float("nan")
            return code
    return "geardesign " + " ".join(repr(a) if not a or " " in a else a for a in args) + \
        (f" (files {list(files)}: {str(list(files.values()))[:80]})" if files else ""), call


def _stamp(path):
    try:
        with open(path, "rb") as fh:
            return hash(fh.read())
    except OSError:
        return None


MACHINES = {"engine": _engine, "joint_forces": _joint_forces, "load_spectrum": _spectrum_target,
            "pair_life": _pair_life, "damage_optimize": _damage_optimize, "worm": _worm, "select_worm": _select_worm,
            "bearing": _bearing, "shaft": _shaft, "stage_efficiency": _stage_efficiency, "cli_machines": _cli_machines}
MACHINES = {k: _judging(v) for k, v in MACHINES.items()}
