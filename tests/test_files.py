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


# --- issue 29 §3.8, §3.9 -------------------------------------------------------------------

def test_a_valid_250_character_name_is_written_and_its_temporary_name_fits(tmp_path):
    """§3.8: the temporary name '.<stem>.XXXXXXXX.tmp<suffix>' of a 250-character name passed 255 bytes."""
    from geardesign.files import NAME_MAX_BYTES
    target = tmp_path / ("g" * 246 + ".csv")
    seen = []

    def write(tmp):
        seen.append(os.path.basename(tmp))
        with open(tmp, "w") as fh:
            fh.write("x\n")
    check_output_path(target, suffixes=(".csv",))
    write_file_atomic(target, write)
    assert target.read_text() == "x\n" and sorted(os.listdir(tmp_path)) == [target.name]
    assert len(os.fsencode(seen[0])) <= NAME_MAX_BYTES and seen[0].startswith(".g")
    multibyte = tmp_path / ("é" * 125 + ".csv")          # 254 bytes
    write_file_atomic(multibyte, write)
    assert multibyte.read_text() == "x\n"


def test_a_name_longer_than_the_file_system_takes_is_refused_before_work(tmp_path):
    with pytest.raises(GearDesignError, match="256 bytes long; at most 255"):
        check_output_path(tmp_path / ("g" * 252 + ".csv"), suffixes=(".csv",))
    with pytest.raises(GearDesignError, match="bytes long"):
        check_output_dir(tmp_path / ("d" * 300))


def test_one_commands_outputs_are_all_or_nothing(tmp_path):
    from geardesign.files import all_or_nothing
    a, b = tmp_path / "a.png", tmp_path / "b.csv"
    a.write_text("old a")

    def ok(tmp):
        with open(tmp, "w") as fh:
            fh.write("new")

    def fails(tmp):
        raise RuntimeError("disk full")
    with pytest.raises(RuntimeError):
        with all_or_nothing():
            write_file_atomic(a, ok)
            assert a.read_text() == "old a"          # not moved yet
            write_file_atomic(b, fails)
    assert sorted(os.listdir(tmp_path)) == ["a.png"] and a.read_text() == "old a"
    with all_or_nothing():
        write_file_atomic(a, ok)
        write_file_atomic(b, ok)
    assert sorted(os.listdir(tmp_path)) == ["a.png", "b.csv"] and a.read_text() == b.read_text() == "new"


def test_a_link_to_a_folder_stays_a_link(tmp_path):
    """§3.9: the link was replaced by a real folder and '.link.XXXX.old -> real' was left behind."""
    real = tmp_path / "real"
    real.mkdir()
    (real / "old.txt").write_text("old")
    link = tmp_path / "link"
    link.symlink_to(real, target_is_directory=True)

    def write(tmp):
        (tmp / "report.md").write_text("new")
    check_output_dir(link, overwrite=True)
    write_dir_atomic(link, write)
    assert link.is_symlink() and os.path.realpath(link) == str(real)
    assert sorted(p.name for p in real.iterdir()) == ["report.md"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["link", "real"]


def test_a_link_to_a_file_stays_a_link(tmp_path):
    real = tmp_path / "real.csv"
    real.write_text("old")
    link = tmp_path / "link.csv"
    link.symlink_to(real)

    def write(tmp):
        with open(tmp, "w") as fh:
            fh.write("new")
    write_file_atomic(link, write)
    assert link.is_symlink() and real.read_text() == "new"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["link.csv", "real.csv"]


def test_read_text_bounded_refuses_devices_folders_big_files_and_non_text(tmp_path):
    from geardesign.files import read_text_bounded
    ok = tmp_path / "a.csv"
    ok.write_text("x\n1\n", encoding="utf-8")
    assert read_text_bounded(ok, "table", 1 << 20) == "x\n1\n"
    for path, match in (("/dev/zero", "not a regular file"), (tmp_path, "not a regular file"),
                        (tmp_path / "none.csv", "cannot be read: No such file"), (None, "must be a file path")):
        with pytest.raises(GearDesignError, match=match):
            read_text_bounded(path, "table", 1 << 20)
    ok.write_bytes(b"\xff\xfe")
    with pytest.raises(GearDesignError, match="is not UTF-8 text"):
        read_text_bounded(ok, "table", 1 << 20)
    ok.write_bytes(b"x" * (2 << 20) + b"\n")
    with pytest.raises(GearDesignError, match="larger than 1 MiB"):
        read_text_bounded(ok, "table", 1 << 20)
