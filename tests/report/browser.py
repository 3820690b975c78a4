"""Headless Chromium for the page tests: find the binary, dump a page's rendered DOM, parse tables.

CI installs Debian's ``chromium`` package; on a machine without any Chromium the browser tests
skip and say why (the page-building tests that need no browser still run)."""
from __future__ import annotations

import os
import re
import shutil
import signal
import subprocess
import tempfile
from pathlib import Path
from html.parser import HTMLParser

import pytest

NAMES = ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable")
FLAGS = ["--headless", "--disable-gpu", "--no-sandbox", "--disable-dev-shm-usage", "--hide-scrollbars", "--run-all-compositor-stages-before-draw",
         "--virtual-time-budget=15000"]


def browser() -> str:
    for name in NAMES:
        path = shutil.which(name)
        if path:
            return path
    if os.environ.get("CI"):       # .ci/run installs it: there a missing browser is a failure, not a skip
        pytest.fail("no Chromium binary on PATH: .ci/run installs Debian's chromium package")
    pytest.skip("no Chromium binary on PATH: the browser tests need it (apt-get install chromium)")


def _run(args, timeout: float = 180) -> str:
    """Run the browser with its output in a file (its helper processes may keep a pipe open after
    it exits) in a session of its own, killed whole if it overruns."""
    with tempfile.TemporaryFile("w+", encoding="utf-8") as out:
        proc = subprocess.Popen([browser(), *FLAGS, *args], stdout=out, stderr=subprocess.DEVNULL,
                                start_new_session=True)
        try:
            code = proc.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
            raise AssertionError(f"chromium took over {timeout} s on {args[-1]}") from None
        assert code == 0, f"chromium exited {code} on {args[-1]}"
        out.seek(0)
        return out.read()


def dump_dom(path) -> str:
    """The DOM of file ``path`` after the page's scripts ran (plotly draws its SVG then)."""
    return _run(["--dump-dom", path.resolve().as_uri()])


def screenshot(path, png, size=(1280, 1600)) -> None:
    _run([f"--screenshot={png}", f"--window-size={size[0]},{size[1]}", path.resolve().as_uri()])


class Tables(HTMLParser):
    """Every <table> of a page as a list of rows of cell texts (colspan cells repeated)."""

    def __init__(self):
        super().__init__()
        self.tables, self._cell, self._span = [], None, 1

    def handle_starttag(self, tag, attrs):
        if tag == "table":
            self.tables.append([])
        elif tag == "tr" and self.tables:
            self.tables[-1].append([])
        elif tag in ("td", "th"):
            self._cell, self._span = [], int(dict(attrs).get("colspan", 1))

    def handle_endtag(self, tag):
        if tag in ("td", "th") and self._cell is not None:
            self.tables[-1][-1] += [re.sub(r"\s+", " ", "".join(self._cell)).strip()] * self._span
            self._cell = None

    def handle_data(self, data):
        if self._cell is not None:
            self._cell.append(data)


def tables(dom: str) -> list:
    p = Tables()
    p.feed(dom)
    return p.tables


def print_pages(path, pdf) -> int:
    """Print file ``path`` to ``pdf`` as Chromium prints it (A4 from the page's @page rule) and
    count the PDF's pages."""
    _run(["--no-pdf-header-footer", f"--print-to-pdf={pdf}", path.resolve().as_uri()])
    return len(re.findall(rb"/Type\s*/Page[^s]", Path(pdf).read_bytes()))
