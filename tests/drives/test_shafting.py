"""geardesign.drives.shafting: the options and the layout description are checked by name, and the default
layout's lengths follow the rule its docstring states."""
import pytest

import geardesign as gd
from geardesign.drives.shafting import DriveShaft, Shafting, default_positions
from geardesign.errors import GearDesignError


def test_default_positions_rule():
    # planes c + b1/2, then gap + (b1 + b2)/2 further; span Σb + (N − 1)·gap + 2c (written out here)
    xs, span = default_positions([30.0, 50.0, 70.0], 15.0, 8.0)
    assert xs == [15.0 + 15.0, 15.0 + 30.0 + 8.0 + 25.0, 15.0 + 30.0 + 8.0 + 50.0 + 8.0 + 35.0]
    assert span == 30.0 + 50.0 + 70.0 + 2 * 8.0 + 2 * 15.0


@pytest.mark.parametrize("kw, name", [(dict(S_min=0.1), "S_min"), (dict(life_h=-5), "life_h"),
                                      (dict(bearing_series="99"), "bearing_series"),
                                      (dict(material="unobtainium"), "material"),
                                      (dict(clearance_mm=1.0), "clearance_mm"), (dict(lubricant=3), "lubricant"),
                                      (dict(lubrication="mist"), "lubrication"),
                                      (dict(layout=[3]), "layout"), (dict(reliability=50), "reliab"),
                                      (dict(bearing_type="angular_contact"), "bearing_type"),
                                      (dict(bearing_type={1: "spherical"}), "bearing_type of shaft 1"),
                                      (dict(bearing_type={-1: "tapered"}), "shaft number"),
                                      (dict(bearing_type="tapered", bearing_series=("62", "63")), "no series of"),
                                      (dict(arrangement="Y"), "arrangement")])
def test_bad_options_are_named(kw, name):
    with pytest.raises(GearDesignError, match=name):
        Shafting(**kw)


def test_drive_shaft_checks():
    ds = DriveShaft(1, [(200.0, 40.0)], [20.0, 180.0], {"fast": 60.0})
    assert ds.length_mm == 200.0 and ds.supports_mm == (20.0, 180.0)
    with pytest.raises(GearDesignError, match="two bearing positions"):
        DriveShaft(1, [(200.0, 40.0)], [20.0, 100.0, 180.0], {"fast": 60.0})
    with pytest.raises(GearDesignError, match="position of 'fast'"):
        DriveShaft(1, [(200.0, 40.0)], [20.0, 180.0], {"fast": 260.0})
    with pytest.raises(GearDesignError, match="bearings"):
        DriveShaft(1, [(200.0, 40.0)], [20.0, 180.0], {"fast": 60.0}, bearings=("6208",))
    with pytest.raises(GearDesignError, match="twice"):
        Shafting(layout=[ds, ds])


def test_drive_refuses_what_is_not_a_shafting():
    st = [gd.GearStage(3, 20, 60, material="42CrMo4", face_width_mm=40)]
    with pytest.raises(GearDesignError, match="shafting must be a Shafting"):
        gd.Drive(power_kw=5, n_in_rpm=1000, stages=st, shafting="yes")
    with pytest.raises(GearDesignError, match="bearing_type: shaft 4 is beyond"):
        gd.Drive(power_kw=5, n_in_rpm=1000, stages=st, shafting=Shafting(bearing_type={4: "tapered"}))
    with pytest.raises(GearDesignError, match="shaft 5"):
        gd.Drive(power_kw=5, n_in_rpm=1000, stages=st, shafting=Shafting(
            layout=[DriveShaft(5, [(200.0, 40.0)], [20.0, 180.0], {"gear": 60.0})]))


def test_bearing_types_and_their_series():
    # the types' series are the catalogs' (geardesign.drives.bearing.SERIES by type)
    from geardesign.drives.bearing import SERIES

    sh = Shafting(bearing_type={1: "tapered", 2: "deep_groove"})
    assert sh.type_of(0) == "auto" and sh.type_of(1) == "tapered" and sh.type_of(2) == "deep_groove"
    assert sh.series_for("tapered") == tuple(s for s, (_, t) in SERIES.items() if t == "tapered_roller")
    assert sh.series_for("auto") == ("62", "63", "NU2", "NU3") + sh.series_for("tapered")
    assert Shafting(bearing_series=("62", "302")).series_for("auto") == ("62", "302")
    assert set(Shafting(bearing_type="deep_groove").series) == {"62", "63"}
