"""The package face: names load on first use, so an import costs only what is used."""
import subprocess
import sys
from pathlib import Path

import pytest


@pytest.mark.parametrize("code, absent", [
    ("import geardesign", ("pandas", "scipy", "matplotlib", "cvxpy")),
    ("import geardesign as gd; gd.GearPair(8, 17, 26, 0.898, 0.517).geometry()", ("pandas", "scipy", "matplotlib")),
    # `geardesign --help` builds every subcommand's parser: it must not pay for pandas (~0.3 s) or the
    # solvers (scipy.optimize ~0.3 s), which made it 7x `import numpy` (issue 36 §3)
    ("import geardesign.cli", ("pandas", "scipy", "matplotlib", "cvxpy", "dask")),
    ("from geardesign.cli import build_parser; build_parser()", ("pandas", "scipy", "matplotlib", "cvxpy", "dask")),
])
def test_imports_load_only_what_is_used(code, absent):
    out = subprocess.run([sys.executable, "-c", f"{code}; import sys; print(sorted(sys.modules))"],
                         capture_output=True, text=True, check=True).stdout
    loaded = {m.split(".")[0] for m in eval(out)}
    assert not loaded & set(absent)

@pytest.mark.parametrize("argv", [
    ["pair", "--module", "8", "--z1", "17", "--z2", "26"],
    ["pair", "--module", "8", "--z1", "17", "--z2", "26", "--x1", "0.898", "--x2", "0.517", "--json"],
    ["pair", "--module", "3", "--z1", "20", "--z2", "60", "--internal", "--beta", "15", "--face-width", "30"],
])
def test_plain_pair_command_loads_no_pandas_and_no_solver(argv):
    """Issue 36 §3: a plain ``geardesign pair`` cost 4x ``import numpy``, pandas' import most of it, for two
    tables that plain rows print the same (tests/cli/test_output.py); its goal is <= 2x
    (benchmarks/bench_startup.py measures it)."""
    code = ("import contextlib, io, sys; from geardesign.cli import main\n"
            f"with contextlib.redirect_stdout(io.StringIO()): main({argv!r})\n"
            "print(sorted(sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    loaded = {m.split(".")[0] for m in eval(out)}
    assert not loaded & {"pandas", "scipy", "matplotlib", "cvxpy", "dask"}


def test_key_only_scene_loads_no_solver_and_no_plotting(tmp_path):
    f = tmp_path / "k.toml"
    f.write_text("[key]\nd_mm = 60\ntorque_nm = 503\nhub_length_mm = 50\n")
    code = (f"from geardesign.scene import run_scene; run_scene({str(f)!r}, {str(tmp_path / 'out')!r}); "
            "import sys; print(sorted(sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    loaded = {m.split(".")[0] for m in eval(out.strip().splitlines()[-1])}
    assert not loaded & {"scipy", "matplotlib", "cvxpy"}
    assert (tmp_path / "out" / "report.md").is_file()


@pytest.mark.parametrize("script", sorted(p.name for p in (Path(__file__).resolve().parents[1] / "studies").glob("*.py")))
def test_study_scripts_import(script):
    """Each runnable study loads (its imports, helpers from tests/ included) without running its main:
    a moved module must not leave README's study commands broken."""
    path = Path(__file__).resolve().parents[1] / "studies" / script
    out = subprocess.run([sys.executable, "-c", f"import runpy; runpy.run_path({str(path)!r}, run_name='check')"],
                         capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr[-2000:]
