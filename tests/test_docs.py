"""The documentation as a test: what README.md and docs/ say must stay true.

* Every Markdown file (README, CHANGELOG, docs/**, catalogs/README) renders with a CommonMark parser
  (markdown-it-py) with no code fence left open and none "closed" by a fence line followed by text
  (CommonMark keeps such a block open and swallows the rest of the page).
* Every ```bash / ```sh command and every ```python block of README.md and docs/*.md runs as written,
  on a copy of the checkout's files in a temporary folder, with the ``geardesign`` command of the
  package under test. A command's expected exit status is 0 unless its comment says ``exit 1`` (a design
  that fails a check). Setup steps a fresh machine needs and this environment has done (``python3 -m venv``,
  ``. .venv/bin/activate``, ``pip install``) are dropped from a ``&&`` chain. A Python block with ``>>>``
  prompts runs as a doctest (its printed figures are compared); the blocks of one file share a namespace.
  A block preceded by ``<!-- doc-test: skip (reason) -->`` is not run: only for what costs minutes.
* A transcript (an unlabelled block whose lines start with ``$ geardesign``) is run too, and every output
  line it shows must appear in the program's output (``...`` inside a line stands for any text).
* Times belong in docs/performance.md (which names the command of each); other pages quote none.
* Local links point at files that exist.
"""
from __future__ import annotations

import doctest
import os
import re
import shutil
import stat
import subprocess
import sys
from pathlib import Path

import pytest

import geardesign

ROOT = Path(__file__).resolve().parents[1]
MARKDOWN = sorted({ROOT / "README.md", ROOT / "CHANGELOG.md", ROOT / "catalogs" / "README.md",
                   *ROOT.glob("docs/**/*.md")})
RUNNABLE = [ROOT / "README.md", *sorted(ROOT.glob("docs/*.md"))]
SKIP = re.compile(r"<!--\s*doc-test:\s*skip\s*\((?P<reason>[^)]+)\)\s*-->")
SETUP = re.compile(r"^(python3? -m venv \S+|\. \S+/bin/activate|source \S+/bin/activate|pip install .*)$")
TIME_EXEMPT = {"performance.md", "CHANGELOG.md"}
# Pages other branches are writing now (issues 25-27), linked from the README already: a link to one of
# them may point nowhere until that branch is merged. Remove a name here once its page exists.
PENDING_PAGES = {"docs/strength.md", "docs/measurement.md", "docs/extending.md"}
COMMAND_TIMEOUT_S = 240


def _rel(path: Path) -> str:
    return str(path.relative_to(ROOT))


def _fences(path: Path):
    """(info, content, first line number, skip reason or None) of every fenced block, via markdown-it-py."""
    from markdown_it import MarkdownIt

    text = path.read_text(encoding="utf-8")
    lines = text.splitlines()
    out = []
    for tok in MarkdownIt("commonmark").parse(text):
        if tok.type != "fence":
            continue
        start = tok.map[0]
        before = "\n".join(lines[max(0, start - 2):start])
        m = SKIP.search(before)
        out.append((tok.info.strip(), tok.content, start + 1, m.group("reason") if m else None))
    return out


# --- (a) every Markdown file renders ---------------------------------------------------------


def fence_problems(text: str, name: str) -> list:
    """Fences left open, and fence lines followed by text inside a block, in a Markdown text."""
    from markdown_it import MarkdownIt

    lines = text.splitlines()
    problems = []
    for tok in MarkdownIt("commonmark").parse(text):
        if tok.type != "fence":
            continue
        first, end = tok.map
        opener = lines[first].strip()
        mark = opener[:len(opener) - len(opener.lstrip(opener[0]))]
        last = lines[end - 1].strip() if end - 1 > first and end <= len(lines) else ""
        if not re.fullmatch(re.escape(mark[0]) + "{%d,}" % len(mark), last):
            problems.append(f"{name}:{first + 1}: the fence opened here is never closed (it runs to line {end})")
        for k, line in enumerate(tok.content.splitlines()):
            if re.match(r"\s{0,3}(```|~~~)", line):
                problems.append(f"{name}:{first + 2 + k}: a fence line followed by text inside a code block "
                                f"(CommonMark does not close a fence there): {line.strip()[:60]!r}")
    return problems


