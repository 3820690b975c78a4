"""Internal-mesh conditions (geardesign/gears/ring.py) against KHK's published tables (SDP/SI D785
§5.2, tests/data/internal_helical_examples.csv, docs/research/internal_helical.md):

* Table 5-3a/5-3b — the smallest ring a shaper cutter of z0 teeth can cut without trimming
  (x0 = x2 = 0, and the shifted cutter x0 = 0.0075 z0 + 0.05): every printed z2 is the first ring
  whose cutter_trimming margin is >= 0;
* Table 5-4 — eight pairs z1/50 with differences 1…8 made to work by x2: KHK states every one is free
  of tip (trochoid) interference and needs axial assembly (trimming fails); the margins equal an
  independent 50-digit recomputation (the research note's script) to 1e-9.
"""
import math
from pathlib import Path

import pandas as pd
import pytest

import geardesign as gd
from geardesign.gears.checks import make_checks
from geardesign.gears.geometry import mesh_geometry
from geardesign.gears.ring import ShaperCutter, cutting_mesh

DATA = pd.read_csv(Path(__file__).parents[1] / "data" / "internal_helical_examples.csv")


def _first_ring(z0, x0):
    cutter = ShaperCutter(z0=z0, x0=x0)
    for z2 in range(z0 + 1, z0 + 200):
        r_a2 = (z2 - 2.0) / 2.0            # m = 1, x2 = 0: d_a2 = d2 − 2 h_a* m
        if cutting_mesh(1.0, z2, 0.0, r_a2, cutter, math.radians(20.0), math.tan(math.radians(20.0)))[4] >= 0:
            return z2
    return None


@pytest.mark.parametrize("row", [r for r in DATA[DATA.parameter == "z2_min_trimming"].itertuples()],
                         ids=lambda r: r.example_id)
def test_smallest_ring_per_cutter_of_khk_table_5_3(row):
    assert _first_ring(int(row.z1), float(row.x1)) == int(float(row.published_value))


def _geo(r):
    mesh = gd.Mesh(int(r.z1), int(r.z2), internal=True, tip_shortening=False)
    return mesh_geometry(mesh, float(r.m), float(r.x1), float(r.x2))


@pytest.mark.parametrize("row", [r for r in DATA[DATA.parameter == "trochoid_margin"].itertuples()
                                 if r.example_id.startswith(("I54", "E3"))], ids=lambda r: r.example_id)
def test_tip_interference_of_khk_table_5_4_and_e3(row):
    checks = {c.name: c for c in make_checks(internal=True, radial_assembly=True)}
    geo = _geo(row)
    margin = float(checks["tip_interference"].margin(geo))
    assert margin >= 0                                          # KHK: no trochoid interference
    assert margin == pytest.approx(float(row.recomputed_value), abs=1e-9)
    trim = DATA[(DATA.example_id == row.example_id) & (DATA.parameter == "trimming_margin")].recomputed_value
    radial = float(checks["radial_assembly"].margin(geo))
    if row.example_id.startswith("I54"):                        # KHK: these must be assembled axially
        assert not radial >= 0
    if not trim.isna().all():
        assert radial == pytest.approx(float(trim.iloc[0]), abs=1e-9)


def test_default_cutter_and_its_refusals():
    assert ShaperCutter().teeth(4.0, 90) == 25 and ShaperCutter().teeth(4.0, 30) == 12
    with pytest.raises(gd.GearDesignError, match=r"x0 must be in \[-1, 1\]"):
        ShaperCutter(x0=3.0)
    with pytest.raises(gd.GearDesignError, match="z0 must be a whole number"):
        ShaperCutter(z0=2)
    # a cutter as large as the ring cannot cut it: the margin fails (NaN), it does not raise
    checks = {c.name: c for c in make_checks(internal=True, cutter=ShaperCutter(z0=60))}
    geo = mesh_geometry(gd.Mesh(20, 60, internal=True), 2.0, 0.0, 0.5)
    assert not float(checks["cutter_trimming"].margin(geo)) >= 0
