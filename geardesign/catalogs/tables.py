"""Catalog tables (CSV, loaded with pandas) and their validation.

Every table lives in the top-level ``catalogs/`` folder of the source tree, which ships in the
wheel as the package ``geardesign.catalog_files``. A table is named (``"gost13568"``,
``"keys"``, ...) or given as the path of a user's own CSV file in the same format (a
manufacturer's chain list, say). Loading validates the file against its schema: required
columns, types, units in the column names, positive and monotone values where they must be.
A broken file raises :class:`~geardesign.errors.CatalogError` naming the file, the row (as
the line number in the file) and the column.

Units are in the column names (``pitch_mm``, ``breaking_load_kn``, ``mass_kg_m``). Every
bundled table carries ``edition`` and ``source`` columns; user files need not.
"""
from __future__ import annotations

import importlib.resources
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import numpy as np

from ..errors import CatalogError, GearDesignError

from typing import TYPE_CHECKING

if TYPE_CHECKING:       # pandas is imported where a table is made (start-up cost)
    import pandas as pd

__all__ = [
    "catalog_dir",
    "catalog_names",
    "register_catalog",
    "unregister_catalog",
    "Schema",
    "Column",
    "load_catalog",
    "chain_catalog",
    "module_series",
    "center_distance_series",
    "preferred_numbers",
    "key_lengths_mm",
]


@dataclass(frozen=True)
class Column:
    """One column of a schema: its kind, whether blanks are allowed and its sign."""

    name: str
    kind: str = "float"  # "float", "int" or "str"
    required: bool = True  # False: blanks (NaN) allowed
    positive: bool = False


@dataclass(frozen=True)
class Schema:
    kind: str
    columns: tuple[Column, ...]
    # columns whose values must increase strictly down the file (within each group, if given)
    increasing: tuple[str, ...] = ()
    increasing_within: tuple[str, ...] = ()
    # (column, "nonincreasing" | "nondecreasing") along ``increasing`` within each group
    trend: tuple[tuple[str, str], ...] = ()
    bundled_only: tuple[str, ...] = ("edition", "source")
    description: str = ""

    @property
    def names(self) -> tuple[str, ...]:
        return tuple(c.name for c in self.columns)


def _f(name, **kw):
    return Column(name, "float", positive=kw.pop("positive", True), **kw)


CHAIN_SCHEMA = Schema(
    "chains",
    (
        Column("designation", "str"),
        _f("pitch_mm"),
        Column("strands", "int", positive=True),
        _f("roller_d1_mm"),
        _f("inner_width_mm"),
        _f("pin_d_mm"),
        _f("transverse_pitch_mm", required=False),
        _f("hinge_area_mm2"),
        _f("breaking_load_kn"),
        _f("mass_kg_m"),
    ),
    description="roller chains: one row per chain and strand count; hinge area per strand",
)

MOTOR_TORQUE_RATIO_MAX = 10.0   # T/T_nom of a cage motor: catalogues print about 1.5 ... 5.5

