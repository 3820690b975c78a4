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
    ("motors_soga_mt3", 0.7, 1400, 1.0), ("motors_soga_mt3", 0.7, 2000, 1.0),
    # Motive Delphi: long-core frames give two motors of one power (4 kW 4-pole: 100LC-4 and 112M-4)
    ("motors_motive_delphi", 4.0, 1450, 1.0), ("motors_motive_delphi", 22.0, 1450, 1.0),
    ("motors_motive_delphi", 5.5, 2900, 1.0), ("motors_motive_delphi", 3.0, 960, 1.0),
    ("motors_motive_delphi", 0.3, 700, 1.0), ("motors_motive_delphi", 25.0, 980, 1.2)])
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


@pytest.mark.parametrize("kw", [dict(power_kw=-1, n_rpm=1500), dict(power_kw=4, n_rpm=0),
                                dict(power_kw=4, n_rpm=1500, service_factor=0.5),
                                dict(power_kw=4, n_rpm=1500, catalog="nope")])
def test_bad_inputs_name_themselves(kw):
    with pytest.raises(GearDesignError) as e:
        gd.motor.select(**kw)
    name = [k for k in kw if k not in ("power_kw", "n_rpm")] or [k for k, v in kw.items() if v in (-1, 0)]
    assert name[0] in str(e.value)


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


# Motive s.r.l. (Italy), "General catalogue Delphi series asynchronous three-phase electric motors",
# 07 04 Rev.03: technical data p. 20 (2 poles), p. 21 (4), p. 22 (6), p. 23 (8) at 400 V 50 Hz; shaft
# end D from the B3 dimension table, p. 16. Read as text at https://github.com/ArtemFilin1990/Mar/blob/
# 7b871a585843d5d9236be7a5c36364a6ecb97a9d/12_Прочее_сопутствующее/Прочее/jelektrodvigateli-motive.md
# As printed: type, page, kW, rpm, Cn N·m, Cs/Cn, Cmax/Cn, efficiency % at 100 % load, kg, Cs N·m,
# Cmax N·m; then D mm of the type's frame and poles on p. 16.
MOTIVE_DELPHI_PRINTED = [
    ("80A-2", 20, 0.75, 2854, 2.51, 2.8, 3.0, 79.0, 10.0, 7.10, 7.50, 19),
    ("132MB-2", 20, 11.0, 2919, 35.99, 2.3, 3.0, 88.6, 55.0, 82.90, 108.10, 38),
    ("180M-2", 20, 22.0, 2959, 71.00, 2.5, 3.1, 91.4, 165.0, 174.50, 220.80, 48),
    ("71B-4", 21, 0.37, 1366, 2.59, 2.3, 2.4, 71.5, 6.3, 6.00, 6.10, 14),
    ("100LC-4", 21, 4.0, 1415, 27.00, 3.0, 3.0, 84.2, 27.0, 80.99, 80.99, 28),
    ("112M-4", 21, 4.0, 1453, 26.29, 2.5, 3.2, 85.8, 28.0, 65.80, 85.20, 28),
    ("200L-4", 21, 30.0, 1480, 193.58, 2.2, 2.3, 92.6, 245.0, 425.88, 445.24, 55),
    ("132MB-6", 22, 5.5, 972, 54.04, 1.6, 2.6, 84.6, 55.0, 84.90, 143.00, 38),
    ("200LB-6", 22, 22.0, 970, 216.60, 2.1, 2.1, 90.1, 244.0, 454.86, 454.86, 55),
    ("160L-8", 23, 7.5, 720, 99.48, 2.0, 2.0, 87.2, 90.0, 198.96, 198.96, 42),
]


