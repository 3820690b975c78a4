"""Build the API reference from the docstrings (pdoc) into a folder, every warning an error.

    python tools/api_reference.py OUT_DIR

Every module of the package gets a page (the package's ``__all__`` would hide the modules it does
not list). A warning while importing or rendering (a docstring pdoc cannot parse, an annotation it
cannot resolve, a module that fails to import) stops the build with exit status 1.
"""
from __future__ import annotations

import os
import pkgutil
import sys
import warnings
from pathlib import Path


def modules() -> list[str]:
    """Every module of geardesign (``__main__`` aside: importing it runs the command)."""
    import geardesign

    return ["geardesign"] + sorted(m.name for m in pkgutil.walk_packages(geardesign.__path__, "geardesign.")
                                   if not m.name.endswith("__main__"))


def specs() -> list[str]:
    """pdoc's module specifications that reach every module once: pdoc walks a package's
    submodules as far as its ``__all__`` lists them, so each module it does not reach is added."""
    import pdoc.extract

    out = ["geardesign"]
    reached = set(pdoc.extract.walk_specs(out))
    for name in modules():        # a package before its modules: adding it may reach them
        if name not in reached:
            out.append(name)
            reached = set(pdoc.extract.walk_specs(out))
    return out


def build(out_dir) -> list[Path]:
    """Render every module's page into ``out_dir``; raise on the first warning. Returns the pages."""
    os.environ.setdefault("MPLBACKEND", "Agg")
    import pdoc
    import pdoc.render

    pdoc.render.configure(docformat="restructuredtext", show_source=False, search=True)
    out = Path(out_dir)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        pdoc.pdoc(*specs(), output_directory=out)
    return sorted(out.rglob("*.html"))


def main(argv=None) -> int:
    sys.path.insert(0, str(Path(__file__).resolve().parents[1]))   # the checkout's package, not an installed one
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 1:
        print(__doc__.strip().splitlines()[2].strip(), file=sys.stderr)
        return 2
    try:
        pages = build(argv[0])
    except Warning as w:
        print(f"API reference: warning treated as an error: {type(w).__name__}: {w}", file=sys.stderr)
        return 1
    print(f"API reference: {len(pages)} pages in {argv[0]}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
