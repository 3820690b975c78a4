"""Options several subcommands share, defined once: the shift objective and method (choices from the
library's registries), and an output file that is never silently replaced."""
from __future__ import annotations

__all__ = ["add_solver_args", "add_output_file"]


def add_solver_args(p, default_objective: str | None = None, objective_help: str | None = None) -> None:
    """--objective (the registry's names) and --method (the shift methods; exact by default)."""
    from ..shifts.objectives import OBJECTIVES
    from ..shifts.optimize import METHODS

    p.add_argument("--objective", choices=sorted(OBJECTIVES), default=default_objective,
                   help=objective_help or "what the optimal shifts maximise or minimise (default max_x_sum): "
                   + "; ".join(f"{k}: {o.description}" for k, o in OBJECTIVES.items()))
    p.add_argument("--method", choices=METHODS, default="exact", help="shift solver: " + ", ".join(METHODS)
                   + " (exact)")


def add_output_file(p, flag: str, metavar: str, what: str) -> None:
    """``flag`` FILE writes ``what`` there; --overwrite allows replacing an existing file."""
    p.add_argument(flag, metavar=metavar, default=None, help=f"write {what} to this {metavar}")
    p.add_argument("--overwrite", action="store_true", help=f"replace an existing {flag} file")
