"""The report's notebooks: found (:func:`notebook_paths`), executed top to bottom in a fresh
kernel each (:func:`execute_notebook`, nbclient; two at a time with progress lines and the
cache of :mod:`analysis.app.report_cache`: :func:`execute_all`), or taken with their stored
outputs (:func:`stored_notebooks`, what ``make test`` builds the site from after nbval has
re-executed them). :mod:`analysis.app.report` builds the site from what these return."""

from __future__ import annotations

import os
import re
import shutil
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

import nbformat
from jupyter_client.manager import KernelManager
from nbclient import NotebookClient
from nbclient.exceptions import CellExecutionError

from analysis.app.plotting import figure_dir

__all__ = [
    "NB_BACKEND",
    "NotebookFailed",
    "Say",
    "execute_all",
    "execute_notebook",
    "first_line_of_error",
    "notebook_paths",
    "notebook_title",
    "stored_notebooks",
]

PROJECT = Path(__file__).resolve().parents[3]
NB_BACKEND = "module://matplotlib_inline.backend_inline"


def notebook_paths(folder: Path | None = None) -> list[Path]:
    """The numbered notebooks (``NN_name.ipynb``) in ``folder`` (default ``notebooks/``)."""
    folder = folder or PROJECT / "notebooks"
    paths = sorted(p for p in folder.glob("[0-9][0-9]_*.ipynb"))
    if not paths:
        raise FileNotFoundError(f"no numbered notebooks (NN_name.ipynb) in {folder}")
    return paths


def notebook_title(nb: nbformat.NotebookNode, fallback: str) -> str:
    for cell in nb.cells:
        if cell.cell_type == "markdown":
            for line in cell.source.splitlines():
                if line.startswith("# "):
                    return line.lstrip("#").strip()
    return fallback


class NotebookFailed(RuntimeError):
    """A notebook raised; the site was still built, with the failure shown on its pages."""


def execute_notebook(
    path: Path,
    timeout: int = 1800,
    *,
    on_cell: Callable[[int, int], None] | None = None,
    into: nbformat.NotebookNode | None = None,
    env: dict[str, str] | None = None,
) -> nbformat.NotebookNode:
    """Execute a notebook top to bottom in a fresh kernel, with its folder as cwd.

    Returns the executed notebook; the file at ``path`` is only read. ``on_cell(i, n)`` is
    called after each code cell (i of n code cells). ``into``: the notebook read from
    ``path``, executed in place (so that a caller still has its outputs up to the failing
    cell when execution raises ``nbclient.exceptions.CellExecutionError``). ``env``: the
    kernel's environment (default this process's).
    """
    nb = into if into is not None else nbformat.read(path, as_version=4)
    for cell in nb.cells:  # no stored output survives, even after a failing cell
        if cell.cell_type == "code":
            cell.outputs = []
            cell.execution_count = None
    n_code = sum(c.cell_type == "code" for c in nb.cells)
    done = 0

    def hook(**_):
        nonlocal done
        done += 1
        if on_cell is not None:
            on_cell(done, n_code)

    # The kernel talks over Unix sockets in a private folder (IPC), not TCP: no free-port race
    # with other kernels starting at the same time (see tests/nbval_kernel.py for the race).
    with tempfile.TemporaryDirectory(prefix="analysis-kernel-") as ipc:
        km = KernelManager(
            kernel_name="python3",
            transport="ipc",
            ip=os.path.join(ipc, "k"),
            connection_file=os.path.join(ipc, "k.json"),
        )
        client = NotebookClient(
            nb,
            km=km,
            timeout=timeout,
            kernel_name="python3",
            resources={"metadata": {"path": str(path.parent)}},
            on_cell_executed=hook,
            shutdown_kernel="immediate",
        )
        try:
            # cleanup_kc: nbclient stops the client's channels and closes the manager's sockets
            # even though the manager is ours (else every notebook left four zmq sockets to the
            # garbage collector: ~130 "ResourceWarning: Unclosed socket" lines in make report)
            client.execute(cleanup_kc=True, **({"env": dict(env)} if env is not None else {}))
        finally:  # if nbclient could not (a failure before its cleanup)
            if km.has_kernel:
                km.shutdown_kernel(now=True)
            km.cleanup_resources()
    return nb


Say = Callable[[str], None]
"""A progress printer: one line with the seconds since the build started."""


