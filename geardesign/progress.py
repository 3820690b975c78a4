"""A progress bar on stderr for the long computations (the drive search, atlases, tooth searches), drawn by
tqdm: shown when stderr is a terminal or when asked, only once a step has run :data:`DELAY_S` seconds, and
never on stdout (``--json`` output stays clean).

``progress`` arguments across the package take: None (a bar when stderr is a terminal), True (a bar),
False (none), or a callable that receives the counts instead of a bar.
"""
from __future__ import annotations

import sys

__all__ = ["Bar", "DELAY_S", "bar_for"]

DELAY_S = 2.0      # a step shorter than this shows nothing ("anything longer than a few seconds")


class Bar:
    """``bar(label, done, total)``: one tqdm bar on ``stream`` (stderr), restarted when the label changes;
    ``close()`` removes it. ``show`` None: only when the stream is a terminal."""

    def __init__(self, show: bool | None = None, stream=None, delay_s: float = DELAY_S, min_interval_s: float = 0.2):
        self.stream = stream or sys.stderr
        self.show = _isatty(self.stream) if show is None else bool(show)
        self.delay_s, self.min_interval_s = delay_s, min_interval_s
        self._bar = None

    def __call__(self, label: str, done: int, total: int) -> None:
        if not self.show:
            return
        total = max(int(total), 1)
        if self._bar is None or self._bar.desc != label or self._bar.total != total:
            self.close()
            from tqdm import tqdm   # here: only a shown bar needs it

            self._bar = tqdm(total=total, desc=label, file=self.stream, leave=False, delay=self.delay_s,
                             dynamic_ncols=True, mininterval=self.min_interval_s)
        self._bar.update(min(int(done), total) - self._bar.n)

    def close(self) -> None:
        if self._bar is not None:
            self._bar.close()
            self._bar = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False


def _isatty(stream) -> bool:
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError):     # a closed or replaced stream
        return False


def bar_for(progress, label: str | None = None):
    """(report, bar) for a ``progress`` argument: ``report(label, done, total)`` and the Bar to close (or
    None). A callable ``progress(done, total)`` receives the steps labelled ``label`` only (all when None)."""
    if callable(progress) and not isinstance(progress, bool):
        def report(step, done, total):
            if label is None or step == label:
                progress(done, total)
        return report, None
    if progress is not None and not isinstance(progress, bool):
        from .errors import GearDesignError
        raise GearDesignError(f"progress must be True, False, None or a callable(done, total), got {progress!r}")
    bar = Bar(progress)
    return bar, bar
