"""Catalog integrity and validation. Numbers are cited from the standards or from the published
tables listed in docs/references.md (REF below), never from geardesign's own output."""
import numpy as np
import pandas as pd
import pytest

from geardesign import catalogs
from geardesign.errors import CatalogError, GearDesignError


@pytest.mark.parametrize("name", catalogs.catalog_names())
def test_every_bundled_table_loads_with_edition_and_source(name):
    frame = catalogs.load_catalog(name)
    assert len(frame) > 0
    for col in ("edition", "source"):
        assert col in frame.columns
        assert (frame[col].astype(str).str.len() > 3).all(), f"{name}: empty {col}"


def test_iso606_series_filters():
    a = catalogs.chain_catalog("iso606a")
    b = catalogs.chain_catalog("iso606b")
    assert set(a["series"]) == {"A"} and set(b["series"]) == {"B"}
    assert len(a) + len(b) == len(catalogs.chain_catalog("iso606"))


def test_iso606_32a_roller_is_28_58():
    # REF README "known conflicts": ISO 606 32A roller diameter is 28.58 mm (25.4 in one source is wrong)
    a = catalogs.chain_catalog("iso606a")
    assert a.loc[a["designation"] == "32A", "roller_d1_mm"].item() == pytest.approx(28.58)


def test_gost_editions_kept_apart():
    # REF README: GOST 13568-97 gives 60 kN for the 25.4 mm chain, GOST 13568-75 gives 56.7 kN
    g = catalogs.chain_catalog("gost13568")
    row = g[g["designation"] == "PR-25,4-60"].iloc[0]
    assert row["breaking_load_kn"] == pytest.approx(60.0)
    assert float(row["breaking_load_gost13568_75_kn"]) == pytest.approx(56.7)


def test_iso_hinge_area_matches_gost_1975_table():
    # hinge area of ISO 606 20A (= d2 x b2) against GOST 13568-75 A = 260 mm2 for PR-31.75 (REF gost13568_chains.csv)
    a = catalogs.chain_catalog("iso606a")
    area = a.loc[a["designation"] == "20A", "hinge_area_mm2"].item()
    assert area == pytest.approx(260.0, rel=0.01)


def test_seed002_chain_row():
    # seed 002, 1.9.5: 2PR-31.75-17700: d1 = 19.05 mm, inner width 19.05 mm, A (strand spacing) 35.76 mm,
    # Q = 177 kN, mass 7.3 kg/m
    g = catalogs.chain_catalog("gost13568")
    row = g[g["designation"] == "2PR-31,75-177"].iloc[0]
    assert (row["roller_d1_mm"], row["inner_width_mm"], row["transverse_pitch_mm"]) == (19.05, 19.05, 35.76)
    assert row["breaking_load_kn"] == 177 and row["mass_kg_m"] == 7.3 and row["strands"] == 2


def test_module_series_iso54():
    # ISO 54:1996 series 1 and 2 between 1 and 50 mm
    s1 = [1, 1.25, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10, 12, 16, 20, 25, 32, 40, 50]
    s2 = [1.125, 1.375, 1.75, 2.25, 2.75, 3.5, 4.5, 5.5, 7, 9, 11, 14, 18, 22, 28, 36, 45]
    np.testing.assert_array_equal(catalogs.module_series(1, 1, 50), s1)
    np.testing.assert_array_equal(catalogs.module_series(2, 1, 50), s2)
    both = catalogs.module_series()
    assert both[0] == 0.05 and both[-1] == 100  # GOST 9563-60 range
    assert 6.5 not in both
    with pytest.raises(GearDesignError, match="series"):
        catalogs.module_series(3)


def test_center_distance_series_gost2185():
    # GOST 2185-66 series 1 (R10 from 40) and series 2 to 1400 mm
    s1 = [40, 50, 63, 80, 100, 125, 160, 200, 250, 315, 400, 500, 630, 800, 1000]
    s2 = [71, 90, 112, 140, 180, 225, 280, 355, 450, 560, 710, 900, 1120, 1400]
    np.testing.assert_array_equal(catalogs.center_distance_series(1, max_mm=1000), s1)
    np.testing.assert_array_equal(catalogs.center_distance_series(2, max_mm=1400), s2)


def test_key_lengths_series():
    # GOST 23360-78 lengths start 6, 8, 10, 12, 14, 16, 18, 20, 22, 25, 28, 32, 36, 40, 45, 50 (REF key_lengths_series.csv)
    np.testing.assert_array_equal(catalogs.key_lengths_mm()[:16],
                                  [6, 8, 10, 12, 14, 16, 18, 20, 22, 25, 28, 32, 36, 40, 45, 50])


# ---------------------------------------------------------------- broken files

def _gost_copy(tmp_path, edit):
    frame = pd.read_csv(catalogs.catalog_dir() / "chains_gost13568.csv", dtype=str, keep_default_na=False)
    frame = edit(frame)
    path = tmp_path / "mine.csv"
    frame.to_csv(path, index=False)
    return path


def test_user_catalog_is_accepted(tmp_path):
    path = _gost_copy(tmp_path, lambda f: f.drop(columns=["edition", "source", "note"]))
    frame = catalogs.chain_catalog(str(path))
    assert len(frame) == len(catalogs.chain_catalog("gost13568"))


def test_missing_column_names_file_and_column(tmp_path):
    path = _gost_copy(tmp_path, lambda f: f.drop(columns=["hinge_area_mm2"]))
    with pytest.raises(CatalogError, match=r"mine\.csv.*hinge_area_mm2"):
        catalogs.chain_catalog(str(path))


def test_negative_value_names_row_and_column(tmp_path):
    def edit(f):
        f.loc[4, "breaking_load_kn"] = "-3"
        return f
    path = _gost_copy(tmp_path, edit)
    # data row index 4 is line 6 of the file (header is line 1)
    with pytest.raises(CatalogError, match=r"mine\.csv, row 6, column 'breaking_load_kn': must be > 0"):
        catalogs.chain_catalog(str(path))


def test_text_in_number_column(tmp_path):
    def edit(f):
        f.loc[0, "pitch_mm"] = "8,0"
        return f
    path = _gost_copy(tmp_path, edit)
    with pytest.raises(CatalogError, match=r"row 2, column 'pitch_mm': not a number"):
        catalogs.chain_catalog(str(path))


def test_multistrand_without_transverse_pitch(tmp_path):
    def edit(f):
        f.loc[f["strands"] == "2", "transverse_pitch_mm"] = ""
        return f
    path = _gost_copy(tmp_path, edit)
    with pytest.raises(CatalogError, match="transverse_pitch_mm"):
        catalogs.chain_catalog(str(path))


def test_non_monotone_lengths(tmp_path):
    path = tmp_path / "lengths.csv"
    path.write_text("length_mm\n6\n10\n8\n")
    with pytest.raises(CatalogError, match=r"row 4, column 'length_mm': values must increase"):
        catalogs.load_catalog(str(path), kind="key_lengths")


def test_unknown_name_and_missing_file(tmp_path):
    with pytest.raises(CatalogError, match="catalog must be one of"):
        catalogs.load_catalog("din8187")
    with pytest.raises(CatalogError, match="not found"):
        catalogs.load_catalog(str(tmp_path / "nothing.csv"))
    with pytest.raises(GearDesignError, match="chain table"):
        catalogs.chain_catalog("keys")
