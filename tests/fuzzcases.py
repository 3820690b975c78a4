"""Generated bad and extreme input for every public entry point, and the one rule it must obey.

Shared by ``tests/test_fuzz.py`` (a small, reproducible sample in CI) and
``tools/fuzz.py`` (a long run that counts outcomes). A case is a target name and a call;
:func:`run_case` classifies what the call did:

* ``ok`` — a result, every number in it finite;
* ``clean_error`` — a :class:`geardesign.GearDesignError` (CLI: exit 2 with exactly one line on
  stderr; exit 1 is an infeasible design, a result);
* ``traceback`` — any other exception;  ``nan_result`` — a NaN or inf passed off as a result;
* ``hang`` — longer than the case's time limit;  ``half_written`` — files left behind by a
  failed command, or one of a command's files written without the others;
* ``fails_checks`` — an optimum (or a row marked feasible) that its own checks refuse when
  re-checked with ``GearPair(...).checks()`` / ``PlanetarySet(...).checks()`` by more than 1e-9,
  or whose gears do not exist or mesh;
* ``feasibility_tol`` — the same re-check failing by at most 1e-9 (issue 29 §2, the tolerance
  the solver and ``checks()`` do not yet share; counted apart);
* ``warning`` — a Python warning escaping a call that returned or refused cleanly;
* ``link_replaced`` — an output path that was a symlink is no longer one.

Every file a case writes goes into its own temporary folder. The targets reaching files, links,
Ctrl-C at start-up are in tests/fuzzsurfaces.py.
"""
from __future__ import annotations

import contextlib
import io
import math
import os
import random
import signal
import tempfile
import time
import zlib
from dataclasses import fields, is_dataclass

import numpy as np
import pandas as pd

import geardesign as gd
from geardesign.cli import main as cli_main
from tests.fuzzrecheck import FailsChecks, FeasibilityTol, recheck_pair, recheck_set, recheck_shift_result

OUTCOMES = ("ok", "clean_error", "traceback", "nan_result", "hang", "half_written", "fails_checks",
            "feasibility_tol", "warning", "link_replaced")

# extremes every numeric input meets now and then
EXTREMES = [0, -0.0, -1, 5e-324, 1e-300, 1e308, -1e308, float("inf"), float("nan"), 10**400, 2**63,
            "abc", "", None, True, [1, 2], [[1], [2, 3]], (), {"a": 1}]


def _pick(rng: random.Random, typical, p_extreme=0.15):
    """A typical value most of the time, an extreme one sometimes."""
    if rng.random() < p_extreme:
        return rng.choice(EXTREMES)
    return typical(rng) if callable(typical) else rng.choice(typical)


def _z(rng):
    return rng.choice([rng.randint(3, 60), rng.randint(60, 400), rng.randint(3, 12), 10000])


def _x(rng):
    return rng.choice([round(rng.uniform(-1.5, 3), 3), 0.0, round(rng.uniform(-5, 8), 2)])


def _m(rng):
    return rng.choice([1, 2, 2.5, 8, round(rng.uniform(0.1, 30), 3), 1e-4, 1e4] + _M_ENDS)


# the module range's ends and just beyond (geometry.M_RANGE_MM): inside answers, outside is refused
_M_ENDS = [1e-4, 1e4, 1e-4 * (1 - 1e-12), 1e4 * (1 + 1e-12), 9.999e3, 1.0001e-4, 1e300, 2.0 ** 63]
# checks dropped: meshing must hold whatever is left (issue 29 §3.1)
_DROPPED = [{"eps_alpha_min": None}, {"eps_alpha_min": None, "sa_min": None}, {"undercut": False},
            {"interference": False}, {"eps_alpha_min": None, "undercut": False, "interference": False},
            {"eps_alpha_min": 0.0}, []]


def _rack(rng):
    if rng.random() < 0.7:
        return None
    return dict(alpha_deg=_pick(rng, lambda r: r.uniform(8, 40)), ha=_pick(rng, lambda r: r.uniform(0.5, 1.5)),
                c=_pick(rng, lambda r: r.uniform(0.0, 0.5)), rho_f=_pick(rng, lambda r: r.uniform(0, 0.5)))


