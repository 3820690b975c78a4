"""A deferred import whose comment names a heavy package loads it (issue 36 §4).

An import inside a function costs every call a dictionary look-up and hides the module's needs from its head; it
pays only where the module it names is costly to load. Issue 36 §4 found about 9 of 28 deferred imports whose
comments named pandas or scipy while the module they import no longer loaded either. This test reads every
import inside a function of the package whose comment (on its line, or the comment lines just above it) names
one of the heavy packages, runs that import in a fresh interpreter after importing the module that holds it,
and asserts that it loads what the comment names.
"""
import ast
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
HEAVY = ("pandas", "scipy", "matplotlib", "cvxpy", "dask")


def _module_name(path: Path) -> str:
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _absolute(node: ast.ImportFrom, path: Path) -> str:
    if not node.level:
        return node.module
    package = _module_name(path).split(".")
    if path.name != "__init__.py":
        package = package[:-1]
    base = package[:len(package) - node.level + 1]
    return ".".join(base + ([node.module] if node.module else []))


def _comment(lines: list, lineno: int) -> str:
    """The comment on the import's line, else the comment lines right above it."""
    line = lines[lineno - 1]
    if "#" in line:
        return line.split("#", 1)[1]
    above, k = [], lineno - 2
    while k >= 0 and lines[k].strip().startswith("#"):
        above.insert(0, lines[k].strip())
        k -= 1
    return " ".join(above)


def deferred_heavy_imports() -> list:
    """(holder module, the import as an absolute statement, heavy packages its comment names) of every import
    inside a function whose comment names a heavy package; an import from outside the package is left out
    (pandas itself is heavy by definition)."""
    found = []
    for path in sorted((ROOT / "geardesign").rglob("*.py")):
        text = path.read_text(encoding="utf-8")
        lines = text.splitlines()
        for fn in ast.walk(ast.parse(text)):
            if not isinstance(fn, (ast.FunctionDef, ast.AsyncFunctionDef)):
                continue
            for node in ast.walk(fn):
                if not isinstance(node, (ast.Import, ast.ImportFrom)):
                    continue
                named = tuple(h for h in HEAVY if h in _comment(lines, node.lineno))
                if not named:
                    continue
                if isinstance(node, ast.ImportFrom):
                    target = _absolute(node, path)
                    names = ", ".join(a.name for a in node.names)
                    statement = f"from {target} import {names}"
                else:
                    target = node.names[0].name
                    statement = f"import {target}"
                if target.startswith("geardesign"):
                    found.append((_module_name(path), statement, named, f"{path.relative_to(ROOT)}:{node.lineno}"))
    return found


CASES = deferred_heavy_imports()


def test_the_reader_finds_the_known_deferrals():
    # the reader itself must see real cases, or the test below could pass on an empty list
    # (the commands import their solvers when they run: `shift`, `atlas`, `teeth`, `planetary`)
    assert len(CASES) >= 6 and any(c[3].startswith("geardesign/cli/") for c in CASES)


@pytest.mark.slow
@pytest.mark.parametrize("holder, statement, named, where", CASES, ids=[c[3] for c in CASES])
def test_a_deferred_import_loads_the_heavy_package_its_comment_names(holder, statement, named, where):
    code = (f"import sys, {holder}\n"
            f"before = {{m.split('.')[0] for m in sys.modules}}\n"
            f"{statement}\n"
            f"print(sorted({{m.split('.')[0] for m in sys.modules}} - before))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, timeout=120)
    assert out.returncode == 0, out.stderr[-2000:]
    loaded = set(eval(out.stdout.strip().splitlines()[-1]))
    assert loaded & set(named), (f"{where}: `{statement}` is deferred for {', '.join(named)}, which it does not "
                                 f"load (already loaded by {holder} or not at all): move it to the top or say why")
