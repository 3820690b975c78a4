"""Geometry at the extremes against the independent 50-digit mpmath reference (tests/reference_mp.py).

Issue #2 ("Extremes against an mpmath reference written in the tests"): z from 5 to 10 000,
x from −1 to +3, α from 10° to 35°, tips near the base circle, near-pointed teeth; every
field of GEOMETRY_FIELDS to 1e-12 relative, or absolute 1e-12·(natural scale) where the
value is near zero (scales in reference_mp.FIELD_SCALE). Designs whose geometry does not
exist (per the reference: inv α_w <= 0, tip inside the base circle, d_f <= 0) are left out
of the grid and must make geardesign raise GearDesignError instead.

The involute function and its inverse: tests/gears/test_involute.py.
"""
from __future__ import annotations

import itertools
import math
from collections import defaultdict
from functools import lru_cache

import mpmath as mp
import numpy as np
import pytest

import geardesign as gd
from tests import reference_mp as ref

RTOL = 1e-12

Z = [5, 6, 8, 12, 17, 40, 150, 1000, 10000]
X = [-1.0, -0.5, 0.0, 0.35, 1.0, 2.0, 3.0]
ALPHA = [10.0, 14.5, 20.0, 25.0, 30.0, 35.0]
MODULES = [0.5, 1.0, 8.0, 25.0]
# (ha, c, rho_f): the standard rack, a stub rack, a sharp-cornered rack, a long-addendum rack
RACKS = [(1.0, 0.25, 0.38), (0.8, 0.3, 0.2), (1.0, 0.25, 0.0), (1.25, 0.2, 0.1)]


def _rho_f_max(alpha_deg, ha, c):
    """Largest fillet radius coefficient that fits on the cutter tip (0 if the tip land is pointed)."""
    a = math.radians(alpha_deg)
    land = math.pi / 2 - 2.0 * (ha + c) * math.tan(a)
    return max(0.0, land * math.cos(a) / (2.0 * (1.0 - math.sin(a))))


def _fit_rack(d):
    """Cap ρ_f* so that the rack exists at steep α (the cutter's tip land shrinks)."""
    d["rho_f"] = min(d["rho_f"], math.floor(_rho_f_max(d["alpha_deg"], d["ha"], d["c"]) * 1e6) / 1e6)
    return d


def _rack(alpha_deg, ha, c, rho_f):
    return gd.BasicRack(alpha_deg=alpha_deg, ha=ha, c=c, rho_f=rho_f)


# --- grid construction (plain Python + the reference; no geardesign numbers) ----------------

def _structured():
    """Every z pair at the x corners for three pressure angles, both tip rules."""
    out = []
    corners = [(-1.0, -1.0), (-1.0, 3.0), (3.0, -1.0), (3.0, 3.0), (0.0, 0.0), (-0.5, 1.0)]
    for alpha_deg, (z1, z2), (x1, x2) in itertools.product((10.0, 20.0, 35.0), itertools.product(Z, Z), corners):
        ts = (z1 + z2 + int(x1 * 2)) % 2 == 0
        out.append(_fit_rack(dict(m=8.0, z1=z1, z2=z2, x1=x1, x2=x2, alpha_deg=alpha_deg,
                                  ha=1.0, c=0.25, rho_f=0.38, ts=ts)))
    return out


def _random(n=1500, seed=20240531):
    """A reproducible random sample of the whole product space."""
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(n):
        ha, c, rho_f = RACKS[rng.integers(len(RACKS))]
        xs = rng.choice(X, 2) if rng.random() < 0.5 else rng.uniform(-1.0, 3.0, 2)
        out.append(_fit_rack(dict(m=float(rng.choice(MODULES)), z1=int(rng.choice(Z)), z2=int(rng.choice(Z)),
                                  x1=float(xs[0]), x2=float(xs[1]), alpha_deg=float(rng.choice(ALPHA)),
                                  ha=ha, c=c, rho_f=rho_f, ts=bool(rng.random() < 0.7))))
    return out


