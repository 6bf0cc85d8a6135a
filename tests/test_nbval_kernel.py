"""The nbval kernel plugin (tests/nbval_kernel.py) under forced TCP port clashes.

Two pytest sessions run in subprocesses on small notebooks written here. Both load a helper
plugin, ``port_clash``, that makes jupyter_client's port selection hand out ports a socket in the
same process is already listening on: the deterministic version of another process taking a
port between selection and the kernel's bind (jupyter/jupyter_client#154, #487).

* Without ``nbval_kernel`` (nbval's own TCP path) the kernel dies and every cell errors with
  "Kernel died before replying to kernel_info", the failure seen in ``make test``.
* With ``nbval_kernel`` the same notebooks run and pass, port selection is never called, and the
  kernel itself reports an IPC connection. The same session checks the bounded retry (a kernel
  that crashes on its first start) and the stderr log (a kernel that always crashes).
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import textwrap
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path

import nbformat
import pytest

import nbval_kernel

pytestmark = pytest.mark.slow  # seconds per test: run first (tests/conftest.py)

TESTS = Path(__file__).resolve().parent


PORT_CLASH = '''
"""pytest plugin for the test: every TCP port jupyter_client picks is already taken."""
import os
import socket

from jupyter_client.connect import LocalPortCache

_held = []


def _occupied_port(self, ip):
    sock = socket.socket()
    sock.bind((ip, 0))
    sock.listen()
    _held.append(sock)
    with open(os.environ["PORT_CLASH_LOG"], "a") as fh:
        fh.write(f"{sock.getsockname()[1]}\\n")
    return sock.getsockname()[1]


LocalPortCache.find_available_port = _occupied_port
'''

STDERR_CELL = (
    "import sys\nprint('Glyph 26080 (\\N{CJK UNIFIED IDEOGRAPH-65E0}) missing', file=sys.stderr)"
)
STDERR_TEXT = "Glyph 26080 (\u65e0) missing"

# A kernel launcher that crashes (writing a line to stderr) while the marker file is missing,
# creating it; with the marker present it runs ipykernel. "always" crashes every time.
CRASHING_KERNEL = """
import os
import runpy
import sys

mode, marker = sys.argv[1], sys.argv[2]
del sys.argv[1:3]
if mode == "always" or not os.path.exists(marker):
    open(marker, "a").close()
    sys.stderr.write(f"crashing_kernel: simulated crash ({mode})\\n")
    sys.exit(3)