SCHEMAS: dict[str, Schema] = {
    "chains": CHAIN_SCHEMA,
    "chain_allowable_pressure": Schema(
        "chain_allowable_pressure",
        (_f("pitch_min_mm"), _f("pitch_max_mm"), _f("n1_rpm"), _f("allowable_pressure_mpa")),
        increasing=("n1_rpm",), increasing_within=("pitch_min_mm",),
        trend=(("allowable_pressure_mpa", "nonincreasing"),),
        description="allowable hinge pressure [p] by pitch group and small-sprocket speed"),
    "chain_safety_factor": Schema(
        "chain_safety_factor",
        (_f("pitch_mm"), _f("n1_rpm"), _f("allowable_safety_factor")),
        description="normative breaking-load safety factor [s] by pitch and speed"),
    "chain_speed_limits": Schema(
        "chain_speed_limits",
        (_f("pitch_mm"), _f("n1_recommended_rpm"), _f("n1_max_rpm"), _f("impacts_allowed_per_s")),
        increasing=("pitch_mm",),
        description="recommended and maximum small-sprocket speed, allowed impacts per second"),
    "chain_operating_factors": Schema(
        "chain_operating_factors",
        (Column("factor", "str"), Column("condition", "str"), _f("value")),
        description="operating factors K_d, K_a, K_n, K_reg, K_lub, K_mode by condition"),
    "chain_strand_factors": Schema(
        "chain_strand_factors",
        (Column("strands", "int", positive=True), _f("hinge_strand_factor"), _f("power_strand_factor")),
        increasing=("strands",),
        trend=(("hinge_strand_factor", "nondecreasing"), ("power_strand_factor", "nondecreasing")),
        description="effective strand counts m*K_m (hinge method) and multiple-strand factors (power rating)"),
    "keys": Schema(
        "keys",
        (_f("d_over_mm"), _f("d_upto_mm"), _f("b_mm"), _f("h_mm"), _f("t1_mm"), _f("t2_mm"),
         _f("l_min_mm", required=False), _f("l_max_mm", required=False)),
        increasing=("d_over_mm",),
        trend=(("b_mm", "nondecreasing"), ("h_mm", "nondecreasing")),
        description="parallel key sections by shaft diameter (GOST 23360-78 / DIN 6885-1)"),
    "key_lengths": Schema(
        "key_lengths", (_f("length_mm"),), increasing=("length_mm",),
        description="standard key lengths"),
    "modules": Schema(
        "modules", (_f("module_mm"), Column("series", "int", positive=True)), increasing=("module_mm",),
        description="gear module series (ISO 54 / GOST 9563)"),
    "center_distances": Schema(
        "center_distances", (_f("a_w_mm"), Column("series", "int", positive=True)), increasing=("a_w_mm",),
        description="standard centre distances (GOST 2185-66)"),
    "preferred_numbers": Schema(
        "preferred_numbers", (_f("value"), Column("series", "int", positive=True)), increasing=("value",),
        description="preferred numbers 1.00 ... 9.50 (ISO 3 basic series R10, R20, R40: the smallest series holding each)"),
    "measuring_balls": Schema(
        "measuring_balls", (_f("ball_mm"), Column("inch", "str", required=False)), increasing=("ball_mm",),
        description="nominal diameters of precision balls (and the pins cut to them) stocked for measuring gears"),
    "motors": Schema(
        "motors",
        (Column("designation", "str"), _f("power_kw"), Column("poles", "int", positive=True), _f("sync_speed_rpm"),
         _f("rated_speed_rpm"), _f("max_torque_ratio", required=False), _f("shaft_d_mm", required=False),
         _f("efficiency_pct", required=False), _f("start_torque_ratio", required=False),
         _f("mass_kg", required=False)),
        # two frames may carry one power step (a catalogue's long-core variant)
        increasing_within=("sync_speed_rpm",), trend=(("power_kw", "nondecreasing"),),
        description="three-phase asynchronous motors: rated power and speed; T_max/T_nom, shaft end diameter, "
                    "efficiency, T_start/T_nom and mass where the source prints them (blank otherwise)"),
    "bearings": Schema(
        "bearings",
        (Column("designation", "str"), Column("series", "str"), Column("type", "str"), _f("d_mm"), _f("D_mm"),
         _f("B_mm"), _f("C_kn"), _f("C0_kn"), _f("Cu_kn", required=False), _f("f0", required=False),
         _f("speed_grease_rpm", required=False), _f("speed_oil_rpm", required=False)),
        increasing=("d_mm",), increasing_within=("series",),
        trend=(("D_mm", "nondecreasing"),),
        description="rolling bearings: bore d, outside diameter D, width B, basic dynamic and static load ratings C, "
                    "C0 and fatigue load limit Cu in kN, the deep groove ball bearing factor f0, allowable speeds"),
    "bearing_factors": Schema(
        "bearing_factors",
        (_f("f0_fa_c0r"), _f("e"), _f("X"), _f("Y")),
        increasing=("f0_fa_c0r",), trend=(("e", "nondecreasing"), ("Y", "nonincreasing")),
        description="e, X and Y of the equivalent dynamic load P = X Fr + Y Fa against f0 Fa/C0r (ISO 281)"),
    "shaft_materials": Schema(
        "shaft_materials",
        (Column("material", "str"), Column("kind", "str"), _f("sigma_B_mpa"), _f("sigma_S_mpa"), _f("d_B_mm")),
        description="shaft steels (DIN 743-3): tensile strength and yield point at the reference diameter d_B"),
}

