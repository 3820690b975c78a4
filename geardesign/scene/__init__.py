"""Scene files: one design case in TOML, validated against a schema built from the library's own
constants, computed section by section, and written up as a report."""
from .scene import Scene, SceneReport, compute_scene, load_scene, run_scene, write_report

__all__ = ["Scene", "SceneReport", "compute_scene", "load_scene", "run_scene", "write_report"]
