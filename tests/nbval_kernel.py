"""pytest plugin: nbval kernels over IPC, a bounded retry of a kernel that dies at start-up,
and each kernel's stderr kept in a log file.

Enable it with ``-p tests.nbval_kernel`` (the Makefile's nbval command does) or, with ``tests``
on ``sys.path``, ``-p nbval_kernel``.

Why
---
jupyter_client 8.10 starts a kernel by choosing five free TCP ports (bind to port 0, read the
number, close the socket), writing them into the connection file and launching the kernel, which
binds them about a second later (``jupyter_client.connect.write_connection_file``,
``LocalPortCache.find_available_port``). Any other process can take one of those ports in
between; ipykernel then fails to bind (``zmq.error.ZMQError: Address already in use``; it does
not retry a port it was given, ``ipykernel.kernelapp.IPKernelApp._bind_socket``) and exits.
``make test`` runs nbval under pytest-xdist, two workers each starting one kernel per notebook,
so the two workers race each other. The client then reports only "Kernel died before replying
to kernel_info", for every cell of the notebook, because nbval sends the kernel's stderr to
``os.devnull``. Upstream: jupyter/jupyter_client#154 and #487 (the in-process ``LocalPortCache``
cannot protect against other processes), jupyter/enhancement-proposals#66 (handshaking, not in
ipykernel 7.4). The workaround the maintainers give is the IPC transport
(``KernelManager.transport = "ipc"``, jupyter/notebook#834).

What this plugin changes
------------------------
1. Kernels use ``transport="ipc"``: the five channels are Unix sockets ``<prefix>-1`` ...
   ``<prefix>-5`` where ``<prefix>`` is a fresh path in a private (mode 0700) directory made by
   this pytest process, so no TCP port is ever chosen and no other process can hold the address.
   The connection file lives beside them (``<prefix>.json``), not in the shared Jupyter runtime
   directory.
2. A kernel whose process exits before it answers ``kernel_info`` is started again, at most
   :data:`MAX_STARTS` times in all, each time on a new IPC prefix. Every retry is logged
   (logger ``nbval_kernel``) and raised as a :class:`KernelStartRetry` warning, so it shows in
   pytest's warnings summary even when the notebook then passes; the reason names the exit code
   and the last lines the kernel wrote to stderr. A kernel that is alive but silent is *not*
   retried (that would multiply ``--nbval-kernel-startup-timeout``).
3. The kernel's stderr goes to ``<log dir>/<notebook path with / as __>.stderr.log``
   (``--nbval-kernel-log-dir``, default ``build/nbval-kernel-logs`` under the rootdir). The
   path, and the last lines of the log, are added to the report of every failing cell, and a
   start that fails for good names the path in its error. The report of a failing cell also
   quotes the text the cell itself wrote to stderr (section "cell stderr"): nbval names only
   the key of an unexpected output ("Unexpected output fields ...: {'stderr'}"), not what it
   says.
4. ``--nbval-kernel-preload m1,m2``: kernels are forked from a server that imported those
   modules once (``tests/kernel_forkserver.py``).
5. ``--nbval-kernel-env NAME=VALUE`` (repeatable) sets a variable for the kernels (and their
   fork server) only, so that one session can run tests that draw with Agg and notebooks whose
   stored figures come from the inline backend (``make test``).
6. An xdist mode that would hand a notebook's cells to different workers (``load``,
   ``worksteal``, ``loadgroup``: see :func:`check_dist`) is refused with a usage error.

Where it hooks in, and why there
--------------------------------
nbval 0.11.0 starts one kernel per notebook in ``IPyNbFile.setup`` with
``RunningKernel(kernel_name, cwd=..., startup_timeout=...)``, looking the name ``RunningKernel``
up in ``nbval.plugin`` at call time. ``RunningKernel.__init__`` calls
``nbval.kernel.start_new_kernel``, which builds ``KernelManager(kernel_name=...,
kernel_spec_manager=NbvalKernelspecManager())`` (no way to pass ``transport`` or ``ip``), passes
``stderr=open(os.devnull, "w")`` and gives up on the first failure. Traitlets configuration
(``c.KernelManager.transport``) is not an option: only Jupyter *applications* load config files,
a bare ``KernelManager()`` as nbval builds it sees none. Subclassing ``IPyNbFile`` would need
nbval's own ``pytest_collect_file`` switched off. So the one seam is that name: at
``pytest_configure`` this plugin rebinds ``nbval.plugin.RunningKernel`` to the subclass
:class:`IpcRunningKernel` and restores it at ``pytest_unconfigure``. The subclass replaces only
how the kernel is started (``__init__``) and stopped (``stop``, which also closes the log);
everything that talks to the running kernel is inherited unchanged. The plugin refuses to load
(``pytest.UsageError``) if that name is missing or is not nbval's ``RunningKernel``, so a future
nbval cannot silently bypass it; ``tests/test_nbval_kernel.py`` checks, from inside a kernel,
that the transport really is IPC.
"""

