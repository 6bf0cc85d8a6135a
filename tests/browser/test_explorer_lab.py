"""The explorer (notebook 09) as a user meets it: in JupyterLab, in Debian's Chromium.

A JupyterLab server from the project's ``.venv`` is started on 127.0.0.1 (a free port, no
token, no browser) in a temporary folder holding a copy of ``notebooks/09_explore.ipynb``
with its stored outputs cleared (so every output on the page comes from this run; the real
notebook is only read). Its configuration, settings, workspaces and runtime files live in
that folder too, with JupyterLab's news and update checks switched off. The browser's
requests to any host but 127.0.0.1 are aborted and recorded.

The test runs the notebook from the Run menu, then drags a slider, types Table 4 row 8,
(200, 500, 600) mm, into the slider boxes, and drags the 3D view, asserting each time on
what the page shows. Screenshots go to ``build/browser`` (see conftest.py).
"""

from __future__ import annotations

import contextlib
import json
import os
import re
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path
from urllib.parse import urlsplit

import nbformat
import pytest

from analysis.app.report import CHROMIUM_FLAGS, NB_BACKEND

from .conftest import LOCAL_HOSTS, PROJECT

NOTEBOOK = PROJECT / "notebooks" / "09_explore.ipynb"
JUPYTER = Path(sys.executable).with_name("jupyter")
START_TIMEOUT_S = 90  # JupyterLab's first start builds nothing, but loads ~100 extensions


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.fixture(scope="module")
def lab(chromium, tmp_path_factory):
    """A JupyterLab server on 127.0.0.1 serving a cleared copy of notebook 09; yields its URL."""
    if not JUPYTER.exists():
        pytest.skip(f"no jupyter at {JUPYTER}: make venv installs JupyterLab")
    root = tmp_path_factory.mktemp("lab")
    nb = nbformat.read(NOTEBOOK, as_version=4)
    for cell in nb.cells:
        if cell.cell_type == "code":
            cell.outputs, cell.execution_count = [], None
    nb.metadata.pop("widgets", None)
    nbformat.write(nb, root / NOTEBOOK.name)
    settings = root / "settings" / "@jupyterlab" / "apputils-extension"
    settings.mkdir(parents=True)
    (settings / "notification.jupyterlab-settings").write_text(
        json.dumps({"checkForUpdates": False, "fetchNews": "false"})
    )
    # every cell in the DOM (no windowing): what is off screen can be scrolled to and checked
    tracker = root / "settings" / "@jupyterlab" / "notebook-extension"
    tracker.mkdir(parents=True)
    (tracker / "tracker.jupyterlab-settings").write_text(
        json.dumps({"windowingMode": "none", "autoStartDefaultKernel": True})
    )
    env = os.environ | {
        "JUPYTER_CONFIG_DIR": str(root / "config"),
        "JUPYTER_RUNTIME_DIR": str(root / "runtime"),
        "JUPYTERLAB_SETTINGS_DIR": str(root / "settings"),
        "JUPYTERLAB_WORKSPACES_DIR": str(root / "workspaces"),
        "ANALYSIS_FIGURE_DIR": str(root / "figures"),
        "MPLBACKEND": NB_BACKEND,
    }
    port = _free_port()
    cmd = [
        str(JUPYTER),
        "lab",
        "--no-browser",
        "--ServerApp.ip=127.0.0.1",
        f"--ServerApp.port={port}",
        "--ServerApp.port_retries=0",
        "--IdentityProvider.token=",
        "--ServerApp.password=",
        f"--ServerApp.root_dir={root}",
        "--LabApp.extension_manager=readonly",
        "--ServerApp.terminals_enabled=False",
        # CI runs as root
        *(["--allow-root"] if hasattr(os, "geteuid") and os.geteuid() == 0 else []),
    ]
    log = (root / "lab.log").open("w")
    proc = subprocess.Popen(cmd, cwd=root, env=env, stdout=log, stderr=subprocess.STDOUT)
    url = f"http://127.0.0.1:{port}/"
    try:
        deadline = time.monotonic() + START_TIMEOUT_S
        while True:
            if proc.poll() is not None:
                pytest.fail(f"jupyter lab exited {proc.returncode}: {_tail(root / 'lab.log')}")
            with contextlib.suppress(OSError):
                with urllib.request.urlopen(url + "api/status", timeout=2) as r:
                    if r.status == 200:
                        break
            if time.monotonic() > deadline:
                pytest.fail(f"jupyter lab not up in {START_TIMEOUT_S} s: {_tail(root / 'lab.log')}")
            time.sleep(0.5)
        yield url, root
    finally:
        proc.terminate()
        try:
            proc.wait(timeout=20)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()
        log.close()


