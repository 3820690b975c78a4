"""The basic rack: a pressure angle or fillet radius outside its range raises GearDesignError naming it."""
import pytest

import geardesign as gd


@pytest.mark.parametrize("alpha", [0.0, 45.0, -5.0, float("nan")])
def test_bad_rack(alpha):
    with pytest.raises(gd.GearDesignError, match="alpha_deg"):
        gd.BasicRack(alpha_deg=alpha)


def test_bad_fillet():
    with pytest.raises(gd.GearDesignError, match=r"rho_f must be in \[0, 0\.47"):
        gd.BasicRack(rho_f=0.6)