from __future__ import annotations

import contextvars
import hashlib
import logging
import os
import shutil
import subprocess
import sys
import tempfile
import time
import warnings
from collections.abc import Generator
from pathlib import Path
from typing import IO, Any

# rfc3987_syntax builds an Earley parser for RFC 3987 when it is imported: 0.8 s of CPU, a third
# of a pytest process's start-up here (nbval imports nbformat, nbformat jsonschema, jsonschema
# rfc3987_syntax). jsonschema imports it only to check the "iri" and "iri-reference" string
# formats, which no schema validated in these processes uses (nbformat's: checked in
# tests/test_nbval_kernel.py); blocked, jsonschema leaves those two formats unchecked. This
# module is imported before nbval when loaded with -p (pytest loads -p plugins first).
sys.modules.setdefault("rfc3987_syntax", None)  # type: ignore[arg-type]

import pytest  # noqa: E402
from nbval.kernel import NbvalKernelspecManager, RunningKernel  # noqa: E402

MAX_STARTS = 3
"""Kernel starts per notebook (the first one and two retries)."""

TAIL_LINES = 15
"""Lines of a kernel's stderr log quoted in a failure report."""

FORKSERVER = Path(__file__).resolve().with_name("kernel_forkserver.py")
FORKSERVER_STARTUP = 120.0
"""Seconds a fork server may take to import its preload list."""

# Linux sun_path is 108 bytes including the terminating NUL; leave room for "-<port>".
_MAX_IPC_PREFIX = 100

logger = logging.getLogger("nbval_kernel")

_current_notebook: contextvars.ContextVar[Path | None] = contextvars.ContextVar(
    "nbval_kernel_notebook", default=None
)


class KernelStartRetry(UserWarning):
    """A notebook kernel died before replying to ``kernel_info`` and was started again."""


class KernelStartError(RuntimeError):
    """A notebook kernel could not be started (after :data:`MAX_STARTS` starts if it kept dying)."""


