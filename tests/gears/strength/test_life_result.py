"""LifeResult: the verdict, the per-bin table, its dict/JSON and the S-N plot (a PNG written whole or not at all)."""
from __future__ import annotations

import json

import numpy as np

import pytest

import geardesign as gd
from geardesign.errors import GearDesignError
from geardesign.gears.strength.life_result import LifeResult, service_life

PAIR = gd.GearPair(4, 20, 60, 0.3, 0.1, face_width_mm=40)
SPEC = gd.LoadSpectrum.from_bins([300.0, 150.0, 0.0], 1000, share=[0.2, 0.7, 0.1], duration_h=20000)


def test_result_reads_like_the_chain_dict():
    r = PAIR.life(SPEC, "42CrMo4")
    assert isinstance(r, LifeResult) and r.required_life_h == 20000.0
    assert r.ok is all(getattr(r, "D_" + m) <= 1 for m in ("H1", "H2", "F1", "F2"))
    mode, D = r.governing
    assert D == max(r.D_H1, r.D_H2, r.D_F1, r.D_F2) and mode in ("H1", "H2", "F1", "F2")
    b = r.bins
    assert len(b) == 2                                   # the bin of no torque does no damage
    for col in ("torque_nm", "n_rpm", "time_h", "n1", "n2", "K_v", "K_Hbeta", "K_Halpha", "sigma_H1", "N_H1", "D_F2"):
        assert col in b.columns
    # the bins' damages sum to the Miner sums (every tooth alike, one flank)
    for m in ("H1", "H2", "F1", "F2"):
        assert b["D_" + m].sum() == pytest.approx(getattr(r, "D_" + m), rel=1e-12, abs=1e-300)
    text = repr(r)
    assert "pitting, gear 1" in text and "<array" not in text and len(text.splitlines()) <= 6
    d = json.loads(r.to_json())
    assert d["ok"] is r.ok and isinstance(d["bins"], list) and d["status"] in ("success", "failed")
    assert "<pre>" in r._repr_html_()


def test_material_and_width_are_needed():
    with pytest.raises(GearDesignError, match="material is needed"):
        service_life(PAIR, SPEC)
    with pytest.raises(GearDesignError, match="face_width_mm is needed"):
        service_life(gd.GearPair(4, 20, 60, 0.3, 0.1), SPEC, "42CrMo4")
    with pytest.raises(GearDesignError, match="unknown strength option"):
        service_life(PAIR, SPEC, "42CrMo4", accuracy=6)


def test_plot_writes_a_png_and_refuses_to_overwrite(tmp_path):
    r = PAIR.life(SPEC, "42CrMo4")
    path = tmp_path / "life.png"
    fig = r.plot(path)
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert len(fig.axes) == 4
    with pytest.raises(GearDesignError):       # refused before anything is drawn
        r.plot(path)
    import matplotlib.pyplot as plt

    plt.close(fig)


@pytest.mark.parametrize("sn_curve", ["iso", "original", "elementary", "haibach"])
def test_the_plotted_sn_curve_is_the_inverse_of_the_endured_cycles(sn_curve):
    from geardesign.gears.strength.life_result import _strength_factor
    from geardesign.gears.strength.service_life import cycles_to_failure, life_curve

    pts = life_curve("H", "Eh")
    for r in (1.5, 1.2, 1.0, 0.95, 0.9):
        N = float(cycles_to_failure(r, pts, sn_curve))
        if N != float("inf") and not (sn_curve == "original" and r == 1.0):   # the knee's flat end: any N beyond
            assert float(_strength_factor(np.array([N]), pts, sn_curve)[0]) == pytest.approx(r, rel=1e-12)


def test_damage_table_and_life_read_the_result():
    r = service_life(PAIR, SPEC, "42CrMo4")
    t = r.damage_table()
    assert t[["mode", "gear"]].values.tolist() == [["pitting", 1], ["pitting", 2], ["root", 1], ["root", 2]]
    assert t["D"].tolist() == [r.D_H1, r.D_H2, r.D_F1, r.D_F2] and t["S"].tolist() == [r.S_H1, r.S_H2, r.S_F1, r.S_F2]
    assert t["ok"].tolist() == [d <= 1 for d in t["D"]]
    assert r.life_h == min(r.life_h_H1, r.life_h_H2, r.life_h_F1, r.life_h_F2)


