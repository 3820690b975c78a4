"""--workers N and --scheduler ADDRESS on atlas, teeth, planetary --ratio and run: the same files as
a serial run, one error line (exit 2) for a bad count or an unreachable scheduler, and Ctrl-C on a
local cluster exits 130 leaving no process and no scratch folder."""
import json
import os
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import psutil
import pytest

from geardesign import parallel
from geardesign.cli import main
from tests.dask_cluster import client  # noqa: F401

pytestmark = pytest.mark.slow   # clusters, browsers, notebooks: seconds each (CONTRIBUTING.md)

ROOT = Path(__file__).resolve().parents[2]


def _error_line(capsys, argv, match):
    assert main(argv) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith(f"geardesign {argv[0]}: error:") and match in err[0], err


@pytest.mark.parametrize("bad", ["0", "two", "1.5", str(parallel.LOCAL_WORKERS_MAX + 1), "-3"])
def test_bad_worker_counts_are_one_error_line(capsys, bad):
    _error_line(capsys, ["atlas", "--z1", "17", "--z2", "26", "--workers", bad], "--workers")


def test_workers_and_scheduler_together_are_refused(capsys):
    _error_line(capsys, ["teeth", "--ratio", "2", "--workers", "2", "--scheduler", "tcp://127.0.0.1:9"], "not both")


def test_planetary_takes_a_cluster_only_for_the_tooth_count_search(capsys):
    _error_line(capsys, ["planetary", "--module", "2", "--planets", "3", "--z-sun", "21", "--z-planet", "43",
                         "--z-ring", "108", "--workers", "2"], "go with --ratio")


def test_an_unreachable_scheduler_is_one_error_line(capsys, monkeypatch):
    monkeypatch.setattr(parallel, "CONNECT_TIMEOUT_S", 1)
    _error_line(capsys, ["atlas", "--z1", "17", "--z2", "26", "--scheduler", "tcp://127.0.0.1:9"],
                "scheduler 'tcp://127.0.0.1:9': cannot connect")


def test_atlas_limit_on_the_command_line_scales_with_workers(capsys):
    _error_line(capsys, ["atlas", "--z1", "3:600", "--z2", "3:600"], "at most 100,000")
    _error_line(capsys, ["atlas", "--z1", "3:800", "--z2", "3:800", "--workers", "2"],
                "at most 200,000 (100,000 per worker)")


def test_atlas_with_workers_writes_the_serial_table(tmp_path, capsys):
    args = ["atlas", "--z1", "10:16", "--z2", "16:30"]
    assert main(args + ["--out", str(tmp_path / "serial.csv")]) == 0
    assert main(args + ["--out", str(tmp_path / "cluster.csv"), "--workers", "2"]) == 0
    assert (tmp_path / "serial.csv").read_bytes() == (tmp_path / "cluster.csv").read_bytes()


def test_teeth_planetary_and_run_on_a_scheduler_give_the_serial_output(tmp_path, capsys, client):  # noqa: F811
    address = ["--scheduler", client.scheduler.address]
    teeth = ["teeth", "--ratio", "2.5", "--ratio-tol", "0.03", "--z1-min", "12", "--z1-max", "24"]
    assert main(teeth + ["--out", str(tmp_path / "a.csv")]) == 0
    assert main(teeth + ["--out", str(tmp_path / "b.csv")] + address) == 0
    assert (tmp_path / "a.csv").read_bytes() == (tmp_path / "b.csv").read_bytes()

    planetary = ["planetary", "--module", "2", "--planets", "3", "--ratio", "4.6", "--z-sun-range", "17:21", "--json"]
    capsys.readouterr()
    codes = [main(planetary), main(planetary + address)]
    assert codes[0] == codes[1]
    serial, cluster = (json.loads(t) for t in _two_json(capsys.readouterr().out))
    serial.pop("time_s"), cluster.pop("time_s")
    assert serial == cluster and len(serial["table"]) > 3

    scene = tmp_path / "teeth.toml"
    scene.write_text('title = "tooth counts"\n[teeth]\nratio = 2.5\nratio_tol = 0.03\nz1_range = [12, 24]\n'
                     'module = 2\n', encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "s1")]) == 0
    assert main(["run", str(scene), "--out", str(tmp_path / "s2")] + address) == 0
    assert (tmp_path / "s1" / "teeth.csv").read_bytes() == (tmp_path / "s2" / "teeth.csv").read_bytes()