# Bundled tables: name -> (file, schema kind, row filter on the "series" column or None)
BUNDLED: dict[str, tuple[str, str, str | None]] = {
    "gost13568": ("chains_gost13568.csv", "chains", None),
    "iso606": ("chains_iso606.csv", "chains", None),
    "iso606a": ("chains_iso606.csv", "chains", "A"),
    "iso606b": ("chains_iso606.csv", "chains", "B"),
    "ansi_b29": ("chains_ansi_b29.csv", "chains", None),
    "chain_allowable_pressure": ("chain_allowable_pressure.csv", "chain_allowable_pressure", None),
    "chain_safety_factor": ("chain_safety_factor.csv", "chain_safety_factor", None),
    "chain_speed_limits": ("chain_speed_limits.csv", "chain_speed_limits", None),
    "chain_operating_factors": ("chain_operating_factors.csv", "chain_operating_factors", None),
    "chain_strand_factors": ("chain_strand_factors.csv", "chain_strand_factors", None),
    "keys": ("keys_gost23360.csv", "keys", None),
    "key_lengths": ("key_lengths.csv", "key_lengths", None),
    "modules": ("modules_iso54.csv", "modules", None),
    "center_distances": ("center_distances_gost2185.csv", "center_distances", None),
    "preferred_numbers": ("preferred_numbers_iso3.csv", "preferred_numbers", None),
    "measuring_balls": ("measuring_balls_iso3290.csv", "measuring_balls", None),
    "motors_air": ("motors_air.csv", "motors", None),
    "motors_soga_mt3": ("motors_soga_mt3.csv", "motors", None),
    "motors_motive_delphi": ("motors_motive_delphi.csv", "motors", None),
    "bearings_deep_groove": ("bearings_deep_groove.csv", "bearings", None),
    "bearings_angular_contact": ("bearings_angular_contact.csv", "bearings", None),
    "bearings_cylindrical_roller": ("bearings_cylindrical_roller.csv", "bearings", None),
    "bearing_factors_deep_groove": ("bearing_factors_deep_groove.csv", "bearing_factors", None),
    "shaft_materials_din743": ("shaft_materials_din743.csv", "shaft_materials", None),
    "worm_modules": ("worm_modules_gost19672.csv", "modules", None),
    "worm_center_distances": ("worm_center_distances_gost2144.csv", "center_distances", None),
}
CHAIN_CATALOGS = ("gost13568", "iso606", "iso606a", "iso606b", "ansi_b29")


def register_catalog(name: str, file: str, schema: Schema, series: str | None = None) -> None:
    """Make the bundled CSV ``file`` (in ``catalogs/``) loadable as ``name`` under ``schema`` (a new kind is
    added to :data:`SCHEMAS`): the one step a new table needs besides its file (docs/extending.md)."""
    if name in BUNDLED and BUNDLED[name] != (file, schema.kind, series):
        raise GearDesignError(f"a catalog called {name!r} exists already")
    if SCHEMAS.setdefault(schema.kind, schema) != schema:
        raise GearDesignError(f"a catalog kind {schema.kind!r} with another schema exists already")
    BUNDLED[name] = (file, schema.kind, series)


def unregister_catalog(name: str) -> None:
    """Forget a catalog name :func:`register_catalog` added (its kind stays known)."""
    BUNDLED.pop(name, None)


