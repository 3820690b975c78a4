"""The stage-kind package (geardesign.drives.stage_kinds): the built-in kinds registered in the documented order
(given, gear, chain) and each stage class found by its kind."""
import geardesign as gd
from geardesign.drives import stage_kinds as sk


def test_the_built_in_kinds_in_order():
    assert sk.kind_names()[:3] == ("given", "gear", "chain")
    assert isinstance(sk.kind_named("given"), sk.GivenKind)
    assert isinstance(sk.kind_named("gear"), sk.GearKind) and isinstance(sk.kind_named("chain"), sk.ChainKind)


def test_each_stage_class_finds_its_kind():
    assert sk.kind_of(gd.GivenStage(3.0, 0.95)).name == "given"
    assert sk.kind_of(gd.GearStage(m=3, z1=20, z2=40)).name == "gear"
    assert sk.kind_of(gd.ChainStage(z1=13, z2=13)).name == "chain"
    assert {k.name for k in sk.kinds()} >= {"given", "gear", "chain"}
