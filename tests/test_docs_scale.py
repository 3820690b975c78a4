"""Every code block of docs/scale.md runs as written: the python blocks as scripts (as a user saves
and runs them; Dask's workers import them), the bash blocks' geardesign commands."""
import os
import re
import shlex
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DOC = ROOT / "docs" / "scale.md"


def _blocks(kind):
    return re.findall(rf"```{kind}\n(.*?)```", DOC.read_text(encoding="utf-8"), flags=re.S)


def _env():
    return {**os.environ, "PYTHONPATH": os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")])}


def test_python_blocks_run_as_scripts(tmp_path):
    blocks = _blocks("python")
    assert len(blocks) == 2
    outs = []
    for i, block in enumerate(blocks):
        script = tmp_path / f"block{i}.py"
        script.write_text(block, encoding="utf-8")
        run = subprocess.run([sys.executable, str(script)], cwd=tmp_path, env=_env(), capture_output=True, text=True,
                             timeout=300)
        assert run.returncode == 0, run.stderr[-2000:]
        outs.append(run.stdout)
    assert "30 pairs; the same table as the serial run: True" in outs[0]
    assert "'z1':" in outs[1] and "eps_alpha_min" in outs[1]


def test_bash_blocks_run(tmp_path):
    lines = [ln for b in _blocks("bash") for ln in b.splitlines() if ln.strip()]
    assert len(lines) == 2 and all(ln.startswith("geardesign ") for ln in lines)
    for ln in lines:
        run = subprocess.run([sys.executable, "-m", "geardesign", *shlex.split(ln)[1:]], cwd=tmp_path, env=_env(),
                             capture_output=True, text=True, timeout=300)
        assert run.returncode == 0, (ln, run.stderr[-2000:])
        assert run.stderr == ""
