"""Generated cases for the surfaces issue 29 §3 found defects on: output files (long names, links,
existing folders and files), a command's several outputs, and Ctrl-C at start-up.

Each target returns (description, call) like those of tests/fuzzcases.py, which registers them;
every file a case writes goes into its own temporary folder, removed afterwards. A call raises
``HalfWritten`` (a temporary file left, or some of a command's files written and not the others),
``LinkReplaced`` (a symlink given as an output is not one any more) or AssertionError (a traceback
printed) when the rule is broken.
"""
from __future__ import annotations

import contextlib
import io
import os
import signal
import subprocess
import sys
import tempfile

import geardesign as gd
from geardesign.cli import main as cli_main
from tests.fuzzcases import HalfWritten, LinkReplaced, _pick

_ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# how an output path is given: (kind, stem length); the file system takes names up to 255 bytes
_PATH_KINDS = ["plain", "plain", "long_ok", "long_multibyte", "too_long", "link_to_file", "link_to_folder",
               "existing_folder", "existing_file", "missing_folder"]


def _make_path(rng, tmp: str, kind: str, suffix: str):
    """(path to give, what must hold afterwards): a file name of ``kind`` inside ``tmp``."""
    if kind == "long_ok":
        name = "g" * (250 - len(suffix)) + suffix
    elif kind == "long_multibyte":
        name = "é" * ((250 - len(suffix)) // 2) + suffix
    elif kind == "too_long":
        name = "g" * (256 - len(suffix) + rng.randint(0, 40)) + suffix
    else:
        name = "out" + suffix
    path = os.path.join(tmp, name)
    if kind == "link_to_file":
        real = os.path.join(tmp, "real" + suffix)
        with open(real, "w") as fh:
            fh.write("precious")
        os.symlink(real, path)
    elif kind == "link_to_folder":
        real = os.path.join(tmp, "realdir")
        os.mkdir(real)
        os.symlink(real, path, target_is_directory=True)
    elif kind == "existing_folder":
        os.mkdir(path)
    elif kind == "existing_file":
        with open(path, "w") as fh:
            fh.write("precious")
    elif kind == "missing_folder":
        path = os.path.join(tmp, "no_such_folder", name)
    return path


def _links(tmp: str) -> list:
    """Every symlink under ``tmp`` (the outputs given as links), to be found again afterwards."""
    return [os.path.join(root, n) for root, dirs, files in os.walk(tmp) for n in dirs + files
            if os.path.islink(os.path.join(root, n))]


def _links_kept(links: list) -> None:
    gone = [os.path.basename(p)[:30] for p in links if not os.path.islink(p)]
    if gone:
        raise LinkReplaced(f"{gone} no longer a link")


def _no_temp(tmp: str) -> None:
    left = []
    for root, dirs, files in os.walk(tmp):
        left += [n[:40] for n in dirs + files if n.startswith(".")]
    if left:
        raise HalfWritten(f"temporary files left behind: {left}")


def _profile_files(rng):
    """A tooth, ring or pair outline written to a path of some kind (long, link, folder, existing)."""
    kind = rng.choice(_PATH_KINDS)
    suffix = rng.choice([".csv", ".svg", ".svg", ".csv", ".dxf"])
    overwrite = rng.random() < 0.4
    which = rng.choice(["tooth", "ring", "pair"])
    m, z, x = _pick(rng, [1.0, 2.0, 5.0], 0.05), rng.randint(8, 60), round(rng.uniform(-0.3, 0.8), 3)
    points = 8 if suffix == ".dxf" else rng.choice([8, 20, 60])

    def call():
        with tempfile.TemporaryDirectory() as tmp:
            path = _make_path(rng, tmp, kind, suffix)
            before, links = sorted(os.listdir(tmp)), _links(tmp)
            try:
                if which == "pair":
                    pair = gd.GearPair(m, z, z + rng.randint(5, 40), x, 0.0)
                    return gd.export_profiles(pair, path, overwrite=overwrite, points=points)
                profile = (gd.tooth_profile(m, z, x, points=points) if which == "tooth" else
                           gd.ring_profile(m, z + 30, x + 0.5, points=points))
                return getattr(profile, "to_" + suffix[1:])(path, overwrite=overwrite)
            except gd.GearDesignError:
                if sorted(os.listdir(tmp)) != before:
                    raise HalfWritten(f"a refused write changed the folder: {sorted(os.listdir(tmp))[:5]}")
                raise
            finally:
                _no_temp(tmp)
                _links_kept(links)
    return f"{which} profile (m {m}, z {z}, x {x}, {points} points) to a {kind} {suffix} path, overwrite={overwrite}", call


def _cli_files(rng):
    """A command with several outputs, one of them perhaps bad: all written, or none."""
    cmd = rng.choice(["mesh", "mesh", "planetary", "planetary_ratio", "run", "shift"])

    def call():
        with tempfile.TemporaryDirectory() as tmp:
            wanted = []
            if cmd == "mesh":
                args = ["mesh", "--module", "2", "--z1", str(rng.randint(12, 30)), "--z2", str(rng.randint(31, 60))]
                for flag, sfx in rng.sample([("--plot", ".png"), ("--diagrams", ".png"), ("--svg", ".svg"),
                                             ("--csv", ".csv")], rng.randint(2, 4)):
                    kind = rng.choice(_PATH_KINDS[:6] + ["existing_file"])
                    sub = os.path.join(tmp, flag[2:])
                    os.mkdir(sub)
                    wanted.append(_make_path(rng, sub, kind, sfx))
                    args += [flag, wanted[-1]]
            elif cmd in ("planetary", "planetary_ratio"):
                args = ["planetary", "--module", "2", "--planets", "3"]
                args += (["--ratio", str(round(rng.uniform(3, 8), 2))] if cmd == "planetary_ratio" else
                         ["--z-sun", "21", "--z-planet", "43", "--z-ring", "108"])
                for flag in ("--plot", "--drawing"):
                    wanted.append(os.path.join(tmp, flag[2:] + ".png"))
                    args += [flag, wanted[-1]]
            elif cmd == "run":
                kind = rng.choice(["link_to_folder", "plain", "existing_folder", "long_ok"])
                out = _make_path(rng, tmp, kind, "")
                args = ["run", os.path.join(_ROOT, "studies", "scenes", "seed002_chain.toml"), "--out", out]
                args += ["--overwrite"] if rng.random() < 0.7 else []
            else:
                kind = rng.choice(_PATH_KINDS)
                wanted.append(_make_path(rng, tmp, kind, ".png"))
                args = ["shift", "--z1", "17", "--z2", "26", "--plot", wanted[-1]]
                args += ["--overwrite"] if rng.random() < 0.5 else []
            before, links = {p: _stamp(p) for p in wanted}, _links(tmp)
            err = io.StringIO()
            with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(err):
                try:
                    code = cli_main(args)
                except SystemExit as exc:
                    code = exc.code
            _no_temp(tmp)
            _links_kept(links)
            if "Traceback" in err.getvalue() or code not in (0, 1, 2):
                raise AssertionError(f"exit {code}: {err.getvalue()[-300:]!r}")
            changed = [p for p in wanted if _stamp(p) != before[p]]
            if code == 2 and changed:
                raise HalfWritten(f"exit 2 but wrote {[os.path.basename(p)[:30] for p in changed]}")
            if code == 0 and wanted and len(changed) not in (0, len(wanted)):
                raise HalfWritten(f"wrote {len(changed)} of {len(wanted)} outputs")
            return code
    return f"geardesign {cmd} with several outputs", call


def _stamp(path):
    """What a file's content is now (None: absent), followed through links."""
    try:
        with open(path, "rb") as fh:
            return hash(fh.read())
    except OSError:
        return None


_CHILD = """
import os, signal, sys
target, argv = sys.argv[1], sys.argv[2:]
class CtrlC:
    def find_spec(self, name, path=None, module=None):
        if name == target:
            sys.meta_path.remove(self)
            os.kill(os.getpid(), signal.SIGINT)
        return None
if target != "-":
    sys.meta_path.insert(0, CtrlC())
import runpy
sys.argv = ["geardesign"] + argv
runpy.run_module("geardesign", run_name="__main__", alter_sys=True)
"""
_MODULES = ["numpy", "pandas", "scipy", "matplotlib", "geardesign.cli.pair", "geardesign.cli.shift",
            "geardesign.gears.geometry", "geardesign.errors", "argparse", "cvxpy", "geardesign.cli.engine",
            "geardesign.cli.worm", "geardesign.cli.bearing", "geardesign.cli.shaft", "geardesign.mechanism.engine",
            "geardesign.drives.bearing", "geardesign.drives.shaft_beam", "geardesign.gears.worm.series"]


def _ctrl_c(rng):
    """Ctrl-C at start-up: while a given module imports (deterministic) or after a random delay."""
    argv = rng.choice([["pair", "--module", "2", "--z1", "17", "--z2", "26"], ["shift", "--z1", "17", "--z2", "26"],
                       ["teeth", "--ratio", "2", "--module", "2", "--z1-min", "20", "--z1-max", "21"],
                       ["engine", os.path.join(_ROOT, "examples", "seed000_engine.toml"), "--csv", "t.csv", "--plot",
                        "t.png"], ["worm", "--ratio", "12.5", "--center-distance", "125"],
                       ["bearing", "--series", "62,63", "--bore", "40", "--fr", "3200", "--speed", "650",
                        "--life-h", "20000"],
                       ["shaft", "--sections", "40x35,120x45,40x35", "--supports", "20,180", "--load",
                        "x=100,fy=-1000,torque=120", "--load", "x=200,torque=-120", "--notch", "x=100,kind=key",
                        "--plot", "s.png"]])
    at = rng.choice(_MODULES + ["delay"] * 3)
    delay = round(rng.uniform(0.05, 1.0), 3)

    def call():
        env = {**os.environ, "PYTHONPATH": _ROOT + os.pathsep + os.environ.get("PYTHONPATH", "")}
        with tempfile.TemporaryDirectory() as tmp:
            proc = subprocess.Popen([sys.executable, "-c", _CHILD, "-" if at == "delay" else at, *argv], cwd=tmp,
                                    env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            if at == "delay":
                with contextlib.suppress(subprocess.TimeoutExpired):
                    proc.wait(delay)
                if proc.poll() is None:
                    proc.send_signal(signal.SIGINT)
            out, err = proc.communicate(timeout=60)
            if "Traceback" in err:
                # no geardesign frame: the interpreter's own start-up (site, runpy) had the Ctrl-C before
                # any of the package ran; said in the detail, still counted
                where = "in geardesign" if "geardesign" in err else "before geardesign ran (interpreter start-up)"
                raise AssertionError(f"a traceback on Ctrl-C {where}: {err.strip().splitlines()[-1][:120]!r}")
            if proc.returncode == 130 and len(err.strip().splitlines()) != 1:
                raise AssertionError(f"exit 130 with {len(err.strip().splitlines())} stderr lines")
            _no_temp(tmp)
            return proc.returncode
    return f"Ctrl-C {'while importing ' + at if at != 'delay' else f'after {delay} s'}: geardesign {' '.join(argv)}", call


SURFACES = {"profile_files": _profile_files, "cli_files": _cli_files, "ctrl_c": _ctrl_c}