class _State:
    """Per-process plugin state: the private IPC directory, the log directory, log paths."""

    def __init__(self, log_dir: Path, rootpath: Path) -> None:
        self.log_dir = log_dir
        self.rootpath = rootpath
        self.ipc_dir = _make_ipc_dir()
        self.counter = 0
        self.logs: dict[Path, Path] = {}
        self.preload: list[str] = []
        self.kernel_env: dict[str, str] = {}
        self.forkservers: dict[tuple[str, ...], tuple[subprocess.Popen, str]] = {}

    def forkserver(self, interpreter: tuple[str, ...]) -> str | None:
        """The socket of the fork server for ``interpreter`` (started on first use), or None
        if it could not start (the kernel then starts normally; see the server's log)."""
        if interpreter in self.forkservers:
            proc, sock = self.forkservers[interpreter]
            return sock if proc.poll() is None else None
        sock = os.path.join(self.ipc_dir, f"forkserver{len(self.forkservers)}.sock")
        self.log_dir.mkdir(parents=True, exist_ok=True)
        worker = os.environ.get("PYTEST_XDIST_WORKER", "main")
        log = self.log_dir / f"forkserver-{worker}.stderr.log"
        with open(log, "wb") as fh:
            proc = subprocess.Popen(
                [*interpreter, str(FORKSERVER), "serve", sock, ",".join(self.preload)],
                env=self.env(),
                stdin=subprocess.DEVNULL,
                stdout=fh,
                stderr=fh,
            )
        self.forkservers[interpreter] = (proc, sock)
        deadline = time.monotonic() + FORKSERVER_STARTUP
        while not os.path.exists(sock):
            if proc.poll() is not None or time.monotonic() > deadline:
                message = f"kernel fork server did not start; kernels start normally; see {log}"
                logger.warning(message)
                warnings.warn(message, KernelStartRetry, stacklevel=2)
                proc.kill()
                return None
            time.sleep(0.02)
        return sock

    def stop_forkservers(self) -> None:
        for proc, _ in self.forkservers.values():
            proc.terminate()
        for proc, _ in self.forkservers.values():
            try:
                proc.wait(timeout=10)
            except subprocess.TimeoutExpired:
                proc.kill()

    def env(self) -> dict[str, str]:
        """The kernels' environment: this process's, with ``--nbval-kernel-env`` applied."""
        return {**os.environ, **self.kernel_env}

    def next_ipc_prefix(self) -> str:
        """Return a fresh absolute path prefix for one kernel's IPC sockets."""
        self.counter += 1
        return os.path.join(self.ipc_dir, f"k{self.counter}")

    def log_path(self, notebook: Path | None, cwd: str | None) -> Path:
        """Return the stderr log path for a notebook (``<rel path, / as __>.stderr.log``)."""
        if notebook is None:  # started outside an nbval cell's setup: name it by counter
            name = f"kernel-{os.getpid()}-{self.counter + 1}"
        else:
            notebook = notebook.resolve()
            try:
                name = "__".join(notebook.relative_to(self.rootpath).parts)
            except ValueError:
                digest = hashlib.sha1(str(notebook).encode()).hexdigest()[:8]
                name = f"{notebook.name}-{digest}"
        path = self.log_dir / f"{name}.stderr.log"
        if notebook is not None:
            self.logs[notebook] = path
        return path


_state: _State | None = None
_original_running_kernel: Any = None


def _make_ipc_dir() -> str:
    """Make a private (0700) directory whose paths fit in a Unix socket address."""
    for parent in (tempfile.gettempdir(), "/tmp"):
        path = tempfile.mkdtemp(prefix="nbval-ipc-", dir=parent)
        if len(path) + len("/k999999") <= _MAX_IPC_PREFIX:
            return path
        os.rmdir(path)
    raise pytest.UsageError(
        f"nbval_kernel: no temporary directory gives IPC socket paths under {_MAX_IPC_PREFIX} "
        f"bytes (TMPDIR={tempfile.gettempdir()!r}); set TMPDIR to a short path"
    )


def _tail(path: Path, start: int = 0, lines: int = TAIL_LINES) -> str:
    """Return the last ``lines`` non-empty lines of ``path`` from byte ``start`` on."""
    try:
        with open(path, "rb") as fh:
            fh.seek(start)
            text = fh.read().decode("utf-8", "replace")
    except OSError:
        return ""
    kept = [line for line in text.splitlines() if line.strip()]
    return "\n".join(kept[-lines:])


