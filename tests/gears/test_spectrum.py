"""LoadSpectrum: bins, CSV, level counting of a torque curve per tooth and flank; T_eq and K_A (ISO 6336-6 Annex A).
Closed forms are written here; ISO 6336-6:2019 Annex C's Table 4 is in tests/data (iso6336_6_annexC.md)."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings, strategies as st

import geardesign as gd
from geardesign.errors import GearDesignError
from geardesign.gears.spectrum import LoadSpectrum, application_factor_from_spectrum, equivalent_torque

DATA = Path(__file__).resolve().parents[1] / "data"


def test_bins_from_cycles_time_and_shares():
    s = LoadSpectrum.from_bins([500, 1000], 1500, cycles=[9e6, 1e6])
    assert s.time_h.tolist() == pytest.approx([9e6 / 90000, 1e6 / 90000], rel=1e-15)
    s2 = LoadSpectrum.from_bins([500, 1000], [1500, 1500], time_h=[100.0, 100.0 / 9])
    assert s2.duration_h == pytest.approx(s.duration_h, rel=1e-14)
    s3 = LoadSpectrum.from_bins([500, 1000], 1500, share=[0.9, 0.1], duration_h=1000)
    assert s3.time_h.tolist() == pytest.approx([900.0, 100.0], rel=1e-15)
    # cycles of each gear: 60 n t with its own speed (gear 2 of 20/60 turns three times slower)
    assert s3.cycles(2, (20, 60)).tolist() == pytest.approx([60 * 500 * 900.0, 60 * 500 * 100.0], rel=1e-14)
    assert not s3.reverses and not s3.per_tooth
    assert "2 bins" in repr(s3) and "<array" not in repr(s3)


@pytest.mark.parametrize("kwargs, words", [
    (dict(torque_nm=[1, 2], n_rpm=100), "exactly one of cycles, time_h or share"),
    (dict(torque_nm=[1, 2], n_rpm=100, cycles=[1, 2], time_h=[1, 2]), "exactly one"),
    (dict(torque_nm=[1, 2], n_rpm=100, share=[0.5, 0.6], duration_h=10), "share must sum to 1"),
    (dict(torque_nm=[1, 2], n_rpm=100, share=[0.5, 0.5]), "duration_h"),
    (dict(torque_nm=[1, 2], n_rpm=[1, 2, 3], time_h=[1, 1]), "n_rpm must be one number or one per bin"),
    (dict(torque_nm=[1, 2], n_rpm=-5, time_h=[1, 1]), "n_rpm must be in (0"),
    (dict(torque_nm=[1, float("nan")], n_rpm=5, time_h=[1, 1]), "torque_nm must be finite"),
    (dict(torque_nm=[1, 2], n_rpm=5, time_h=[0, 0]), "some time"),
    (dict(torque_nm=[1, 2], n_rpm=5, cycles=[1]), "cycles must be one per bin"),
])
def test_bad_bins_are_refused_by_name(kwargs, words):
    with pytest.raises(GearDesignError, match=None) as e:
        LoadSpectrum.from_bins(**kwargs)
    assert words in str(e.value)


@given(T=st.floats(1e-3, 1e6), p=st.floats(0.5, 60.0), n=st.floats(1.0, 1e12))
@settings(max_examples=60, deadline=None)
def test_the_equivalent_torque_of_one_bin_is_its_torque(T, p, n):
    assert equivalent_torque([T], [n], p) == pytest.approx(T, rel=1e-12)


def test_equivalent_torque_and_application_factor_closed_form():
    # (Σ n T^p / Σ n)^(1/p) by hand: 1000·(0.1 + 0.9·0.5^6.6)^(1/6.6)
    expect = 1000.0 * (0.1 + 0.9 * 0.5 ** 6.6) ** (1 / 6.6)
    s = LoadSpectrum.from_bins([1000, 500], 1500, cycles=[1e6, 9e6])
    assert s.equivalent_torque(6.6) == pytest.approx(expect, rel=1e-13)
    assert s.application_factor(500.0, 6.6) == pytest.approx(expect / 500.0, rel=1e-13)
    assert application_factor_from_spectrum(expect, 500) == pytest.approx(expect / 500, rel=1e-15)
    # a huge exponent does not overflow (scaled by the largest torque)
    assert equivalent_torque([1e9, 1.0], [1.0, 1.0], 99.0) == pytest.approx(1e9 * 0.5 ** (1 / 99), rel=1e-12)
    with pytest.raises(GearDesignError, match="p must be in"):
        equivalent_torque([1.0], [1.0], 0.0)


def _csv(tmp_path, text):
    p = tmp_path / "spec.csv"
    p.write_text(text, encoding="utf-8")
    return p


def test_csv_spectrum(tmp_path):
    p = _csv(tmp_path, "# a comment line\ntorque_nm,n_rpm,time_h\n400,1500,10\n-200,1500,2\n")
    s = LoadSpectrum.from_csv(p)
    assert s.torque_nm.tolist() == [400.0, -200.0] and s.reverses
    s = LoadSpectrum.from_csv(_csv(tmp_path, "torque_nm,share\n400,0.25\n200,0.75\n"), n_rpm=1000, duration_h=100)
    assert s.time_h.tolist() == [25.0, 75.0]


@pytest.mark.parametrize("text, words", [
    ("torque_nm,n_rpm,time_h\n400,1500,10\n200,abc,2\n", "row 3, column 'n_rpm': 'abc' is not a number"),
    ("torque_nm,n_rpm,time_h\n400,1500,-1\n", "row 2, column 'time_h': -1 is outside"),
    ("torque_nm,n_rpm,time_h\n400,0,1\n", "row 2, column 'n_rpm': 0 is outside"),
    ("torque_nm,n_rpm,time_h\n400,1500\n", "row 2: 2 cells, the header has 3"),
    ("torque_nm,n_rpm,hours\n400,1500,1\n", "unknown column 'hours'"),
    ("torque_nm,n_rpm\n400,1500\n", "exactly one of the columns 'time_h', 'cycles', 'share'"),
    ("n_rpm,time_h\n1500,1\n", "needs a 'torque_nm' column"),
    ("torque_nm,n_rpm,time_h\n", "needs a header and at least one row"),
])
def test_bad_csv_names_the_row_and_column(tmp_path, text, words):
    with pytest.raises(GearDesignError) as e:
        LoadSpectrum.from_csv(_csv(tmp_path, text))
    assert words in str(e.value)


def test_csv_file_missing_and_speed_twice(tmp_path):
    with pytest.raises(GearDesignError, match="cannot be read"):
        LoadSpectrum.from_csv(tmp_path / "none.csv")
    with pytest.raises(GearDesignError, match="not both"):
        LoadSpectrum.from_csv(_csv(tmp_path, "torque_nm,n_rpm,time_h\n1,2,3\n"), n_rpm=5)


def test_a_constant_curve_counts_every_mesh_at_its_torque():
    # gear 1 (z = 20) turns once in 360°: a run of lcm(20, 20, 30) = 60 meshes, each mesh one cycle of one tooth
    s = LoadSpectrum.from_curve([250.0, 250.0], angle_deg=[0.0, 360.0], n_rpm=600, teeth=(20, 30))
    assert set(s.torque_nm.tolist()) == {250.0}
    assert s.meshes.sum() == 60
    # every tooth of gear 1 meets 3 times in the run, every tooth of gear 2 twice
    assert np.bincount(s.tooth1, weights=s.meshes).tolist() == [3.0] * 20
    assert np.bincount(s.tooth2, weights=s.meshes).tolist() == [2.0] * 30
    # the run lasts 3 turns of gear 1 at 600 rpm: 0.3 s
    assert s.duration_h == pytest.approx(3 / 600 / 60, rel=1e-13)
    assert s.cycles(1, (20, 30)).sum() == 60


def test_a_four_stroke_peak_loads_the_same_teeth_every_cycle():
    """A gear on the crankshaft (z1 = 20) under a 720° cycle with one firing peak at φ = 0: each tooth meshes twice
    per cycle, at φ and φ + 360°; the tooth at φ = 0 meets the peak every cycle (no hunting), the others never."""
    phi = np.linspace(0.0, 720.0, 721)
    T = 100.0 + 900.0 * np.exp(-((phi - 0.0) / 5.0) ** 2) + 900.0 * np.exp(-((phi - 720.0) / 5.0) ** 2)
    s = LoadSpectrum.from_curve(T, angle_deg=phi, n_rpm=1700, teeth=(20, 40), levels=100)
    top = s.torque_nm.max()
    assert top == pytest.approx(1000.0, rel=1e-12)        # the class end of the largest torque: the peak itself
    assert set(s.tooth1[s.torque_nm == top].tolist()) == {0}
    per_tooth = np.bincount(s.tooth1, weights=s.meshes)
    assert per_tooth.tolist() == [per_tooth[0]] * 20       # every tooth meshes equally often


def test_a_reversing_curve_loads_the_other_flank():
    phi = np.linspace(0.0, 360.0, 361)
    T = 300.0 * np.sin(np.radians(phi))
    s = LoadSpectrum.from_curve(T, angle_deg=phi, n_rpm=1000, teeth=(18, 36), levels=10)
    assert s.reverses and s.torque_nm.min() < 0 < s.torque_nm.max()
    # classes counted at their end farthest from zero: k/10 of the largest torque at a mesh of each sign, here
    # 300·sin 80° (the meshes fall every 20°)
    for sign in (1, -1):
        top = 300.0 * math.sin(math.radians(80.0))
        assert sign * s.torque_nm.max() == pytest.approx(top, rel=1e-12) if sign > 0 else True
        levels = sign * s.torque_nm[sign * s.torque_nm > 0] / (top / 10.0)
        assert np.allclose(levels, np.round(levels), atol=1e-9)


def test_a_curve_over_time_is_its_curve_over_angle():
    n = 600.0   # 10 turns per second: 360° in 0.1 s
    t = np.linspace(0.0, 0.1, 101)
    a = LoadSpectrum.from_curve(100 + 50 * np.cos(2 * np.pi * t / 0.1), time_s=t, n_rpm=n, teeth=(25, 50))
    b = LoadSpectrum.from_curve(100 + 50 * np.cos(np.radians(360 * t / 0.1)), angle_deg=360 * t / 0.1, n_rpm=n,
                                teeth=(25, 50))
    assert np.allclose(a.torque_nm, b.torque_nm, rtol=1e-12) and np.array_equal(a.meshes, b.meshes)


@pytest.mark.parametrize("kwargs, words", [
    (dict(torque_nm=[1.0, 2.0], angle_deg=[0.0, 100.0], n_rpm=100, teeth=(20, 30)), "whole number of mesh pitches"),
    (dict(torque_nm=[1.0, 2.0], angle_deg=[0.0, 0.0], n_rpm=100, teeth=(20, 30)), "increase strictly"),
    (dict(torque_nm=[1.0, 2.0], n_rpm=100, teeth=(20, 30)), "angle_deg or over time_s"),
    (dict(torque_nm=[1.0, 2.0], angle_deg=[0.0, 360.0], n_rpm=100, teeth=(20,)), "teeth must be the pair's"),
    (dict(torque_nm=[1.0], angle_deg=[0.0], n_rpm=100, teeth=(20, 30)), "at least 2 points"),
])
def test_bad_curves_are_refused(kwargs, words):
    with pytest.raises(GearDesignError) as e:
        LoadSpectrum.from_curve(**kwargs)
    assert words in str(e.value)


def test_annex_c_table4_cycles_over_30_years():
    """ISO 6336-6:2019 Annex C: Table 4's pinion cycles extrapolated from the 70-day measurement (1681.8 h) to 30
    years end where Figure C.1's spectra end: 5.997e5 cycles (tests/data/iso6336_6_annexC.md)."""
    t = pd.read_csv(DATA / "iso6336_6_annexC_table4.csv")
    s = LoadSpectrum.from_bins(t["Torque_Max_Nm"], 35.2, time_h=t["time_h"])
    years30 = 30 * 365.25 * 24
    # bin 48 is the idle time (no torque): it counts in the duration, not in the cycles
    total = s.cycles(1, (17, 60))[s.torque_nm != 0].sum() * years30 / s.duration_h
    # the typed table's time_h are rounded to 3 digits: its cycles column, scaled the same way, is the reference
    expect = t["load_cycles"].sum() * years30 / t["time_h"].sum()
    assert total == pytest.approx(expect, rel=3e-3)
    fig = pd.read_csv(DATA / "iso6336_6_annexC_fig_c1.csv")
    end = fig.loc[fig["N_H2"] > 0, "N_H2"].max()
    assert total == pytest.approx(end, rel=0.03)             # the figure's digitised end: 6.04e5


