"""The motor catalog and gd.motor.select. The rule is re-implemented in the test as a plain loop;
catalog values are checked against seed 002 where it states them."""
import math

import pytest

import geardesign as gd
from geardesign.catalogs.tables import load_catalog
from geardesign.errors import CatalogError, GearDesignError


def test_catalog_rows_cite_a_source_and_hold_the_series_rules():
    t = load_catalog("motors_air")
    assert len(t) == 50
    assert t["source"].str.len().min() > 20 and t["edition"].notna().all()
    # 50 Hz: n_s = 6000/poles; an asynchronous motor slips below it
    assert ((t["sync_speed_rpm"] * t["poles"]) == 6000).all()
    assert (t["rated_speed_rpm"] < t["sync_speed_rpm"]).all()
    # IEC 60034 / GOST power steps only
    steps = {0.37, 0.55, 0.75, 1.1, 1.5, 2.2, 3.0, 4.0, 5.5, 7.5, 11.0, 15.0, 18.5, 22.0, 30.0}
    assert set(t["power_kw"]) <= steps


def test_seed002_motor_row():
    # Seed 002 (brake stand, motor data): 4 kW, 1500 rpm asynchronous, T_max/T_nom = 2.2.
    row = load_catalog("motors_air").set_index("designation").loc["AIR100L4"]
    assert (row["power_kw"], row["sync_speed_rpm"], row["max_torque_ratio"]) == (4.0, 1500, 2.2)


def test_rated_torque_formula():
    # T = P/ω written out: 4000 W / (2π·1410/60 rad/s)
    assert gd.motor.rated_torque_nm(4.0, 1410) == pytest.approx(4000 / (2 * math.pi * 1410 / 60), rel=1e-15)


@pytest.mark.parametrize("power, speed, sf", [(3.5, 1450, 1.0), (4.0, 1500, 1.0), (4.0, 1500, 1.2), (0.3, 700, 1.0),
                                              (10.0, 3000, 1.5), (0.5, 1000, 2.0), (21.0, 980, 1.0)])
def test_select_matches_a_plain_loop(power, speed, sf):
    rows = load_catalog("motors_air").to_dict("records")
    best_per_series = {}
    for r in rows:
        if r["power_kw"] >= power * sf:
            s = r["sync_speed_rpm"]
            if s not in best_per_series or r["power_kw"] < best_per_series[s]["power_kw"]:
                best_per_series[s] = r
    want = min(best_per_series.values(), key=lambda r: (abs(r["rated_speed_rpm"] - speed), -r["sync_speed_rpm"]))
    sel = gd.motor.select(power, speed, service_factor=sf)
    assert sel.found and sel.motor["designation"] == want["designation"]
    assert sel.motor["rated_torque_nm"] == pytest.approx(9549.296585513721 * want["power_kw"] / want["rated_speed_rpm"])


def test_select_too_much_power_is_a_result():
    sel = gd.motor.select(40, 1500)
    assert not sel.found and sel.status == "failed" and "30 kW" in sel.message


@pytest.mark.parametrize("kw", [dict(power_kw=-1, speed_rpm=1500), dict(power_kw=4, speed_rpm=0),
                                dict(power_kw=4, speed_rpm=1500, service_factor=0.5),
                                dict(power_kw=4, speed_rpm=1500, catalog="nope")])
def test_bad_inputs_name_themselves(kw):
    with pytest.raises(GearDesignError) as e:
        gd.motor.select(**kw)
    name = [k for k in kw if k not in ("power_kw", "speed_rpm")] or [k for k, v in kw.items() if v in (-1, 0)]
    assert name[0].split("_")[0] in str(e.value)


def test_broken_motor_file_names_row_and_column(tmp_path):
    text = (load_catalog("motors_air").drop(columns=["edition", "source", "note"]).head(3)
            .to_csv(index=False))
    lines = text.splitlines()
    lines[2] = lines[2].replace(",3000.0,", ",1500.0,")    # a two-pole motor at 1500 rpm synchronous
    path = tmp_path / "motors.csv"
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(CatalogError) as e:
        load_catalog(path, kind="motors")
    assert "row 3" in str(e.value) and "sync_speed_rpm" in str(e.value)
