"""Running a scene (geardesign.scene.report): computed in memory first, then written whole or not at
all (common rules: files written to a temporary name and moved into place, no overwrite without
--overwrite). A bought-unit drive keeps every figure hand-checkable: T = P/ω·u·η."""
import math

import pytest

from geardesign.errors import GearDesignError
from geardesign.scene import load_scene
from geardesign.scene.report import compute_scene, run_scene, write_report
from tests.scene_files import GIVEN_DRIVE, write

BODY = 'title = "hand drive"' + GIVEN_DRIVE


def _file(tmp_path, body=BODY):
    return write(tmp_path, body, "s.toml")


def test_compute_writes_nothing_and_reports_progress(tmp_path):
    path = _file(tmp_path)
    before = sorted(tmp_path.iterdir())
    calls = []
    rep = compute_scene(load_scene(str(path)), progress=lambda *a: calls.append(a))
    assert sorted(tmp_path.iterdir()) == before
    assert calls == [(0, 1, "drive"), (1, 1, "done")]
    assert rep.markdown[0] == "# hand drive"
    t1 = 4000 / (2 * math.pi * 1500 / 60) * 12.5 * 0.87
    flow = rep.results["drive"]["analysis"].flow
    assert flow["torque_nm"].iloc[1] == pytest.approx(t1, rel=1e-14)


def test_written_whole_with_every_listed_file(tmp_path):
    out = tmp_path / "out"
    rep = run_scene(str(_file(tmp_path)), out)
    text = (out / "report.md").read_text()
    names = {p.name for p in out.iterdir()}
    assert names == {"report.md"} | {f"{k}.csv" for k in rep.tables} | {f"{k}.png" for k in rep.figures}
    for k in rep.tables:
        assert f"`{k}.csv`" in text


def test_existing_folder_refused_and_kept_unless_overwrite(tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    (out / "mine.txt").write_text("keep")
    with pytest.raises(GearDesignError, match="overwrite"):
        run_scene(str(_file(tmp_path)), out)
    assert [p.name for p in out.iterdir()] == ["mine.txt"]
    rep = compute_scene(load_scene(str(_file(tmp_path))))
    write_report(rep, out, overwrite=True)
    assert (out / "report.md").is_file() and not (out / "mine.txt").exists()


def test_a_failing_section_writes_nothing(tmp_path, monkeypatch):
    import geardesign.scene.report as report

    def fails(rep, section):
        rep.markdown.append("half a section")
        raise GearDesignError("stage 1 broke")

    monkeypatch.setattr(report, "RUNNERS", [("drive", fails)])
    path, out = _file(tmp_path), tmp_path / "out"
    with pytest.raises(GearDesignError, match=r"s\.toml: stage 1 broke"):
        run_scene(str(path), out)
    assert not out.exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s.toml"]