def _kind(rng) -> dict:
    """Helical and internal pairs (issue 12) a third of the time, now and then with a bad value."""
    if rng.random() < 0.67:
        return {}
    out = {}
    if rng.random() < 0.6:
        out["beta_deg"] = _pick(rng, [8.0, 15.0, 30.0, 45.0, 46.0, -1.0], 0.2)
    if rng.random() < 0.6:
        out["internal"] = _pick(rng, [True, True, False, 1, "yes"], 0.05)
    if rng.random() < 0.3:
        out["face_width_mm"] = _pick(rng, [20.0, 60.0, 0.0, -5.0], 0.2)
    return out


def _make_rack(spec):
    return None if spec is None else gd.BasicRack(**spec)


# --- the targets: each returns (description, call) ------------------------------------------

def _pair(rng):
    a = dict(m=_pick(rng, _m), z1=_pick(rng, _z), z2=_pick(rng, _z), x1=_pick(rng, _x), x2=_pick(rng, _x),
             **_kind(rng))
    rack = _rack(rng)
    limits = dict(eps_alpha_min=_pick(rng, [1.0, 1.2, 1.5], 0.1), sa_min=_pick(rng, [0.25, 0.4], 0.1))

    def call():
        p = gd.GearPair(rack=_make_rack(rack) or gd.BasicRack(), **a)
        return p.geometry(), p.checks(**limits)
    return f"GearPair({a}, rack={rack}).checks({limits})", call


def _pair_geometry(rng):
    n = rng.choice([1, 3, 50])
    a = dict(m=_pick(rng, _m), z1=[_z(rng) for _ in range(n)], z2=_pick(rng, _z),
             x1=[_x(rng) for _ in range(rng.choice([n, n, 2]))], x2=_pick(rng, _x), **_kind(rng))
    return f"pair_geometry({a})", lambda: gd.pair_geometry(**a)


def _from_center_distance(rng):
    z1, z2 = _z(rng), _z(rng)
    m = _pick(rng, _m)
    scale = m if isinstance(m, (int, float)) and not isinstance(m, bool) and 0 < abs(m) < 1e6 else 1.0
    a_w = _pick(rng, lambda r: (z1 + z2) / 2 * scale * r.uniform(0.9, 1.2))
    x1 = _pick(rng, [None, 0.0, 0.5], 0.1)
    kind = _kind(rng)
    return (f"GearPair.from_center_distance({m}, {z1}, {z2}, {a_w}, x1={x1}, **{kind})",
            lambda: gd.GearPair.from_center_distance(m, z1, z2, a_w, x1=x1, **kind).geometry())


def _optimize(rng):
    z1, z2 = _pick(rng, lambda r: r.randint(5, 80), 0.1), _pick(rng, lambda r: r.randint(5, 200), 0.1)
    kw = dict(objective=_pick(rng, [None, "max_x_sum", "max_eps_alpha", "balanced_sliding",
                                    "min_specific_pressure", "max_margin"], 0.1),
              method=_pick(rng, ["exact", "exact", "grid", "convex"], 0.05))
    if kw["method"] == "convex" and rng.random() < 0.7:
        kw["method"] = "exact"     # convex is slow; keep it a minority
    if rng.random() < 0.3:
        kw["m"] = _pick(rng, _m)
        kw["a_w"] = _pick(rng, lambda r: (r.randint(10, 90)) * r.uniform(0.9, 1.3))
    if rng.random() < 0.2:
        kw["tol"] = _pick(rng, [1e-3, 1e-9, 1e-14, 0.5])
    if rng.random() < 0.15:
        kw["bounds"] = _pick(rng, [(-0.5, 1.0), (-1, 2), (0, 0), (3, -1)])
    if rng.random() < 0.1:
        kw["grid_n"] = _pick(rng, [5, 101, 5000])
    if rng.random() < 0.4:
        kw["checks"] = _pick(rng, [{}, {"undercut": False}, {"interference": False}, {"sa_min": 0.4},
                                   {"eps_alpha_min": None}, [], {"bogus": 1}, {"radial_assembly": True}] + _DROPPED)
    kw.update(_kind(rng))
    if rng.random() < 0.25 and isinstance(z1, int) and isinstance(z2, int):   # ring pairs with checks dropped
        kw["internal"], z2 = True, z1 + rng.randint(1, 120)
    rack = _rack(rng)
    kind = {k: kw[k] for k in ("beta_deg", "internal", "face_width_mm") if k in kw}

    def call():
        r = gd.optimize_shifts(z1, z2, rack=_make_rack(rack), **kw)
        recheck_shift_result(r, kw.get("m"), kw.get("checks"), _make_rack(rack), kind)
        return r
    return f"optimize_shifts({z1}, {z2}, rack={rack}, **{kw})", call


