"""The contact life factor Z_NT (geardesign.gears.strength.life): ISO 6336-2:2019 Table 2's points, the
log-log interpolation written out here, and ISO/TR 6336-30:2017 example 1's printed N_L and Z_NT
(tests/data/iso6336_tr30_example1.md)."""
import math
from pathlib import Path

import pandas as pd
import pytest

from geardesign.errors import GearDesignError
from geardesign.gears.strength.life import contact_life_curve, contact_life_factor, load_cycles

TR30 = pd.read_csv(Path(__file__).parents[2] / "data" / "iso6336_tr30_example1.csv").set_index("quantity")


def _printed(q):
    return float(TR30.loc[q, "value"]), float(TR30.loc[q, "rel_tol"])


def test_load_cycles_of_the_tr30_example():
    # pinion 17 teeth at 360 rpm, wheel 103 teeth, 50 000 h: N_L = 60 n L_h
    n1 = 360.0
    value, rel = _printed("N_L1")
    assert load_cycles(n1, 50_000) == pytest.approx(value, rel=rel)
    value, rel = _printed("N_L2")
    assert load_cycles(n1 * 17 / 103, 50_000) == pytest.approx(value, rel=rel)
    assert load_cycles(100.0, 1000.0, 3) == 60 * 100 * 1000 * 3     # a sun among three planets: three contacts


def test_z_nt_of_the_tr30_example():
    for q, n_l in (("Z_NT1", 1.08e9), ("Z_NT2", 1.783e8)):
        value, rel = _printed(q)
        assert float(contact_life_factor(n_l, "Eh")) == pytest.approx(value, rel=rel)   # the CSV says how many digits are printed


@pytest.mark.parametrize("kind, pitting, points", [
    ("Eh", False, ((1e5, 1.6), (5e7, 1.0), (1e10, 0.85))),
    ("St", True, ((6e5, 1.6), (1e7, 1.0), (1e9, 1.0), (1e10, 0.85))),
    ("NT", False, ((1e5, 1.3), (2e6, 1.0), (1e10, 0.85))),
    ("NV(nitrocar)", False, ((1e5, 1.1), (2e6, 1.0), (1e10, 0.85))),
])
def test_table_2_points_and_the_lines_between(kind, pitting, points):
    """ISO 6336-2:2019 Table 2: the static value below the first point, straight lines in log-log between
    the points, 0.85 at 10^10 (1.0 with optimum conditions)."""
    assert contact_life_curve(kind, pitting) == points
    for n, z in points:
        assert float(contact_life_factor(n, kind, pitting)) == pytest.approx(z, rel=1e-12)
    assert float(contact_life_factor(points[0][0] / 100, kind, pitting)) == pytest.approx(points[0][1], rel=1e-12)
    (n0, z0), (n1, z1) = points[0], points[1]
    mid = math.sqrt(n0 * n1)           # halfway in log N: the geometric mean of the two Z
    assert float(contact_life_factor(mid, kind, pitting)) == pytest.approx(math.sqrt(z0 * z1), rel=1e-12)
    assert float(contact_life_factor(1e10, kind, pitting, optimum=True)) == pytest.approx(1.0, rel=1e-12)


def test_an_unknown_kind_is_refused_by_name():
    with pytest.raises(GearDesignError, match="kind must be one of"):
        contact_life_curve("steel")
