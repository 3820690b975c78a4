"""The drawing's data block (geardesign.gears.data_block): its rows are the measuring sizes, tolerances and mate."""
import pytest

import geardesign as gd
from geardesign.errors import GearDesignError
from geardesign.gears.data_block import data_block, data_block_lines
from geardesign.gears.tolerances import flank_tolerances


def test_rows_carry_the_sizes_of_the_gear_and_its_mate():
    pair = gd.GearPair(3, 12, 24, 0.6, 0.36)
    t = data_block(pair, 2, 7, thickness_allowance_mm=(-0.05, -0.1), center_distance_allowance_mm=(-0.02, 0.02))
    assert list(t.columns) == ["parameter", "symbol", "value", "unit"]
    v = t.set_index("symbol")["value"]
    m = pair.measurements(gear=2, thickness_allowance_mm=(-0.05, -0.1))
    assert v["z"] == "24" and v["z_mate"] == "12" and v["k"] == str(int(m.k))
    assert v["W_k"] == f"{m.w_k:.4f} ({m.w_k_max - m.w_k:+.4f} / {m.w_k_min - m.w_k:+.4f})"
    assert v["M_d"].startswith(f"{m.m_d:.4f} (") and v["D_M"] == f"{m.ball_mm:.4f}"
    assert v["f_pT"] == f"{flank_tolerances(3, 24, 7).f_pT:g}"
    assert v["a_w"] == f"{float(pair.geometry().a_w):.4f} (+0.0200 / -0.0200)"
    # W_k: the thinner tooth gives the smaller span, m cos(alpha) per mm of thickness
    assert m.w_k_min == pytest.approx(m.w_k - 0.1 * 0.9396926207859084, abs=1e-12)


def test_helical_ring_states_hand_and_the_ring_convention():
    pair = gd.GearPair(2, 20, 60, 0.3, 0.6, internal=True, beta_deg=10, face_width_mm=20)
    t = data_block(pair, 2, 6, helix_hand="left")
    text = "\n".join(data_block_lines(t))
    assert "left" in text and "between balls" in text and "GOST 19274" in text and "F_betaT" in text
    assert len(data_block_lines(t)) == len(t)


@pytest.mark.parametrize("kwargs, word", [
    (dict(gear=3), "gear"), (dict(gear=1, helix_hand="right"), "helix_hand"),
    (dict(gear=1, accuracy_class=12), "accuracy_class"), (dict(gear=1, accuracy_class=[1, 2]), "accuracy_class"),
    (dict(gear=True), "gear"), (dict(gear=1, ball_mm=(1,)), "ball_mm"),
    (dict(gear=1, center_distance_allowance_mm=0.02), "center_distance_allowance_mm"),
])
def test_errors(kwargs, word):
    with pytest.raises(GearDesignError, match=word):
        data_block(gd.GearPair(3, 12, 24, 0.6, 0.36), **kwargs)