def _tail(path: Path, n: int = 2000) -> str:
    return path.read_text(errors="replace")[-n:]


@pytest.fixture(scope="module")
def lab_page(chromium, lab, tmp_path_factory):
    from playwright.sync_api import sync_playwright

    blocked: list[str] = []

    def route(r):
        if (urlsplit(r.request.url).hostname or "") in LOCAL_HOSTS:
            r.continue_()
        else:
            blocked.append(r.request.url)
            r.abort()

    with sync_playwright() as p:
        ctx = p.chromium.launch_persistent_context(
            str(tmp_path_factory.mktemp("lab-profile")),
            executable_path=chromium,
            headless=True,
            args=list(CHROMIUM_FLAGS),
            viewport={"width": 1400, "height": 1000},
        )
        ctx.route("**/*", route)
        page = ctx.new_page()
        page.set_default_timeout(60_000)
        page.blocked = blocked
        yield page
        ctx.close()


def _attached(locator, what: str, root: Path, shots: Path, timeout: float = 60_000) -> None:
    """Wait for ``locator``; on timeout keep a screenshot and say what the page had."""
    from playwright.sync_api import TimeoutError as PlaywrightTimeout

    try:
        locator.wait_for(state="attached", timeout=timeout)
    except PlaywrightTimeout:
        page = locator.page
        page.screenshot(path=shots / "lab-explorer-failed.png", full_page=False)
        outs = page.locator(".jp-OutputArea-output").evaluate_all(
            "os => os.map(o => o.className + ': ' + o.innerText.slice(0, 200))"
        )
        raise AssertionError(
            f"no {what} after Run All Cells; outputs: {outs}; JupyterLab log: "
            f"{_tail(root / 'lab.log')}"
        ) from None


def _message(page) -> str:
    return page.locator(".explorer-message").first.inner_text()


def _slider(page, label: str):
    """The ipywidgets slider whose description is ``label``."""
    return page.locator(".widget-slider").filter(
        has=page.locator(".widget-label", has_text=re.compile(rf"^{re.escape(label)}$"))
    )


def _type_into(page, label: str, value: float) -> None:
    """Type ``value`` into the slider's readout box and press Enter, as a user would."""
    readout = _slider(page, label).locator(".widget-readout")
    readout.click()
    page.keyboard.press("Control+A")
    page.keyboard.type(f"{value:g}")
    page.keyboard.press("Enter")


def _camera(plot) -> dict:
    return plot.evaluate("el => el._fullLayout.scene._scene.getCamera().eye")


def _settled_camera(page, plot, timeout_s: float = 10) -> dict:
    """The camera once two reads 200 ms apart agree (the last mouse events of a drag may still
    be moving it when the drag returns)."""
    deadline = time.monotonic() + timeout_s
    eye = _camera(plot)
    while time.monotonic() < deadline:
        page.wait_for_timeout(200)
        now = _camera(plot)
        if now == eye:
            return now
        eye = now
    raise AssertionError(f"the 3D view kept moving for {timeout_s} s: {eye}")


def _drag(page, box, dx: float, dy: float) -> None:
    x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    page.mouse.move(x, y)
    page.mouse.down()
    page.mouse.move(x + dx, y + dy, steps=12)
    page.mouse.up()


