"""Three-phase asynchronous motors from a catalog, and the choice of one for a drive.

Three bundled tables (docs/drive_train.md says where each value comes from):

- ``motors_air`` (the default): the AIR series as the Russian course-design books tabulate it:
  rated power P (the IEC 60034 power steps 0.37 … 30 kW), synchronous speed n_s = 6000/poles rpm
  (50 Hz), rated speed n, T_max/T_nom and the shaft-end diameter; efficiency, T_start/T_nom and
  mass are not in its source, so they are blank.
- ``motors_soga_mt3``: SOGA's MT3 IE3 series (catalogue table, 400 V 50 Hz): power, rated speed,
  efficiency, T_start/T_nom and mass as printed; T_max/T_nom and the shaft diameter are not in
  that table, so they are blank.
- ``motors_motive_delphi``: Motive's Delphi series (general catalogue 07 04 Rev.03, 400 V 50 Hz,
  S1), 2, 4, 6 and 8 poles, 0.06 … 315 kW: every column — power, rated speed, efficiency,
  T_start/T_nom, T_max/T_nom and mass from the technical-data tables, the shaft-end diameter from
  the catalogue's B3 dimension table (by frame and poles).

A blank is a value the source does not print, never an estimate.

Rated torque T = 9550·P/n [N·m] (P in kW, n in rpm), i.e. T = P/ω with ω = 2πn/60.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import pandas as pd

from ..catalogs.tables import load_catalog
from ..errors import GearDesignError
from ..renamed import renamed_keywords
from ..results import Result
from ..validate import one_number, require_range

__all__ = ["MotorSelection", "select", "rated_torque_nm", "MOTOR_CATALOGS", "SERVICE_FACTOR_RANGE",
           "POWER_RANGE_KW", "SPEED_RANGE_RPM"]

MOTOR_CATALOGS = ("motors_air", "motors_soga_mt3", "motors_motive_delphi")   # the first is the default
SERVICE_FACTOR_RANGE = (1.0, 5.0)    # a design allowance on the power, not a second motor
POWER_RANGE_KW = (1e-3, 1e5)
SPEED_RANGE_RPM = (1.0, 10_000.0)    # 50 Hz mains: at most 3000 rpm synchronous; a wish above is a slip


# the optional catalog values the message reports when the row has them
_PRINTED = (("T_max/T_nom", "max_torque_ratio", ""), ("T_start/T_nom", "start_torque_ratio", ""),
            ("efficiency", "efficiency_pct", " %"), ("mass", "mass_kg", " kg"))


@renamed_keywords(speed_rpm="n_rpm")
def rated_torque_nm(power_kw, n_rpm):
    """Rated torque T = P/ω = 9550·P/n [N·m], P in kW, n in rpm (ω = 2πn/60).

    Seed 002's AIR100L4 (4 kW) at its 1410 rpm rated speed:

    >>> round(rated_torque_nm(4.0, 1410), 3)
    27.09
    """
    return 1000.0 * power_kw / (2.0 * math.pi * n_rpm / 60.0)


@dataclass(frozen=True, eq=False)
class MotorSelection(Result):
    """Result of :func:`select`: the chosen motor (a catalog row) and every row considered.

    ``motor`` has the catalog's columns plus ``rated_torque_nm``, ``max_torque_nm`` and
    ``start_torque_nm`` (NaN, None in ``to_dict``, where the catalog leaves the ratio blank);
    ``candidates`` lists the rows with enough power, nearest speed first.
    """

    found: bool
    message: str
    power_kw: float
    speed_rpm: float
    service_factor: float
    motor: pd.Series | None
    candidates: pd.DataFrame

    _success_field = "found"
    _table_fields = ("candidates",)

    def __repr__(self) -> str:
        return f"MotorSelection(P >= {self.power_kw * self.service_factor:g} kW, n ~ {self.speed_rpm:g} rpm): {self.message}"


@renamed_keywords(speed_rpm="n_rpm")
def select(power_kw, n_rpm, service_factor=1.0, catalog="motors_air") -> MotorSelection:
    """The motor for a drive: the smallest rated power P >= power_kw·service_factor, of the
    synchronous speed whose rated speed is nearest ``n_rpm`` (``speed_rpm=`` is its old name; the
    result keeps the field ``speed_rpm``, a key of the ``drive`` command's JSON) (the usual course-design
    rule: pick the speed series, then the first power step that covers the need).

    Ties in speed go to the faster series (a smaller, lighter motor for the same power); two
    frames of one power in a series (SOGA MT3 lists some) go to the lighter.

    >>> select(3.5, 1450).motor["designation"]
    'AIR100L4'
    """
    p = one_number("power_kw", require_range("power_kw", power_kw, *POWER_RANGE_KW, unit="kW"))
    n = one_number("n_rpm", require_range("n_rpm", n_rpm, *SPEED_RANGE_RPM, unit="rpm"))
    sf = one_number("service_factor", require_range("service_factor", service_factor, *SERVICE_FACTOR_RANGE))
    if not (isinstance(catalog, str) and (catalog in MOTOR_CATALOGS or catalog.lower().endswith(".csv"))):
        raise GearDesignError(f"catalog must be one of {', '.join(MOTOR_CATALOGS)} or a motor CSV path, got {catalog!r}")
    table = load_catalog(catalog, kind="motors")
    need = p * sf
    enough = table[table["power_kw"] >= need * (1 - 1e-12)].copy()
    if enough.empty:
        top = table["power_kw"].max()
        return MotorSelection(False, f"no motor in {catalog!r} gives {need:g} kW (the largest is {top:g} kW)",
                              p, n, sf, None, enough)
    enough["rated_torque_nm"] = rated_torque_nm(enough["power_kw"], enough["rated_speed_rpm"])
    enough["max_torque_nm"] = enough["rated_torque_nm"] * enough["max_torque_ratio"]
    enough["start_torque_nm"] = enough["rated_torque_nm"] * enough["start_torque_ratio"]
    enough["speed_error_rpm"] = (enough["rated_speed_rpm"] - n).abs()
    # one row per speed series: its first power step that covers the need (of two frames with
    # one power, the lighter where the catalog prints masses, else the first listed)
    first = (enough.sort_values(["sync_speed_rpm", "power_kw", "mass_kg"], kind="stable", na_position="last")
             .groupby("sync_speed_rpm").head(1))
    ranked = first.sort_values(["speed_error_rpm", "sync_speed_rpm"], ascending=[True, False], kind="stable")
    ranked = ranked.reset_index(drop=True)
    best = ranked.iloc[0]
    printed = [f"{label} = {best[col]:g}{unit}" for label, col, unit in _PRINTED if not math.isnan(best[col])]
    msg = (f"{best['designation']}: {best['power_kw']:g} kW, {best['rated_speed_rpm']:g} rpm "
           f"({best['sync_speed_rpm']:g} rpm synchronous), T_nom = {best['rated_torque_nm']:.4g} N·m"
           + "".join(", " + s for s in printed) + f"; needed {need:g} kW"
           + (f" (= {p:g} kW x service factor {sf:g})" if sf != 1.0 else ""))
    return MotorSelection(True, msg, p, n, sf, best, ranked)