def _region(rng):
    z1, z2 = _pick(rng, lambda r: r.randint(5, 80), 0.1), _pick(rng, lambda r: r.randint(5, 200), 0.1)
    kw = {}
    if rng.random() < 0.3:
        kw["n"] = _pick(rng, [11, 41, 201, 10**5])
    if rng.random() < 0.3:
        kw["checks"] = _pick(rng, [{}, [], {"undercut": False, "interference": False}, {"sa_min": 0.26}])
    kw.update(_kind(rng))
    return f"feasible_region({z1}, {z2}, **{kw})", lambda: gd.feasible_region(z1, z2, **kw)


def _atlas(rng):
    z1 = _pick(rng, [range(10, 13), [17], 17, range(3, 100000)], 0.1)
    z2 = _pick(rng, [range(20, 23), [26, 40], 26], 0.1)
    obj = rng.choice(["max_x_sum", "balanced_sliding"])
    kind = _kind(rng)
    checks = rng.choice(_DROPPED) if rng.random() < 0.3 else None

    def call():
        df = gd.shift_atlas(z1, z2, objective=obj, checks=checks, **kind)
        names = [c[len("margin_"):] for c in df.columns if c.startswith("margin_")]
        for row in df[df["feasible"]].head(4).itertuples():
            recheck_pair(1.0, row.z1, row.z2, row.x1, row.x2, checks, None, "atlas row", names, **kind)
        return df
    return f"shift_atlas({z1}, {z2}, {obj}, checks={checks}, **{kind})", call


def _teeth(rng):
    kw = dict(ratio=_pick(rng, lambda r: round(r.uniform(1, 8), 3)),
              m=_pick(rng, [2, 3, 8, None, 0.2, 32.5] + _M_ENDS, 0.1))
    if rng.random() < 0.3:
        kw["ratio_tol"] = _pick(rng, [0.01, 0.05, 0.0, 2.0])
    if rng.random() < 0.3:
        kw["z1_range"] = _pick(rng, [(12, 20), (8, 40), (40, 8), (3, 100000)])
    elif rng.random() < 0.5:
        lo = rng.randint(8, 40)
        kw["z1_range"] = (lo, lo + rng.randint(0, 3))
    if rng.random() < 0.3:
        kw["checks"] = rng.choice(_DROPPED)
    kw.update(_kind(rng))

    def call():
        sel = gd.select_teeth(**kw)
        kind = {k: kw[k] for k in ("beta_deg", "internal", "face_width_mm") if k in kw}
        for _, row in sel.feasible.head(4).iterrows():     # rows marked feasible re-check as feasible
            names = [c[len("margin_"):] for c in sel.table.columns if c.startswith("margin_")]
            recheck_pair(float(row["module_mm"]), row["z1"], row["z2"], row["x1"], row["x2"], kw.get("checks"),
                         None, "row marked feasible", names, **kind)
        return sel
    return f"select_teeth(**{kw})", call


def _planetary_sizes(rng):
    """Tooth counts of a set: near-standard mostly, anything now and then."""
    z_s, z_p = _pick(rng, lambda r: r.randint(8, 60), 0.1), _pick(rng, lambda r: r.randint(8, 60), 0.1)
    if isinstance(z_s, int) and isinstance(z_p, int) and rng.random() < 0.8:
        z_r = z_s + 2 * z_p + rng.randint(-3, 3)
    else:
        z_r = _pick(rng, _z)
    return z_s, z_p, z_r, _pick(rng, [1, 3, 3, 4, 5, 7], 0.1)


