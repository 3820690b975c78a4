"""The strength model's defaults (geardesign.gears.strength.defaults): each inside its own range, and the ones a
call leaves out are the ones the chain uses (a default is written in one place only)."""
import inspect

import pytest

from geardesign.errors import GearDesignError
from geardesign.gears.strength import Load, chain, pair_strength
from geardesign.gears.strength import defaults as d
from geardesign.gears.strength.options import StrengthOptions


def test_each_default_is_inside_its_range():
    assert d.RZ_RANGE_UM[0] <= d.RZ_FLANK_UM <= d.RZ_RANGE_UM[1]
    assert d.RZ_RANGE_UM[0] <= d.RZ_ROOT_UM <= d.RZ_ROOT_MAX_UM
    assert d.NU40_RANGE[0] <= d.NU40_MM2_S <= d.NU40_RANGE[1]
    assert d.K_GAMMA_RANGE[0] == 1.0          # ideal load sharing is the lowest K_γ (ISO 6336-1:2019 6.4)
    assert 0 <= d.ACCURACY_GRADE <= 12         # an ISO 1328-1:1995 grade
    assert "no value" in d.MIN_SAFETY_SOURCE   # ISO 6336-1 leaves S_Hmin, S_Fmin to agreement: said so


def test_the_chain_uses_these_defaults():
    # the options' defaults: StrengthOptions' fields (pair_strength's options=, DEFAULT_OPTIONS without it)
    sig = inspect.signature(StrengthOptions).parameters
    assert chain.DEFAULT_OPTIONS == StrengthOptions()
    assert sig["S_Hmin"].default == d.S_HMIN and sig["S_Fmin"].default == d.S_FMIN
    assert sig["nu40"].default == d.NU40_MM2_S and sig["accuracy_grade"].default == d.ACCURACY_GRADE
    assert sig["Rz_flank_um"].default == d.RZ_FLANK_UM and sig["Rz_root_um"].default == d.RZ_ROOT_UM
    out = pair_strength(3, 20, 40, 0.0, 0.0, load=Load(torque_nm=100, n_rpm=1000), material1="42CrMo4",
                        face_width_mm=30)
    assert float(out["S_Hmin"]) == d.S_HMIN and float(out["S_Fmin"]) == d.S_FMIN


@pytest.mark.parametrize("kw, words", [
    (dict(Rz_root_um=d.RZ_ROOT_MAX_UM + 1), "Rz_root_um"),     # beyond the end of the Y_RrelT curves
    (dict(Rz_flank_um=d.RZ_RANGE_UM[1] * 2), "Rz_flank_um"),
    (dict(K_gamma=d.K_GAMMA_RANGE[1] + 0.5), "K_gamma"),
    (dict(nu40=d.NU40_RANGE[1] * 2), "nu40"),
])
def test_outside_a_range_is_refused_by_name(kw, words):
    with pytest.raises(GearDesignError, match=words):
        pair_strength(3, 20, 40, 0.0, 0.0, load=Load(torque_nm=100, n_rpm=1000), material1="42CrMo4",
                      face_width_mm=30, **kw)