def _two_json(text):
    """The two JSON documents printed one after the other."""
    dec = json.JSONDecoder()
    first, end = dec.raw_decode(text)
    second, _ = dec.raw_decode(text[end:].lstrip())
    return json.dumps(first), json.dumps(second)


def test_ctrl_c_on_a_local_cluster_exits_130_and_leaves_nothing():
    """Ctrl-C reaches the whole process group (the command and its workers); one while the workers
    start is lost (they start deaf to it), so it is pressed again every few seconds, as a user would."""
    scratch = {n for n in os.listdir(tempfile.gettempdir()) if n.startswith("geardesign-dask-")}
    p = subprocess.Popen([sys.executable, "-m", "geardesign", "atlas", "--z1", "8:120", "--z2", "8:300", "--workers",
                          "2"], cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                         start_new_session=True, preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    proc, seen, t0 = psutil.Process(p.pid), set(), time.monotonic()
    try:
        while time.monotonic() - t0 < 60 and len(seen) < 2:      # the two workers are starting
            seen |= {k.pid for k in proc.children(recursive=True)}
            time.sleep(0.1)
        for _ in range(20):
            seen |= {k.pid for k in proc.children(recursive=True)}
            os.killpg(p.pid, signal.SIGINT)
            try:
                p.wait(3)
                break
            except subprocess.TimeoutExpired:
                pass
        _, err = p.communicate(timeout=30)
    finally:
        if p.poll() is None:
            os.killpg(p.pid, signal.SIGKILL)
    assert p.returncode == 130
    assert err.strip().splitlines() == ["geardesign atlas: interrupted, nothing written"]
    assert len(seen) >= 2


    def alive():
        return [pid for pid in seen if psutil.pid_exists(pid) and psutil.Process(pid).status() != psutil.STATUS_ZOMBIE]

    end = time.monotonic() + 15            # multiprocessing's resource tracker leaves once its pipe closes
    while alive() and time.monotonic() < end:
        time.sleep(0.2)
    assert alive() == []
    assert {n for n in os.listdir(tempfile.gettempdir()) if n.startswith("geardesign-dask-")} <= scratch


def test_one_ctrl_c_while_the_workers_start_ends_the_command(tmp_path):
    """Issue 36 §1.3: a Ctrl-C pressed once, while the local cluster starts (its child processes are
    appearing), was thrown away: the search ran to its end and exited 0. It is held back until the start ends,
    then acted on: exit 130, one line, no process and no scratch folder left (Dask's own included)."""
    env = dict(os.environ, TMPDIR=str(tmp_path))
    p = subprocess.Popen([sys.executable, "-m", "geardesign", "planetary", "-m", "2", "--planets", "3", "--ratio",
                          "5.2", "--torque", "80", "--speed", "1500", "--material", "18CrNiMo7-6", "--face-width",
                          "20", "--workers", "2"], cwd=ROOT, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         text=True, start_new_session=True,
                         preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    proc, seen, t0 = psutil.Process(p.pid), set(), time.monotonic()
    try:
        while p.poll() is None and len(seen) < 2 and time.monotonic() - t0 < 120:
            seen |= {k.pid for k in proc.children(recursive=True)}
            time.sleep(0.02)
        assert len(seen) >= 2, "the cluster never started its processes"
        os.killpg(p.pid, signal.SIGINT)
        out, err = p.communicate(timeout=180)
    finally:
        if p.poll() is None:
            os.killpg(p.pid, signal.SIGKILL)
    assert p.returncode == 130, (out[-300:], err[-300:])
    assert err.strip().splitlines() == ["geardesign planetary: interrupted, nothing written"]

    def alive():
        return [pid for pid in seen if psutil.pid_exists(pid) and psutil.Process(pid).status() != psutil.STATUS_ZOMBIE]

    end = time.monotonic() + 15            # multiprocessing's resource tracker leaves once its pipe closes
    while alive() and time.monotonic() < end:
        time.sleep(0.2)
    assert alive() == []
    assert list(tmp_path.iterdir()) == []