def _planetary_set(rng):
    sizes = _planetary_sizes(rng)
    m = _pick(rng, _m)
    xs = [_pick(rng, _x) for _ in range(3)]
    kw = {}
    if rng.random() < 0.3:
        kw["beta_deg"] = _pick(rng, [10.0, 30.0, 50.0])
    if rng.random() < 0.2:
        kw["arrangement"] = _pick(rng, ["carrier_fixed", "sun_fixed", "ring_in"], 0.2)
    if rng.random() < 0.3:
        return (f"PlanetarySet.coaxial({m}, *{sizes}, {xs[0]}, {xs[1]}, **{kw})",
                lambda: gd.PlanetarySet.coaxial(m, *sizes, xs[0], xs[1], **kw).checks())
    return f"PlanetarySet({m}, *{sizes}, *{xs}, **{kw})", lambda: gd.PlanetarySet(m, *sizes, *xs, **kw).checks()


def _optimize_planetary(rng):
    sizes = _planetary_sizes(rng)
    kw = dict(m=_pick(rng, [1.0, 2.0, 1.75, 8.0], 0.1),
              objective=_pick(rng, [None, "max_x_sum", "max_eps_alpha", "balanced_sliding", "max_margin"], 0.1),
              method=_pick(rng, ["exact", "exact", "grid"], 0.05))
    if rng.random() < 0.25:
        plain = all(type(v) in (int, float) and abs(v) < 1e4 for v in (kw["m"], sizes[0], sizes[1]))
        half = (sizes[0] + sizes[1]) * kw["m"] / 2 if plain else 20.0
        kw["a_w"] = _pick(rng, lambda r: half * r.uniform(0.95, 1.1))
    if rng.random() < 0.35:
        kw["checks"] = _pick(rng, [{}, {"neighbour_clearance": 0.0}, {"neighbour_clearance": None},
                                   {"undercut": False}, {"bogus": 1}, [1]] + [d for d in _DROPPED if d != []])

    def call():
        r = gd.optimize_planetary_shifts(*sizes, **kw)
        if r.success:
            recheck_set(kw["m"], *sizes, r.x_sun, r.x_planet, r.x_ring, kw.get("checks"))
        return r
    return f"optimize_planetary_shifts(*{sizes}, **{kw})", call


def _planetary_teeth(rng):
    kw = dict(ratio=_pick(rng, lambda r: round(r.uniform(2.5, 9), 3)), n_planets=_pick(rng, [3, 4, 5], 0.1),
              m=_pick(rng, [2, 3, 1.5], 0.1))
    lo = rng.randint(12, 30)
    kw["z_sun_range"] = _pick(rng, [(lo, lo + rng.randint(0, 3)), (30, 12), (3, 1000)], 0.1)
    if rng.random() < 0.3:
        kw["ratio_tol"] = _pick(rng, [0.0, 0.01, 0.6])
    if rng.random() < 0.2:
        kw["arrangement"] = _pick(rng, ["carrier_fixed", "sun_fixed"])
    if rng.random() < 0.3:
        kw["checks"] = rng.choice([d for d in _DROPPED if d != []] + [{"neighbour_clearance": None}])

    def call():
        sel = gd.select_planetary_teeth(**kw)
        for _, row in sel.table[sel.table["feasible"]].head(3).iterrows():
            recheck_set(kw["m"], row["z_sun"], row["z_planet"], row["z_ring"], kw["n_planets"], row["x_sun"],
                        row["x_planet"], row["x_ring"], kw.get("checks"), what="row marked feasible",
                        arrangement=kw.get("arrangement", "ring_fixed"))
        return sel
    return f"select_planetary_teeth(**{kw})", call