def stored_notebooks(
    paths: list[Path], dl_nb: Path, fig_dir: Path, figures: str | Path | None, say: Say
) -> list[tuple[Path, nbformat.NotebookNode, float]]:
    """The notebooks with their stored outputs (``execute=False``), copied to the downloads
    ``dl_nb``, and the figures a run of them saved in ``figures`` copied to ``fig_dir``."""
    executed: list[tuple[Path, nbformat.NotebookNode, float]] = []
    n = len(paths)
    saved = Path(figures) if figures is not None else figure_dir()
    for i, path in enumerate(paths, start=1):
        say(f"notebook {i}/{n}: {path.name}: stored outputs (not executed)")
        nb = nbformat.read(path, as_version=4)
        nbformat.write(nb, dl_nb / path.name)
        executed.append((path, nb, 0.0))
        # the figures this notebook saves (not stale ones of notebooks since removed)
        code = "\n".join(c.source for c in nb.cells if c.cell_type == "code")
        for stem in re.findall(r"save_figure\(\s*\w+,\s*\"([^\"]+)\"", code):
            for f in saved.glob(f"{stem}.*"):
                if f.suffix in (".svg", ".png", ".json"):
                    shutil.copyfile(f, fig_dir / f.name)
    return executed


def execute_all(
    paths: list[Path],
    dl_nb: Path,
    fig_dir: Path,
    failed: dict[str, str],
    say: Say,
    *,
    cache=None,
    workers: int = 2,
) -> list[tuple[Path, nbformat.NotebookNode, float]]:
    """Execute every notebook (fresh kernel each, ``workers`` at a time) and copy it to the
    downloads ``dl_nb``; its figures go to ``fig_dir``. A notebook whose code and inputs are
    in ``cache`` (:class:`analysis.app.report_cache.NotebookCache`) is taken from it (its
    figures too) instead of executed; one that raises is recorded in ``failed`` (stem -> first
    line of the error) and not cached. The time of a cached notebook is 0."""
    from concurrent.futures import ThreadPoolExecutor

    n = len(paths)
    results: dict[Path, tuple[nbformat.NotebookNode, float]] = {}
    todo = []
    for i, path in enumerate(paths, start=1):
        nb = nbformat.read(path, as_version=4)
        hit = cache.get(nb, fig_dir) if cache is not None else None
        if hit is not None:
            say(f"notebook {i}/{n}: {path.name}: unchanged, taken from the cache")
            results[path] = (hit, 0.0)
        else:
            todo.append((i, path, nb))

    def run(item) -> None:
        i, path, nb = item
        say(f"notebook {i}/{n}: executing {path.name} ...")
        t = time.perf_counter()
        last = [t]

        def beat(k: int, m: int) -> None:
            now = time.perf_counter()
            if now - last[0] >= 10:
                last[0] = now
                say(f"notebook {i}/{n}: {path.name} cell {k}/{m}, {now - t:.0f} s")

        with tempfile.TemporaryDirectory(prefix="analysis-figures-") as tmp:
            env = os.environ | {"ANALYSIS_FIGURE_DIR": tmp, "MPLBACKEND": NB_BACKEND}
            try:
                execute_notebook(path, on_cell=beat, into=nb, env=env)
            except CellExecutionError as exc:
                failed[path.stem] = first_line_of_error(exc)
            figures = sorted(Path(tmp).glob("*"))
            for f in figures:
                shutil.copyfile(f, fig_dir / f.name)
            if cache is not None and path.stem not in failed:
                cache.put(nb, str(path), figures, Path(tmp))
        dt = time.perf_counter() - t
        results[path] = (nb, dt)
        if path.stem in failed:
            say(f"notebook {i}/{n}: {path.name} FAILED after {dt:.1f} s: {failed[path.stem]}")
        else:
            say(f"notebook {i}/{n}: {path.name} done in {dt:.1f} s")

    # the biggest notebooks first, so that the two workers finish together
    todo.sort(key=lambda item: -item[1].stat().st_size)
    if todo:
        with ThreadPoolExecutor(max_workers=max(1, workers)) as pool:
            list(pool.map(run, todo))
    executed = []
    for path in paths:
        nb, dt = results[path]
        nbformat.write(nb, dl_nb / path.name)
        executed.append((path, nb, dt))
    return executed


def first_line_of_error(exc: Exception) -> str:
    """'ImportError: cannot import name ...' from nbclient's CellExecutionError."""
    ename, evalue = getattr(exc, "ename", ""), getattr(exc, "evalue", "")
    if ename:
        return f"{ename}: {evalue}".strip()
    return str(exc).strip().splitlines()[-1] if str(exc).strip() else type(exc).__name__
