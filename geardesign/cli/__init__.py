"""The ``geardesign`` command: one entry point, one subcommand per job.

Each subcommand lives in its own module with two functions, ``add_parser(subparsers)``
and ``run(args) -> int``. Errors of the GearDesignError family print one line on stderr
and exit with status 2; nothing prints a traceback for bad input.
"""
from __future__ import annotations

import sys

# Nothing heavy is imported at module level: the console script imports this module before it
# calls main(), and a Ctrl-C during those imports (numpy, pandas, matplotlib take ~0.5 s) would
# print a traceback. main() imports them inside its own Ctrl-C handler instead.

# Subcommand modules, in the order ``geardesign --help`` lists them.
SUBCOMMANDS = ("pair", "measure", "mesh", "shift", "atlas", "teeth", "planetary", "worm", "chain", "key", "bearing",
               "shaft", "engine", "drive", "run")


def build_parser():
    import importlib   # here and in _main: inside main's Ctrl-C handler (see the note above)

    from .options import OneLineParser   # a bad option value: one line naming it, exit 2

    parser = OneLineParser(
        prog="geardesign",
        description="Gear-pair geometry and profile-shift optimisation, roller chains and keys. Every command "
                    "exits 0 when the design passes, 1 when it fails a check (the output names it), 2 on bad input.")
    from .. import __version__

    parser.add_argument("--version", action="version", version=f"geardesign {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    sub.required = True
    for name in SUBCOMMANDS:
        module = importlib.import_module(f"{__name__}.{name}")
        p = module.add_parser(sub)
        p.set_defaults(_run=module.run, _parser=p)
    return parser


BROKEN_PIPE = 141   # the exit status when the output's reader stops early (`geardesign pair ... | head -1`)


def main(argv=None) -> int:
    """Run one command; exit status 0 (done), 1 (no feasible design), 2 (bad input, one line on
    stderr), 130 (Ctrl-C, one line on stderr, no traceback, nothing written) or 141 (the output's reader stopped
    reading early)."""
    try:
        code = _main(argv)
    except KeyboardInterrupt:   # during start-up: the imports and the parser
        print("geardesign: interrupted", file=sys.stderr)
        code = 130
    if code == 130 and argv is None:
        # the command (the process: argv from the command line) is ending: a Ctrl-C pressed again while the
        # interpreter shuts down (a second or two after a cluster) must not kill it by SIGINT (status -2) half-way
        import signal

        signal.signal(signal.SIGINT, signal.SIG_IGN)
    return code


def _main(argv) -> int:
    import warnings   # here: inside main's Ctrl-C handler (see the note above)

    import numpy as np

    from ..errors import GearDesignError

    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        # numpy's divide/invalid warnings at the edges of existence are handled in the code
        # (NaN -> a named failure); they must not reach the user's terminal beside the one line
        with warnings.catch_warnings(), np.errstate(all="ignore"):
            warnings.simplefilter("ignore", RuntimeWarning)
            return int(args._run(args) or 0)
    except GearDesignError as exc:
        from pathlib import Path

        from .options import option_names   # the library's keyword named by the command's option

        text = ' '.join(str(exc).split())
        if not (hasattr(args, "scene") and text.startswith(f"{Path(args.scene)}: ")):   # a scene's keys stay keys
            text = option_names(text, args._parser)
        print(f"geardesign {args.command}: error: {text}", file=sys.stderr)
        return 2
    except BrokenPipeError:  # output piped into `head` and the like: stop quietly
        import os

        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        # 141 (128 + SIGPIPE), as a writer whose reader went away ends in a shell: not 0, which would say a design
        # passes when its verdict line was read but its checks were not all written
        return BROKEN_PIPE
    except KeyboardInterrupt:   # outputs are written whole or not at all (geardesign.files)
        print(f"geardesign {args.command}: interrupted, nothing written", file=sys.stderr)
        return 130


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