def catalog_dir():
    """The folder holding the bundled CSV tables.

    The source tree's ``catalogs/`` when running in-tree (tests from the repository root),
    otherwise the installed package ``geardesign.catalog_files``.
    """
    here = Path(__file__).resolve().parents[2] / "catalogs"   # geardesign/catalogs/tables.py -> repo root
    if (here / "chains_gost13568.csv").is_file():
        return here
    return importlib.resources.files("geardesign.catalog_files")


def catalog_names() -> tuple[str, ...]:
    """Names accepted by :func:`load_catalog`."""
    return tuple(BUNDLED)


def _where(path, line: int | None = None, column: str | None = None) -> str:
    parts = [str(path)]
    if line is not None:
        parts.append(f"row {line}")
    if column is not None:
        parts.append(f"column '{column}'")
    return ", ".join(parts)


def _validate(frame: pd.DataFrame, schema: Schema, path, bundled: bool) -> pd.DataFrame:
    """Check and coerce ``frame`` in place of a fresh copy; raise CatalogError on the first fault.

    Row numbers in messages are line numbers of the CSV file (the header is line 1).
    """
    frame = frame.copy()
    _check_columns(frame, schema, path, bundled)
    for col in schema.columns:
        if col.name not in frame.columns:     # an optional column left out: all blank
            frame[col.name] = np.nan
    lines = np.arange(len(frame)) + 2
    for col in schema.columns:
        if col.kind == "str":
            frame[col.name] = _text_column(frame[col.name], col, path, lines)
        else:
            frame[col.name] = _number_column(frame[col.name], col, path, lines)
    _check_order(frame, schema, path, lines)
    _row_rules(frame, schema, path, lines)
    return frame


def _check_columns(frame: pd.DataFrame, schema: Schema, path, bundled: bool) -> None:
    """That the table has rows and every column its schema requires (provenance too when bundled)."""
    if frame.empty:
        raise CatalogError(f"{path}: no rows (a {schema.kind} table needs at least one)")
    needed = tuple(c.name for c in schema.columns if c.required) + (schema.bundled_only if bundled else ())
    missing = [c for c in needed if c not in frame.columns]
    if missing:
        raise CatalogError(
            f"{path}: missing column(s) {', '.join(repr(m) for m in missing)} "
            f"(a {schema.kind} table needs {', '.join(needed)})")


def _text_column(raw: pd.Series, col: Column, path, lines) -> pd.Series:
    """A text column, stripped; a required one must have no blank cell."""
    blank = raw.isna() | (raw.astype(str).str.strip() == "")
    if col.required and blank.any():
        i = int(np.argmax(blank.to_numpy()))
        raise CatalogError(f"{_where(path, lines[i], col.name)}: empty, a text value is required")
    return raw.astype(str).str.strip()


def _number_column(raw: pd.Series, col: Column, path, lines) -> np.ndarray:
    """A number column as floats (int64 for a whole-number column without blanks), each cell checked:
    a number, present if required, finite, > 0 if positive, whole if an int."""
    import pandas as pd   # here: pandas costs ~0.3 s to import; `geardesign --help` reads this module's constants only

    values = pd.to_numeric(raw, errors="coerce")
    bad_type = values.isna() & raw.notna() & (raw.astype(str).str.strip() != "")
    if bad_type.any():
        i = int(np.argmax(bad_type.to_numpy()))
        raise CatalogError(f"{_where(path, lines[i], col.name)}: not a number, got {raw.iloc[i]!r}")
    arr = values.to_numpy(dtype=float)
    if col.required and np.isnan(arr).any():
        i = int(np.argmax(np.isnan(arr)))
        raise CatalogError(f"{_where(path, lines[i], col.name)}: empty, a number is required")
    if np.isinf(arr).any():
        i = int(np.argmax(np.isinf(arr)))
        raise CatalogError(f"{_where(path, lines[i], col.name)}: must be finite, got {arr[i]!r}")
    if col.positive and (arr <= 0).any():
        i = int(np.argmax(arr <= 0))
        raise CatalogError(f"{_where(path, lines[i], col.name)}: must be > 0, got {arr[i]!r}")
    if col.kind != "int":
        return arr
    frac = ~np.isnan(arr) & (arr != np.round(arr))
    if frac.any():
        i = int(np.argmax(frac))
        raise CatalogError(f"{_where(path, lines[i], col.name)}: must be a whole number, got {arr[i]!r}")
    # a blank in an optional whole-number column keeps it float (NaN has no int64)
    return arr.astype(np.int64) if not np.isnan(arr).any() else arr


