"""The ``geardesign`` command: one entry point, one subcommand per job.

Each subcommand lives in its own module with two functions, ``add_parser(subparsers)``
and ``run(args) -> int``. Errors of the GearDesignError family print one line on stderr
and exit with status 2; nothing prints a traceback for bad input.
"""
from __future__ import annotations

import argparse
import importlib
import sys
import warnings

import numpy as np

from ..errors import GearDesignError

# Subcommand modules, in the order ``geardesign --help`` lists them.
SUBCOMMANDS = ("pair", "mesh", "shift", "atlas", "teeth", "planetary", "chain", "key", "drive", "run")


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="geardesign",
        description="Gear-pair geometry and profile-shift optimisation, roller chains and keys. Every command "
                    "exits 0 when the design passes, 1 when it fails a check (the output names it), 2 on bad input.")
    from .. import __version__

    parser.add_argument("--version", action="version", version=f"geardesign {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    sub.required = True
    for name in SUBCOMMANDS:
        try:
            module = importlib.import_module(f"{__name__}.{name}")
        except ModuleNotFoundError as exc:
            if exc.name == f"{__name__}.{name}":
                continue  # subcommand not built yet
            raise
        p = module.add_parser(sub)
        p.set_defaults(_run=module.run)
    return parser


def main(argv=None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        # numpy's divide/invalid warnings at the edges of existence are handled in the code
        # (NaN -> a named failure); they must not reach the user's terminal beside the one line
        with warnings.catch_warnings(), np.errstate(all="ignore"):
            warnings.simplefilter("ignore", RuntimeWarning)
            return int(args._run(args) or 0)
    except GearDesignError as exc:
        print(f"geardesign {args.command}: error: {' '.join(str(exc).split())}", file=sys.stderr)
        return 2
    except BrokenPipeError:  # output piped into `head` and the like: stop quietly
        import os

        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0
    except KeyboardInterrupt:   # outputs are written whole or not at all (geardesign.files)
        print(f"geardesign {args.command}: interrupted, nothing written", file=sys.stderr)
        return 130


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