def _drive(rng):
    """A linked drive: a given stage, a gear stage and a chain with keyed shafts, analysed or optimised."""
    power = _pick(rng, [2.0, 4.0, 7.5], 0.1)
    n_in = _pick(rng, [1410.0, 950.0, 2850.0], 0.1)
    ratio = _pick(rng, lambda r: round(r.uniform(2, 30), 2), 0.1)
    given = dict(ratio=_pick(rng, [2.0, 4.0, 12.5], 0.1), efficiency=_pick(rng, [0.87, 0.95], 0.1))
    gear = dict(m=_pick(rng, [2.0, 3.0, 4.0], 0.1))
    shaft = dict(d_mm=_pick(rng, [30.0, 40.0, 60.0], 0.1), hub_length_mm=_pick(rng, [50.0, 80.0], 0.1))
    kw = dict(total_ratio=ratio, ratio_tol=_pick(rng, [0.03, 0.05], 0.1),
              objective=_pick(rng, ["min_size", "min_mass", "max_margin"], 0.05))
    use_gear = rng.random() < 0.5

    def call():
        stages = [gd.GivenStage(**given, name="gear motor")]
        stages += [gd.GearStage(**gear)] if use_gear else []
        stages += [gd.ChainStage()]
        drive = gd.Drive(power_kw=power, n_in_rpm=n_in, stages=stages,
                         shafts=[gd.Shaft(**shaft, at=len(stages))])
        return drive.optimize(**kw)
    return f"Drive({power} kW, {n_in} rpm, {given}, gear={use_gear and gear}, {shaft}).optimize(**{kw})", call


def _margin_centres(rng):
    """Many tooth pairs' max_margin shifts at once (a max_margin drive's solver); every certified answer is
    re-checked as optimize_shifts' would be."""
    from geardesign.gears.checks import FEASIBILITY_TOL
    from geardesign.gears.mesh import Mesh
    from geardesign.shifts.centres import margin_centres
    from geardesign.shifts.problem import Problem

    n = rng.choice([1, 2, 7, 40])
    z1 = _pick(rng, lambda r: [_z(r) for _ in range(n)], 0.1)
    z2 = _pick(rng, lambda r: [_z(r) for _ in range(n if r.random() < 0.95 else n + 1)], 0.1)
    kw = dict(m=_pick(rng, _m, 0.1))
    if rng.random() < 0.4:
        kw["checks"] = _pick(rng, [{}, {"undercut": False}, {"sa_min": 0.4}, {"bogus": 1}] + _DROPPED)
    if rng.random() < 0.3:
        kw["beta_deg"] = _pick(rng, [8.0, 15.0, 30.0, 46.0], 0.2)
    if rng.random() < 0.15:
        kw["bounds"] = _pick(rng, [(-0.5, 1.0), (-1, 2), (0, 0), (3, -1)])

    def call():
        r = margin_centres(z1, z2, **kw)
        for i in np.flatnonzero(r["ok"]):
            prob = Problem(Mesh(int(z1[i]), int(z2[i]), beta_deg=kw.get("beta_deg", 0.0)), kw.get("checks"),
                           "max_margin", kw["m"])
            M = prob.margins(prob.geo(np.float64(r["x1"][i]), np.float64(r["x2"][i])))
            if (M < -FEASIBILITY_TOL).any():
                raise FailsChecks(f"pair {i}: margins {dict(zip(prob.names, M.tolist()))}")
        return {k: v for k, v in r.items() if k == "ok"}
    return f"margin_centres({z1}, {z2}, **{kw})", call


def _chain(rng):
    kw = dict(torque_nm=_pick(rng, lambda r: round(r.uniform(1, 2000), 2)),
              n1_rpm=_pick(rng, lambda r: round(r.uniform(20, 1500), 1)),
              ratio=_pick(rng, lambda r: round(r.uniform(1, 10), 3)),
              catalog=_pick(rng, ["gost13568", "iso606", "iso606a", "iso606b", "ansi_b29", "nope"], 0.05),
              method=_pick(rng, ["hinge_pressure", "power_rating"], 0.05))
    if rng.random() < 0.3:
        kw["strands"] = _pick(rng, [(1,), (1, 2, 3), (2, 3), (), (5,)])
    if rng.random() < 0.3:
        kw["center_distance_mm"] = _pick(rng, lambda r: r.choice([10, 12.35, 300, 1000, 1e300]))
    if rng.random() < 0.2:
        kw["z1"] = _pick(rng, [13, [13, 17], [], 7])
    return f"chain.design(**{kw})", lambda: gd.chain.design(**kw)


