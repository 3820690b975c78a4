"""An infeasible pair names a conflicting set of checks, and that set alone admits no point."""
import numpy as np

import geardesign as gd
from geardesign import checks as ck
from geardesign.gears.geometry import mesh_geometry
from geardesign.gears.mesh import Mesh


def test_infeasible_pair_names_conflict():
    r = gd.optimize_shifts(5, 5, method="exact")
    assert not r.success
    assert r.conflict, r.message
    assert "conflict" in r.message
    # the named set really is infeasible on its own: no node of a fine grid satisfies it
    sub = [c for c in ck.make_checks() if c.name in r.conflict]
    g = np.linspace(-1.5, 3.0, 401)
    X1, X2 = np.meshgrid(g, g)
    geo = mesh_geometry(Mesh(5, 5, gd.BasicRack(), True), 1.0, X1, X2)
    ok = np.ones(X1.shape, bool)
    for c in sub:
        ok &= np.nan_to_num(c.margin(geo), nan=-1) >= 0
    assert not ok.any()
