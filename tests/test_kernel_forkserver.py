"""The kernel fork server (tests/kernel_forkserver.py) as jupyter_client drives a kernel:
start, execute, interrupt (SIGINT through the stub), and a kill of the stub taking the forked
kernel with it. nbval's use of it (preload, working directory, environment) is checked in
tests/test_nbval_kernel.py."""

from __future__ import annotations

import json
import os
import random
import subprocess
import sys
import time
from pathlib import Path

import pytest

from kernel_forkserver import _IMPORT_TIME_STATE, GC_THRESHOLD, SYMPY_SEED

pytestmark = pytest.mark.slow  # seconds per test: run first (tests/conftest.py)

FORKSERVER = Path(__file__).resolve().with_name("kernel_forkserver.py")


def _wait_for(path: str, proc: subprocess.Popen, timeout: float = 60) -> None:
    deadline = time.monotonic() + timeout
    while not os.path.exists(path):
        assert proc.poll() is None, proc.stderr.read()
        assert time.monotonic() < deadline, "fork server did not start"
        time.sleep(0.02)


@pytest.fixture
def server(tmp_path: Path):
    sock = str(tmp_path / "fs.sock")
    proc = subprocess.Popen(
        [sys.executable, str(FORKSERVER), "serve", sock, "json,sympy.core.random"],
        stderr=subprocess.PIPE,
        text=True,
    )
    _wait_for(sock, proc)
    yield sock
    proc.terminate()
    proc.wait(timeout=10)
    assert not os.path.exists(sock)


def _manager(tmp_path: Path, sock: str):
    from jupyter_client.kernelspec import KernelSpecManager
    from jupyter_client.manager import KernelManager

    fallback = [sys.executable, "-m", "ipykernel_launcher"]
    argv = [sys.executable, "-I", "-S", str(FORKSERVER), "stub", sock, str(len(fallback))]
    spec = tmp_path / "kernels" / "forked"
    spec.mkdir(parents=True)
    spec.joinpath("kernel.json").write_text(
        json.dumps({"argv": [*argv, *fallback, "-f", "{connection_file}"], "display_name": "f"})
    )
    ksm = KernelSpecManager(kernel_dirs=[str(tmp_path / "kernels")])
    return KernelManager(
        kernel_name="forked",
        kernel_spec_manager=ksm,
        transport="ipc",
        ip=str(tmp_path / "k"),
        connection_file=str(tmp_path / "k.json"),
    )


def _run(kc, code: str, timeout: float = 30) -> tuple[str, list[str]]:
    """Execute ``code``; return the reply status and the stdout text."""
    msg_id = kc.execute(code)
    out = []
    while True:
        msg = kc.get_iopub_msg(timeout=timeout)
        if msg["parent_header"].get("msg_id") != msg_id:
            continue
        if msg["msg_type"] == "stream":
            out.append(msg["content"]["text"])
        if msg["msg_type"] == "status" and msg["content"]["execution_state"] == "idle":
            break
    reply = _reply(kc, msg_id, timeout)
    return reply["content"]["status"], "".join(out).split()


def _reply(kc, msg_id: str, timeout: float) -> dict:
    """The shell reply to ``msg_id``, skipping replies to earlier requests: under load
    ``wait_for_ready`` sends more than one kernel_info_request and reads one reply, so the
    others are still queued (seen: each later reply read one request behind)."""
    deadline = time.monotonic() + timeout
    while True:
        reply = kc.get_shell_msg(timeout=max(deadline - time.monotonic(), 0.1))
        if reply["parent_header"].get("msg_id") == msg_id:
            return reply


def test_forked_kernel_runs_is_interrupted_and_dies_with_its_stub(tmp_path, server):
    km = _manager(tmp_path, server)
    km.start_kernel()
    kc = km.client()
    kc.start_channels()
    try:
        kc.wait_for_ready(timeout=30)
        status, out = _run(kc, "import os, sys\nprint(os.getpid(), 'json' in sys.modules)")
        assert status == "ok" and out[1] == "True"  # preloaded in the server
        kernel_pid = int(out[0])
        assert kernel_pid != km.provisioner.process.pid  # the stub is not the kernel
        # SymPy's generator starts from the server's seed in every kernel
        status, out = _run(kc, "from sympy.core.random import rng\nprint(rng.random())")
        assert status == "ok" and float(out[0]) == random.Random(SYMPY_SEED).random()
        # and the collector's settings: the preload frozen, the tests' threshold
        status, out = _run(kc, "import gc\nprint(gc.get_threshold(), gc.get_freeze_count() > 0)")
        assert status == "ok" and " ".join(out) == f"{GC_THRESHOLD} True"

        # an interrupt (SIGINT to the stub's process group) reaches the forked kernel
        msg_id = kc.execute("import time\ntime.sleep(60)", stop_on_error=False)
        # not "as soon as execute_input is published": that comes before the cell runs, and an
        # interrupt then is caught by the kernel's loop ("KeyboardInterrupt caught in kernel",
        # no reply; seen under load). A second is long enough for the cell to be sleeping.
        time.sleep(1.0)
        km.interrupt_kernel()
        reply = _reply(kc, msg_id, timeout=20)
        assert reply["content"]["status"] == "error"
        assert reply["content"]["ename"] == "KeyboardInterrupt"
        assert _run(kc, "print(6 * 7)") == ("ok", ["42"])  # still alive after it

        # killing the stub (what shutdown_kernel(now=True) does) kills the kernel
        km.shutdown_kernel(now=True)
        deadline = time.monotonic() + 10
        while _alive(kernel_pid):
            assert time.monotonic() < deadline, f"forked kernel {kernel_pid} outlived its stub"
            time.sleep(0.05)
    finally:
        kc.stop_channels()
        if km.has_kernel:
            km.shutdown_kernel(now=True)


def _alive(pid: int) -> bool:
    try:
        with open(f"/proc/{pid}/stat") as fh:
            return fh.read().split()[2] != "Z"
    except FileNotFoundError:
        return False


def test_a_normal_shutdown_passes_the_exit_code_back(tmp_path, server):
    km = _manager(tmp_path, server)
    km.start_kernel()
    kc = km.client()
    kc.start_channels()
    kc.wait_for_ready(timeout=30)
    kc.stop_channels()
    km.shutdown_kernel()  # shutdown_request: the kernel exits 0, the stub with it
    assert (
        km.provisioner is None
        or km.provisioner.process is None
        or (km.provisioner.process.returncode == 0)
    )


@pytest.mark.parametrize("module", ["pandas", "IPython"])
def test_a_preload_that_captures_its_surroundings_is_refused(tmp_path, module):
    assert module in _IMPORT_TIME_STATE
    sock = str(tmp_path / "fs.sock")
    proc = subprocess.run(
        [sys.executable, str(FORKSERVER), "serve", sock, module],
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert proc.returncode != 0 and module in proc.stderr and not os.path.exists(sock)
