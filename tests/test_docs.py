"""The documentation as a test: what README.md and docs/ say must stay true.

* Every Markdown file (README, CHANGELOG, docs/**, catalogs/README) renders with a CommonMark parser
  (markdown-it-py) with no code fence left open and none "closed" by a fence line followed by text
  (CommonMark keeps such a block open and swallows the rest of the page).
* Every ```bash / ```sh command and every ```python block of README.md, CONTRIBUTING.md, examples/README.md
  and docs/*.md runs as written,
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
MARKDOWN = sorted({ROOT / "README.md", ROOT / "CHANGELOG.md", ROOT / "CONTRIBUTING.md", ROOT / "catalogs" / "README.md",
                   ROOT / "examples" / "README.md", *ROOT.glob("docs/**/*.md")})
RUNNABLE = [ROOT / "README.md", ROOT / "CONTRIBUTING.md", ROOT / "examples" / "README.md", *sorted(ROOT.glob("docs/*.md"))]
SKIP = re.compile(r"<!--\s*doc-test:\s*skip\s*\((?P<reason>[^)]+)\)\s*-->")
SETUP = re.compile(r"^(python3? -m venv \S+|\. \S+/bin/activate|source \S+/bin/activate|pip install .*)$")
TIME_EXEMPT = {"performance.md", "CHANGELOG.md"}
# Pages other branches are writing now (issues 25-27), linked from the README already: a link to one of
# them may point nowhere until that branch is merged. Remove a name here once its page exists.
PENDING_PAGES = set()   # pages linked before they are written
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
    for f in ("README.md", "CHANGELOG.md", "CONTRIBUTING.md", "examples/README.md"):   # the working copy's docs
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


@pytest.mark.slow
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


@pytest.mark.slow
@pytest.mark.parametrize("path", _python_files())
def test_python_blocks_run(path, checkout, monkeypatch):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    cwd, _ = checkout(path)
    monkeypatch.chdir(cwd)
    # a module object in sys.modules: a documented dataclass looks its module up there
    import types
    module = types.ModuleType("__doctest__")
    monkeypatch.setitem(sys.modules, "__doctest__", module)
    globs = module.__dict__
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


@pytest.mark.slow
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


# --- (c) figures quoted in prose and in code comments, against the program ------------------------
#
# Each entry: the page, the text it quotes, and how the program produces that text. A figure that drifts
# fails here; a page that stops quoting it fails here too (then drop the entry). Figures in doctests and
# transcripts are checked above; times live in docs/performance.md only.


def _engine():
    import geardesign as gd

    return gd.GearPair(8, 17, 26, 0.898, 0.517)


def _atlas():
    import geardesign as gd

    if not hasattr(_atlas, "df"):
        _atlas.df = gd.shift_atlas(range(8, 41), range(8, 121), objective="max_x_sum")
    return _atlas.df


def _atlas_active(text):
    df = _atlas()
    return str(int(df.loc[df["feasible"], "active"].value_counts()[text]))


def _chain_seed002(field, fmt):
    import geardesign as gd

    r = gd.chain.design(torque_nm=380, n1_rpm=120, ratio=1, z1=13, k_e=2.148, allowable_pressure_mpa=29,
                        strands=(1, 2), objective="min_sprocket_diameter")
    return format(float(r.best[field]), fmt)


def _key_seed002():
    import geardesign as gd

    k = gd.key.select(d_mm=60, torque_nm=503.129, hub_length_mm=50, allowable_crush_mpa=300,
                      allowable_shear_mpa=120)
    return (f"one key {k.b_mm:g}x{k.h_mm:g}x{k.length_mm:g}", f"t1 = {k.t1_mm:g} mm in the shaft, t2 = {k.t2_mm:g} mm",
            f"crush {k.crush_mpa:.1f}/300 MPa, shear {k.shear_mpa:.1f}/120 MPa")


def _teeth_row(rank):
    import geardesign as gd

    if not hasattr(_teeth_row, "sel"):
        _teeth_row.sel = gd.select_teeth(1.5, m=8, z_sum_max=45)
    r = _teeth_row.sel.table.iloc[rank - 1]
    return (f"| {rank} | {int(r.z1)}/{int(r.z2)} | {r.ratio:.4g} | {r.a_w_mm:.2f} | {r.x1:.3f} | {r.x2:.3f} | "
            f"{r.eps_alpha:.3f} | {r.objective:.3f} | {'yes' if r.feasible else 'no'} |")


def _teeth_fixed():
    import geardesign as gd

    b = gd.select_teeth(1.5, m=8, a_w=180).best
    return f"split x1 = {b.x1:.3f}, x2 = {b.x2:.3f} for equal specific sliding (ε_α = {b.eps_alpha:.3f})".replace("-", "−")


def _khk_ring():
    import geardesign as gd

    pair = gd.GearPair(3, 16, 24, 0.0, 0.5, internal=True)
    ring = gd.pair_profiles(pair)[1]
    g = pair.geometry()
    return (f"{ring.tip_thickness_mm:.3f} mm thick on the generated profile against KHK's involute "
            f"s_a2 = {g.sa2:.3f} mm. The pair's own checks fail too (the pinion is undercut, x1 = 0 < x_min = "
            f"{g.x_min1:.3f}, and interference1 by {pair.checks().set_index('check').loc['interference1', 'margin']:.4f}"
            ).replace("-0.", "−0.")


def _ring_root():
    import geardesign as gd

    pair = gd.GearPair(2, 20, 60, 0.3, 0.6, internal=True)
    return (f"(20/60, x2 = 0.6: {2 * gd.pair_profiles(pair)[1].r_root_mm:.3f} mm generated, "
            f"{pair.geometry().df2:.4g} mm rack-equivalent)")


def _chain_free_z1():
    import geardesign as gd

    b = gd.chain.design(torque_nm=380, n1_rpm=120, ratio=1, k_e=2.148, allowable_pressure_mpa=29, strands=(1, 2)).best
    return (f"(F_t = {b.force_n:.0f} N), so a single 31.75 mm strand carries the load at p = {b.pressure_mpa:.1f} MPa "
            f"(margin {b.margin_pressure:+.2f}). The sprockets grow to d = {b.sprocket1_pitch_diameter_mm:.1f} mm")


FIGURES = [
    ("docs/teeth.md", "split x1 = 0.181, x2 = −0.181 for equal specific sliding (ε_α = 1.563)", _teeth_fixed),
    ("docs/mesh.md", "2.340 mm thick on the generated profile against KHK's involute s_a2 = 2.621 mm. The pair's own "
     "checks fail too (the pinion is undercut, x1 = 0 < x_min = 0.064, and interference1 by −0.0097", _khk_ring),
    ("docs/mesh.md", "(20/60, x2 = 0.6: 127.033 mm generated, 127.4 mm rack-equivalent)", _ring_root),
    ("docs/chains_and_keys.md", "(F_t = 2785 N), so a single 31.75 mm strand carries the load at p = 23.0 MPa (margin +0.21). "
     "The sprockets grow to d = 273.5 mm", _chain_free_z1),
    ("docs/teeth.md", "| 1 | 18/27 | 1.5 | 189.55 | 0.400 | 0.998 | 1.200 | 1.398 | yes |", lambda: _teeth_row(1)),
    ("docs/teeth.md", "| 6 | 17/26 | 1.529 | 181.13 | 0.360 | 0.977 | 1.200 | 1.337 | yes |", lambda: _teeth_row(6)),
    ("docs/internal_helical.md", "# 13.1683 mm",
     lambda: f"# {__import__('geardesign').GearPair(3, 16, 24, 0.0, 0.5, internal=True).geometry().a_w:.6g} mm"),
    ("docs/planetary.md", "# 56.79992, 56.80008 mm (printed a = 56.8), 6.14286", lambda: (lambda s: (
        f"# {s.a_w:.7g}, {s.a_w_planet_ring:.7g} mm (printed a = 56.8), {s.ratio:.6g}"))(
        __import__("geardesign").PlanetarySet(1.75, 21, 43, 108, 3, x_sun=0.438, x_planet=0.0426, x_ring=0.0))),
    ("docs/planetary.md", "# -0.2283, 0.8262, 0.8894, 56.9847 mm", lambda: (lambda r: (
        f"# {r.x_sun:.4f}, {r.x_planet:.4f}, {r.x_ring:.4f}, {r.a_w:.4f} mm"))(
        __import__("geardesign").optimize_planetary_shifts(21, 43, 108, 3, m=1.75, objective="max_eps_alpha"))),
    ("docs/chains_and_keys.md", "one key 18x11x45", lambda: _key_seed002()[0]),
    ("docs/chains_and_keys.md", "t1 = 7 mm in the shaft, t2 = 4.4 mm", lambda: _key_seed002()[1]),
    ("docs/chains_and_keys.md", "crush 155.3/300 MPa, shear 34.5/120 MPa", lambda: _key_seed002()[2]),
    ("docs/chains_and_keys.md", "# 504.0 N·m",
     lambda: f"# {__import__('geardesign').key.capacity(60, 32, 300, 120)['torque_nm']:.1f} N·m"),
    ("docs/chains_and_keys.md", "p = 28.1 MPa against [p] = 29 MPa (margin +0.031)",
     lambda: f"p = {_chain_seed002('pressure_mpa', '.1f')} MPa against [p] = 29 MPa "
             f"(margin {_chain_seed002('margin_pressure', '+.3f')})"),
    ("docs/chains_and_keys.md", "d = 132.67 mm, D_e = 144.69 mm",
     lambda: f"d = {_chain_seed002('sprocket1_pitch_diameter_mm', '.2f')} mm, "
             f"D_e = {_chain_seed002('sprocket1_tip_diameter_mm', '.2f')} mm"),
    ("docs/studies.md", "p = 28.11 MPa against [p] = 29 (margin +0.031)",
     lambda: f"p = {_chain_seed002('pressure_mpa', '.2f')} MPa against [p] = 29 "
             f"(margin {_chain_seed002('margin_pressure', '+.3f')})"),
    ("docs/studies.md", "| 0.038859 (decimal slip)", lambda: f"| {_engine().geometry().inv_alpha_w:.5g} (decimal slip)"),
    ("docs/studies.md", "| 27.126° |", lambda: f"| {_engine().geometry().alpha_w_deg:.3f}° |"),
    ("docs/studies.md", "**1.1532 < 1.2:", lambda: f"**{_engine().geometry().eps_alpha:.4f} < 1.2:"),
    ("docs/studies.md", "0.3603 / 0.9768 (on ε_α = 1.2; a_w = 181.13 mm)", lambda: (lambda r: (
        f"{r.x1:.4f} / {r.x2:.4f} (on ε_α = {r.eps_alpha:.1f}; a_w = {r.a_w:.2f} mm)"))(
        __import__("geardesign").optimize_shifts(17, 26, m=8))),
    ("docs/studies.md", "d(x1 + x2)/d(ε_α,min) = −3.8685", lambda: (
        f"d(x1 + x2)/d(ε_α,min) = {__import__('geardesign').optimize_shifts(17, 26).sensitivity['contact_ratio']:.4f}"
        .replace("-", "−"))),
    ("docs/studies.md", "It covers 3201 pairs, and 3157 of them are feasible",
     lambda: f"It covers {len(_atlas())} pairs, and {int(_atlas()['feasible'].sum())} of them are feasible"),
    ("docs/studies.md", "(z = 8/8 is infeasible) to 5.29", lambda: (
        f"(z = 8/8 is {'in' if not bool(_atlas().iloc[0]['feasible']) else ''}feasible) to {_atlas()['area'].max():.2f}")),
    ("docs/studies.md", "The optimal x1 + x2 ranges from 0.58 to 3.47", lambda: (lambda f: (
        f"The optimal x1 + x2 ranges from {(f.x1 + f.x2).min():.2f} to {(f.x1 + f.x2).max():.2f}"))(
        _atlas()[_atlas()["feasible"]])),
    ("docs/studies.md", "| interference of gear 2 + ε_α | 1944 |",
     lambda: f"| interference of gear 2 + ε_α | {_atlas_active('interference2,contact_ratio')} |"),
    ("docs/studies.md", "| ε_α alone | 642 |", lambda: f"| ε_α alone | {_atlas_active('contact_ratio')} |"),
    ("docs/studies.md", "| undercut of gear 1 + ε_α | 571 |",
     lambda: f"| undercut of gear 1 + ε_α | {_atlas_active('undercut1,contact_ratio')} |"),
]


@pytest.mark.parametrize("page, quoted, compute", FIGURES, ids=[f"{p}: {q[:40]}" for p, q, _ in FIGURES])
def test_quoted_figure_comes_from_the_program(page, quoted, compute):
    text = " ".join((ROOT / page).read_text(encoding="utf-8").split())
    assert " ".join(quoted.split()) in text, f"{page} no longer quotes {quoted!r}: drop the entry"
    assert compute() == quoted


def test_readme_is_a_front_page():
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    assert len(text.splitlines()) <= 150
    assert "minutes on 2 cores" in text and "python -m pytest tests" in text
    assert "pip install \".[dev]\"" in text and "geardesign shift --z1 17 --z2 26 --module 8 --plot contour.png" in text
    assert len(re.findall(r"!\[[^]]*\]\(docs/[^)]+\.png\)", text)) >= 5