def _run_all(page, timeout_s: float = 90) -> None:
    """Run > Run All Cells once the kernel is idle (taking the preferred kernel if JupyterLab
    asks which one to start), until a cell shows that it runs."""
    from playwright.sync_api import TimeoutError as PlaywrightTimeout

    deadline = time.monotonic() + timeout_s
    status = page.locator(".jp-StatusBar-Widget", has_text="| Idle")
    started = page.locator(".jp-InputPrompt", has_text=re.compile(r"\[(\*|\d+)\]"))
    while time.monotonic() < deadline:
        dialog = page.locator(".jp-Dialog")
        if dialog.count() and dialog.first.is_visible():
            dialog.get_by_role("button", name="Select", exact=True).click()
        elif status.count():
            page.get_by_role("menuitem", name="Run", exact=True).click()
            page.get_by_role("menuitem", name=re.compile(r"^Run All Cells")).click()
            with contextlib.suppress(PlaywrightTimeout):
                started.first.wait_for(state="attached", timeout=10_000)
                return
        page.wait_for_timeout(250)
    raise AssertionError(f"could not run the notebook within {timeout_s} s")


def test_explorer_in_jupyterlab(lab, lab_page, shots):
    url, root = lab
    page = lab_page
    t0 = time.perf_counter()
    page.goto(url + f"lab/tree/{NOTEBOOK.name}")
    page.locator(".jp-Notebook").first.wait_for()
    _run_all(page)

    # the explorer: controls, message and the 3D view (plotly, JupyterLab's renderer)
    x = _slider(page, "x [mm]")
    _attached(x, "the explorer's x slider", root, shots, timeout=120_000)
    x.scroll_into_view_if_needed()
    plot = page.locator(".jp-RenderedPlotly.js-plotly-plot").first  # JupyterLab's renderer
    _attached(plot, "the 3D view (plotly)", root, shots)
    page.wait_for_function("() => document.querySelector('.explorer-message')?.innerText")
    first = _message(page)
    assert first.startswith("ok — front-up") and "(500, 113, -1724)" in first, first
    table = page.locator(".explorer-table").first.inner_text()
    assert "w [10⁶ mm³/rad³]" in table and "pulse error [mm]" in table
    plot.scroll_into_view_if_needed()
    page.screenshot(path=shots / "lab-explorer.png", full_page=False)

    # 1. a slider moved with the mouse changes what is shown
    handle = x.locator(".noUi-handle")
    _drag(page, handle.bounding_box(), 40, 0)
    page.wait_for_function(
        "old => document.querySelector('.explorer-message').innerText !== old", arg=first
    )
    moved = _message(page)
    assert moved != first and "x [mm]" not in moved
    readout = float(x.locator(".widget-readout").inner_text())
    assert readout > 100.0  # dragged to the right: x grew from Table 4 row 1's 100 mm

    # 2. Table 4 row 8, typed: the unreachable message (the paper's 无解)
    for label, v in (("x [mm]", 200), ("y [mm]", 500), ("z [mm]", 600)):
        _type_into(page, label, v)
    page.wait_for_function(
        "() => document.querySelector('.explorer-message').innerText.includes('31.849 mm beyond')"
    )
    row8 = _message(page)
    assert row8.startswith("out-of-reach — target (200, 500, 600) mm"), row8
    assert page.locator(".explorer-table").count() == 0  # no numbers for a bad target
    page.screenshot(path=shots / "lab-explorer-row8.png", full_page=False)

    # 3. the 3D view rotates with the mouse, and keeps its camera when the target changes
    plot.scroll_into_view_if_needed()
    before = _camera(plot)
    _drag(page, plot.bounding_box(), 120, 40)
    after = _settled_camera(page, plot)
    assert after != before, (before, after)
    _type_into(page, "x [mm]", 100)
    _type_into(page, "y [mm]", 100)
    page.wait_for_function(
        "() => document.querySelector('.explorer-message').innerText.startsWith('ok')"
    )
    page.wait_for_timeout(500)  # the view is redrawn (Plotly.react) after the message
    kept = _camera(page.locator(".jp-RenderedPlotly.js-plotly-plot").first)
    assert kept == pytest.approx(after, abs=1e-6)
    page.screenshot(path=shots / "lab-explorer-rotated.png", full_page=False)
    assert not page.blocked or all("127.0.0.1" not in u for u in page.blocked)
    print(f"JupyterLab explorer test: {time.perf_counter() - t0:.1f} s in the browser")
