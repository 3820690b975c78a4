"""Output files are whole or absent, checked before any work, never overwritten unasked."""
import os
import stat

import pytest

from geardesign import GearDesignError
from geardesign.files import check_output_dir, check_output_path, write_dir_atomic, write_file_atomic


def test_output_path_checks(tmp_path):
    with pytest.raises(GearDesignError, match="must end in .png"):
        check_output_path(tmp_path / "c.txt")
    with pytest.raises(GearDesignError, match="does not exist"):
        check_output_path(tmp_path / "nowhere" / "c.png")
    with pytest.raises(GearDesignError, match="is a folder"):
        (tmp_path / "d.png").mkdir()
        check_output_path(tmp_path / "d.png")
    (tmp_path / "e.png").write_bytes(b"x")
    with pytest.raises(GearDesignError, match="--overwrite"):
        check_output_path(tmp_path / "e.png")
    assert check_output_path(tmp_path / "e.png", overwrite=True).name == "e.png"


def test_output_dir_checks(tmp_path):
    (tmp_path / "full").mkdir()
    (tmp_path / "full" / "a").write_text("a")
    with pytest.raises(GearDesignError, match="not empty"):
        check_output_dir(tmp_path / "full")
    (tmp_path / "f").write_text("f")
    with pytest.raises(GearDesignError, match="is a file"):
        check_output_dir(tmp_path / "f")
    assert check_output_dir(tmp_path / "new").name == "new"


def test_failed_write_leaves_nothing_and_keeps_the_old_file(tmp_path):
    target = tmp_path / "t.csv"
    target.write_text("old")

    def boom(tmp):
        with open(tmp, "w") as fh:
            fh.write("half")
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        write_file_atomic(target, boom)
    assert target.read_text() == "old" and sorted(os.listdir(tmp_path)) == ["t.csv"]


def test_failed_folder_write_leaves_the_folder_as_it_was(tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    (out / "keep.md").write_text("keep")

    def boom(tmp):
        (tmp / "report.md").write_text("half")
        raise RuntimeError("disk full")

    with pytest.raises(RuntimeError):
        write_dir_atomic(out, boom)
    assert sorted(os.listdir(tmp_path)) == ["out"] and (out / "keep.md").read_text() == "keep"


def test_written_files_have_the_permissions_of_a_plain_create(tmp_path):
    mask = os.umask(0o022)
    try:
        f = write_file_atomic(tmp_path / "a.png", lambda tmp: open(tmp, "wb").write(b"png"))
        d = write_dir_atomic(tmp_path / "d", lambda tmp: (tmp / "r.md").write_text("r"))
    finally:
        os.umask(mask)
    assert stat.S_IMODE(f.stat().st_mode) == 0o644
    assert stat.S_IMODE(d.stat().st_mode) == 0o755
    assert stat.S_IMODE((d / "r.md").stat().st_mode) == 0o644