sys.argv[0] = "ipykernel_launcher"
runpy.run_module("ipykernel_launcher", run_name="__main__")
"""

# Imported by the fork server (--nbval-kernel-preload preloaded_marker), not by the kernel.
PRELOADED_MARKER = "import os\nIMPORTED_BY, PARENT = os.getpid(), os.getppid()\n"
FORK_CELL = textwrap.dedent(
    """\
    import sys
    marker = sys.modules.get("preloaded_marker")
    print(marker is not None and os.getppid() == marker.IMPORTED_BY)
    print(os.path.exists("ipc.ipynb"), os.environ.get("JPY_PARENT_PID") == str(marker.PARENT))
    print(os.environ["MPLBACKEND"])
    """
)
# --nbval-kernel-env sets it for the kernels (and their fork server) only: the pytest session
# itself runs with Agg
KERNEL_BACKEND = "module://matplotlib_inline.backend_inline"

TRANSPORT_CELL = textwrap.dedent(
    """\
    import json
    from ipykernel.connect import get_connection_info
    info = json.loads(get_connection_info())
    print(info["transport"], os.path.isabs(info["ip"]), info["shell_port"])
    """
)


@dataclass
class Session:
    """What a pytest subprocess left behind."""

    returncode: int
    output: str
    outcomes: dict[str, str]  # "<notebook>::Cell <n>" -> passed / failed / error
    ports_chosen: int
    log_dir: Path


def _notebook(path: Path, kernel: str, cells: list[tuple[str, str]]) -> None:
    """Write a notebook whose code cells print ``stdout`` (the nbval reference)."""
    nb = nbformat.v4.new_notebook()
    nb.metadata["kernelspec"] = {"name": kernel, "display_name": kernel, "language": "python"}
    for count, (source, stdout) in enumerate(cells, start=1):
        cell = nbformat.v4.new_code_cell(source, execution_count=count)
        if stdout:
            cell.outputs = [nbformat.v4.new_output("stream", name="stdout", text=stdout)]
        nb.cells.append(cell)
    nbformat.write(nb, path)


def _kernelspec(share: Path, name: str, mode: str, marker: Path, script: Path) -> None:
    spec = share / "kernels" / name
    spec.mkdir(parents=True)
    argv = [sys.executable, str(script), mode, str(marker), "-f", "{connection_file}"]
    spec.joinpath("kernel.json").write_text(
        json.dumps({"argv": argv, "display_name": name, "language": "python"})
    )


def _start(
    tmp: Path, name: str, notebooks: list[str], plugins: list[str], timeout: int = 30
) -> subprocess.Popen:
    """Start ``pytest --nbval`` on ``notebooks`` (names in ``tmp``) in a subprocess.

    ``timeout`` is ``--nbval-kernel-startup-timeout`` [s]."""
    env = {k: v for k, v in os.environ.items() if not k.startswith(("PYTEST_", "COV_"))}
    env.update(
        PYTHONPATH=os.pathsep.join([str(tmp), str(TESTS)]),
        JUPYTER_PATH=str(tmp / "share"),
        PORT_CLASH_LOG=str(tmp / f"{name}.ports"),
        MPLBACKEND="Agg",
    )
    (tmp / f"{name}.ports").write_text("")
    args = [sys.executable, "-m", "pytest", "-c", str(tmp / "pytest.ini"), "--rootdir", str(tmp)]
    for plugin in plugins:
        args += ["-p", plugin]
    args += ["-p", "no:cacheprovider", "--nbval", "--junitxml", str(tmp / f"{name}.xml"), "-rA"]
    args += ["--nbval-kernel-startup-timeout", str(timeout), "-W", "always::UserWarning"]
    if "nbval_kernel" in plugins:
        args += ["--nbval-kernel-log-dir", str(tmp / f"{name}-logs")]
        args += ["--nbval-kernel-preload", "preloaded_marker"]
        args += ["--nbval-kernel-env", f"MPLBACKEND={KERNEL_BACKEND}"]
    return subprocess.Popen(
        [*args, *notebooks],
        cwd=tmp,
        env=env,
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
    )


def _finish(tmp: Path, name: str, proc: subprocess.Popen) -> Session:
    """Wait for a session started by :func:`_start` and collect what it left."""
    output, _ = proc.communicate(timeout=120)
    outcomes = {}
    for case in ET.parse(tmp / f"{name}.xml").getroot().iter("testcase"):
        kinds = [child.tag for child in case if child.tag in ("failure", "error", "skipped")]
        outcomes[f"{case.get('classname')}::{case.get('name')}"] = kinds[0] if kinds else "passed"
    ports = len((tmp / f"{name}.ports").read_text().split())
    return Session(proc.returncode, output, outcomes, ports, tmp / f"{name}-logs")


@pytest.fixture(scope="module")
def workdir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Notebooks, kernel specs and the clash plugin in a fresh directory."""
    tmp = tmp_path_factory.mktemp("nbval_kernel")
    (tmp / "pytest.ini").write_text("[pytest]\n")
    (tmp / "port_clash.py").write_text(PORT_CLASH)
    (tmp / "preloaded_marker.py").write_text(PRELOADED_MARKER)
    script = tmp / "crashing_kernel.py"
    script.write_text(CRASHING_KERNEL)
    _kernelspec(tmp / "share", "crash_once", "once", tmp / "crash_once.marker", script)
    _kernelspec(tmp / "share", "crash_always", "always", tmp / "crash_always.marker", script)
    two = ("x = 1 + 1\nprint(x)", "2\n")
    _notebook(tmp / "tcp.ipynb", "python3", [two])
    ipc = [
        ("import os", ""),
        (TRANSPORT_CELL, "ipc True 1\n"),
        (FORK_CELL, f"True\nTrue True\n{KERNEL_BACKEND}\n"),
    ]
    _notebook(tmp / "ipc.ipynb", "python3", ipc)
    # a cell whose stored output has no stderr writes to it: the failure report quotes the text
    _notebook(tmp / "stderr.ipynb", "python3", [(STDERR_CELL, "")])
    _notebook(tmp / "once.ipynb", "crash_once", [two])
    _notebook(tmp / "always.ipynb", "crash_always", [two])
    return tmp


