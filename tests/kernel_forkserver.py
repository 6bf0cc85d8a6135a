"""A fork server for notebook kernels: the heavy modules are imported once, each kernel is a fork.

Used by ``tests/nbval_kernel.py`` (``--nbval-kernel-preload``). Every notebook's first cell
imports numpy, pandas, SymPy, matplotlib, Numba and Pinocchio, about 3 s of CPU per kernel
start on the 2-core test machine, for eleven notebooks per ``make test``. The server imports
them once (plus ipykernel) and forks one child per kernel, which then runs ipykernel exactly as
``python -m ipykernel_launcher -f <connection file>`` would. A module import is cached in
``sys.modules``; it puts no name in the notebook's namespace, so a notebook that forgets an
import still fails under nbval.

Why a fork server and not a library: ``multiprocessing.forkserver`` hands work to forked
children over pipes, but a Jupyter kernel must be a *process* that jupyter_client starts,
signals and waits for (``LocalProvisioner``: ``Popen``, ``killpg``, ``poll``). So the kernel
spec's command becomes a stub, ``python -I -S kernel_forkserver.py stub ...`` (standard library
only, about 20 ms), which

1. connects to the server's Unix socket and sends its argv, working directory and environment,
   with its stdin, stdout and stderr file descriptors (``socket.send_fds``): the child writes to
   the same stderr log that ``nbval_kernel`` gave the stub;
2. forwards SIGINT (nbval's interrupt on a cell timeout), SIGTERM, SIGHUP and SIGQUIT to the
   child;
3. exits with the child's exit code (the server reaps the child and sends the code); if the
   stub is killed, the server sees the socket close and kills the child (SIGKILL).

If no server answers, the stub execs the kernel spec's own command (a normal kernel start).

What a forked kernel inherits, and what it does not
-------------------------------------------------
* Environment, working directory, ``sys.argv`` and ``sys.path[0]`` are the stub's, set in the
  child before ipykernel starts. Values read *at import time* by a preloaded module are the
  server's: the server is started with the pytest worker's environment, which is the one the
  kernels get (jupyter_client adds only ``JPY_*`` and kernel-spec variables). Where one of
  the variables read at start-up or import (``_IMPORT_TIME_ENV``: ``PYTHONHASHSEED``,
  ``MPLBACKEND``, ...) differs, the child execs the kernel spec's own command instead.
* Modules that capture their surroundings when imported are refused (``_IMPORT_TIME_STATE``):
  ipykernel reads ``JPY_PARENT_PID`` into class defaults, pandas chooses
  ``display.max_columns`` by whether it runs inside a kernel, the inline backend hooks into
  the running shell. The server exits, naming them, if the preload list imports any.
* Python's ``random`` re-seeds itself in a forked child; NumPy's legacy global generator does
  not (every notebook here uses seeded ``default_rng`` generators). SymPy's own generator
  (``sympy.core.random``: multivariate factorisation draws random evaluation points) is seeded
  in the server after the preload, so every kernel starts from one state and a notebook takes
  the same path through SymPy in every run (a rare slow path then shows every time or never).
* No thread is running in the server when it forks (checked: ``threading.active_count()``;
  OpenBLAS' pool re-initialises through its own ``pthread_atfork`` handlers).
"""

from __future__ import annotations

import gc
import json
import os
import signal
import socket
import struct
import sys

_HEADER = struct.Struct("!I")
SYMPY_SEED = 20161
"""The seed of SymPy's generator in every forked kernel (module docstring) and before every
test (conftest.py)."""
GC_THRESHOLD = (100_000, 50, 100)
"""The cyclic collector's thresholds in every forked kernel and test process (conftest.py)."""
_FORWARDED = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP, signal.SIGQUIT)
# read by Python or a preloaded module when it starts or is imported
# modules that capture where they run when imported: ipykernel/IPython read JPY_PARENT_PID and
# friends into class-level defaults, pandas sets display.max_columns from get_ipython(), the
# inline backend installs its hooks into the running shell. They are never preloaded.
_IMPORT_TIME_STATE = frozenset(
    {"IPython", "ipykernel", "pandas", "matplotlib.pyplot", "matplotlib_inline", "zmq"}
)
_IMPORT_TIME_ENV = (
    "PYTHONHASHSEED",
    "MPLBACKEND",
    "MPLCONFIGDIR",
    "NUMBA_CACHE_DIR",
    "OMP_NUM_THREADS",
)


