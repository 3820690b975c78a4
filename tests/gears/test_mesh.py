"""The Mesh object: tooth counts, rack and tip shortening, refused by name when wrong."""
import numpy as np
import pytest

from geardesign.errors import GearDesignError
from geardesign.gears.mesh import Mesh


def test_mesh_refuses_by_name_and_keeps_arrays():
    with pytest.raises(GearDesignError, match=r"z2 must be a whole number in \[3, 100000\], got 2"):
        Mesh(17, 2)
    with pytest.raises(GearDesignError, match="rack must be a geardesign.BasicRack"):
        Mesh(17, 26, rack="ISO 53")
    batch = Mesh(np.array([17, 20]), np.array([26, 40]))
    assert batch.is_batch and not Mesh(17, 26).is_batch
