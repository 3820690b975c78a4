"""Running a scene: every section computed in memory, then written whole or not at all."""
from __future__ import annotations

import time
from pathlib import Path

from .. import parallel
from ..errors import GearDesignError
from ..files import check_output_dir, write_dir_atomic
from .load import Scene, load_scene
from .sections import RUNNERS, SceneReport, run_study

__all__ = ["compute_scene", "write_report", "run_scene"]

_BATCH_SECTIONS = ("teeth", "planetary", "study", "drive")   # sections whose searches can go to a cluster


def compute_scene(scene: Scene, progress=None, *, client=None, workers=None) -> SceneReport:
    """Run every section of a validated scene in memory (nothing is written).

    ``progress(done, total, section)`` is called before each section and at the end. ``client`` /
    ``workers``: the batch sections ([teeth] and [planetary] searches, [study] sweeps, [drive]
    searches) run on that Dask cluster; a local one of ``workers`` processes serves every section
    and is closed at the end (see :mod:`geardesign.parallel`)."""
    t0 = time.perf_counter()
    rep = SceneReport(scene)
    rep.markdown += [f"# {scene.title}", ""]
    if scene.description:
        rep.markdown += [scene.description.strip(), ""]
    rep.markdown += [f"Scene file: `{Path(scene.path).name}`; sections modelled: "
                     f"{', '.join(f'[{s}]' for s in scene.sections)}.", ""]
    s = scene.sections
    runners = RUNNERS
    todo = [name for name, _ in runners if name in s] + (["study"] if "study" in s else [])
    step = progress or (lambda done, total, section: None)
    try:
        with parallel.cluster(client, workers) as c:
            # the batch sections find the cluster under "_client" (None: solve here)
            s = {k: ({**v, "_client": c} if k in _BATCH_SECTIONS else v) for k, v in s.items()}
            for name, fn in runners:
                if name in s:
                    step(todo.index(name), len(todo), name)
                    fn(rep, s[name])
            if "study" in s:
                step(len(todo) - 1, len(todo), "study")
                run_study(rep, s["study"], s)
        step(len(todo), len(todo), "done")
    except GearDesignError as exc:
        _close(rep.figures)
        raise GearDesignError(f"{scene.path}: {exc}") from None
    rep.markdown += ["## Files", "", *[f"- `{k}.csv`" for k in rep.tables], *[f"- `{k}.png`" for k in rep.figures], ""]
    rep.time_s = time.perf_counter() - t0
    return rep


def write_report(rep: SceneReport, out_dir, overwrite: bool = False) -> Path:
    """Write report.md, the CSV tables and the PNG plots into ``out_dir``: a new or empty
    folder (its contents replaced only with ``overwrite``). Everything is written into a
    temporary folder beside it first and moved into place whole; a failure leaves nothing."""
    out = check_output_dir(out_dir, overwrite=overwrite)

    def write(tmp: Path) -> None:
        for name, frame in rep.tables.items():
            frame.to_csv(tmp / f"{name}.csv", index=False)
        for name, fig in rep.figures.items():
            fig.savefig(tmp / f"{name}.png", dpi=110, bbox_inches="tight")
        _close(rep.figures)
        (tmp / "report.md").write_text("\n".join(rep.markdown), encoding="utf-8")

    return write_dir_atomic(out, write)


def run_scene(path, out_dir, overwrite: bool = False, progress=None, *, client=None, workers=None) -> SceneReport:
    """Load, validate and run a scene file, then write its report into ``out_dir``.

    The output folder is checked first; nothing is written when the scene is wrong or a
    section fails. ``client`` / ``workers`` as for :func:`compute_scene`.
    """
    check_output_dir(out_dir, overwrite=overwrite)
    rep = compute_scene(load_scene(path), progress, client=client, workers=workers)
    write_report(rep, out_dir, overwrite=overwrite)
    return rep


def _close(figures: dict) -> None:
    """Close the report's figures (pyplot is loaded already when there are any)."""
    if figures:
        import matplotlib.pyplot as plt
        for fig in figures.values():
            plt.close(fig)
