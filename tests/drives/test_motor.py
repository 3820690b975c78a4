"""The motor catalogs and gd.motor.select. The rule is re-implemented in the test as a plain loop;
catalog values are checked against seed 002 and against the SOGA MT3 catalogue table as printed."""
import json
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


@pytest.mark.parametrize("catalog, power, speed, sf", [
    ("motors_air", 3.5, 1450, 1.0), ("motors_air", 4.0, 1500, 1.0), ("motors_air", 4.0, 1500, 1.2),
    ("motors_air", 0.3, 700, 1.0), ("motors_air", 10.0, 3000, 1.5), ("motors_air", 0.5, 1000, 2.0),
    ("motors_air", 21.0, 980, 1.0),
    # SOGA MT3 has two frames for 1.5, 5.5 and 11 kW: the lighter one wins
    ("motors_soga_mt3", 1.4, 2900, 1.0), ("motors_soga_mt3", 5.0, 2900, 1.0), ("motors_soga_mt3", 10.0, 2950, 1.0),
    ("motors_soga_mt3", 0.7, 1400, 1.0), ("motors_soga_mt3", 0.7, 2000, 1.0)])
def test_select_matches_a_plain_loop(catalog, power, speed, sf):
    rows = load_catalog(catalog).to_dict("records")
    mass = lambda r: r["mass_kg"] if r["mass_kg"] == r["mass_kg"] else math.inf   # blank (NaN): last
    best_per_series = {}
    for r in rows:
        if r["power_kw"] >= power * sf:
            s = r["sync_speed_rpm"]
            b = best_per_series.get(s)
            if b is None or (r["power_kw"], mass(r)) < (b["power_kw"], mass(b)):
                best_per_series[s] = r
    want = min(best_per_series.values(), key=lambda r: (abs(r["rated_speed_rpm"] - speed), -r["sync_speed_rpm"]))
    sel = gd.motor.select(power, speed, service_factor=sf, catalog=catalog)
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


# SOGA S.p.A., catalogue "MT3 three phase IEC IE3 motors", p. 17, tables "2 POLES" and "4 POLES",
# 400 V / 50 Hz, S1 (https://cdn.shopify.com/s/files/1/0771/6585/5068/files/SOGA-MT3-THREE-PHASE-IEC-IE3-MOTORS.pdf),
# as printed: model, kW, r.p.m., efficiency %, rated torque Nm, Msp/M p.u., mass for B3 kg.
SOGA_MT3_PRINTED = [
    ("MT3 80 MA/2", 0.75, 2900, 80.7, 2.5, 3.9, 10.0),
    ("MT3 90 SA/2", 1.5, 2900, 84.2, 4.9, 3.3, 14.0),
    ("MT3 112 MA/2", 4.0, 2930, 88.1, 13.0, 5.2, 33.0),
    ("MT3 132 MA/2", 9.2, 2950, 90.7, 29.8, 3.6, 59.7),
    ("MT3 160 LA/2", 18.5, 2955, 92.4, 59.8, 3.6, 117.0),
    ("MT3 180 MA/2", 22.0, 2970, 92.7, 70.6, 3.7, 177.0),
    ("MT3 80 MA/4", 0.75, 1430, 82.5, 5.0, 3.0, 12.0),
]


@pytest.mark.parametrize("name, kw, rpm, eta, torque, start, mass", SOGA_MT3_PRINTED)
def test_soga_mt3_rows_as_printed(name, kw, rpm, eta, torque, start, mass):
    row = load_catalog("motors_soga_mt3").set_index("designation").loc[name]
    assert (row["power_kw"], row["rated_speed_rpm"], row["efficiency_pct"], row["start_torque_ratio"], row["mass_kg"]) \
        == (kw, rpm, eta, start, mass)
    # the catalogue's own torque column, printed to 0.1 N·m (2-3 digits), agrees with T = 9550·P/n
    assert gd.motor.rated_torque_nm(kw, rpm) == pytest.approx(torque, abs=0.05 + 0.005 * torque)


def test_soga_mt3_blanks_are_what_the_table_does_not_print():
    t = load_catalog("motors_soga_mt3")
    assert len(t) == 17 and t["source"].str.contains("p. 17").all()
    assert t["max_torque_ratio"].isna().all() and t["shaft_d_mm"].isna().all()
    assert t[["efficiency_pct", "start_torque_ratio", "mass_kg"]].notna().all().all()
    assert ((t["sync_speed_rpm"] * t["poles"]) == 6000).all() and (t["rated_speed_rpm"] < t["sync_speed_rpm"]).all()
    # the AIR table's source prints none of the three: blank, not guessed
    air = load_catalog("motors_air")
    assert air[["efficiency_pct", "start_torque_ratio", "mass_kg"]].isna().all().all()


def test_select_reports_the_printed_values_and_blanks_as_none():
    sel = gd.motor.select(4.0, 2900, catalog="motors_soga_mt3")
    assert sel.motor["designation"] == "MT3 112 MA/2"
    for text in ("T_start/T_nom = 5.2", "efficiency = 88.1 %", "mass = 33 kg"):
        assert text in sel.message
    assert "T_max" not in sel.message
    assert sel.motor["start_torque_nm"] == pytest.approx(5.2 * 9549.296585513721 * 4.0 / 2930)
    d = json.loads(sel.to_json())["motor"]
    assert d["max_torque_ratio"] is None and d["max_torque_nm"] is None and d["mass_kg"] == 33.0
    air = gd.motor.select(4.0, 1450)
    assert "T_max/T_nom = 2.2" in air.message and "efficiency" not in air.message


@pytest.mark.parametrize("column, value, text", [("efficiency_pct", "100", "below 100"),
                                                 ("start_torque_ratio", "12", "torque ratio above 10"),
                                                 ("mass_kg", "-3", "> 0")])
def test_broken_optional_motor_value_names_row_and_column(tmp_path, column, value, text):
    frame = load_catalog("motors_soga_mt3").drop(columns=["edition", "source", "note"]).head(4)
    frame[column] = frame[column].astype(object)
    frame.loc[2, column] = value
    path = tmp_path / "motors.csv"
    frame.to_csv(path, index=False)
    with pytest.raises(CatalogError) as e:
        load_catalog(path, kind="motors")
    assert "row 4" in str(e.value) and column in str(e.value) and text in str(e.value)


def test_a_user_motor_file_may_leave_out_the_optional_columns(tmp_path):
    path = tmp_path / "motors.csv"
    path.write_text("designation,power_kw,poles,sync_speed_rpm,rated_speed_rpm\nM1,4,4,1500,1440\nM2,5.5,4,1500,1450\n")
    sel = gd.motor.select(5.0, 1450, catalog=str(path))
    assert sel.found and sel.motor["designation"] == "M2" and math.isnan(sel.motor["max_torque_nm"])
