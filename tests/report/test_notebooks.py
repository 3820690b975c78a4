"""The example notebooks run as they are (nbclient, a real IPython kernel), so they cannot rot.

Each runs in a temporary folder (the files it writes land there) with this checkout's package
first on the kernel's path."""
import os
import shutil
from pathlib import Path

import pytest

pytestmark = pytest.mark.slow   # clusters, browsers, notebooks: seconds each (CONTRIBUTING.md)

ROOT = Path(__file__).resolve().parents[2]
NOTEBOOKS = sorted((ROOT / "examples").glob("*.ipynb"))


def _run(path: Path, tmp_path: Path, monkeypatch):
    import nbclient      # the dev extra's: a missing one fails here, it is not skipped
    import nbformat
    monkeypatch.setenv("PYTHONPATH", os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]))
    monkeypatch.setenv("MPLBACKEND", "module://matplotlib_inline.backend_inline")
    work = tmp_path / path.name
    shutil.copy(path, work)
    book = nbformat.read(work, as_version=4)
    nbclient.NotebookClient(book, timeout=120, kernel_name="python3",
                            resources={"metadata": {"path": str(tmp_path)}}).execute()
    return book


def _outputs(book, mime: str) -> list:
    return [o.get("data", {}).get(mime) for c in book.cells if c.cell_type == "code" for o in c.get("outputs", [])
            if mime in o.get("data", {})]


def test_there_are_four():
    assert {p.stem for p in NOTEBOOKS} == {"engine_pair", "fixed_housing", "planetary", "drive"}


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_notebook_runs(path, tmp_path, monkeypatch):
    book = _run(path, tmp_path, monkeypatch)
    errors = [o for c in book.cells if c.cell_type == "code" for o in c.get("outputs", []) if o.output_type == "error"]
    assert not errors
    # every notebook shows a picture: a plot, or a result's inline view
    pictures = _outputs(book, "image/png") + [h for h in _outputs(book, "text/html") if "data:image/png" in h]
    assert pictures, path.name
    if path.stem == "engine_pair":
        text = "".join(o.get("text", "") for c in book.cells if c.cell_type == "code" for o in c.get("outputs", []))
        a_w, eps = _engine_pair_mp()
        assert f"a_w = {a_w:.4f} mm" in text and f"eps_alpha = {eps:.3f}" in text
        assert (tmp_path / "engine_pair.html").exists() and (tmp_path / "engine_contour.html").exists()


def _engine_pair_mp():
    """a_w and ε_α of 17/26, m 8, x 0.898/0.517 (tips shortened by Δy·m) in 40 digits, from the
    textbook formulas (ISO 21771 eq. (62) for inv α_w; GOST 16532-70 Table 1 for d_a, ε_α)."""
    import mpmath as mp

    mp.mp.dps = 40
    m, z1, z2, x1, x2 = 8, 17, 26, mp.mpf("0.898"), mp.mpf("0.517")
    al = mp.radians(20)
    inv = lambda a: mp.tan(a) - a   # noqa: E731
    target = inv(al) + 2 * (x1 + x2) * mp.tan(al) / (z1 + z2)
    aw_angle = mp.findroot(lambda a: inv(a) - target, mp.mpf("0.47"))
    a = m * (z1 + z2) / mp.mpf(2)
    a_w = a * mp.cos(al) / mp.cos(aw_angle)
    dy = (x1 + x2) - (a_w - a) / m
    ra = [m * z / mp.mpf(2) + (1 + x - dy) * m for z, x in ((z1, x1), (z2, x2))]
    rb = [m * z * mp.cos(al) / 2 for z in (z1, z2)]
    g = sum(mp.sqrt(r * r - b * b) for r, b in zip(ra, rb)) - a_w * mp.sin(aw_angle)
    return float(a_w), float(g / (mp.pi * m * mp.cos(al)))