def _check_order(frame: pd.DataFrame, schema: Schema, path, lines) -> None:
    """The ``increasing`` columns rise and the ``trend`` columns keep their sense down the table,
    within each group of equal ``increasing_within`` values."""
    if schema.increasing_within:
        codes = frame.groupby(list(schema.increasing_within), sort=False).ngroup().to_numpy()
        groups = [frame.index.to_numpy()[codes == g] for g in np.unique(codes)]
    else:
        groups = [frame.index.to_numpy()]
    for idx in groups:
        for col in schema.increasing:
            v = frame.loc[idx, col].to_numpy(dtype=float)
            bad = np.flatnonzero(np.diff(v) <= 0)
            if bad.size:
                i = idx[bad[0] + 1]
                raise CatalogError(
                    f"{_where(path, lines[frame.index.get_loc(i)], col)}: values must increase down the "
                    f"table, got {v[bad[0] + 1]!r} after {v[bad[0]]!r}")
        for col, how in schema.trend:
            v = frame.loc[idx, col].to_numpy(dtype=float)
            step = np.diff(v)
            bad = np.flatnonzero(step > 0 if how == "nonincreasing" else step < 0)
            if bad.size:
                i = idx[bad[0] + 1]
                word = "rise" if how == "nonincreasing" else "fall"
                raise CatalogError(
                    f"{_where(path, lines[frame.index.get_loc(i)], col)}: must not {word} down the table, "
                    f"got {v[bad[0] + 1]!r} after {v[bad[0]]!r}")


