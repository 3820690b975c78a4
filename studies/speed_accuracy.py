"""Speed against accuracy of every shift-optimisation method and tolerance, and of the geometry.

Error of a shift method: max |x − x_ref| over a sample of tooth pairs, where x_ref is an
independent brute-force optimum (nested zooming grids over the vectorised geometry, no solver:
``reference_optimum`` of tests/shifts/test_optimize.py), whose active contact-ratio boundary is then
confirmed by the 50-digit mpmath geometry of tests/reference_mp.py. Every method, ``exact``
included, is measured against it, so the plot shows what each really achieves (down to the
reference's own resolution, printed). Geometry: pair_geometry (vectorised, per design) and
GearPair (one design) timed; accuracy against the same 50-digit reference.
Writes studies/out/speed_accuracy.csv and speed_accuracy.png.
"""
import sys
import time
from pathlib import Path

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import pandas as pd

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # run from a checkout
import geardesign as gd  # noqa: E402
from geardesign.gears.geometry import GEOMETRY_FIELDS

HERE = Path(__file__).resolve().parent
OUT = HERE / "out"
sys.path.insert(0, str(HERE.parent / "tests"))
from reference_mp import pair_reference  # noqa: E402
from tests.shifts.test_optimize import reference_optimum  # noqa: E402

PAIRS = [(11, 30), (10, 40), (12, 30), (14, 60), (17, 26), (20, 50), (25, 25), (30, 90), (36, 100), (40, 120)]
CASES = [("grid", 0.05), ("grid", 0.01), ("grid", 0.002), ("convex", 1e-4), ("convex", 1e-7),
         ("exact", 1e-6), ("exact", 1e-9)]


def main():
    OUT.mkdir(exist_ok=True)
    ref = {}
    worst_ref = 0.0
    for p in PAIRS:
        x1, x2, score = reference_optimum(*p, lambda g: g["_x1"] + g["_x2"])
        # the brute-force point sits on the ε_α = 1.2 boundary: how far off it is, in 50 digits
        fields, _ = pair_reference(1.0, p[0], p[1], x1, x2)
        worst_ref = max(worst_ref, abs(float(fields["eps_alpha"]) - 1.2))
        ref[p] = type("Ref", (), {"x1": x1, "x2": x2, "fun": score})
    print(f"reference: brute-force optima; worst |eps_alpha - 1.2| at them (50 digits): {worst_ref:.1e}")
    gd.optimize_shifts(17, 26, method="convex")          # compile cvxpy once, outside the timing
    rows = []
    for method, tol in CASES:
        errs, ferrs, times = [], [], []
        for p in PAIRS:
            t0 = time.perf_counter()
            r = gd.optimize_shifts(*p, method=method, tol=tol)
            times.append(time.perf_counter() - t0)
            errs.append(max(abs(r.x1 - ref[p].x1), abs(r.x2 - ref[p].x2)))
            ferrs.append(abs(r.fun - ref[p].fun))
        rows.append({"what": "shifts", "method": method, "tol": tol, "time_ms": 1e3 * np.median(times),
                     "max_error": max(errs), "median_error": float(np.median(errs)),
                     "max_fun_error": max(ferrs)})
    # geometry: vectorised and one-at-a-time, error against mpmath on a random sample
    rng = np.random.default_rng(1)
    n = 300
    z1 = rng.integers(8, 200, n); z2 = z1 + rng.integers(0, 400, n)
    x1 = rng.uniform(-0.3, 1.0, n); x2 = rng.uniform(-0.3, 1.0, n)
    big = 1_000_000
    Z1, Z2 = np.resize(z1, big), np.resize(z2, big)
    X1, X2 = np.resize(x1, big), np.resize(x2, big)
    t0 = time.perf_counter(); gd.pair_geometry(1.0, Z1, Z2, X1, X2); tv = time.perf_counter() - t0
    t0 = time.perf_counter()
    for i in range(n):
        gd.GearPair(1.0, int(z1[i]), int(z2[i]), float(x1[i]), float(x2[i])).geometry()
    ts = (time.perf_counter() - t0) / n
    geo = gd.pair_geometry(1.0, z1, z2, x1, x2)
    worst = 0.0
    for i in range(n):
        fields, _ = pair_reference(1.0, z1[i], z2[i], x1[i], x2[i])
        if fields is None:
            continue
        for k in GEOMETRY_FIELDS:
            r = float(fields[k])
            worst = max(worst, abs(float(np.ravel(getattr(geo, k))[i]) - r) / max(abs(r), 1.0))
    rows.append({"what": "geometry", "method": "pair_geometry (vectorised, 1e6 designs)", "tol": np.nan,
                 "time_ms": 1e3 * tv / big, "max_error": worst, "median_error": np.nan})
    rows.append({"what": "geometry", "method": "GearPair (one design)", "tol": np.nan, "time_ms": 1e3 * ts,
                 "max_error": worst, "median_error": np.nan})
    df = pd.DataFrame(rows)
    df.to_csv(OUT / "speed_accuracy.csv", index=False)

    fig, ax = plt.subplots(figsize=(7.5, 5.2))
    for j, (method, g) in enumerate(df.groupby("method", sort=False)):
        line, = ax.loglog(g["time_ms"], np.maximum(g["max_error"], 1e-17), "o-", label=f"{method}: max")
        med = g["median_error"].to_numpy(dtype=float)
        if np.isfinite(med).any():
            ax.loglog(g["time_ms"], np.maximum(med, 1e-17), "s--", mfc="none", color=line.get_color(), lw=0.8,
                      label=f"{method}: median")
        for k, r in enumerate(g.itertuples()):
            if np.isfinite(r.tol):
                ax.annotate(f"tol {r.tol:g}", (r.time_ms, max(r.max_error, 1e-17)), fontsize=7,
                            textcoords="offset points", xytext=(5, 6 + 9 * (k % 2) - 18 * (j == 2)))
    ax.set_xlabel("time per call [ms] (median; geometry: per design)")
    ax.set_ylabel("max error (shifts: |x − x_ref|, brute force; geometry: relative vs mpmath)")
    ax.set_title("Speed against accuracy")
    ax.legend(fontsize=7)
    fig.savefig(OUT / "speed_accuracy.png", dpi=110, bbox_inches="tight")
    with pd.option_context("display.width", 140):
        print(df.to_string(index=False, float_format=lambda v: f"{v:.3g}"))


if __name__ == "__main__":
    main()