def test_gd_exports_the_spectrum():
    assert gd.LoadSpectrum is LoadSpectrum
    s = LoadSpectrum.from_bins([1.0], 1.0, time_h=[1.0])
    assert list(s.to_frame().columns) == ["torque_nm", "n_rpm", "time_h"]
    assert math.isclose(s.duration_h, 1.0)


def test_per_tooth_bins_need_their_pair():
    t = np.array([0, 1])
    with pytest.raises(GearDesignError, match="go together"):
        LoadSpectrum([1.0, 2.0], 100.0, [1.0, 1.0], 1, t, t)
    with pytest.raises(GearDesignError, match="needs teeth"):
        LoadSpectrum([1.0, 2.0], 100.0, [1.0, 1.0], 1, t, t, np.array([1.0, 1.0]))
    with pytest.raises(GearDesignError, match=r"in \[0, z\)"):
        LoadSpectrum([1.0, 2.0], 100.0, [1.0, 1.0], 1, t, np.array([0, 30]), np.array([1.0, 1.0]), (20, 30))
    s = LoadSpectrum([1.0, 2.0], 100.0, [1.0, 1.0], 1, t, t, np.array([1.0, 1.0]), (20, 30))
    assert s.per_tooth and s.teeth == (20, 30) and list(s.to_frame().columns)[-1] == "meshes"