def _key(rng):
    d = _pick(rng, lambda r: r.choice([20, 35, 60, 90, 6.5, 500]))
    if rng.random() < 0.5:
        kw = dict(torque_nm=_pick(rng, lambda r: round(r.uniform(10, 3000), 1)),
                  hub_length_mm=_pick(rng, lambda r: r.choice([20, 50, 80, 5, 1e308])))
        return f"key.select({d}, **{kw})", lambda: gd.key.select(d, **kw)
    length = _pick(rng, lambda r: r.choice([20, 32, 56, 1e308]))
    return f"key.capacity({d}, {length})", lambda: gd.key.capacity(d, length)


_SCENE_SNIPPETS = [
    '[gear]\nmodule = {m}\nz1 = {z1}\nz2 = {z2}\n',
    '[gear]\nmodule = {m}\nz1 = {z1}\nz2 = {z2}\nx1 = {x1}\nx2 = {x2}\n',
    '[chain]\ntorque_nm = {t}\nn1_rpm = {n}\nratio = {u}\n',
    '[key]\nd_mm = {d}\ntorque_nm = {t}\nhub_length_mm = {h}\n',
    '[teeth]\nratio = {u}\nmodule = {m}\n',
    '[gear]\nmodule = 8\nz1 = 17\nz2 = 26\n[study]\nparameter = "eps_alpha_min"\nvalues = {vals}\n',
    'a = ' + '[' * 600 + ']' * 600 + '\n',
    '[gear]\nmodule = {big}\nz1 = 17\nz2 = 26\n',
    '[gear\nbroken',
    '[nonsense]\nq = 1\n',
]


def _toml(v) -> str:
    if isinstance(v, str):
        return '"' + v + '"'
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, float) and not math.isfinite(v):
        return "nan" if math.isnan(v) else ("inf" if v > 0 else "-inf")
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_toml(x) for x in v) + "]"
    if v is None or isinstance(v, dict):
        return '"none"'
    return repr(v)


def _scene(rng):
    text = rng.choice(_SCENE_SNIPPETS).format(
        m=_toml(_pick(rng, _m)), z1=_toml(_pick(rng, _z)), z2=_toml(_pick(rng, _z)), x1=_toml(_pick(rng, _x)),
        x2=_toml(_pick(rng, _x)), t=_toml(_pick(rng, [100, 380, 5000])), n=_toml(_pick(rng, [120, 720])),
        u=_toml(_pick(rng, [1, 2.5, 9.5])), d=_toml(_pick(rng, [30, 60])), h=_toml(_pick(rng, [40, 60])),
        vals=_toml(_pick(rng, [[1.1, 1.2, 1.3], list(range(20000)), []])), big="9" * 400)

    def call():
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "case.toml")
            with open(path, "w", encoding="utf-8") as fh:
                fh.write(text)
            out = os.path.join(tmp, "out")
            try:
                return gd.run_scene(path, out)
            finally:
                _no_temp_left(tmp, out)
    return f"run_scene({text[:120]!r})", call


class HalfWritten(Exception):
    pass


def _no_temp_left(folder, out):
    left = [f for f in os.listdir(folder) if f.startswith(".")]
    if left:
        raise HalfWritten(f"temporary files left behind: {left}")


