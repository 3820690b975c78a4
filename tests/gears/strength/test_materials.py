"""Gear materials (geardesign.gears.strength.materials): a group's allowable stress numbers are its ISO 6336-5
line A·x + B at the hardness (computed here from the table), the named steel of ISO/TR 6336-30 example 1, and
the refusals."""
import pytest

from geardesign.catalogs.materials import material_group_lines
from geardesign.errors import GearDesignError
from geardesign.gears.strength.materials import Material, material, material_names


def _line(group, quality, stress):
    lines = material_group_lines()
    return lines[(lines.group == group) & (lines.quality == quality) & (lines.stress == stress)].iloc[0]


@pytest.mark.parametrize("group, quality", [("V_alloy", "MQ"), ("V_alloy", "ML"), ("Eh", "MQ"), ("St", "MQ")])
def test_a_group_at_a_hardness_is_its_iso_6336_5_line(group, quality):
    contact, bending = _line(group, quality, "contact"), _line(group, quality, "bending")
    h = (max(contact.hardness_min, bending.hardness_min) + min(contact.hardness_max, bending.hardness_max)) / 2
    m = material(group, hardness=h, quality=quality)
    assert m.quality == quality and m.hardness == h
    assert m.sigma_Hlim_mpa == pytest.approx(contact.A * h + contact.B, abs=0.051)   # rounded to 0.1 MPa
    assert m.sigma_Flim_mpa == pytest.approx(bending.A * h + bending.B, abs=0.051)


def test_the_tr30_examples_steel():
    m = material("18CrNiMo7-6")      # ISO/TR 6336-30 example 1: case-hardened, σ_Hlim = 1500 MPa
    assert (m.kind, m.sigma_Hlim_mpa, m.E_mpa, m.nu) == ("Eh", 1500.0, 206000.0, 0.3)


def test_names_and_aliases():
    names = material_names()
    assert {"42CrMo4", "18CrNiMo7-6", "V_alloy", "Eh"} <= set(names)
    assert material("40Х").name == "40Cr"       # the GOST grade's alias


@pytest.mark.parametrize("make, words", [
    (lambda: material("unobtainium"), "material must be a name"),
    (lambda: Material("x", "steel", 206000, 0.3, 300, "HV", 700, 300, "MQ", ""), "kind must be one of"),
    (lambda: material("42CrMo4", quality="MX"), "quality"),
])
def test_refusals_name_the_input(make, words):
    with pytest.raises(GearDesignError, match=words):
        make()