def _row_rules(frame: pd.DataFrame, schema: Schema, path, lines) -> None:
    """Consistency rules between columns of one row."""
    def fail(mask, col, text):
        if mask.any():
            i = int(np.argmax(mask))
            raise CatalogError(f"{_where(path, lines[i], col)}: {text}")

    if schema.kind == "chains":
        multi = frame["strands"].to_numpy() > 1
        fail(multi & np.isnan(frame["transverse_pitch_mm"].to_numpy(dtype=float)), "transverse_pitch_mm",
             "a chain with more than one strand needs its transverse pitch")
        fail(frame["roller_d1_mm"].to_numpy() >= frame["pitch_mm"].to_numpy(), "roller_d1_mm",
             "the roller diameter must be smaller than the pitch")
        fail(frame["pin_d_mm"].to_numpy() >= frame["roller_d1_mm"].to_numpy(), "pin_d_mm",
             "the pin diameter must be smaller than the roller diameter")
    elif schema.kind == "chain_allowable_pressure":
        fail(frame["pitch_max_mm"].to_numpy() < frame["pitch_min_mm"].to_numpy(), "pitch_max_mm",
             "pitch_max_mm must be >= pitch_min_mm")
    elif schema.kind == "keys":
        fail(frame["d_upto_mm"].to_numpy() <= frame["d_over_mm"].to_numpy(), "d_upto_mm",
             "d_upto_mm must be > d_over_mm")
        gap = frame["d_over_mm"].to_numpy()[1:] != frame["d_upto_mm"].to_numpy()[:-1]
        fail(np.concatenate([[False], gap]), "d_over_mm", "shaft ranges must join (d_over = previous d_upto)")
        fail(frame["t1_mm"].to_numpy() >= frame["h_mm"].to_numpy(), "t1_mm", "shaft depth t1 must be < key height h")
        lmin, lmax = frame["l_min_mm"].to_numpy(dtype=float), frame["l_max_mm"].to_numpy(dtype=float)
        fail(lmax < lmin, "l_max_mm", "l_max_mm must be >= l_min_mm")
    elif schema.kind == "motors":
        sync, rated = frame["sync_speed_rpm"].to_numpy(), frame["rated_speed_rpm"].to_numpy()
        fail(np.abs(sync * frame["poles"].to_numpy() - 6000.0) > 1e-9, "sync_speed_rpm",
             "the synchronous speed must be 6000/poles rpm (50 Hz mains)")
        fail(rated >= sync, "rated_speed_rpm", "an asynchronous motor runs below its synchronous speed")
        fail(frame["max_torque_ratio"].to_numpy() <= 1.0, "max_torque_ratio", "T_max/T_nom must exceed 1")
        fail(frame["efficiency_pct"].to_numpy() >= 100.0, "efficiency_pct", "efficiency must be below 100 %")
        for col, top in (("max_torque_ratio", MOTOR_TORQUE_RATIO_MAX), ("start_torque_ratio", MOTOR_TORQUE_RATIO_MAX)):
            fail(frame[col].to_numpy() > top, col, f"a torque ratio above {top:g} is not a catalogue motor's")
    elif schema.kind == "bearings":
        d, D, B = (frame[c].to_numpy(dtype=float) for c in ("d_mm", "D_mm", "B_mm"))
        fail(D <= d, "D_mm", "the outside diameter must exceed the bore")
        fail(B >= D - d, "B_mm", "the width must be less than D - d (a radial bearing)")
        fail(frame["C0_kn"].to_numpy() > 3.0 * frame["C_kn"].to_numpy(), "C0_kn",
             "C0 above 3 C is not a radial bearing's rating (a slip of the decimal point)")
        fail(frame["Cu_kn"].to_numpy(dtype=float) >= frame["C0_kn"].to_numpy(), "Cu_kn",
             "the fatigue load limit must be below C0")
    elif schema.kind in ("modules", "center_distances"):
        fail(~frame["series"].isin([1, 2]).to_numpy(), "series", "series must be 1 or 2")
    elif schema.kind == "preferred_numbers":
        fail(~frame["series"].isin([10, 20, 40]).to_numpy(), "series", "series must be 10, 20 or 40 (R10, R20, R40)")
        value = frame["value"].to_numpy()
        fail((value < 1.0) | (value >= 10.0), "value", "preferred numbers of one decade lie in [1, 10)")


def _schema_for(frame_columns, kind: str | None, path) -> Schema:
    if kind is not None:
        if kind not in SCHEMAS:
            raise GearDesignError(f"catalog kind must be one of {', '.join(SCHEMAS)}, got {kind!r}")
        return SCHEMAS[kind]
    for schema in SCHEMAS.values():
        if {c.name for c in schema.columns if c.required} <= set(frame_columns):
            return schema
    raise CatalogError(
        f"{path}: columns {', '.join(frame_columns)} match no known table; pass kind= one of {', '.join(SCHEMAS)}")


CATALOG_BYTES_MAX = 4 << 20   # 4 MiB: the largest bundled table is a few kB