def _wait_for_ready(km: Any, kc: Any, timeout: float) -> None:
    """``kc.wait_for_ready(timeout)`` with the kernel's death noticed within 0.1 s.

    jupyter_client 8.10's loop (``KernelClient._async_wait_for_ready``) sends ``kernel_info``,
    waits up to 1 s for the reply and only then asks whether the kernel is alive: a kernel that
    crashes at start-up costs a second per start. Same protocol here (ready = a
    ``kernel_info_reply`` and then any IOPub message, which shows IOPub is connected; then
    IOPub is flushed), with the shell polled every 0.1 s and ``kernel_info`` re-sent every
    second, as there. Raises RuntimeError with jupyter_client's messages."""
    from queue import Empty

    deadline = time.monotonic() + timeout
    resend = 0.0
    while True:
        if time.monotonic() >= resend:
            kc.kernel_info()
            resend = time.monotonic() + 1.0
        try:
            msg = kc.get_shell_msg(timeout=0.1)
        except Empty:
            msg = None
        if msg is not None and msg["msg_type"] == "kernel_info_reply":
            try:
                kc.get_iopub_msg(timeout=0.2)
            except Empty:
                resend = 0.0  # IOPub not connected yet: ask again
            else:
                handle = getattr(kc, "_handle_kernel_info_reply", None)
                if handle is not None:  # protocol version adaptation, as jupyter_client does
                    handle(msg)
                break
        if not km.is_alive():
            raise RuntimeError("Kernel died before replying to kernel_info")
        if time.monotonic() > deadline:
            raise RuntimeError(f"Kernel didn't respond in {timeout:g} seconds")
    while True:  # flush IOPub
        try:
            kc.get_iopub_msg(timeout=0.2)
        except Empty:
            break


def _exit_code(km: Any) -> int | None:
    """The kernel process's exit code, if the manager has a finished process."""
    process = getattr(getattr(km, "provisioner", None), "process", None)
    return None if process is None else process.poll()


class IpcRunningKernel(RunningKernel):
    """nbval's ``RunningKernel``, started over IPC with retries and a stderr log.

    Parameters
    ----------
    kernel_name : str
        Kernel spec name (nbval's ``:nbval-parent-env`` included).
    cwd : str, optional
        Working directory of the kernel (nbval passes the notebook's directory).
    startup_timeout : float, default 60
        Seconds to wait for one start to answer ``kernel_info``.

    Attributes
    ----------
    stderr_log : pathlib.Path
        The file the kernel's stderr is written to.
    starts : int
        How many kernel processes were started (1 unless a start died).
    """

    def __init__(self, kernel_name: str, cwd: str | None = None, startup_timeout: float = 60):
        from jupyter_client.manager import KernelManager

        state = _require_state()
        notebook = _current_notebook.get()
        self.stderr_log = state.log_path(notebook, cwd)
        self.stderr_log.parent.mkdir(parents=True, exist_ok=True)
        self.stderr_log.write_bytes(b"")
        # Append mode (O_APPEND): the kernel shares this file description, so without it our
        # marker lines could overwrite what the kernel wrote.
        self._log: IO[str] = open(self.stderr_log, "a", encoding="utf-8")
        what = f"kernel {kernel_name!r} for {notebook or cwd}"
        self.starts = 0
        try:
            for attempt in range(1, MAX_STARTS + 1):
                self.starts = attempt
                prefix = state.next_ipc_prefix()
                self._log.write(
                    f"--- nbval_kernel: start {attempt}/{MAX_STARTS} of {what}, ipc {prefix} ---\n"
                )
                self._log.flush()
                offset = self.stderr_log.stat().st_size
                km = KernelManager(
                    kernel_name=kernel_name,
                    kernel_spec_manager=_ForkingSpecManager(),
                    transport="ipc",
                    ip=prefix,
                    connection_file=prefix + ".json",
                )
                km.start_kernel(stderr=self._log, cwd=cwd, env=state.env())
                kc = km.client()
                kc.start_channels()
                try:
                    _wait_for_ready(km, kc, startup_timeout)
                except RuntimeError as exc:
                    died = not km.is_alive()
                    code = _exit_code(km)
                    kc.stop_channels()
                    km.shutdown_kernel(now=True)
                    tail = _tail(self.stderr_log, offset, lines=3).replace("\n", " | ")
                    reason = f"{exc} (exit code {code}; stderr: {tail or 'empty'})"
                    if not died:
                        raise KernelStartError(
                            f"{what} did not answer kernel_info within {startup_timeout} s "
                            f"(--nbval-kernel-startup-timeout); kernel stderr: {self.stderr_log}"
                        ) from exc
                    if attempt == MAX_STARTS:
                        raise KernelStartError(
                            f"{what} died before replying to kernel_info on all {MAX_STARTS} "
                            f"starts; last: {reason}; kernel stderr: {self.stderr_log}"
                        ) from exc
                    message = (
                        f"{what} died at start {attempt}/{MAX_STARTS}: {reason}; starting it "
                        f"again; kernel stderr: {self.stderr_log}"
                    )
                    logger.warning(message)
                    warnings.warn(message, KernelStartRetry, stacklevel=2)
                    continue
                self.km, self.kc = km, kc
                break
            self._ensure_iopub_up()
        except BaseException:
            if hasattr(self, "km"):
                self.stop()
            else:
                self._log.close()
            raise

    def stop(self) -> None:
        """Stop the channels and the kernel, then close the stderr log."""
        try:
            super().stop()
        finally:
            self._log.close()