def _solve_x1(d, target):
    """x1 (a double) with target(x1) = 0 for the design d (mpmath findroot on the reference)."""
    def f(x1):
        fields, _ = ref.pair_reference(d["m"], d["z1"], d["z2"], x1, d["x2"], d["alpha_deg"],
                                       d["ha"], d["c"], d["rho_f"], d["ts"])
        return target(fields)
    # the reference rounds x1 to a double, so f is flat below 1 ulp: no verification by findroot,
    # but the root must hold to the double rounding of x1 (|f| < 1e-12 in units of m)
    try:
        x1 = float(mp.findroot(f, mp.mpf(d["x1"]), verify=False))
        ok = abs(f(x1)) < 1e-12 * d["m"]
    except (ValueError, TypeError, ZeroDivisionError):
        return None
    return x1 if ok else None


def _near_base_tip():
    """Tip of gear 1 only 1e-3·m above its base circle: r_a1 − r_b1 = 1e-3·m.

    Without shortening x1 = 1e-3 − h_a* − z1(1 − cos α)/2 in closed form; with shortening Δy
    depends on x1, so solve with findroot on the reference. Only designs whose root circle
    stays positive exist (z1 ≳ 4.5/cos α).
    """
    out = []
    for alpha_deg, z1, (z2, x2), ts in itertools.product(
            ALPHA, (5, 6, 8, 12, 17, 40), ((5, 0.0), (17, 1.0), (40, 3.0), (1000, 0.5), (10000, -1.0)),
            (True, False)):
        d = _fit_rack(dict(m=2.0, z1=z1, z2=z2, x2=x2, alpha_deg=alpha_deg, ha=1.0, c=0.25, rho_f=0.38, ts=ts))
        a = mp.mpf(math.radians(alpha_deg))
        d["x1"] = float(mp.mpf("1e-3") - 1 - z1 * (1 - mp.cos(a)) / 2)
        if ts:
            def target(f):
                return mp.mpf(1e3) if f is None else (f["da1"] - f["db1"]) / 2 - mp.mpf("1e-3") * d["m"]
            x1 = _solve_x1(d, target)
            if x1 is None:
                continue
            d["x1"] = x1
        out.append(d)
        # the mirror case: gear 2's tip near its base circle
        out.append(dict(d, z1=d["z2"], z2=d["z1"], x1=d["x2"], x2=d["x1"]))
    return out


def _near_pointed():
    """Near-pointed teeth of gear 1: s_a1 = 0 (to double rounding of x1) and s_a1 = 1e-3·m."""
    out = []
    for alpha_deg, z1, (z2, x2), ts, sa in itertools.product(
            (10.0, 20.0, 35.0), (5, 8, 17, 40, 150), ((12, 0.0), (150, 1.0), (10000, -0.5)),
            (True, False), ("0", "1e-3")):
        d = _fit_rack(dict(m=4.0, z1=z1, z2=z2, x2=x2, alpha_deg=alpha_deg, ha=1.0, c=0.25, rho_f=0.38, ts=ts))
        # start: the pointed-tip shift grows with z1 (≈ 0.6 at z 5, 20°)
        d["x1"] = 0.5 + 0.05 * z1 * (20.0 / alpha_deg) ** 2

        def target(f, sa=sa, d=d):
            return mp.mpf(-1) if f is None else f["sa1"] - mp.mpf(sa) * d["m"]
        x1 = _solve_x1(d, target)
        if x1 is None or not (-1.0 <= x1 <= 6.0):
            continue
        d["x1"] = x1
        out.append(d)
        out.append(dict(d, z1=d["z2"], z2=d["z1"], x1=d["x2"], x2=d["x1"]))   # gear 2 pointed
    return out


@lru_cache(maxsize=None)
def grid():
    """(valid, invalid) designs; each valid one carries its reference fields (mpmath)."""
    designs = _structured() + _random() + _near_base_tip() + _near_pointed()
    valid, invalid = [], []
    for d in designs:
        fields, reason = ref.pair_reference(d["m"], d["z1"], d["z2"], d["x1"], d["x2"], d["alpha_deg"],
                                            d["ha"], d["c"], d["rho_f"], d["ts"])
        if fields is None:
            invalid.append(dict(d, reason=reason))
        else:
            valid.append(dict(d, ref=fields))
    return valid, invalid