def _send(sock: socket.socket, payload: dict, fds: list[int] | None = None) -> None:
    data = json.dumps(payload).encode()
    if fds:
        socket.send_fds(sock, [_HEADER.pack(len(data)) + data], fds)
    else:
        sock.sendall(_HEADER.pack(len(data)) + data)


def _recv_exact(sock: socket.socket, n: int, buf: bytes = b"") -> bytes:
    while len(buf) < n:
        chunk = sock.recv(n - len(buf))
        if not chunk:
            raise EOFError("fork server connection closed")
        buf += chunk
    return buf


def _recv(sock: socket.socket, with_fds: int = 0) -> tuple[dict, list[int]]:
    fds: list[int] = []
    if with_fds:
        first, fds, _, _ = socket.recv_fds(sock, 65536, with_fds)
        if not first:
            raise EOFError("fork server connection closed")
    else:
        first = b""
    head = _recv_exact(sock, _HEADER.size, first)
    (size,) = _HEADER.unpack(head[: _HEADER.size])
    body = _recv_exact(sock, size, head[_HEADER.size :])
    return json.loads(body[:size]), fds


# --- the stub (what the kernel spec runs) ---------------------------------------------------
def stub(sock_path: str, fallback: list[str], kernel_args: list[str]) -> int:
    """Ask the server at ``sock_path`` for a kernel; exec ``fallback + kernel_args`` if none."""
    sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    try:
        sock.connect(sock_path)
    except OSError:
        os.execv(fallback[0], [*fallback, *kernel_args])
    request = {
        "argv": ["ipykernel_launcher", *kernel_args],
        "cwd": os.getcwd(),
        "env": dict(os.environ),
        "fallback": fallback,
    }
    _send(sock, request, [0, 1, 2])
    pid = _recv(sock)[0]["pid"]

    def forward(signum: int, _frame: object) -> None:
        try:
            os.kill(pid, signum)
        except ProcessLookupError:
            pass

    for signum in _FORWARDED:
        signal.signal(signum, forward)
    return int(_recv(sock)[0]["exit"])


# --- the server ------------------------------------------------------------------------------
def _child(conn: socket.socket, request: dict, fds: list[int], closing: list, wake_w: int) -> None:
    """In the forked child: become ``python -m ipykernel_launcher`` for the stub's request."""
    try:
        for sig in (signal.SIGCHLD, *_FORWARDED):
            signal.signal(sig, signal.SIG_DFL)
        signal.set_wakeup_fd(-1)
        os.close(wake_w)
        for obj in closing:
            obj.close()
        conn.close()
        for target, fd in enumerate(fds):
            os.dup2(fd, target)
            os.close(fd)
        os.setpgid(0, 0)
        os.chdir(request["cwd"])
        env = request["env"]
        changed = [k for k in _IMPORT_TIME_ENV if env.get(k) != os.environ.get(k)]
        if changed:  # a preloaded module read another value: start a kernel of its own
            sys.stderr.write(f"kernel_forkserver: {changed} differ from the server's; exec\n")
            sys.stderr.flush()
            os.execve(request["fallback"][0], [*request["fallback"], *request["argv"][1:]], env)
        os.environ.clear()
        os.environ.update(request["env"])
        sys.argv = list(request["argv"])
        sys.path[0] = request["cwd"]  # as ``python -m`` puts the working directory first
        from ipykernel import kernelapp

        kernelapp.launch_new_instance()
        code = 0
    except SystemExit as exc:
        code = exc.code if isinstance(exc.code, int) else (0 if exc.code is None else 1)
    except BaseException:  # report anything on the kernel's stderr
        import traceback

        traceback.print_exc()
        code = 1
    finally:
        sys.stdout.flush()
        sys.stderr.flush()
    os._exit(code)