@lru_cache(maxsize=64)
def _read_cached(path_text: str, mtime_ns: int, kind: str | None, bundled: bool, series: str | None):
    path = Path(path_text)
    if not path.is_file():
        raise CatalogError(f"{path}: not a regular file (a catalog is a CSV text file)")
    if path.stat().st_size > CATALOG_BYTES_MAX:
        raise CatalogError(f"{path}: larger than {CATALOG_BYTES_MAX >> 20} MiB; a catalog is a table of standard sizes")
    import pandas as pd   # here: pandas costs ~0.3 s to import; `geardesign --help` reads this module's constants only

    try:
        raw = pd.read_csv(path, dtype=str, keep_default_na=False, na_values=[""], comment=None)
    except pd.errors.EmptyDataError:
        raise CatalogError(f"{path}: empty (a catalog needs a header row and at least one row)") from None
    except pd.errors.ParserError as exc:
        raise CatalogError(f"{path}: not a readable CSV file ({exc})") from None
    except UnicodeDecodeError as exc:
        raise CatalogError(f"{path}: not UTF-8 text ({exc})") from None
    raw.columns = [c.strip() for c in raw.columns]
    schema = _schema_for(tuple(raw.columns), kind, path)
    frame = _validate(raw, schema, path, bundled)
    if series is not None:
        frame = frame[frame["series"] == series].reset_index(drop=True)
    frame.attrs["path"] = str(path)
    frame.attrs["kind"] = schema.kind
    return frame


def load_catalog(name_or_path, kind: str | None = None) -> pd.DataFrame:
    """Load and validate a catalog table.

    Parameters
    ----------
    name_or_path : str or path-like
        A bundled table name (see :func:`catalog_names`: ``"gost13568"``, ``"iso606a"``,
        ``"keys"``, ``"modules"``, ...) or the path of a CSV file in the same format.
    kind : str, optional
        The schema a user file must follow (``"chains"``, ``"keys"``, ...). Inferred from the
        columns when omitted.

    Returns
    -------
    pandas.DataFrame
        A fresh copy (safe to modify); ``frame.attrs["path"]`` and ``["kind"]`` say where it
        came from. Lengths in mm, forces in kN, masses in kg/m, speeds in rpm.

    Raises
    ------
    CatalogError
        Unknown name, missing file, or a file that breaks its schema (names file, row, column).
    """
    series = None
    bundled = False
    if isinstance(name_or_path, str) and name_or_path in BUNDLED:
        file, bundled_kind, series = BUNDLED[name_or_path]
        if kind is not None and kind != bundled_kind:
            raise GearDesignError(f"catalog {name_or_path!r} is a {bundled_kind} table, not {kind!r}")
        kind = bundled_kind
        path = catalog_dir() / file
        bundled = True
    elif isinstance(name_or_path, (str, Path)) and (
            isinstance(name_or_path, Path) or name_or_path.lower().endswith(".csv") or "/" in name_or_path
            or "\\" in name_or_path):
        path = Path(name_or_path)
    else:   # offer only the tables of the kind asked for (a chain catalog is never a key table)
        names = [n for n, (_, k, _) in BUNDLED.items() if kind is None or k == kind]
        what = "catalog" if kind is None else f"{kind} catalog"
        raise CatalogError(
            f"{what} must be one of {', '.join(names)} or the path of a .csv file, got {name_or_path!r}")
    try:
        with importlib.resources.as_file(path) as real:
            real = Path(real)
            if not real.is_file():
                raise CatalogError(f"{real}: catalog file not found")
            frame = _read_cached(str(real), real.stat().st_mtime_ns, kind, bundled, series)
    except OSError as exc:
        raise CatalogError(f"{path}: cannot read catalog file ({exc})") from None
    out = frame.copy()
    out.attrs = dict(frame.attrs)
    return out


def chain_catalog(name_or_path="gost13568") -> pd.DataFrame:
    """A validated roller-chain table (see :data:`CHAIN_SCHEMA`), sorted by pitch and strands.

    ``name_or_path`` is one of ``"gost13568"``, ``"iso606"``, ``"iso606a"``, ``"iso606b"``,
    ``"ansi_b29"`` or a path to a CSV with the chain columns (a manufacturer's list).
    """
    if isinstance(name_or_path, str) and name_or_path in BUNDLED and name_or_path not in CHAIN_CATALOGS:
        raise GearDesignError(
            f"catalog must be a chain table ({', '.join(CHAIN_CATALOGS)}) or a CSV path, got {name_or_path!r}")
    frame = load_catalog(name_or_path, kind="chains")
    attrs = dict(frame.attrs)
    frame = frame.sort_values(["pitch_mm", "strands", "breaking_load_kn"], kind="stable").reset_index(drop=True)
    frame.attrs = attrs
    frame.attrs["name"] = str(name_or_path)
    return frame