_CLI = [
    lambda r: ["pair", "--module", str(_pick(r, _m)), "--z1", str(_pick(r, _z)), "--z2", str(_pick(r, _z)),
               "--x1", str(_pick(r, _x)), "--x2", str(_pick(r, _x))],
    lambda r: ["shift", "--z1", str(r.randint(5, 60)), "--z2", str(r.randint(5, 150))]
    + r.choice([[], ["--center-distance", str(r.uniform(10, 90))], ["--module", "2", "--center-distance",
                                                                   str(r.uniform(20, 150))]])
    + r.choice([[], ["--objective", "max_eps_alpha"], ["--method", "grid"], ["--allow-interference"]]),
    lambda r: ["chain", "--torque", str(_pick(r, [380, 9.97, 1e6])), "--n1", str(_pick(r, [120, 162.8])),
               "--ratio", str(_pick(r, [1, 8.67, 9.5, 11]))],
    lambda r: ["key", "--d", str(_pick(r, [60, 30, 5])), "--torque", "503", "--hub-length", str(_pick(r, [50, 10]))],
    lambda r: ["teeth", "--ratio", str(round(r.uniform(1, 6), 2)), "--module", "2"],
    lambda r: [r.choice(["shift", "teeth"]), "--internal", "--beta", str(r.choice([0, 12, 45, 60]))]
    + (["--z1", str(r.randint(5, 40)), "--z2", str(r.randint(5, 120))] if r.random() < 0.5 else
       ["--ratio", str(round(r.uniform(1, 6), 2)), "--module", "2"]),
    lambda r: ["atlas", "--z1", r.choice(["10:12", "3:100000", "17"]), "--z2", r.choice(["20:22", "26"])],
]


def _cli(rng):
    argv = rng.choice(_CLI)(rng)
    write = rng.random() < 0.3 and argv[0] in ("shift", "atlas", "teeth")

    def call():
        with tempfile.TemporaryDirectory() as tmp:
            args = list(argv)
            if write:
                suffix = ".png" if argv[0] == "shift" else ".csv"
                args += ["--plot" if argv[0] == "shift" else "--out", os.path.join(tmp, "o" + suffix)]
            out, err = io.StringIO(), io.StringIO()
            with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
                try:
                    code = cli_main(args)
                except SystemExit as exc:       # argparse's own usage errors
                    code = exc.code
            _no_temp_left(tmp, None)
            lines = err.getvalue().strip().splitlines()
            if code == 2 and len(lines) != 1:      # argparse's errors too: one line (issue 35 §7)
                raise AssertionError(f"exit 2 with {len(lines)} stderr lines: {err.getvalue()[:300]!r}")
            if code not in (0, 1, 2):
                raise AssertionError(f"exit {code}")
            if code in (0, 1) and ("nan" in out.getvalue().split() or " nan " in out.getvalue()):
                return float("nan")
            return code
    return f"geardesign {' '.join(argv)}" + (" (writing a file)" if write else ""), call


TARGETS = {
    "pair": _pair, "pair_geometry": _pair_geometry, "from_center_distance": _from_center_distance,
    "optimize_shifts": _optimize, "feasible_region": _region, "shift_atlas": _atlas, "select_teeth": _teeth,
    "chain": _chain, "key": _key, "scene": _scene, "cli": _cli,
    "planetary_set": _planetary_set, "optimize_planetary_shifts": _optimize_planetary,
    "select_planetary_teeth": _planetary_teeth, "drive": _drive, "margin_centres": _margin_centres,
}


def _surfaces():
    """The targets of tests/fuzzsurfaces.py (files, links, a command's outputs, Ctrl-C) and of
    tests/fuzzstrength.py (the load-capacity surfaces, ISO 6336) and of tests/fuzzmachines.py (the engine,
    spectra and life, worms, bearings, shafts, efficiency and their commands), added here
    so that one TARGETS lists every surface; imported late, as they use this module's helpers."""
    from tests.fuzzmachines import MACHINES
    from tests.fuzzstrength import STRENGTH
    from tests.fuzzsurfaces import SURFACES
    TARGETS.update(SURFACES)
    TARGETS.update(STRENGTH)
    TARGETS.update(MACHINES)


# --- judging a result -----------------------------------------------------------------------

# Geometry fields whose description says when they are NaN by design ("not applicable": a ring's
# undercut limit, ε_β without a face width); any other NaN is a fault.
NOT_APPLICABLE = frozenset(k for k, (_, text) in gd.GEOMETRY_FIELDS.items() if "NaN" in text)