def serve(sock_path: str, preload: list[str]) -> None:
    """Import ``preload``, then fork a kernel per connection until SIGTERM."""
    import importlib
    import selectors
    import threading

    for name in preload:
        importlib.import_module(name)
    leaked = sorted(_IMPORT_TIME_STATE.intersection(sys.modules))
    if leaked:
        raise SystemExit(f"kernel_forkserver: preloading {preload} imported {leaked}")

    if threading.active_count() != 1:
        raise SystemExit(f"kernel_forkserver: preloading {preload} started threads; cannot fork")
    if "sympy.core.random" in sys.modules:
        sys.modules["sympy.core.random"].seed(SYMPY_SEED)
    # what the kernels inherit from the collector: the preloaded modules moved out of its reach
    # (gc.freeze, as Python's documentation advises before forking: no child scans or touches
    # them) and the tests' first threshold (tests/conftest.py: SymPy-heavy cells, fewer runs)
    gc.freeze()
    gc.set_threshold(*GC_THRESHOLD)

    wake_r, wake_w = os.pipe()
    os.set_blocking(wake_w, False)
    signal.set_wakeup_fd(wake_w)
    signal.signal(signal.SIGCHLD, lambda *_: None)
    stop = []
    signal.signal(signal.SIGTERM, lambda *_: stop.append(True))

    listener = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    listener.bind(sock_path + ".tmp")
    listener.listen(16)
    os.replace(sock_path + ".tmp", sock_path)  # the path appears only once we accept
    sel = selectors.DefaultSelector()
    sel.register(listener, selectors.EVENT_READ, "accept")
    sel.register(wake_r, selectors.EVENT_READ, "signal")
    children: dict[int, socket.socket | None] = {}  # None: its stub has gone
    by_conn: dict[socket.socket, int] = {}
    wake_file = os.fdopen(wake_r, "rb", buffering=0)
    while not stop:
        for key, _ in sel.select():
            if key.data == "accept":
                conn, _ = listener.accept()
                try:
                    request, fds = _recv(conn, with_fds=3)
                except (EOFError, OSError, ValueError):
                    conn.close()
                    continue
                pid = os.fork()
                if pid == 0:
                    _child(conn, request, fds, [listener, wake_file, *by_conn], wake_w)
                for fd in fds:
                    os.close(fd)
                _send(conn, {"pid": pid})
                children[pid] = conn
                by_conn[conn] = pid
                sel.register(conn, selectors.EVENT_READ, "stub")
            elif key.data == "signal":
                wake_file.read(512)
                while children:
                    pid, status = os.waitpid(-1, os.WNOHANG)
                    if pid == 0:
                        break
                    conn = children.pop(pid, None)
                    if conn is not None:
                        by_conn.pop(conn, None)
                        sel.unregister(conn)
                        try:
                            _send(conn, {"exit": os.waitstatus_to_exitcode(status)})
                        except OSError:
                            pass
                        conn.close()
            else:  # the stub closed its end (it was killed): kill its kernel
                conn = key.fileobj
                pid = by_conn.pop(conn)
                sel.unregister(conn)
                conn.close()
                children[pid] = None  # still reaped above; the exit code goes nowhere
                try:
                    os.kill(pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
    for pid in children:
        try:
            os.kill(pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
    listener.close()
    os.unlink(sock_path)


if __name__ == "__main__":
    if sys.argv[1] == "stub":
        # stub SOCK N FALLBACK... KERNEL_ARGS...: the first N words after N are the fallback
        n = int(sys.argv[3])
        sys.exit(stub(sys.argv[2], sys.argv[4 : 4 + n], sys.argv[4 + n :]))
    elif sys.argv[1] == "serve":
        serve(sys.argv[2], [m for m in sys.argv[3].split(",") if m])
    else:
        raise SystemExit(f"usage: {sys.argv[0]} stub|serve ...")