def test_histogram_sums_the_time_of_each_torque_class_over_the_teeth():
    """Three meshes a period at 100, -50, 100 N·m on a 3-tooth pinion (a 360° curve, 120° a pitch): two thirds of
    the time at +100 (drive flank), one third at -50 (coast flank), whatever the teeth."""
    s = LoadSpectrum.from_curve([100.0, -50.0, 100.0], angle_deg=[0.0, 120.0, 240.0], n_rpm=60, teeth=(3, 6),
                                period_deg=360.0, levels=1)
    h = s.histogram()
    assert h["torque_nm"].tolist() == [100.0, -50.0] and h["flank"].tolist() == ["drive", "coast"]
    assert h["share"].tolist() == pytest.approx([2 / 3, 1 / 3], rel=1e-12)
    assert h["time_h"].sum() == pytest.approx(s.duration_h, rel=1e-12)


def test_plot_draws_both_flanks(tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    s = LoadSpectrum.from_bins([120, -60, 90], 1000, time_h=[1, 2, 3])
    ax = s.plot()
    heights = sorted(round(p.get_height(), 9) for p in ax.patches)
    assert heights == pytest.approx([100 / 6, 100 / 3, 50.0])
    assert [t.get_text() for t in ax.get_legend().get_texts()] == ["drive flank (T > 0)",
                                                                    "coast flank (T < 0: the torque reversed)"]
    plt.close(ax.figure)
    with pytest.raises(GearDesignError, match="ax"):
        s.plot(ax="not axes")


@pytest.mark.parametrize("make, match", [
    (lambda: LoadSpectrum.from_curve([100.0, 120.0], angle_deg=[0.0, 360.0], n_rpm=[1, 2], teeth=(20, 40)),
     "n_rpm must be one number"),
    (lambda: LoadSpectrum.from_curve([100.0, 120.0], angle_deg=[0.0, 360.0], n_rpm=600, teeth=(20, 40),
                                     levels=np.array([1.0])), "levels must be one number"),
    (lambda: LoadSpectrum.from_bins([100.0, 50.0], 1000, share=[0.5, 0.5], duration_h=[1, 2]),
     "duration_h must be one number"),
])
def test_a_list_where_one_number_belongs_is_refused_by_name(make, match):
    """Fuzzing found 'TypeError: only 0-dimensional arrays can be converted to Python scalars' for these."""
    with pytest.raises(GearDesignError, match=match):
        make()


def test_cycles_at_a_vanishing_speed_are_refused_by_name_without_a_warning():
    """Fuzzing found a RuntimeWarning (overflow in cycles/(60·n)) escaping from_bins at n_rpm = 5e-324."""
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(GearDesignError, match=r"cycles at n_rpm must give time_h = cycles/\(60·n_rpm\) in "
                                                  r"\[0, 1e\+09\] h, got inf h \(1 cycles at 4.94066e-324 rpm, bin 0\)"):
            LoadSpectrum.from_bins([1410.5, 2972.2], 5e-324, cycles=[1.0, 1e9])
        with pytest.raises(GearDesignError, match=r"got 1\.66667e\+13 h \(1e\+18 cycles at 1000 rpm, bin 1\)"):
            LoadSpectrum.from_bins([100.0, 50.0], 1000, cycles=[1e6, 1e18])


@pytest.mark.parametrize("on_gear", [np.array([]), np.array([1.0]), [1], True, "1", 3])
def test_on_gear_that_is_no_gear_number_is_refused_by_name(on_gear):
    """Fuzzing found 'truth value of an empty array is ambiguous' (from_bins) and 'only integer scalar arrays can
    be converted to a scalar index' (from_curve) for on_gear given as an array."""
    with pytest.raises(GearDesignError, match="on_gear must be 1 or 2"):
        LoadSpectrum.from_bins([100.0, 50.0], 1000, time_h=[1.0, 2.0], on_gear=on_gear)
    with pytest.raises(GearDesignError, match="on_gear must be 1 or 2"):
        LoadSpectrum.from_curve([100.0, 120.0], angle_deg=[0.0, 360.0], n_rpm=600, teeth=(20, 40), on_gear=on_gear)


def test_a_spectrum_that_is_no_text_file_is_refused_by_name(tmp_path):
    """Fuzzing found `geardesign pair --spectrum /dev/zero` reading without end (unbounded work): a device, a folder
    or a file beyond SPECTRUM_BYTES_MAX is refused before it is read whole."""
    from geardesign.gears import spectrum as sp
    for path in ("/dev/zero", tmp_path):
        with pytest.raises(GearDesignError, match="spectrum file .* is not a regular file"):
            LoadSpectrum.from_csv(path, n_rpm=1000)
    big = tmp_path / "big.csv"
    with open(big, "wb") as fh:
        fh.write(b"torque_nm,time_h\n")
        fh.seek(sp.SPECTRUM_BYTES_MAX)
        fh.write(b"1,1\n")
    with pytest.raises(GearDesignError, match="is larger than 16 MiB"):
        LoadSpectrum.from_csv(big, n_rpm=1000)


def test_a_spectrums_arrays_are_read_only_copies():
    """A spectrum is frozen (pair_life keeps what it derives from one, per spectrum): its arrays, the teeth of a
    spectrum counted per tooth too, cannot be written, and writing the caller's arrays does not change them."""
    teeth = np.array([0, 1, 2])
    s = LoadSpectrum(np.array([100.0, 50.0, 80.0]), 1000.0, np.array([1.0, 2.0, 3.0]), tooth1=teeth,
                     tooth2=np.array([0, 1, 3]), meshes=np.array([1.0, 1.0, 1.0]), teeth=(3, 4))
    for name in ("torque_nm", "n_rpm", "time_h", "tooth1", "tooth2", "meshes"):
        with pytest.raises(ValueError):
            getattr(s, name)[0] = 7
    teeth[0] = 2
    assert s.tooth1.tolist() == [0, 1, 2]
