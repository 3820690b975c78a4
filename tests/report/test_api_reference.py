"""The API reference builds from the docstrings with every warning an error (tools/api_reference.py)."""
import importlib.util
import os
import pkgutil
import subprocess
import sys
from pathlib import Path

import pytest

import geardesign

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "tools" / "api_reference.py"


def _script():
    spec = importlib.util.spec_from_file_location("api_reference", SCRIPT)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


@pytest.mark.slow
def test_api_reference_builds_without_warnings(tmp_path):
    import pdoc  # noqa: F401  (the dev extra's: a missing one fails here, it is not skipped)
    out = subprocess.run([sys.executable, str(SCRIPT), str(tmp_path / "api")], cwd=ROOT, capture_output=True,
                         text=True, timeout=300, env={**os.environ, "MPLBACKEND": "Agg"})
    assert out.returncode == 0, out.stderr[-3000:]
    pages = {p.relative_to(tmp_path / "api").as_posix() for p in (tmp_path / "api").rglob("*.html")}
    # one page per module (but __main__, which runs the command), and the index
    names = [m.name for m in pkgutil.walk_packages(geardesign.__path__, "geardesign.") if not m.name.endswith("__main__")]
    expected = {n.replace(".", "/") + ".html" for n in ["geardesign", *names]} | {"index.html"}
    assert pages == expected
    region = (tmp_path / "api" / "geardesign" / "shifts" / "region.html").read_text(encoding="utf-8")
    assert "feasible_region" in region and "to_html" in region and "blocking contour" in region
    assert "report" in (tmp_path / "api" / "geardesign" / "gears" / "pair.html").read_text(encoding="utf-8")


def test_a_warning_fails_the_build(tmp_path, monkeypatch, capsys):
    import pdoc  # noqa: F401  (the dev extra's: a missing one fails here, it is not skipped)
    mod = _script()
    # a package given twice: pdoc warns that one module would be documented twice
    monkeypatch.setattr(mod, "specs", lambda: ["geardesign.catalogs", "geardesign.catalogs"])
    monkeypatch.setattr(sys, "path", list(sys.path))
    assert mod.main([str(tmp_path / "api")]) == 1
    assert "warning treated as an error" in capsys.readouterr().err
