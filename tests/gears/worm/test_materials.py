"""The worm wheel materials table: loads under its schema, every row sourced, values as the sources print them."""
import pytest

from geardesign.errors import GearDesignError
from geardesign.gears.worm.materials import worm_material, worm_materials


def test_every_row_has_a_source_and_an_edition():
    frame = worm_materials()
    assert len(frame) >= 8
    assert frame["source"].str.len().min() > 40 and frame["edition"].str.startswith("EN 1982").all()
    assert frame["name"].is_unique
    assert (frame["Rp02_mpa"] < frame["Rm_mpa"]).all()          # proof stress below tensile strength
    both = frame.dropna(subset=["E_min_mpa", "E_max_mpa"])
    assert (both["E_min_mpa"] <= both["E_max_mpa"]).all() and len(both) == 2


def test_printed_values():
    # EN 1982 minimums as the 'Tin Bronze' table prints them: CuSn12Ni centrifugal 300/180/8/100
    row = worm_material("CuSn12Ni2-C-GZ")
    assert (row.Rm_mpa, row.Rp02_mpa, row.elongation_pct, row.hardness_HB) == (300, 180, 8, 100)
    # Kemper's CuSn12Ni2-C-GS sheet: 280/160/12/85, E 90-110 GPa, 8.6 g/cm3
    row = worm_material("CuSn12Ni2-C-GS")
    assert (row.Rm_mpa, row.Rp02_mpa, row.elongation_pct, row.hardness_HB) == (280, 160, 12, 85)
    assert (row.E_min_mpa, row.E_max_mpa, row.density_kg_m3) == (90000, 110000, 8600)


def test_an_unknown_name_is_refused_with_the_choices():
    with pytest.raises(GearDesignError, match="worm material must be one of .*CuSn12Ni2-C-GZ.*got 'bronze'"):
        worm_material("bronze")
