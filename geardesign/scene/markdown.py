"""What the scene's sections share to write their reports: Markdown tables, and matplotlib's pyplot
on the file backend, imported only when a section draws (a key-only scene never does)."""
from __future__ import annotations

__all__ = ["md_table", "pyplot"]


def pyplot():
    """matplotlib.pyplot on the file backend, imported when a section draws (a key-only scene never does)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def md_table(frame, floatfmt="{:.6g}") -> str:
    import numpy as np

    def cell(v):
        if isinstance(v, (bool, np.bool_)):
            return "yes" if v else "no"
        if isinstance(v, (float, np.floating)):
            return "–" if not np.isfinite(v) else floatfmt.format(v)
        return str(v).replace("|", "\\|")
    cols = list(frame.columns)
    lines = ["| " + " | ".join(map(str, cols)) + " |", "|" + "---|" * len(cols)]
    for row in frame.itertuples(index=False):
        lines.append("| " + " | ".join(cell(v) for v in row) + " |")
    return "\n".join(lines)