@pytest.mark.parametrize("path", MARKDOWN, ids=_rel)
def test_markdown_renders_with_every_fence_closed(path):
    from markdown_it import MarkdownIt

    text = path.read_text(encoding="utf-8")
    assert MarkdownIt("commonmark").render(text).strip()
    assert fence_problems(text, _rel(path)) == []


def test_fence_check_catches_a_fence_closed_with_text():
    """Issue 28's defect: a closing fence followed by text keeps the block open to the page's end."""
    bad = "# t\n\n```bash\nls\n``` Use this.\n\n## Next\n\n```\nx\n```\ntext\n"
    problems = fence_problems(bad, "bad.md")
    assert any("never closed" in p for p in problems) and any("followed by text" in p for p in problems)
    assert fence_problems("```bash\nls\n```\n\n~~~~\na\n~~~~\n", "good.md") == []


@pytest.mark.parametrize("path", MARKDOWN, ids=_rel)
def test_local_links_exist(path):
    text = path.read_text(encoding="utf-8")
    for target in re.findall(r"\]\(([^)\s]+)\)", text):
        if re.match(r"[a-z]+:", target) or target.startswith("#"):
            continue
        file = (path.parent / target.split("#")[0]).resolve()
        pending = file.is_relative_to(ROOT) and str(file.relative_to(ROOT)) in PENDING_PAGES
        assert file.exists() or pending, f"{_rel(path)}: link to {target!r}, which does not exist"


@pytest.mark.parametrize("path", [p for p in MARKDOWN if p.name not in TIME_EXEMPT], ids=_rel)
def test_times_only_in_performance_page(path):
    """A time measured once drifts; docs/performance.md holds them with their commands."""
    text = path.read_text(encoding="utf-8")
    found = re.findall(r"\d(?:[\d.,–-]*\d)?\s?(?:ms|µs|us)\b|\d(?:[\d.,–-]*\d)? s\b(?! *[=<>])", text)
    assert not found, f"{_rel(path)} quotes times {found[:5]}: they belong in docs/performance.md"


# --- (b) the documented commands and code run -------------------------------------------------


@pytest.fixture(scope="module")
def checkout(tmp_path_factory):
    """A copy of the checkout's files (what a fresh clone holds), and a bin folder whose
    ``geardesign`` runs the package under test."""
    dest = tmp_path_factory.mktemp("checkout")
    try:
        files = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True,
                               check=True).stdout.split()
    except (OSError, subprocess.CalledProcessError):
        files = [str(p.relative_to(ROOT)) for p in ROOT.rglob("*")
                 if p.is_file() and ".git" not in p.parts and "__pycache__" not in p.parts]
    for f in files:
        src = ROOT / f
        if src.is_file():
            (dest / f).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(src, dest / f)
    for f in ("README.md", "CHANGELOG.md"):        # the working copy's docs, committed or not
        shutil.copy2(ROOT / f, dest / f)
    for p in ROOT.glob("docs/*.md"):
        shutil.copy2(p, dest / "docs" / p.name)
    bin_dir = dest / ".doc-test-bin"
    bin_dir.mkdir()
    shim = bin_dir / "geardesign"
    shim.write_text(f"#!/bin/sh\nexec {sys.executable} -m geardesign \"$@\"\n")
    shim.chmod(shim.stat().st_mode | stat.S_IEXEC)
    package_root = str(Path(geardesign.__file__).resolve().parents[1])
    env = dict(os.environ, PATH=f"{bin_dir}{os.pathsep}{os.environ.get('PATH', '')}", MPLBACKEND="Agg",
               PYTHONPATH=package_root + os.pathsep + os.environ.get("PYTHONPATH", ""), COLUMNS="100")
    copies = {}

    def for_doc(path: Path) -> tuple[Path, dict]:
        """The doc's own copy of the checkout (its blocks share it; other docs' outputs never collide)."""
        if path not in copies:
            copies[path] = tmp_path_factory.mktemp("doc") / "checkout"
            shutil.copytree(dest, copies[path], symlinks=True)
        return copies[path], env

    return for_doc


