"""The progress bar (geardesign.progress): shown on its stream only when asked or on a terminal, counts what it
is told, restarts on a new step, and a callable receives the counts instead."""
import io

import pytest

from geardesign.errors import GearDesignError
from geardesign.progress import Bar, bar_for


def test_a_bar_off_a_terminal_draws_nothing_unless_asked():
    quiet = io.StringIO()
    with Bar(stream=quiet) as bar:            # StringIO is no terminal: show=None means off
        bar("walk", 5, 10)
    assert quiet.getvalue() == ""
    shown = io.StringIO()
    with Bar(True, stream=shown, delay_s=0.0, min_interval_s=0.0) as bar:
        bar("walk", 5, 10)
        assert bar._bar.n == 5 and bar._bar.total == 10
        bar("walk", 12, 10)                    # never past the total
        assert bar._bar.n == 10
        bar("bounds", 1, 4)                    # a new step: a new bar
        assert bar._bar.desc == "bounds" and bar._bar.n == 1
    assert "walk" in shown.getvalue()


def test_a_callable_receives_its_steps_counts():
    seen = []
    report, bar = bar_for(lambda done, total: seen.append((done, total)), label="walk")
    report("walk", 1, 3)
    report("bounds", 2, 3)                    # another step's counts are not this callable's
    report("walk", 3, 3)
    assert bar is None and seen == [(1, 3), (3, 3)]


def test_a_bad_progress_argument_is_refused_by_name():
    with pytest.raises(GearDesignError, match="progress must be True, False, None or a callable"):
        bar_for("yes")