def _groups(designs):
    """Designs grouped by (rack, tip rule): one vectorised pair_geometry call per group."""
    g = defaultdict(list)
    for d in designs:
        g[(d["alpha_deg"], d["ha"], d["c"], d["rho_f"], d["ts"])].append(d)
    return g


def _conditioning(name, r):
    """How much the problem itself amplifies a one-ulp change of its inputs, where that exceeds
    what 1e-12 can absorb. Specific sliding at a root divides by ρ_p, which is a difference of
    two lengths of size r_b tan α_w: one ulp of x moves ρ_p by ~ε·r_b tan α_w, so the sliding
    there is only defined to ~ε·r_b tan α_w/|ρ_p| relative (z = 5/6 at α = 10° puts ρ_p at
    1.5e-4·m). Everywhere else this factor is 1."""
    if name in ("sliding1_root", "sliding2_root"):
        j = name[7]
        big = r[f"db{j}"] / 2 * mp.tan(mp.radians(r["alpha_w_deg"]))
        return max(1.0, float(16 * mp.mpf(2) ** -52 * big / abs(r[f"rho_p{j}"]) / mp.mpf(RTOL)))
    return 1.0


def compare(valid):
    """Per field: worst error relative to max(|reference|, scale) and the design where it occurs."""
    worst = {name: (0.0, None) for name in gd.GEOMETRY_FIELDS}
    for (alpha_deg, ha, c, rho_f, ts), ds in _groups(valid).items():
        cols = {k: np.array([d[k] for d in ds]) for k in ("m", "z1", "z2", "x1", "x2")}
        geo = gd.pair_geometry(cols["m"], cols["z1"], cols["z2"], cols["x1"], cols["x2"],
                               rack=_rack(alpha_deg, ha, c, rho_f), tip_shortening=ts)
        for name in gd.GEOMETRY_FIELDS:
            ours = np.asarray(getattr(geo, name))
            assert ours.shape == (len(ds),), name
            for i, d in enumerate(ds):
                r = d["ref"][name]
                scale = max(abs(float(r)), ref.field_scale(name, d["m"], alpha_deg))
                err = float(abs(mp.mpf(float(ours[i])) - r)) / scale if scale > 0 else abs(float(ours[i]))
                err /= _conditioning(name, d["ref"])
                if not err <= worst[name][0]:      # also catches NaN
                    worst[name] = (err, dict({k: d[k] for k in d if k != "ref"}, ours=float(ours[i]),
                                             reference=mp.nstr(r, 20)))
    return worst


@pytest.mark.slow
def test_grid_covers_the_extremes():
    valid, invalid = grid()
    assert 2000 <= len(valid) + len(invalid) <= 5000
    z_seen = {d["z1"] for d in valid} | {d["z2"] for d in valid}
    assert set(Z) <= z_seen
    assert {d["alpha_deg"] for d in valid} == set(ALPHA)
    assert min(d["x1"] for d in valid) <= -1.0 and max(d["x1"] for d in valid) >= 3.0
    # the deliberate cases made it into the grid
    near_base = [d for d in valid if (d["ref"]["da1"] - d["ref"]["db1"]) / 2 < 2e-3 * d["m"]]
    assert len(near_base) >= 40
    pointed = [d for d in valid if abs(d["ref"]["sa1"]) < 2e-3 * d["m"]]
    assert len(pointed) >= 40
    assert {d["reason"] for d in invalid} >= {"inv_alpha_w <= 0", "d_f1 <= 0", "tip1 inside base circle"}


@pytest.mark.parametrize("name", list(gd.GEOMETRY_FIELDS))
def test_field_matches_reference(name, worst_errors):
    err, where = worst_errors[name]
    assert err <= RTOL, f"{name}: error {err:.3g} (relative to max(|ref|, scale)) at {where}"


@pytest.fixture(scope="module")
def worst_errors():
    valid, _ = grid()
    return compare(valid)


