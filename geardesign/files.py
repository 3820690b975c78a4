"""Output files that are either whole or absent: paths checked before any work, results written
under a temporary name and moved into place only when complete, nothing overwritten unasked.

A mistyped ``--plot`` or ``--out`` must not destroy a user's file, and a run that fails (bad
input found late, a full disk, Ctrl-C) must leave the target exactly as it was.
"""
from __future__ import annotations

import contextlib
import contextvars
import os
import shutil
import tempfile
from pathlib import Path

from .errors import GearDesignError

__all__ = ["check_output_path", "check_output_dir", "write_file_atomic", "write_dir_atomic", "all_or_nothing",
           "parents_made", "NAME_MAX_BYTES", "read_text_bounded"]

# The longest file name (one path component) the common file systems take: ext4, XFS, APFS, NTFS
# (255 UTF-16 units there); the temporary names below are kept within it too.
NAME_MAX_BYTES = 255
_RANDOM = 8        # the characters tempfile adds to a prefix and a suffix


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def _as_if_created(path, mode: int) -> None:
    """Give a temporary file (0600) or folder (0700) the permissions a plain create would."""
    os.chmod(path, mode & ~_umask())


def _name_ok(path: Path, what: str) -> None:
    size = len(os.fsencode(path.name))
    if size > NAME_MAX_BYTES:
        raise GearDesignError(f"{what} {_cut(str(path))}: the file name is {size} bytes long; "
                              f"at most {NAME_MAX_BYTES} are allowed")


def _cut(text: str) -> str:
    """A path for a message, cut like a value (validate._short)."""
    return repr(text) if len(text) <= 60 else repr(text[:40]) + f"... ({len(text)} characters)"


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
    _name_ok(p, what)
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
    _name_ok(p, what)
    if p.exists() and not p.is_dir():
        raise GearDesignError(f"{what} {str(p)!r} is a file, not a folder")
    _parent_ok(p, what)
    if p.is_dir() and any(p.iterdir()) and not overwrite:
        raise GearDesignError(f"{what} {str(p)!r} is not empty: give --overwrite to replace its contents")
    return p


@contextlib.contextmanager
def parents_made(path, what: str = "--out"):
    """Create the missing parent folders of ``path`` for the block; when the block ends in an error
    (Ctrl-C included) the folders it created are removed again, so a failed run leaves nothing. An
    ancestor that is a file, or a folder that cannot be made, is one GearDesignError naming ``what``."""
    p = Path(os.fspath(path))
    missing, parent = [], p.parent
    while str(parent) not in ("", ".") and not os.path.lexists(parent):
        missing.append(parent)
        parent = parent.parent
    if os.path.lexists(parent) and not parent.is_dir():
        raise GearDesignError(f"{what} {_cut(str(p))}: {_cut(str(parent))} is a file, not a folder")
    made = []
    try:
        for d in reversed(missing):
            try:
                os.mkdir(d)
            except OSError as exc:
                raise GearDesignError(f"{what} {_cut(str(p))}: cannot make the folder {_cut(str(d))}: "
                                      f"{exc.strerror}") from None
            made.append(d)
        yield p
    except BaseException:
        for d in reversed(made):
            with contextlib.suppress(OSError):   # a folder something else has written to stays
                os.rmdir(d)
        raise


def _temp_affixes(name: str, suffix: str = "") -> tuple[str, str]:
    """(prefix, suffix) of a hidden temporary name beside ``name`` that stays within
    NAME_MAX_BYTES however long ``name`` is: ``.<name cut>.XXXXXXXX<suffix>``."""
    suffix = suffix if len(os.fsencode(suffix)) <= 24 else suffix[:4]
    room = NAME_MAX_BYTES - 2 - _RANDOM - len(os.fsencode(suffix))
    stem = os.fsencode(name)[:room].decode("utf-8", "ignore")   # a character cut in two is dropped
    return "." + stem + ".", suffix


def _real(p: Path) -> Path:
    """Where a symlink points (the link itself stays as it is); any other path as given."""
    return Path(os.path.realpath(p)) if p.is_symlink() else p


# The outputs of one command are written as a group (:func:`all_or_nothing`): each to its temporary
# name first, all moved into place only when every one is complete.
_GROUP: contextvars.ContextVar = contextvars.ContextVar("geardesign_files_group", default=None)


