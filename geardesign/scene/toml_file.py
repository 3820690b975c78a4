"""Reading a scene file: a bounded read of a regular file, TOML parsed, its nesting and integers checked; shared by
:func:`geardesign.scene.load.load_scene` and :func:`geardesign.scene.engine.load_engine`."""
from __future__ import annotations

import tomllib
from pathlib import Path

from ..errors import GearDesignError

__all__ = ["read_scene_toml", "SCENE_BYTES_MAX", "SCENE_DEPTH_MAX", "SCENE_INT_MAX"]

SCENE_BYTES_MAX = 1 << 20    # 1 MiB: a scene is a page of settings, not data

SCENE_DEPTH_MAX = 8          # sections, tables of tables, lists: a few levels at most

SCENE_INT_MAX = 10**15       # integers beyond this are typing slips (and overflow floats)


def _read_bounded(path: Path) -> bytes:
    """The scene file's bytes: a regular file of at most SCENE_BYTES_MAX (a device such as
    /dev/zero, a folder or a huge file is refused before it is read)."""
    try:
        if not path.exists():
            raise GearDesignError(f"{path}: cannot read the scene file (no such file)")
        if not path.is_file():
            raise GearDesignError(f"{path}: not a regular file (a scene is a .toml text file)")
        with open(path, "rb") as fh:
            text = fh.read(SCENE_BYTES_MAX + 1)
    except OSError as exc:
        raise GearDesignError(f"{path}: cannot read the scene file ({exc.strerror or exc})") from None
    if len(text) > SCENE_BYTES_MAX:
        raise GearDesignError(f"{path}: larger than {SCENE_BYTES_MAX // 1024} KiB; a scene file is a page of settings")
    return text


def _check_values(path: Path, value, key: str = "", depth: int = 0) -> None:
    """Refuse nesting deeper than SCENE_DEPTH_MAX and integers beyond SCENE_INT_MAX, by key."""
    if depth > SCENE_DEPTH_MAX:
        raise GearDesignError(f"{path}: {key or 'the file'} is nested deeper than {SCENE_DEPTH_MAX} levels")
    if isinstance(value, dict):
        for k, v in value.items():
            _check_values(path, v, f"{key}.{k}" if key else str(k), depth + 1)
    elif isinstance(value, list):
        for v in value:
            _check_values(path, v, key, depth + 1)
    elif isinstance(value, int) and not isinstance(value, bool) and abs(value) > SCENE_INT_MAX:
        raise GearDesignError(f"{path}: {key} = an integer of {len(str(abs(value)))} digits; "
                              f"whole numbers must be within ±{SCENE_INT_MAX:.0e}")



def read_scene_toml(path) -> dict:
    """The scene file at ``path`` parsed (:func:`_read_bounded`, then TOML, then :func:`_check_values`); one
    GearDesignError naming the file on the first problem."""
    path = Path(path)
    text = _read_bounded(path)
    try:
        raw = tomllib.loads(text.decode("utf-8"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as exc:
        raise GearDesignError(f"{path}: not a valid TOML file: {' '.join(str(exc).split())}") from None
    except RecursionError:
        raise GearDesignError(f"{path}: nested deeper than a scene can be (at most {SCENE_DEPTH_MAX} levels)") from None
    _check_values(path, raw)
    return raw
