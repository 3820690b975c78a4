"""Scene files: one design case in TOML, validated against a schema built from the library's own
constants, computed section by section, and written up as a report.

schema (keys and their ranges) -> load (read, validate, cross-check) -> sections (run each into a
report in memory) -> report (write it whole or not at all).
"""
from .load import Scene, load_scene
from .report import compute_scene, run_scene, write_report
from .schema import SECTIONS
from .sections import SceneReport

__all__ = ["SECTIONS", "Scene", "SceneReport", "compute_scene", "load_scene", "run_scene", "write_report"]