def _series_values(name: str, column: str, series) -> np.ndarray:
    wanted = (series,) if np.ndim(series) == 0 else tuple(series)
    bad = [s for s in wanted if s not in (1, 2)]
    if bad or not wanted:
        raise GearDesignError(f"series must be 1, 2 or (1, 2), got {series!r}")
    frame = load_catalog(name)
    return np.sort(frame.loc[frame["series"].isin(wanted), column].to_numpy(dtype=float))


def module_series(series=(1, 2), min_mm: float | None = None, max_mm: float | None = None) -> np.ndarray:
    """Standard gear modules in mm (ISO 54:1996 1-50 mm; GOST 9563-60 0.05-100 mm), sorted.

    ``series`` is 1 (preferred), 2, or (1, 2). ``min_mm``/``max_mm`` bound the range.

    >>> module_series(1, 1, 3).tolist()
    [1.0, 1.25, 1.5, 2.0, 2.5, 3.0]
    """
    values = _series_values("modules", "module_mm", series)
    lo = -np.inf if min_mm is None else min_mm
    hi = np.inf if max_mm is None else max_mm
    return values[(values >= lo) & (values <= hi)]


def measuring_ball_series() -> np.ndarray:
    """Nominal diameters of the precision balls a shop can buy for the dimension over balls, mm, sorted (ISO 3290-1
    metric and inch sizes, as a maker stocks them: ``catalogs/measuring_balls_iso3290.csv``).

    >>> [float(v) for v in measuring_ball_series()[:4]]
    [1.5, 1.5875, 2.0, 2.3812]
    """
    return np.sort(load_catalog("measuring_balls")["ball_mm"].to_numpy(dtype=float))


def center_distance_series(series=(1, 2), min_mm: float | None = None, max_mm: float | None = None) -> np.ndarray:
    """Standard centre distances a_w in mm (GOST 2185-66, series 1 and 2), sorted.

    >>> center_distance_series(2, 100, 200).tolist()
    [112.0, 140.0, 180.0]
    """
    values = _series_values("center_distances", "a_w_mm", series)
    lo = -np.inf if min_mm is None else min_mm
    hi = np.inf if max_mm is None else max_mm
    return values[(values >= lo) & (values <= hi)]


def preferred_numbers(series: str = "R20", min_value: float = 1.0, max_value: float = 1e4) -> np.ndarray:
    """The ISO 3 preferred numbers of basic series ``series`` ("R10", "R20" or "R40") in [min_value, max_value],
    sorted: the table's decade 1.00 ... 9.50 times the powers of ten.

    >>> preferred_numbers("R20", 100, 200).tolist()
    [100.0, 112.0, 125.0, 140.0, 160.0, 180.0, 200.0]
    """
    names = {"R10": (10,), "R20": (10, 20), "R40": (10, 20, 40)}
    if series not in names:
        raise GearDesignError(f"series must be one of {', '.join(names)}, got {series!r}")
    frame = load_catalog("preferred_numbers")
    decade = frame.loc[frame["series"].isin(names[series]), "value"].to_numpy(dtype=float)
    lo, hi = int(np.floor(np.log10(min_value))) - 1, int(np.ceil(np.log10(max_value))) + 1
    # round to the table's two decimals after scaling, so that 1.12 × 100 is 112 exactly
    values = np.concatenate([np.round(decade * 10.0 ** k, max(2 - k, 0)) for k in range(lo, hi + 1)])
    return np.sort(values[(values >= min_value) & (values <= max_value)])


def key_lengths_mm() -> np.ndarray:
    """The standard parallel-key lengths in mm (GOST 23360-78), ascending."""
    return load_catalog("key_lengths")["length_mm"].to_numpy(dtype=float)