# Both sessions run at once (the TCP one mostly waits out its startup timeout), from one
# fixture used by one test: under ``pytest -n 2`` tests of one module may land on both workers,
# and a module fixture shared by tests on both would run its sessions twice. (``--dist
# loadgroup`` would pin them to one worker, but with pytest 9.2 and xdist 3.8 it silently stops
# grouping: pytest-dev/pytest-xdist#1386.)
@pytest.fixture(scope="module")
def sessions(workdir: Path) -> tuple[Session, Session]:
    """(tcp, ipc): nbval's own TCP kernel start under the clash, and the plugin's IPC start
    under the clash with a crash-once and a crash-always kernel.

    The TCP session's kernel never answers, and nbval waits out the startup timeout before
    reporting the death: 5 s keeps it short (the plugin's session keeps 30 s for real starts)."""
    tcp = _start(workdir, "tcp", ["tcp.ipynb"], ["port_clash"], timeout=5)
    notebooks = ["ipc.ipynb", "once.ipynb", "always.ipynb", "stderr.ipynb"]
    ipc = _start(workdir, "ipc", notebooks, ["port_clash", "nbval_kernel"])
    return _finish(workdir, "tcp", tcp), _finish(workdir, "ipc", ipc)


def test_a_taken_port_kills_the_tcp_kernel_and_the_plugin_survives_it(
    sessions: tuple[Session, Session],
) -> None:
    tcp_session, ipc_session = sessions
    # nbval's own path: the kernel dies
    assert tcp_session.ports_chosen == 5, tcp_session.output
    assert tcp_session.outcomes == {"tcp.ipynb::Cell 0": "error"}, tcp_session.output
    assert "Kernel died before replying to kernel_info" in tcp_session.output
    assert tcp_session.returncode == 1

    # the plugin's path: IPC, a retry, and a clear error naming the log
    out = ipc_session.output
    # Despite taken ports: the second cell prints the transport as the kernel sees it; nbval
    # compares it to "ipc ...".
    assert ipc_session.outcomes["ipc.ipynb::Cell 0"] == "passed", out
    assert ipc_session.outcomes["ipc.ipynb::Cell 1"] == "passed", out
    # The python3 kernel was forked from the fork server (which imported the preload list), runs
    # in the notebook's directory and has the environment jupyter_client gave the kernel process
    # (JPY_PARENT_PID: the pytest process, the server's parent; the server's own has none),
    # with the MPLBACKEND of --nbval-kernel-env (the server has it too: the stub compares them
    # and execs a plain kernel, not a fork, where they differ).
    assert ipc_session.outcomes["ipc.ipynb::Cell 2"] == "passed", out
    # the crashing kernels' specs are not plain ipykernel ones: they start as processes
    assert "kernel_forkserver" not in (ipc_session.log_dir / "once.ipynb.stderr.log").read_text()
    assert ipc_session.ports_chosen == 0, "the plugin's path asked jupyter_client for TCP ports"

    # An unexpected stderr output: nbval names only its key; the report quotes its text.
    assert ipc_session.outcomes["stderr.ipynb::Cell 0"] == "failure", out
    assert "Unexpected output fields from running code: {'stderr'}" in out, out
    assert "cell stderr" in out and STDERR_TEXT in out, out

    # A kernel that dies at its first start is started again.
    assert ipc_session.outcomes["once.ipynb::Cell 0"] == "passed", out
    assert "KernelStartRetry" in out and "died at start 1/3" in out, out
    assert "simulated crash (once)" in out, "the retry warning should quote the kernel's stderr"
    log = (ipc_session.log_dir / "once.ipynb.stderr.log").read_text()
    assert log.count("--- nbval_kernel: start") == 2 and "simulated crash (once)" in log, log

    # One that always dies is given up after MAX_STARTS, naming its stderr log.
    assert ipc_session.outcomes["always.ipynb::Cell 0"] == "error", out
    log_path = ipc_session.log_dir / "always.ipynb.stderr.log"
    assert f"on all {nbval_kernel.MAX_STARTS} starts" in out
    assert f"kernel stderr: {log_path}" in out
    log = log_path.read_text()
    assert log.count("simulated crash (always)") == nbval_kernel.MAX_STARTS, log
    assert ipc_session.returncode == 1


