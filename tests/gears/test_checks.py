"""Checks: the analytic gradients of each check's smooth parts against central differences of
their margins on the float path (the property tests in tests/test_properties.py hold the whole
checks' gradients on the array path)."""
from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given

from geardesign.gears.checks import make_checks
from geardesign.gears.geometry import mesh_geometry_float
from geardesign.gears.mesh import Mesh

from tests.strategies import SETTINGS, designs


@pytest.mark.slow
@SETTINGS
@given(designs())
def test_part_gradients_match_central_differences(d):
    """Interference's two parts (above the limit point, above the base circle) are smooth."""
    m, rack, ts = d["m"], d["rack"], d["ts"]
    geo = mesh_geometry_float(Mesh(d["z1"], d["z2"], rack, ts), m, d["x1"], d["x2"])
    h = 1e-6
    for check in make_checks():
        an = np.array(check.part_gradients(geo), dtype=float)
        for j, (dx1, dx2) in enumerate(((h, 0.0), (0.0, h))):
            up = mesh_geometry_float(Mesh(d["z1"], d["z2"], rack, ts), m, d["x1"] + dx1, d["x2"] + dx2)
            dn = mesh_geometry_float(Mesh(d["z1"], d["z2"], rack, ts), m, d["x1"] - dx1, d["x2"] - dx2)
            fd = (np.array(check.part_margins(up)) - np.array(check.part_margins(dn))) / (2 * h)
            assert np.allclose(an[:, j], fd, rtol=1e-6, atol=1e-6), (check.name, j, an[:, j], fd)