class _ForkingSpecManager(NbvalKernelspecManager):
    """nbval's kernel spec manager; with ``--nbval-kernel-preload`` a plain ipykernel spec
    (``python [flags] -m ipykernel_launcher -f {connection_file}``) is started through the
    fork server of ``tests/kernel_forkserver.py``."""

    def get_kernel_spec(self, kernel_name: str) -> Any:
        spec = super().get_kernel_spec(kernel_name)
        state = _require_state()
        argv = list(spec.argv)
        tail = ["-m", "ipykernel_launcher", "-f", "{connection_file}"]
        if not state.preload or len(argv) < 5 or argv[-4:] != tail:
            return spec
        sock = state.forkserver(tuple(argv[:-4]))
        if sock is None:
            return spec
        fallback = argv[:-2]
        spec.argv = [argv[0], "-I", "-S", str(FORKSERVER), "stub", sock, str(len(fallback))]
        spec.argv += [*fallback, "-f", "{connection_file}"]
        return spec


def parse_kernel_env(pairs: list[str]) -> dict[str, str]:
    """``--nbval-kernel-env NAME=VALUE`` options as a dict; a pair without ``=`` or without a
    name is a usage error naming it."""
    env = {}
    for pair in pairs:
        name, sep, value = pair.partition("=")
        if not sep or not name:
            raise pytest.UsageError(f"--nbval-kernel-env {pair!r}: expected NAME=VALUE")
        env[name] = value
    return env


def check_dist(nbval: bool, dist: str) -> None:
    """Refuse an xdist mode that would split a notebook's cells between workers.

    nbval runs a notebook's cells in order in one kernel, started for the first cell; under
    ``--dist load`` or ``worksteal`` a later cell can land on the other worker, which has no
    kernel with that notebook's state. ``loadgroup`` would be right but with pytest 9.2 and
    pytest-xdist 3.8 it ignores the groups (xdist writes the retired ``Item._nodeid``;
    pytest-dev/pytest-xdist#1386), so it is refused too."""
    if nbval and dist not in ("no", "each", "loadfile", "loadscope"):
        raise pytest.UsageError(
            f"nbval_kernel: --dist {dist} would hand the cells of one notebook to different "
            "workers (each cell must run in that notebook's kernel, in order); use --dist "
            "loadscope or loadfile"
        )


def _require_state() -> _State:
    if _state is None:
        raise RuntimeError("nbval_kernel: plugin used before pytest_configure")
    return _state


def pytest_addoption(parser: pytest.Parser) -> None:
    """Add ``--nbval-kernel-log-dir``."""
    parser.getgroup("nbval").addoption(
        "--nbval-kernel-log-dir",
        default=None,
        help="directory for the notebook kernels' stderr logs "
        "(default: build/nbval-kernel-logs under the rootdir)",
    )
    parser.getgroup("nbval").addoption(
        "--nbval-kernel-preload",
        default="",
        help="comma-separated modules a fork server imports once; each ipykernel kernel is "
        "then forked from it (tests/kernel_forkserver.py); default: none, no fork server",
    )
    parser.getgroup("nbval").addoption(
        "--nbval-kernel-env",
        action="append",
        default=[],
        metavar="NAME=VALUE",
        help="set an environment variable for the notebook kernels only (repeatable), e.g. "
        "their matplotlib backend when the tests in the same session draw with Agg",
    )


