"""Output files that are either whole or absent: paths checked before any work, results written
under a temporary name and moved into place only when complete, nothing overwritten unasked.

A mistyped ``--plot`` or ``--out`` must not destroy a user's file, and a run that fails (bad
input found late, a full disk, Ctrl-C) must leave the target exactly as it was.
"""
from __future__ import annotations

import os
import shutil
import tempfile
from pathlib import Path

from .errors import GearDesignError

__all__ = ["check_output_path", "check_output_dir", "write_file_atomic", "write_dir_atomic"]


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def _as_if_created(path, mode: int) -> None:
    """Give a temporary file (0600) or folder (0700) the permissions a plain create would."""
    os.chmod(path, mode & ~_umask())


def _parent_ok(path: Path, what: str) -> None:
    parent = path.parent if str(path.parent) else Path(".")
    if not parent.is_dir():
        raise GearDesignError(f"{what} {str(path)!r}: the folder {str(parent)!r} does not exist")
    if not os.access(parent, os.W_OK | os.X_OK):
        raise GearDesignError(f"{what} {str(path)!r}: the folder {str(parent)!r} is not writable")


def check_output_path(path, *, overwrite: bool = False, suffixes=(".png",), what: str = "--plot") -> Path:
    """The path of one output file, checked before any computation: a known extension, an
    existing writable folder, not a folder itself, and not an existing file unless ``overwrite``.

    >>> check_output_path("contour.txt", suffixes=(".png",))
    Traceback (most recent call last):
    ...
    geardesign.errors.GearDesignError: --plot 'contour.txt': the file name must end in .png
    """
    p = Path(os.fspath(path))
    if p.suffix.lower() not in suffixes:
        raise GearDesignError(f"{what} {str(p)!r}: the file name must end in {' or '.join(suffixes)}")
    if p.is_dir():
        raise GearDesignError(f"{what} {str(p)!r} is a folder, not a file")
    _parent_ok(p, what)
    if p.exists() and not overwrite:
        raise GearDesignError(f"{what} {str(p)!r} exists: give --overwrite to replace it")
    return p


def check_output_dir(path, *, overwrite: bool = False, what: str = "--out") -> Path:
    """An output folder, checked before any computation: new (in an existing folder) or empty;
    a folder with files in it, or a file, only with ``overwrite`` (then replaced whole)."""
    p = Path(os.fspath(path))
    if p.exists() and not p.is_dir():
        raise GearDesignError(f"{what} {str(p)!r} is a file, not a folder")
    _parent_ok(p, what)
    if p.is_dir() and any(p.iterdir()) and not overwrite:
        raise GearDesignError(f"{what} {str(p)!r} is not empty: give --overwrite to replace its contents")
    return p


def write_file_atomic(path, write) -> Path:
    """Call ``write(tmp)`` with a temporary path beside ``path`` (same suffix), then move it into
    place; on any failure, Ctrl-C included, the temporary file is removed and the error raised."""
    p = Path(os.fspath(path))
    fd, tmp = tempfile.mkstemp(prefix=f".{p.stem}.", suffix=f".tmp{p.suffix}", dir=p.parent if str(p.parent) else ".")
    os.close(fd)
    try:
        write(tmp)
        _as_if_created(tmp, 0o666)
        os.replace(tmp, p)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise
    return p


def write_dir_atomic(path, write) -> Path:
    """Call ``write(tmp_dir)`` with a new temporary folder beside ``path``, then put it in place
    of ``path`` (which must be absent, empty, or allowed to be replaced by the caller's check);
    on any failure nothing is left and ``path`` is as it was."""
    p = Path(os.fspath(path))
    parent = p.parent if str(p.parent) else Path(".")
    tmp = Path(tempfile.mkdtemp(prefix=f".{p.name}.", suffix=".tmp", dir=parent))
    old = None
    try:
        write(tmp)
        _as_if_created(tmp, 0o777)
        for f in tmp.iterdir():
            if f.is_file():
                _as_if_created(f, 0o666)
        if p.exists():
            old = Path(tempfile.mkdtemp(prefix=f".{p.name}.", suffix=".old", dir=parent))
            os.rmdir(old)
            os.replace(p, old)
        os.replace(tmp, p)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        if old is not None and old.exists() and not p.exists():
            os.replace(old, p)
        raise
    if old is not None:
        shutil.rmtree(old, ignore_errors=True)
    return p
