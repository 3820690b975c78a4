"""The linter's configuration (pyproject.toml, [tool.ruff]) holds for the package and the tools.

`ruff` is in the dev extra; a missing one fails here, it is not skipped.
"""
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _ruff(*args, cwd=ROOT):
    import ruff  # noqa: F401  (the dev extra's)
    exe = shutil.which("ruff", path=str(Path(sys.executable).parent)) or shutil.which("ruff")
    assert exe, "the ruff command is not installed (pip install '.[dev]')"
    return subprocess.run([exe, "check", "--no-cache", *args], cwd=cwd, capture_output=True, text=True, timeout=120)


def test_ruff_finds_nothing_in_the_package_and_tools():
    out = _ruff("geardesign", "tools")
    assert out.returncode == 0, out.stdout[-4000:] + out.stderr[-2000:]


def test_ruff_reads_the_projects_rules_and_fails_on_a_finding(tmp_path):
    # the same configuration on a file with an unused import and a mutable default: both reported, exit 1
    (tmp_path / "pyproject.toml").write_text((ROOT / "pyproject.toml").read_text(encoding="utf-8"), encoding="utf-8")
    (tmp_path / "bad.py").write_text("import os\n\n\ndef f(a=[]):\n    return a\n", encoding="utf-8")
    out = _ruff("bad.py", cwd=tmp_path)
    assert out.returncode == 1
    assert "F401" in out.stdout and "B006" in out.stdout