def pytest_configure(config: pytest.Config) -> None:
    """Rebind ``nbval.plugin.RunningKernel`` to :class:`IpcRunningKernel`."""
    global _state, _original_running_kernel
    import nbval.kernel
    import nbval.plugin

    current = getattr(nbval.plugin, "RunningKernel", None)
    if current is not nbval.kernel.RunningKernel:
        raise pytest.UsageError(
            "nbval_kernel: nbval.plugin.RunningKernel is "
            f"{current!r}, not nbval.kernel.RunningKernel; this plugin was written for "
            "nbval 0.11.0 and cannot hook into this version"
        )
    option = config.getoption("nbval_kernel_log_dir")
    log_dir = Path(option) if option else config.rootpath / "build" / "nbval-kernel-logs"
    _state = _State(log_dir.resolve(), config.rootpath.resolve())
    _state.preload = [m for m in config.getoption("nbval_kernel_preload").split(",") if m]
    _state.kernel_env = parse_kernel_env(config.getoption("nbval_kernel_env"))
    check_dist(config.getoption("nbval", False), config.getoption("dist", "no"))
    _original_running_kernel = current
    nbval.plugin.RunningKernel = IpcRunningKernel


def pytest_unconfigure(config: pytest.Config) -> None:
    """Restore nbval's ``RunningKernel`` and remove the private IPC directory."""
    global _state
    import nbval.plugin

    if _original_running_kernel is not None:
        nbval.plugin.RunningKernel = _original_running_kernel
    if _state is not None:
        _state.stop_forkservers()
        shutil.rmtree(_state.ipc_dir, ignore_errors=True)
        _state = None


def cell_stderr(outputs: list[Any] | None) -> str:
    """The text a cell wrote to stderr, from nbval's record of its outputs (``test_outputs``:
    stream outputs with ``name`` and ``text``), in order; "" if none."""
    return "".join(
        str(out.get("text", ""))
        for out in outputs or ()
        if out.get("output_type") == "stream" and out.get("name") == "stderr"
    )


def _notebook_of(item: pytest.Item) -> Path | None:
    from nbval.plugin import IPyNbFile

    parent = item.parent
    return Path(parent.path) if isinstance(parent, IPyNbFile) else None


@pytest.hookimpl(wrapper=True, tryfirst=True)
def pytest_runtest_setup(item: pytest.Item) -> Generator[None, Any, Any]:
    """Tell :class:`IpcRunningKernel` which notebook it is being started for."""
    token = _current_notebook.set(_notebook_of(item))
    try:
        return (yield)
    finally:
        _current_notebook.reset(token)


@pytest.hookimpl(wrapper=True)
def pytest_runtest_makereport(
    item: pytest.Item, call: pytest.CallInfo[None]
) -> Generator[None, pytest.TestReport, pytest.TestReport]:
    """Add the cell's own stderr text and the kernel's stderr log (path and last lines) to a
    failing cell's report.

    nbval reports an unexpected stderr output only by its key ("Unexpected output fields from
    running code: {'stderr'}"); the text (a warning, say) is what says why, so it is quoted."""
    report = yield
    notebook = _notebook_of(item)
    if report.failed and notebook is not None:
        text = cell_stderr(getattr(item, "test_outputs", None))
        if text:
            report.sections.append(("cell stderr", text))
    if report.failed and notebook is not None and _state is not None:
        path = _state.logs.get(notebook.resolve())
        if path is not None:
            tail = _tail(path)
            report.sections.append(
                ("nbval kernel stderr", f"{path}\n{tail}" if tail else f"{path} (empty)")
            )
    return report