def test_nonexistent_geometry_raises():
    """Exactly the designs the reference rejects raise GearDesignError (one by one)."""
    valid, invalid = grid()
    assert len(invalid) >= 100
    for d in invalid:
        with pytest.raises(gd.GearDesignError):
            gd.pair_geometry(d["m"], d["z1"], d["z2"], d["x1"], d["x2"],
                             rack=_rack(d["alpha_deg"], d["ha"], d["c"], d["rho_f"]), tip_shortening=d["ts"])
    # and a whole group with one bad design in it raises too
    d = invalid[0]
    good = [v for v in valid if (v["alpha_deg"], v["ha"], v["c"], v["rho_f"], v["ts"]) ==
            (d["alpha_deg"], d["ha"], d["c"], d["rho_f"], d["ts"])][:20] + [d]
    with pytest.raises(gd.GearDesignError):
        gd.pair_geometry(*(np.array([v[k] for v in good]) for k in ("m", "z1", "z2", "x1", "x2")),
                         rack=_rack(d["alpha_deg"], d["ha"], d["c"], d["rho_f"]), tip_shortening=d["ts"])


# --- focused cases: one design per cancellation found by the grid ------------------------------
# Each names the formula that cancels; the reference is the 50-digit one above.

def _check_fields(names, m, z1, z2, x1, x2, alpha_deg=20.0, ha=1.0, c=0.25, rho_f=0.38, ts=True):
    fields, _ = ref.pair_reference(m, z1, z2, x1, x2, alpha_deg, ha, c, rho_f, ts)
    geo = gd.pair_geometry(m, z1, z2, x1, x2, rack=_rack(alpha_deg, ha, c, rho_f), tip_shortening=ts)
    bad = {}
    for name in names:
        r = fields[name]
        scale = max(abs(float(r)), ref.field_scale(name, m, alpha_deg))
        err = float(abs(mp.mpf(getattr(geo, name)) - r)) / scale
        if not err <= RTOL:
            bad[name] = (getattr(geo, name), mp.nstr(r, 20), f"{err:.2g}")
    assert not bad, bad


def test_cancellation_y_from_operating_angle_at_large_z():
    """y = z_Σ sin((α_w+α)/2) sin((α_w−α)/2)/cos α_w takes α_w − α as a difference of two
    angles (absolute error ~1 ulp of α_w), so y carries an absolute error ~z_Σ·ε and Δy, the
    shortened tips and s_a inherit it. Solve for Δt = tan α_w − tan α directly instead."""
    _check_fields(["y", "dy", "da1", "sa1"], 8.0, 10000, 10000, 3.0, 3.0, alpha_deg=35.0, rho_f=0.0)


def test_cancellation_near_base_tip_with_huge_mate():
    """Tip of gear 1 1e-3·m above its base circle with a 10 000-tooth mate: the gap
    m(z sin²(α/2) + h_a* + x − Δy) inherits Δy's z_Σ·ε error, relative 1e-9 on the gap."""
    fields = ["alpha_a1_deg", "sa1", "eps_alpha", "g_alpha", "sliding1_tip"]
    d = dict(m=2.0, z1=40, z2=10000, x1=-3.67, x2=-1.0, alpha_deg=30.0, ha=1.0, c=0.25, rho_f=0.110349, ts=True)
    x1 = _solve_x1(d, lambda f: (f["da1"] - f["db1"]) / 2 - mp.mpf("1e-3") * d["m"])
    assert x1 is not None
    _check_fields(fields, 2.0, 40, 10000, x1, -1.0, alpha_deg=30.0, rho_f=0.110349)


def test_cancellation_path_of_contact_with_huge_mate():
    """ρ_p1 = a_w sin α_w − ρ_a2 and g_α = ρ_a1 + ρ_a2 − a_w sin α_w subtract numbers of size
    r_b2 tan α_w ~ m·z2; ρ_p1 small (near interference) then loses ~log10(z2) digits and the
    specific sliding 1 − ρ_a2/(u ρ_p1) with it."""
    _check_fields(["rho_p1", "g_alpha", "sliding1_root", "sliding2_tip"], 8.0, 17, 10000, 0.0, 0.0, ts=False)


def test_cancellation_clearance_at_large_z():
    """clearance = a_w − r_a1 − r_f2 subtracts numbers of size a_w ~ m·z_Σ/2; exactly it is
    m(c* + k − Δy) (k = Δy with shortening, 0 without)."""
    _check_fields(["clearance1", "clearance2"], 0.5, 10000, 10000, 2.11360430397952, 0.8005205826672905,
                  ts=False)
