"""``make lab``: JupyterLab on working copies of the notebooks, as root or not.

The notebooks in ``notebooks/`` are the references that nbval compares (``make test``), and
JupyterLab autosaves what it shows: the explorer of notebook 09 moved to another arm, widget
state, outputs of cells re-run by hand. So Lab never opens them: :func:`prepare` copies them
into ``build/lab/`` (a copy is refreshed only when the stored notebook is newer than it, e.g.
after ``make notebooks`` or a pull, so edits made in Lab survive a restart), and Lab's root
is that folder. To change a stored notebook, edit ``notebooks/NN_*.ipynb`` and run
``make notebooks NB=...``.

Chosen over a contents manager that strips outputs on save (it would still rewrite the
references, with whatever the user did) and over read-only files (Lab then refuses to save
at all, and asks on every autosave). ``--allow-root`` is passed when running as root (the
usual case in a container), where Jupyter otherwise exits.
"""

from __future__ import annotations

import contextlib
import json
import os
import shutil
import socket
import subprocess
import sys
import time
import urllib.request
from collections.abc import Iterator
from pathlib import Path

from analysis.paths import PROJECT

__all__ = ["LAB_DIR", "command", "prepare", "serve", "tail"]

LAB_DIR = PROJECT / "build" / "lab"


def prepare(work: Path = LAB_DIR, source: Path | None = None) -> list[Path]:
    """Copy the numbered notebooks of ``source`` (default ``notebooks/``) into ``work`` where
    the copy is missing or older than the stored notebook; returns the copies refreshed."""
    source = source or PROJECT / "notebooks"
    work.mkdir(parents=True, exist_ok=True)
    fresh = []
    for nb in sorted(source.glob("[0-9][0-9]_*.ipynb")):
        dst = work / nb.name
        if not dst.exists() or dst.stat().st_mtime < nb.stat().st_mtime:
            shutil.copy2(nb, dst)
            fresh.append(dst)
    return fresh


def command(root: Path, *extra: str) -> list[str]:
    """The ``jupyter lab`` command serving ``root`` (``--allow-root`` when run as root)."""
    jupyter = Path(sys.executable).with_name("jupyter")
    root_flag = ["--allow-root"] if hasattr(os, "geteuid") and os.geteuid() == 0 else []
    return [str(jupyter), "lab", f"--ServerApp.root_dir={root}", *root_flag, *extra]


START_TIMEOUT_S = 90  # JupyterLab's first start builds nothing, but loads ~100 extensions


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def tail(path: Path, n: int = 2000) -> str:
    """The last ``n`` characters of a log."""
    return path.read_text(errors="replace")[-n:]


@contextlib.contextmanager
def serve(root: Path, sessions: dict[str, str], env: dict[str, str] | None = None) -> Iterator[str]:
    """A JupyterLab server on 127.0.0.1 (a free port, no token, no browser, no terminals,
    news and update checks off) serving ``root``, which holds its configuration, settings,
    workspaces and runtime files too; every notebook of ``sessions`` (path -> kernel name) has
    its session and kernel started over the REST API as soon as the server is up (their start
    overlaps the page's loading). Yields the server's URL; the log is ``root/lab.log``; the
    server is stopped on exit. What the browser tests (tests/browser/test_explorer_lab.py) and
    the latency bench (benchmarks/explorer_latency.py) open."""
    settings = root / "settings" / "@jupyterlab" / "apputils-extension"
    settings.mkdir(parents=True, exist_ok=True)
    (settings / "notification.jupyterlab-settings").write_text(
        json.dumps({"checkForUpdates": False, "fetchNews": "false"})
    )
    # every cell in the DOM (no windowing): what is off screen can be scrolled to and checked
    tracker = root / "settings" / "@jupyterlab" / "notebook-extension"
    tracker.mkdir(parents=True, exist_ok=True)
    (tracker / "tracker.jupyterlab-settings").write_text(
        json.dumps({"windowingMode": "none", "autoStartDefaultKernel": True})
    )
    env = (
        os.environ
        | (env or {})
        | {
            "JUPYTER_CONFIG_DIR": str(root / "config"),
            "JUPYTER_RUNTIME_DIR": str(root / "runtime"),
            "JUPYTERLAB_SETTINGS_DIR": str(root / "settings"),
            "JUPYTERLAB_WORKSPACES_DIR": str(root / "workspaces"),
        }
    )
    port = _free_port()
    cmd = command(
        root,
        "--no-browser",
        "--ServerApp.ip=127.0.0.1",
        f"--ServerApp.port={port}",
        "--ServerApp.port_retries=0",
        "--IdentityProvider.token=",
        "--ServerApp.password=",
        "--LabApp.extension_manager=readonly",
        "--ServerApp.terminals_enabled=False",
    )
    log = (root / "lab.log").open("w")
    proc = subprocess.Popen(cmd, cwd=root, env=env, stdout=log, stderr=subprocess.STDOUT)
    url = f"http://127.0.0.1:{port}/"
    try:
        deadline = time.monotonic() + START_TIMEOUT_S
        while True:
            if proc.poll() is not None:
                raise RuntimeError(
                    f"jupyter lab exited {proc.returncode}: {tail(root / 'lab.log')}"
                )
            with contextlib.suppress(OSError):
                with urllib.request.urlopen(url + "api/status", timeout=2) as r:
                    if r.status == 200:
                        break
            if time.monotonic() > deadline:
                raise RuntimeError(
                    f"jupyter lab not up in {START_TIMEOUT_S} s: {tail(root / 'lab.log')}"
                )
            time.sleep(0.5)
        for path, kernel in sessions.items():
            _start_session(url, path, kernel)
        yield url
    finally:
        proc.terminate()
        try:
            proc.wait(timeout=20)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()
        log.close()


def _start_session(url: str, path: str, kernel: str) -> None:
    """Ask the server for ``path``'s session and kernel (what opening the notebook does; the
    page then joins it)."""
    from http.cookiejar import CookieJar

    jar = CookieJar()
    opener = urllib.request.build_opener(urllib.request.HTTPCookieProcessor(jar))
    opener.open(url + "lab", timeout=30).close()  # the page sets the _xsrf cookie
    xsrf = next(c.value for c in jar if c.name == "_xsrf")
    body = {"path": path, "name": path, "type": "notebook", "kernel": {"name": kernel}}
    req = urllib.request.Request(
        url + "api/sessions",
        data=json.dumps(body).encode(),
        method="POST",
        headers={"Content-Type": "application/json", "X-XSRFToken": xsrf},
    )
    with opener.open(req, timeout=30) as r:
        if r.status != 201:
            raise RuntimeError(f"session for {path}: HTTP {r.status} {r.read()[:300]!r}")


def main(argv: list[str]) -> None:
    fresh = prepare()
    print(
        f"JupyterLab works on copies in {LAB_DIR.relative_to(PROJECT)}/ "
        f"({len(fresh)} refreshed from notebooks/); the stored notebooks are nbval's "
        "references: change one in notebooks/ and run make notebooks NB=...",
        flush=True,
    )
    cmd = command(LAB_DIR, *argv)
    os.execv(cmd[0], cmd)


if __name__ == "__main__":
    main(sys.argv[1:])
