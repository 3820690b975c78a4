"""Largest relative error of pair_geometry against the 50-digit mpmath reference over a grid
of z (5 .. 10 000), x (-1 .. 3) and α (10° .. 35°), as a map (z against x, worst over α and
over every geometry field). Error of a field: |value − ref| / max(|ref|, its natural scale).

Writes studies/out/extremes.csv and extremes.png.
"""
import sys
import time
from pathlib import Path

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import pandas as pd

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))            # run from a checkout
sys.path.insert(0, str(HERE.parent / "tests"))
import geardesign as gd  # noqa: E402
from geardesign.errors import GearDesignError  # noqa: E402
from geardesign.gears.geometry import GEOMETRY_FIELDS  # noqa: E402
from reference_mp import field_scale, pair_reference  # noqa: E402

OUT = HERE / "out"
Z = np.unique(np.round(np.geomspace(5, 10000, 24)).astype(int))
X = np.linspace(-1.0, 3.0, 21)
ALPHA = (10.0, 14.5, 20.0, 25.0, 30.0, 35.0)


def main():
    OUT.mkdir(exist_ok=True)
    t0 = time.perf_counter()
    rows = []
    for alpha in ALPHA:
        rack = gd.BasicRack(alpha_deg=alpha, rho_f=min(0.38, 0.95 * gd.BasicRack(alpha_deg=alpha, rho_f=0).rho_f_max))
        for z in Z:
            for x in X:
                z2 = 2 * z                                    # gear 2 twice the size, x2 = x as well
                fields, reason = pair_reference(1.0, z, z2, x, x, alpha_deg=alpha, rho_f=rack.rho_f)
                if fields is None:
                    rows.append({"alpha_deg": alpha, "z1": z, "x": x, "exists": False, "max_rel_error": np.nan,
                                 "field": reason})
                    continue
                try:
                    geo = gd.pair_geometry(1.0, z, z2, x, x, rack=rack)
                except GearDesignError as exc:
                    rows.append({"alpha_deg": alpha, "z1": z, "x": x, "exists": True, "max_rel_error": np.inf,
                                 "field": f"raised: {exc}"})
                    continue
                worst, where = 0.0, ""
                for k in GEOMETRY_FIELDS:
                    r = float(fields[k])
                    e = abs(float(getattr(geo, k)) - r) / max(abs(r), field_scale(k, 1.0, alpha))
                    if e > worst:
                        worst, where = e, k
                rows.append({"alpha_deg": alpha, "z1": z, "x": x, "exists": True, "max_rel_error": worst,
                             "field": where})
    df = pd.DataFrame(rows)
    df.to_csv(OUT / "extremes.csv", index=False)
    ok = df[df["exists"]]
    piv = ok.groupby(["z1", "x"])["max_rel_error"].max().unstack("x")
    fig, ax = plt.subplots(figsize=(9, 5.5))
    im = ax.pcolormesh(piv.columns, np.arange(len(piv.index)), np.log10(np.maximum(piv.values, 1e-17)),
                       shading="nearest", cmap="magma", vmin=-17, vmax=-12)
    ax.set_yticks(np.arange(len(piv.index)), [str(z) for z in piv.index])
    fig.colorbar(im, ax=ax, label="log10 largest relative error (over α and all fields)")
    ax.set_xlabel("x1 = x2"); ax.set_ylabel("z1 (z2 = 2·z1)")
    ax.set_title("pair_geometry against a 50-digit mpmath reference (blank: geometry does not exist)")
    fig.savefig(OUT / "extremes.png", dpi=110, bbox_inches="tight")
    w = ok.loc[ok["max_rel_error"].idxmax()]
    print(f"{len(df)} designs ({len(ok)} exist) in {time.perf_counter() - t0:.1f} s")
    print(f"largest relative error {w['max_rel_error']:.3g} ({w['field']}) at z1 = {w['z1']}, x = {w['x']:.3g}, "
          f"alpha = {w['alpha_deg']:g} deg; median {ok['max_rel_error'].median():.3g}")
    print(f"raised although the reference exists: {int(np.isinf(ok['max_rel_error']).sum())}")


if __name__ == "__main__":
    main()