def test_ipc_prefixes_are_fresh_private_and_fit_a_socket_address(tmp_path: Path) -> None:
    state = nbval_kernel._State(tmp_path / "logs", tmp_path)
    try:
        prefixes = [state.next_ipc_prefix() for _ in range(50)]
        assert len(set(prefixes)) == 50
        assert all(os.path.isabs(p) and len(p) + 2 <= 107 for p in prefixes)
        assert os.stat(state.ipc_dir).st_mode & 0o077 == 0, "IPC directory readable by others"
    finally:
        os.rmdir(state.ipc_dir)


def test_log_names_follow_the_notebook_path(tmp_path: Path) -> None:
    state = nbval_kernel._State(tmp_path / "logs", tmp_path)
    try:
        inside = state.log_path(tmp_path / "notebooks" / "01_a.ipynb", None)
        outside = state.log_path(Path("/elsewhere/01_a.ipynb"), None)
    finally:
        os.rmdir(state.ipc_dir)
    assert inside == tmp_path / "logs" / "notebooks__01_a.ipynb.stderr.log"
    assert outside.name.startswith("01_a.ipynb-") and outside != inside


def test_kernel_env_options_are_name_value_pairs() -> None:
    assert nbval_kernel.parse_kernel_env(["MPLBACKEND=a=b", "EMPTY="]) == {
        "MPLBACKEND": "a=b",
        "EMPTY": "",
    }
    for bad in ("MPLBACKEND", "=value"):
        with pytest.raises(pytest.UsageError, match=f"--nbval-kernel-env '{bad}'"):
            nbval_kernel.parse_kernel_env([bad])


@pytest.mark.parametrize("dist", ["load", "worksteal", "loadgroup"])
def test_a_dist_mode_that_splits_notebooks_is_refused(dist: str) -> None:
    with pytest.raises(pytest.UsageError, match=f"--dist {dist} would hand the cells"):
        nbval_kernel.check_dist(True, dist)
    nbval_kernel.check_dist(False, dist)  # without --nbval nothing to protect
    for fine in ("no", "each", "loadfile", "loadscope"):
        nbval_kernel.check_dist(True, fine)


def test_no_notebook_schema_uses_the_formats_left_unchecked() -> None:
    """nbval_kernel blocks rfc3987_syntax (start-up time); jsonschema then skips only the "iri"
    and "iri-reference" formats, which nbformat's schemas (every version) never use."""
    import json

    import nbformat

    def formats(node: object) -> set[str]:
        if isinstance(node, dict):
            own = {node["format"]} if isinstance(node.get("format"), str) else set()
            return own.union(*(formats(v) for v in node.values()))
        if isinstance(node, list):
            return set().union(*(formats(v) for v in node))
        return set()

    schemas = sorted(Path(nbformat.__file__).parent.glob("v*/*.json"))
    assert len(schemas) >= 7
    used = set().union(*(formats(json.loads(p.read_text())) for p in schemas))
    assert not used & {"iri", "iri-reference"}, used