def test_a_per_tooth_spectrum_is_plotted_on_its_governing_tooth_flank():
    """The S-N panel of a spectrum counted per tooth shows the cycles of one tooth flank (the one whose damage is
    D), not the sum over every tooth: its last stair ends at that flank's cycles."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    phi = np.linspace(0, 720, 721)
    T = 300 + 500 * np.exp(-((phi - 20) / 15) ** 2) - 150 * np.exp(-((phi - 380) / 30) ** 2)
    spec = gd.LoadSpectrum.from_curve(T, angle_deg=phi, n_rpm=1700, teeth=(17, 26), levels=24)
    r = gd.GearPair(8, 17, 26, 0.5, 0.3, face_width_mm=30).life(spec, "42CrMo4", life_h=5000,
                                                                 mean_stress_factor=0.7)
    fig = r.plot()
    b = r.bins
    group = b["tooth1"] * 2 + (b["torque_nm"] < 0)
    D = b.groupby(group)["D_H1"].sum()
    assert D.max() == pytest.approx(r.D_H1, rel=1e-9)
    top = int(D.idxmax())
    ax = fig.axes[0]
    assert f"tooth {top // 2}, {'coast' if top % 2 else 'drive'} flank" in ax.get_title()
    edges = ax.patches[0].get_data().edges
    assert edges[-1] == pytest.approx(b.loc[group == top, "n1"].sum(), rel=1e-12)
    assert edges[-1] < b["n1"].sum() / 10           # one flank of 17 teeth, not all of them
    plt.close(fig)


def test_a_result_pickled_before_its_table_is_read_keeps_the_table():
    """The per-bin table is built when first read: a result sent elsewhere (pickled: a Dask worker's) before that
    carries what builds it, and reads the same table; its D column sums to the result's D (one group per flank)."""
    import pickle

    pair = gd.GearPair(4, 20, 60, 0.3, 0.1, face_width_mm=40)
    spec = gd.LoadSpectrum.from_bins([120, 90, 60], 1000, time_h=[2000, 8000, 10000])
    r = pair.life(spec, "42CrMo4")
    sent = pickle.loads(pickle.dumps(r))
    assert sent.bins.equals(r.bins)
    assert sent.bins["D_H1"].sum() == pytest.approx(sent.D_H1, rel=1e-12)
    assert json.loads(sent.to_json())["bins"][0]["torque_nm"] == 120.0


@pytest.mark.parametrize("width", [1e-300, 5e-324, 9.99e-4])
def test_a_face_width_below_a_micrometre_is_refused_by_name(width):
    """Fuzzing found NaN (and infinite) damage from pair.life at a 1e-300 mm face width (the line load F_t/b
    overflows): the strength chain, its checks and the life take b >= 1 µm, as the mesh loss does."""
    s = gd.LoadSpectrum.from_bins([500.0, 1000.0], 1000.0, time_h=[1e3, 1e2])
    calls = (lambda: gd.GearPair(4, 20, 60, 0.3, 0.1, face_width_mm=width).life(s, "42CrMo4"),
             lambda: gd.pair_life(4, 20, 60, 0.3, 0.1, spectrum=s, material1="42CrMo4", face_width_mm=width),
             lambda: gd.GearPair(4, 20, 60, 0.3, 0.1, face_width_mm=width).strength(
                 gd.Load(torque_nm=100.0, n_rpm=1000.0), "42CrMo4"))
    for call in calls:
        with pytest.raises(GearDesignError, match=r"face_width_mm must be in \[0\.001, 100000\] mm"):
            call()
    r = gd.GearPair(4, 20, 60, 0.3, 0.1, face_width_mm=1e-3).life(s, "42CrMo4")     # the least width answers
    assert all(np.isfinite(v) for v in r.to_dict().values() if isinstance(v, float))