@contextlib.contextmanager
def all_or_nothing():
    """Inside this block :func:`write_file_atomic` writes each file under its temporary name and
    defers the move; when the block ends without an error every file is moved into place, on any
    error (Ctrl-C included) every temporary file is removed and no target is touched."""
    if _GROUP.get() is not None:        # nested: the outer group decides
        yield
        return
    pending: list = []
    token = _GROUP.set(pending)
    try:
        yield
    except BaseException:
        _discard(pending)
        raise
    finally:
        _GROUP.reset(token)
    _move_all(pending)


def _discard(pending) -> None:
    for tmp, _ in pending:
        with contextlib.suppress(OSError):
            os.unlink(tmp)


def _move_all(pending) -> None:
    """Move every (tmp, target) into place; if one move fails, the files this group created are
    removed again and the remaining temporary files too (targets it replaced stay replaced)."""
    done = []
    try:
        for tmp, target in pending:
            existed = os.path.lexists(target)
            os.replace(tmp, target)
            done.append((target, existed))
    except BaseException as exc:
        _discard(pending[len(done):])
        for target, existed in done:
            if not existed:
                with contextlib.suppress(OSError):
                    os.unlink(target)
        if isinstance(exc, OSError):
            raise GearDesignError(f"cannot write {_cut(str(exc.filename or ''))}: {exc.strerror}") from None
        raise


def write_file_atomic(path, write) -> Path:
    """Call ``write(tmp)`` with a temporary path beside ``path`` (same suffix), then move it into
    place; on any failure, Ctrl-C included, the temporary file is removed and the error raised
    (an OSError as a GearDesignError naming the file). A symlink is kept: its target is written.
    Inside :func:`all_or_nothing` the move waits for the group."""
    p = _real(Path(os.fspath(path)))
    prefix, suffix = _temp_affixes(p.stem, f".tmp{p.suffix}")
    try:
        fd, tmp = tempfile.mkstemp(prefix=prefix, suffix=suffix, dir=p.parent if str(p.parent) else ".")
    except OSError as exc:
        raise GearDesignError(f"cannot write {_cut(str(p))}: {exc.strerror}") from None
    os.close(fd)
    group = _GROUP.get()
    try:
        write(tmp)
        _as_if_created(tmp, 0o666)
        if group is None:
            os.replace(tmp, p)
        else:
            group.append((tmp, p))
    except BaseException as exc:
        if os.path.exists(tmp):
            os.unlink(tmp)
        if isinstance(exc, OSError):
            raise GearDesignError(f"cannot write {_cut(str(p))}: {exc.strerror}") from None
        raise
    return Path(os.fspath(path))


def write_dir_atomic(path, write) -> Path:
    """Call ``write(tmp_dir)`` with a new temporary folder beside ``path``, then put it in place
    of ``path`` (which must be absent, empty, or allowed to be replaced by the caller's check);
    on any failure nothing is left and ``path`` is as it was. A symlink to a folder is kept: the
    folder it points to is the one replaced."""
    given = Path(os.fspath(path))
    p = _real(given)
    parent = p.parent if str(p.parent) else Path(".")
    prefix, _ = _temp_affixes(p.name, ".tmp")
    tmp = Path(tempfile.mkdtemp(prefix=prefix, suffix=".tmp", dir=parent))
    old = None
    try:
        write(tmp)
        _as_if_created(tmp, 0o777)
        for f in tmp.iterdir():
            if f.is_file():
                _as_if_created(f, 0o666)
        if p.exists():
            old = Path(tempfile.mkdtemp(prefix=prefix, suffix=".old", dir=parent))
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
    return given


def read_text_bounded(path, what: str, max_bytes: int) -> str:
    """The UTF-8 text of the regular file ``path`` of at most ``max_bytes`` (``what`` names it in the errors): a
    device such as /dev/zero, a folder or a larger file is refused before it is read whole (no unbounded read)."""
    shown = repr(str(path))
    try:
        if os.path.exists(path) and not os.path.isfile(path):
            raise GearDesignError(f"{what} {shown} is not a regular file (a CSV text file is expected)")
        with open(path, "rb") as fh:
            raw = fh.read(max_bytes + 1)
    except GearDesignError:                 # a ValueError too: not the one below
        raise
    except OSError as e:
        raise GearDesignError(f"{what} {shown} cannot be read: {e.strerror or e}") from None
    except (TypeError, ValueError):         # not a path at all (None, a number, a NUL in the name)
        raise GearDesignError(f"{what} must be a file path, got {path!r}") from None
    if len(raw) > max_bytes:
        raise GearDesignError(f"{what} {shown} is larger than {max_bytes >> 20} MiB")
    try:
        return raw.decode("utf-8")
    except UnicodeDecodeError:
        raise GearDesignError(f"{what} {shown} is not UTF-8 text") from None
