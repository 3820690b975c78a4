"""The specific sliding's gradient in the shifts (geardesign.gears.checks.gradients) against central differences
of the geometry's own ϑ at the root, computed here, for external and internal pairs."""
import pytest

from geardesign.gears.checks.gradients import sliding_root_gradient
from geardesign.gears.geometry import mesh_geometry_float
from geardesign.gears.mesh import Mesh

H = 1e-6


@pytest.mark.parametrize("z1, z2, x1, x2, internal, beta", [
    (17, 26, 0.3, 0.2, False, 0.0), (12, 24, 0.6, 0.36, False, 0.0), (20, 60, 0.1, -0.2, False, 15.0),
    (20, 60, 0.3, 0.6, True, 0.0), (17, 71, 0.5, 0.8, True, 12.0),
])
def test_sliding_root_gradient_is_the_central_difference(z1, z2, x1, x2, internal, beta):
    mesh = Mesh(z1, z2, beta_deg=beta, internal=internal)
    geo = mesh_geometry_float(mesh, 3.0, x1, x2)
    for gear in (1, 2):
        key = f"sliding{gear}_root"
        d1 = (mesh_geometry_float(mesh, 3.0, x1 + H, x2)[key] - mesh_geometry_float(mesh, 3.0, x1 - H, x2)[key]) / (2 * H)
        d2 = (mesh_geometry_float(mesh, 3.0, x1, x2 + H)[key] - mesh_geometry_float(mesh, 3.0, x1, x2 - H)[key]) / (2 * H)
        g1, g2 = sliding_root_gradient(geo, gear)
        assert g1 == pytest.approx(d1, rel=1e-6, abs=1e-8)
        assert g2 == pytest.approx(d2, rel=1e-6, abs=1e-8)