def non_finite(obj, depth=0) -> str | None:
    """Where a NaN or inf hides in a result, or None."""
    if depth > 6:
        return None
    if isinstance(obj, (bool, np.bool_, str, type(None))):
        return None
    if isinstance(obj, (int, np.integer)):
        return None
    if isinstance(obj, (float, np.floating)):
        return None if math.isfinite(obj) else repr(obj)
    if isinstance(obj, np.ndarray):
        if obj.dtype.kind in "fc" and not np.isfinite(obj).all():
            return "array"
        return None
    if isinstance(obj, pd.DataFrame):
        return None       # tables carry 'not applicable' cells; their key figures are checked by value
    if isinstance(obj, pd.Series):
        return None
    if isinstance(obj, dict):
        for k, v in obj.items():
            w = non_finite(v, depth + 1)
            if w:
                return f"{k}: {w}"
        return None
    if isinstance(obj, (list, tuple)):
        for v in obj:
            w = non_finite(v, depth + 1)
            if w:
                return w
        return None
    if is_dataclass(obj):
        for f in fields(obj):
            # "_chain": a StrengthResult's raw chain dict (N_L is NaN for "no life given"; its figures are fields)
            if f.name in ("candidates", "problem", "table", "skipped", "blocking", "boundary", "_chain"):
                continue
            if isinstance(obj, gd.Geometry) and f.name in NOT_APPLICABLE:
                continue
            w = non_finite(getattr(obj, f.name), depth + 1)
            if w:
                return f"{f.name}: {w}"
        return None
    return None


def _result_problem(result) -> str | None:
    where = non_finite(result)
    if where:
        return where
    best = getattr(result, "best", None)    # a chain design: its chosen row's figures
    if isinstance(best, pd.Series):
        for k in ("center_distance_mm", "links", "speed_m_s", "force_n", "min_margin"):
            v = best.get(k)
            if v is not None and not (isinstance(v, (int, float, np.number)) and math.isfinite(v)):
                return f"best.{k}: {v!r}"
    return None


class _Timeout(Exception):
    pass


class LinkReplaced(Exception):
    """An output path that was a symlink is a symlink no more."""


def _warned(caught, desc):
    """("warning", ...) when a warning escaped the call, else None."""
    if caught:
        w = caught[0]
        return "warning", desc, f"{w.category.__name__}: {str(w.message)[:120]} ({len(caught)} in all)"
    return None


def _alarm(signum, frame):
    raise _Timeout()


def run_case(target: str, seed: int, time_limit_s: float = 30.0):
    """(outcome, description, detail) of one generated case."""
    rng = random.Random(seed * 7919 + zlib.crc32(target.encode()) % 1000)   # stable across processes
    desc, call = TARGETS[target](rng)
    old = signal.signal(signal.SIGALRM, _alarm)
    signal.setitimer(signal.ITIMER_REAL, time_limit_s)
    t0 = time.perf_counter()
    import warnings
    caught = []
    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            result = call()
        problem = _result_problem(result)
        if problem:
            return "nan_result", desc, problem
        return _warned(caught, desc) or ("ok", desc, "")
    except _Timeout:
        return "hang", desc, f"> {time_limit_s:g} s"
    except HalfWritten as exc:
        return "half_written", desc, str(exc)
    except LinkReplaced as exc:
        return "link_replaced", desc, str(exc)
    except FailsChecks as exc:
        return "fails_checks", desc, str(exc)
    except FeasibilityTol as exc:
        return "feasibility_tol", desc, str(exc)
    except gd.GearDesignError as exc:
        text = str(exc)
        if "\n" in text.strip():
            return "traceback", desc, f"multi-line error: {text[:200]!r}"
        return _warned(caught, desc) or ("clean_error", desc, text[:200])
    except Exception as exc:   # noqa: BLE001 - every other exception is what we count
        return "traceback", desc, f"{type(exc).__name__}: {str(exc)[:200]}"
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)
        _ = time.perf_counter() - t0


_surfaces()
