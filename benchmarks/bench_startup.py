"""What a user pays before the command does anything: ``geardesign --help`` and a plain ``geardesign pair``
as CPU time of a fresh process, against ``python -c "import numpy"`` timed in the same run (issue 36 §3: the
help took 7.2× `import numpy` when the CLI loaded pandas and scipy.optimize at start-up; goal ≤ 2×).

Each command runs as a child process with Python's bytecode cache on (as an installed package has it; a
private cache directory, so the checkout gets no ``__pycache__``), once to fill the cache, then ``--repeats``
times interleaved; the CPU time is the children's user + system time (``resource.getrusage``), the median
of the repeats. Also printed: ``import pandas`` and ``import scipy.optimize`` alone, which say what a
command that needs them cannot get below.

Run: python benchmarks/bench_startup.py [--repeats 7]
Prints figures; asserts nothing (speed is measured, not tested).
"""
import argparse
import os
import resource
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

COMMANDS = {
    "import numpy": ["-c", "import numpy"],
    "import pandas": ["-c", "import pandas"],
    "import scipy.optimize": ["-c", "import scipy.optimize"],
    "geardesign --help": ["-m", "geardesign", "--help"],
    "geardesign pair (plain)": ["-m", "geardesign", "pair", "--module", "8", "--z1", "17", "--z2", "26"],
}


def child_cpu(argv, env) -> float:
    """User + system CPU seconds of one child process running ``python argv``."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([sys.executable, *argv], env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                   cwd=ROOT)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--repeats", type=int, default=7)
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as cache:
        env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
        env["PYTHONPYCACHEPREFIX"] = cache
        env["PYTHONPATH"] = str(ROOT) + os.pathsep + env.get("PYTHONPATH", "")
        for argv in COMMANDS.values():      # fill the bytecode cache
            child_cpu(argv, env)
        times = {name: [] for name in COMMANDS}
        for _ in range(args.repeats):
            for name, argv in COMMANDS.items():
                times[name].append(child_cpu(argv, env))
    ref = statistics.median(times["import numpy"])
    print(f"load average {os.getloadavg()[0]:.2f}; {args.repeats} repeats, median CPU time of a fresh process")
    for name, ts in times.items():
        med = statistics.median(ts)
        print(f"{name:26s} {med * 1e3:7.0f} ms CPU  {med / ref:5.2f}x import numpy  (min {min(ts) / ref:.2f}x,"
              f" max {max(ts) / ref:.2f}x)")


if __name__ == "__main__":
    main()