def _commands(block: str):
    """Each command of a shell block (continuation lines joined), with its expected exit status."""
    joined = re.sub(r"\\\n\s*", " ", block)
    for line in joined.splitlines():
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        code, _, comment = line.partition("   #")
        if "#" in code and not comment:
            code, _, comment = line.partition(" # ")
        m = re.search(r"\bexit (?:status )?(\d)", comment)
        parts = [p.strip() for p in code.split("&&")]
        parts = [p for p in parts if not SETUP.match(p)]
        if parts:
            yield " && ".join(parts), int(m.group(1)) if m else 0


def _shell_blocks():
    out = []
    for path in RUNNABLE:
        for info, content, line, skip in _fences(path):
            if info in ("bash", "sh", "shell"):
                out.append(pytest.param(path, content, skip, id=f"{_rel(path)}:{line}"))
    return out


@pytest.mark.parametrize("path, content, skip", _shell_blocks())
def test_shell_block_runs(path, content, skip, checkout):
    if skip:
        pytest.skip(f"marked in the doc: {skip}")
    cwd, env = checkout(path)
    for command, expected in _commands(content):
        proc = subprocess.run(["bash", "-c", command], cwd=cwd, env=env, capture_output=True, text=True,
                              timeout=COMMAND_TIMEOUT_S)
        assert proc.returncode == expected, (
            f"{_rel(path)}: `{command}` exited {proc.returncode}, the doc says {expected}\n"
            f"{proc.stdout[-1500:]}\n{proc.stderr[-1500:]}")


def _python_files():
    return [pytest.param(p, id=_rel(p)) for p in RUNNABLE
            if any(info == "python" for info, *_ in _fences(p))]


@pytest.mark.parametrize("path", _python_files())
def test_python_blocks_run(path, checkout, monkeypatch):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    cwd, _ = checkout(path)
    monkeypatch.chdir(cwd)
    globs = {"__name__": "__doctest__"}
    parser = doctest.DocTestParser()
    try:
        for info, content, line, skip in _fences(path):
            if info != "python" or skip:
                continue
            name = f"{_rel(path)}:{line}"
            if ">>>" in content:
                test = parser.get_doctest(content, globs, name, str(path), line)
                runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
                out = []
                runner.run(test, out=out.append, clear_globs=False)
                globs.update(test.globs)          # the next block sees this one's names (DocTest copies)
                assert runner.failures == 0, f"{name}:\n" + "".join(out)
            else:
                exec(compile(content, name, "exec"), globs)
    finally:
        plt.close("all")


# --- (c) transcripts show what the program prints --------------------------------------------


def _transcripts():
    out = []
    for path in RUNNABLE:
        for info, content, line, skip in _fences(path):
            if info == "" and content.lstrip().startswith("$ geardesign"):
                out.append(pytest.param(path, content, skip, id=f"{_rel(path)}:{line}"))
    return out


def _steps(content: str):
    """(command, shown output lines) of each ``$`` line of a transcript."""
    steps = []
    for line in re.sub(r"\\\n\s*", " ", content).splitlines():
        if line.startswith("$ "):
            steps.append((line[2:].split("   #")[0].strip(), []))
        elif steps and line.strip() and line.strip() != "...":
            steps[-1][1].append(line.strip())
    return steps


@pytest.mark.parametrize("path, content, skip", _transcripts())
def test_transcript_matches_the_program(path, content, skip, checkout):
    if skip:
        pytest.skip(f"marked in the doc: {skip}")
    cwd, env = checkout(path)
    for command, shown in _steps(content):
        proc = subprocess.run(["bash", "-c", command], cwd=cwd, env=env, capture_output=True, text=True,
                              timeout=COMMAND_TIMEOUT_S)
        assert proc.returncode in (0, 1), f"{_rel(path)}: `{command}` failed:\n{proc.stderr[-1500:]}"
        printed = [" ".join(x.split()) for x in proc.stdout.splitlines()]
        for want in shown:
            pattern = ".*".join(re.escape(part) for part in " ".join(want.split()).split("..."))
            assert any(re.fullmatch(pattern, got) for got in printed), (
                f"{_rel(path)}: `{command}` does not print {want!r}; it prints:\n{proc.stdout[:3000]}")