@pytest.mark.parametrize("name, page, kw, rpm, cn, start, top, eta, mass, cs_nm, cmax_nm, d", MOTIVE_DELPHI_PRINTED)
def test_motive_delphi_rows_as_printed(name, page, kw, rpm, cn, start, top, eta, mass, cs_nm, cmax_nm, d):
    row = load_catalog("motors_motive_delphi").set_index("designation").loc["Delphi " + name]
    poles = int(name[-1])
    assert (row["power_kw"], row["poles"], row["sync_speed_rpm"], row["rated_speed_rpm"]) == (kw, poles, 6000 / poles, rpm)
    assert (row["start_torque_ratio"], row["max_torque_ratio"], row["efficiency_pct"], row["mass_kg"],
            row["shaft_d_mm"]) == (start, top, eta, mass, d)
    assert f"p. {page}," in row["source"] and "p. 16" in row["source"]
    # the catalogue's rated torque is Cn = 9550·P/n printed to 0.01 N·m; ours (P/ω) agrees to 1e-4
    assert abs(9550 * kw / rpm - cn) <= 0.005 + 1e-9
    assert gd.motor.rated_torque_nm(kw, rpm) == pytest.approx(cn, rel=1e-4, abs=0.006)
    # the ratios (printed to 0.1) are the catalogue's own torques over Cn: Cs = (Cs/Cn)·Cn, Cmax = (Cmax/Cn)·Cn
    assert row["start_torque_ratio"] * cn == pytest.approx(cs_nm, abs=0.05 * cn + 0.01)
    assert row["max_torque_ratio"] * cn == pytest.approx(cmax_nm, abs=0.05 * cn + 0.01)


def test_motive_delphi_has_every_column_for_every_row():
    t = load_catalog("motors_motive_delphi")
    assert len(t) == 129 and t["poles"].value_counts().to_dict() == {4: 41, 2: 40, 6: 27, 8: 21}
    cols = ["power_kw", "rated_speed_rpm", "efficiency_pct", "start_torque_ratio", "max_torque_ratio",
            "shaft_d_mm", "mass_kg", "frame", "source"]
    assert t[cols].notna().all().all()
    pages = {2: "p. 20,", 4: "p. 21,", 6: "p. 22,", 8: "p. 23,"}
    assert all(pages[p] in s for p, s in zip(t["poles"], t["source"]))
    # a breakdown torque is the top of the torque-speed curve, so T_max >= T_start; four small motors are
    # printed the other way round (by 0.1 ... 0.3) and carry a note saying so
    odd = t[t["start_torque_ratio"] > t["max_torque_ratio"]]
    assert sorted(odd["designation"]) == ["Delphi 63C-2", "Delphi 71B-2", "Delphi 90LB-4", "Delphi 90S-4"]
    assert odd["note"].str.contains("exceeds").all()
    # Motive's brake-motor catalogue ATDC (REV00, dimension table, same frames) prints the same shaft ends:
    # ATDC 63 ... 160L: D = 11, 14, 19, 24, 24, 28, 28, 38, 38, 42, 42 mm
    atdc = {"63": 11, "71": 14, "80": 19, "90S": 24, "90L": 24, "100L": 28, "112M": 28, "132S": 38, "132M": 38,
            "160M": 42, "160L": 42}
    for frame, d in atdc.items():
        assert set(t.loc[t["frame"] == frame, "shaft_d_mm"]) == {d}, frame


def test_motive_delphi_select_four_kw_at_1450():
    # p. 21 prints two 4 kW 4-pole motors: 100LC-4 (1415 rpm, 27 kg) and 112M-4 (1453 rpm, 28 kg); the
    # 2-pole 4 kW motors run at 2885 rpm. The speed series is 1500 rpm; of one power the lighter frame wins.
    sel = gd.motor.select(4.0, 1450, catalog="motors_motive_delphi")
    assert sel.found and sel.motor["designation"] == "Delphi 100LC-4" and sel.motor["shaft_d_mm"] == 28
    for text in ("T_max/T_nom = 3", "T_start/T_nom = 3", "efficiency = 84.2 %", "mass = 27 kg"):
        assert text in sel.message
    assert sel.motor["max_torque_nm"] == pytest.approx(3.0 * 27.00, rel=2e-3)
    assert list(sel.candidates["sync_speed_rpm"]) == [1500, 1000, 750, 3000]
