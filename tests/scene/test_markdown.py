"""The Markdown table and the plotting import the scene's sections share."""
import math

import pandas as pd

from geardesign.scene.markdown import md_table, pyplot


def test_md_table_writes_a_pipe_table_cell_by_cell():
    frame = pd.DataFrame({"check": ["a|b", "c"], "ok": [True, False], "margin": [0.1234567891, math.nan]})
    assert md_table(frame).splitlines() == [
        "| check | ok | margin |",
        "|---|---|---|",
        "| a\\|b | yes | 0.123457 |",       # a pipe inside a cell is escaped; floats to 6 significant digits
        "| c | no | – |",                  # a missing number is a dash, not "nan"
    ]
    assert md_table(frame, floatfmt="{:.2f}").splitlines()[2].endswith("| 0.12 |")


def test_pyplot_is_matplotlib_on_the_file_backend():
    plt = pyplot()
    import matplotlib

    assert plt.__name__ == "matplotlib.pyplot" and matplotlib.get_backend().lower() == "agg"
