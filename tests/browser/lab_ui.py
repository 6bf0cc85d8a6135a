"""Driving notebook 09's explorer in JupyterLab (or Notebook 7) from Playwright: what the
Lab browser tests (test_explorer_lab.py) and the latency bench (benchmarks/explorer_latency.py)
both do: a cleared copy of the notebook, Run All, a slider's box typed into, the 3D view
waited on until it has nothing left to draw."""

from __future__ import annotations

import contextlib
import json
import re
import time
import urllib.request
from pathlib import Path

import nbformat

from analysis.app.lab import prepare


def cleared_copies(root: Path, notebook: Path, *names: str) -> str:
    """``make lab``'s copies of ``notebook``'s folder in ``root``, with ``notebook`` cleared
    of its outputs and widget state (every output on the page comes from this run) and also
    written as ``names``; returns its kernel's name."""
    prepare(root, notebook.parent)
    nb = nbformat.read(root / notebook.name, as_version=4)
    for cell in nb.cells:
        if cell.cell_type == "code":
            cell.outputs, cell.execution_count = [], None
    nb.metadata.pop("widgets", None)
    for name in (notebook.name, *names):
        nbformat.write(nb, root / name)
    return nb.metadata.kernelspec.name


def slider(page, label: str):
    """The ipywidgets slider whose description is ``label``."""
    return page.locator(".widget-slider").filter(
        has=page.locator(".widget-label", has_text=re.compile(rf"^{re.escape(label)}$"))
    )


def type_into(page, label: str, value: float) -> None:
    """Type ``value`` into the slider's readout box and press Enter, as a user would."""
    readout = slider(page, label).locator(".widget-readout")
    readout.click()
    page.keyboard.press("Control+A")
    page.keyboard.type(f"{value:g}")
    page.keyboard.press("Enter")


def quiet(page, timeout_ms: float = 20_000) -> None:
    """Wait until the 3D view has nothing left to draw: the kernel's pose is for the
    controls' current values and every redraw asked for is on screen (a redraw during a drag
    would put the camera back where plotly last saved it)."""
    from playwright.sync_api import TimeoutError as PlaywrightTimeout

    try:
        page.wait_for_function(
            """() => { const w = document.querySelector('.arm3d-widget');
            return w && w.arm3dKernelCurrent === true && !w.arm3dPending; }""",
            timeout=timeout_ms,
        )
    except PlaywrightTimeout:
        state = page.evaluate("""() => { const w = document.querySelector('.arm3d-widget');
            return w && [w.arm3dKernelCurrent, w.arm3dPending, JSON.stringify(w.arm3dKeys)]; }""")
        raise AssertionError(f"the 3D view still drawing: {state}") from None


def kernel_idle(url: str, path: str) -> bool:
    """The Jupyter server has a session for ``path`` whose kernel is idle (REST API)."""
    with contextlib.suppress(OSError, ValueError):
        with urllib.request.urlopen(url + "api/sessions", timeout=2) as r:
            for sess in json.load(r):
                if sess.get("path") == path:
                    return (sess.get("kernel") or {}).get("execution_state") == "idle"
    return False


def run_all(page, timeout_s: float = 90, ready=None) -> None:
    """Run > Run All Cells once the kernel is idle (``ready()``; default JupyterLab's status
    bar says so), taking the preferred kernel if asked which one to start, until a cell shows
    that it runs."""
    from playwright.sync_api import TimeoutError as PlaywrightTimeout

    deadline = time.monotonic() + timeout_s
    status = page.locator(".jp-StatusBar-Widget", has_text="| Idle")
    ready = ready or status.count
    started = page.locator(".jp-InputPrompt", has_text=re.compile(r"\[(\*|\d+)\]"))
    while time.monotonic() < deadline:
        dialog = page.locator(".jp-Dialog")
        if dialog.count() and dialog.first.is_visible():
            dialog.get_by_role("button", name="Select", exact=True).click()
        elif ready():
            page.get_by_role("menuitem", name="Run", exact=True).click()
            page.get_by_role("menuitem", name=re.compile(r"^Run All Cells")).click()
            with contextlib.suppress(PlaywrightTimeout):
                started.first.wait_for(state="attached", timeout=10_000)
                return
        page.wait_for_timeout(250)
    raise AssertionError(f"could not run the notebook within {timeout_s} s")
