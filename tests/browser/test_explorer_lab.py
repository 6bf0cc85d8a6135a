"""The explorer (notebook 09) as a user meets it: in JupyterLab and in Notebook 7, in Debian's
Chromium.

A JupyterLab server from the project's ``.venv`` is started on 127.0.0.1 (a free port, no
token, no browser) in a temporary folder holding two copies of ``notebooks/09_explore.ipynb``
with its stored outputs cleared (so every output on the page comes from this run; the real
notebook is only read), one for JupyterLab (``/lab/tree/...``) and one for Notebook 7's
interface (``/notebooks/...``, the ``notebook`` package on the same server); their kernels
are started over the REST API as soon as the server is up. Configuration, settings,
workspaces and runtime files live in that folder too, with JupyterLab's news and update
checks switched off. The browser's requests to any host but 127.0.0.1 are aborted and
recorded.

The tests run the notebook from the Run menu, then type targets (Table 4 row 8, (200, 500,
600) mm, among them) into the slider boxes, drag a slider, pick branches and drag the 3D view,
asserting each time on what the page draws: the joint positions held to IK then FK computed
here in Python, and the camera where the drag left it (on screen, at rest) kept through the next
redraw. Waits are on events (a draw on screen, the kernel's pose in, plotly's relayout, the
save's response), not on fixed timeouts. Screenshots, the latencies and the seconds per step
go to ``build/browser`` (see conftest.py).
"""

from __future__ import annotations

import importlib.util
import json
import os
import re
import sys
import time
from pathlib import Path
from urllib.parse import urlsplit

import pytest

from analysis.app.explore_logic import FK_CAPTION, fk_line, plain_message, pose_report
from analysis.app.lab import serve as lab_server
from analysis.app.lab import tail as _tail
from analysis.app.report import CHROMIUM_FLAGS, NB_BACKEND

from .conftest import LOCAL_HOSTS, PROJECT
from .lab_ui import cleared_copies
from .lab_ui import kernel_idle as _kernel_idle
from .lab_ui import quiet as _quiet
from .lab_ui import run_all as _run_all
from .lab_ui import slider as _slider
from .lab_ui import type_into as _type_into
from .screen import STALE_RGB, assert_arm_on_screen
from .screen import close as _close

NOTEBOOK = PROJECT / "notebooks" / "09_explore.ipynb"
STORED = NOTEBOOK.read_bytes()  # what nbval compares: the Lab session must leave it as it is
JUPYTER = Path(sys.executable).with_name("jupyter")  # lab_command runs this one
NB7_COPY = "09_explore_notebook7.ipynb"  # the same cleared notebook, opened in Notebook 7


@pytest.fixture(scope="module")
def lab(chromium, tmp_path_factory):
    """A JupyterLab server on 127.0.0.1 serving a cleared copy of notebook 09; yields its URL."""
    if not JUPYTER.exists():
        pytest.skip(f"no jupyter at {JUPYTER}: make venv installs JupyterLab")
    root = tmp_path_factory.mktemp("lab")
    kernel = cleared_copies(root, NOTEBOOK, NB7_COPY)
    env = {"ANALYSIS_FIGURE_DIR": str(root / "figures"), "MPLBACKEND": NB_BACKEND}
    try:
        with lab_server(root, {NOTEBOOK.name: kernel, NB7_COPY: kernel}, env) as url:
            yield url, root
    except RuntimeError as exc:  # the server did not start
        pytest.fail(str(exc))


@pytest.fixture(scope="module")
def lab_page(pw, chromium, lab, tmp_path_factory):
    blocked: list[str] = []

    def route(r):
        if (urlsplit(r.request.url).hostname or "") in LOCAL_HOSTS:
            r.continue_()
        else:
            blocked.append(r.request.url)
            r.abort()

    ctx = pw.chromium.launch_persistent_context(
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
    page.console = []  # the browser's console, for failure messages
    page.on("console", lambda m: page.console.append(f"{m.type}: {m.text}"))
    page.on("pageerror", lambda e: page.console.append(f"pageerror: {e}"))
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


def _camera(plot) -> dict:
    return plot.evaluate("el => el._fullLayout.scene._scene.getCamera().eye")


def _drag_view(page, plot, dx: float, dy: float) -> tuple[dict, dict]:
    """Rotate the 3D view with the mouse; return the camera plotly saved as the user's at
    mouseup (its ``plotly_relayout`` event, ``layout.scene.camera``) and the live one."""
    plot.evaluate(
        """gd => { window.arm3dRelayout = null;
        gd.once('plotly_relayout', e => { window.arm3dRelayout = e; }); }"""
    )
    _drag(page, plot.bounding_box(), dx, dy)
    page.wait_for_function("() => window.arm3dRelayout && window.arm3dRelayout['scene.camera']")
    saved = plot.evaluate("gd => gd.layout.scene.camera.eye")
    return saved, _camera(plot)


def _camera_at_rest(page, plot, timeout_s: float = 5) -> dict:
    """The live camera once two reads 150 ms apart agree exactly."""
    last, end = _camera(plot), time.monotonic() + timeout_s
    while time.monotonic() < end:
        page.wait_for_timeout(150)
        now = _camera(plot)
        if now == last:
            return now
        last = now
    raise AssertionError(f"the 3D camera kept moving for {timeout_s} s after the drag: {last}")


def _drag(page, box, dx: float, dy: float) -> None:
    x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    page.mouse.move(x, y)
    page.mouse.down()
    page.mouse.move(x + dx, y + dy, steps=12)
    page.mouse.up()


# --- what the 3D view draws ------------------------------------------------------------------
_DRAWN = """() => {
    const w = document.querySelector('.arm3d-widget');
    const gd = w && w.querySelector('.js-plotly-plot');
    if (!gd || !gd._fullData) return null;
    const arm = gd._fullData.find(t => t.name === 'arm');
    const tgt = gd._fullData.find(t => t.name === 'target');
    const pts = t => (t && t.x ? t.x.map((x, i) => [x, t.y[i], t.z[i]]) : []);
    const tool = gd.data.find(t => t.meta && t.meta.arm3d && t.name.startsWith('tool'));
    return {arm: pts(arm), target: pts(tgt), title: gd._fullLayout.title.text,
            tool: tool ? [pts(tool), tool.meta.arm3d.length] : null,
            draws: (w.arm3dDraws || []).length};
}"""


PLOT = ".arm3d-widget .js-plotly-plot"
# the kernel's disagreement with the browser's pose: [mm, the note's text] ([None, ""]: none)
_NOTE = """() => { const w = document.querySelector('.arm3d-widget');
    const n = w.querySelector('.arm3d-disagree');
    return [w.arm3dDisagreement ? w.arm3dDisagreement.mm : null,
            n.style.display === 'none' ? '' : n.textContent]; }"""
# the title plotly shows (its SVG text)
_TITLE_SHOWN = "() => document.querySelector('.arm3d-widget .g-gtitle text.gtitle').textContent"
# the browser's kinematics made wrong: the tool point drawn 5 mm further in x
_SABOTAGE = """() => { const A = analysisArm3d; A.truePose = A.truePose || A.pose;
    A.pose = (arm, args) => { const r = A.truePose(arm, args);
        if (r.frames) { r.frames = r.frames.map(p => p.slice());
            r.frames[r.frames.length - 1][0] += 5; }
        return r; }; }"""
PHASES: list = []  # per change: ms from the key press to draw(), plotly start, return, painted


def _drawn(page) -> dict:
    return page.evaluate(_DRAWN)


def _mark(page) -> None:
    """Stamp the next Enter key press (the change) and forget earlier draws."""
    page.evaluate(
        """() => { window.arm3dChangeAt = null;
        const stamp = e => { if (e.key !== 'Enter') return;
            window.arm3dChangeAt = performance.now();
            document.removeEventListener('keydown', stamp, {capture: true}); };
        document.addEventListener('keydown', stamp, {capture: true}); }"""
    )


def _drawn_after_change(page, timeout_ms: float = 20_000) -> tuple[dict, float]:
    """Wait for the first draw after the stamped change; return what is drawn and the time
    [ms] from the key press to that pose on screen."""
    from playwright.sync_api import TimeoutError as PlaywrightTimeout

    try:
        page.wait_for_function(
            """() => window.arm3dChangeAt !== null && (document.querySelector('.arm3d-widget')
            .arm3dDraws || []).some(d => d.t > window.arm3dChangeAt)""",
            timeout=timeout_ms,
        )
    except PlaywrightTimeout:
        state = page.evaluate(
            "() => [window.arm3dChangeAt, (document.querySelector("
            "'.arm3d-widget').arm3dDraws || []).map(d => [d.t, d.source])]"
        )
        raise AssertionError(
            f"no new pose drawn after the change: {state}; console: "
            f"{[c for c in page.console if 'GL Driver' not in c][-8:]}"
        ) from None
    ms = page.evaluate(
        """() => { const t0 = window.arm3dChangeAt;
        const d = document.querySelector('.arm3d-widget').arm3dDraws.find(d => d.t > t0);
        return [d.asked - t0, d.started - t0, d.plotted - t0, d.t - t0, d.path, d.source]; }"""
    )
    PHASES.append(ms)
    return _drawn(page), ms[-3]


def _assert_tool_frame(drawn: dict, arm, target, branch: str) -> None:
    """The tool frame drawn (js/arm3d_view.js from the printed kinematics' transforms, or the
    kernel's) is the FK's (analysis.app.arm3d_frames): origin and axes, read back from the
    triad's points (o, o + L x, gap, o, o + L y, gap, o, o + L z, gap)."""
    import numpy as np

    sol = arm.solve(target, (branch,))
    T = arm.tool_transform(sol.theta[0])
    pts, length = drawn["tool"]
    pts = np.array([[np.nan if v is None else v for v in p] for p in pts], dtype=float)
    np.testing.assert_allclose(pts[0], T[:3, 3], atol=2e-3)
    np.testing.assert_allclose((pts[[1, 4, 7]] - pts[0]).T / length, T[:3, :3], atol=1e-6)


def _settled(page, expect, timeout_s: float = 20) -> dict:
    """What is drawn once it equals ``expect`` (the kernel's pose follows the browser's), or
    the last drawing when it never does."""
    deadline = time.monotonic() + timeout_s
    while True:
        d = _drawn(page)
        if (d and _close(d["arm"], expect)) or time.monotonic() > deadline:
            return d
        page.wait_for_timeout(100)


def _fk_pose(arm, target, branch: str):
    """The frame origins Python puts the arm at for ``target`` on ``branch`` (IK, then FK)."""
    sol = arm.solve(target, (branch,))
    assert sol.ok[0], (target, branch)
    return arm.frames(sol.theta[0])


def test_explorer_in_jupyterlab(lab, lab_page, shots):
    """Run the notebook as a user would; every change must move the drawn arm to where the
    corrected kinematics (IK, then FK, computed here in Python) puts it, within 2 um; the time
    from a change to the new pose on screen is measured (build/browser/lab-latency.json)."""
    import numpy as np

    from analysis.kinematics.arm import paper_arm

    arm = paper_arm()
    url, root = lab
    page = lab_page
    t0 = time.perf_counter()
    steps: dict[str, float] = {}  # seconds each part took (build/browser/lab-latency.json)

    def step(name: str) -> None:
        steps[name] = round(time.perf_counter() - t0 - sum(steps.values()), 2)

    page.goto(url + f"lab/tree/{NOTEBOOK.name}")
    page.locator(".jp-Notebook").first.wait_for()
    step("open: Lab page")
    _run_all(page)
    step("open: Run All started")

    # the explorer: controls, message and the 3D view (the widget's plotly figure)
    x = _slider(page, "x [mm]")
    _attached(x, "the explorer's x slider", root, shots, timeout=120_000)
    x.scroll_into_view_if_needed()
    plot = page.locator(".arm3d-widget .js-plotly-plot").first
    step("open: controls shown")
    _attached(plot, "the 3D view (the explorer's widget)", root, shots)
    step("open: 3D view shown")
    page.wait_for_function("() => document.querySelector('.explorer-message')?.innerText")
    first = _message(page)
    assert first.startswith("ok — front-up") and "(500, 113, -1724)" in first, first
    table = page.locator(".explorer-table").first.inner_text()
    assert "w [10⁶ mm³/rad³]" in table and "pulse error [mm]" in table
    row1 = _fk_pose(arm, [100, 100, 600], "front-up")
    drawn = _settled(page, row1)
    assert _close(drawn["arm"], row1), (drawn, page.console[-10:])
    assert "45.00, 10.21, -155.13" in drawn["title"]
    plot.scroll_into_view_if_needed()
    assert_arm_on_screen(page, PLOT, row1)
    page.screenshot(path=shots / "lab-explorer.png", full_page=False)
    # WebGL rendered in software (headless Chromium, --disable-gpu): the view's scene without
    # multisampling, which took most of each redraw's time (js/arm3d_view.js)
    soft, aa = page.evaluate(
        """() => { const v = document.querySelector('.arm3d-widget');
        const gd = v.querySelector('.js-plotly-plot');
        return [v.arm3dSoftwareGL, gd._fullLayout.scene._scene.glplot.gl
            .getContextAttributes().antialias]; }"""
    )
    assert soft and aa is False, (soft, aa)

    step("open and run")
    # 1. typed changes: the drawn arm moves to FK(IK(target)) at once; latency measured
    latencies = []
    shown = row1
    for k, (label, v, target) in enumerate(
        [
            ("x [mm]", 150, [150, 100, 600]),
            ("y [mm]", 50, [150, 50, 600]),
            ("z [mm]", 700, [150, 50, 700]),
            ("x [mm]", 250, [250, 50, 700]),
            ("y [mm]", 100, [250, 100, 700]),
            ("z [mm]", 600, [250, 100, 600]),
        ]
    ):
        _mark(page)
        _type_into(page, label, v)
        drawn, ms = _drawn_after_change(page)
        latencies.append(ms)
        expect = _fk_pose(arm, target, "front-up")
        assert _close(drawn["arm"], expect), (k, target, drawn["arm"], expect.tolist())
        assert _close(drawn["target"], [target]), drawn["target"]
        _assert_tool_frame(drawn, arm, target, "front-up")  # the tool frame, drawn with it
        assert_arm_on_screen(page, PLOT, expect, previous=shown)  # the picture moved too
        # the title on screen is the pose's (set in place, not by a relayout)
        assert page.evaluate(_TITLE_SHOWN) == drawn["title"], page.evaluate(_TITLE_SHOWN)
        shown = expect
    page.wait_for_function(
        "() => document.querySelector('.explorer-message').innerText.includes('(250, 100, 600)')"
        " || document.querySelector('.explorer-message').innerText.includes('front-up')"
    )
    _quiet(page)  # the kernel agreed with every pose the browser drew: no note
    assert page.evaluate(_NOTE) == [None, ""], page.evaluate(_NOTE)

    step("1 typed")
    # 1b. the kernel confirms: the browser's kinematics made wrong (the tool point 5 mm off in
    # x), a typed value is drawn wrong at once, then the kernel's pose replaces it and the note
    # says by how much; right again, the note goes
    page.evaluate(_SABOTAGE)
    _mark(page)
    _type_into(page, "x [mm]", 240)
    _drawn_after_change(page)
    first = page.evaluate(
        """() => document.querySelector('.arm3d-widget').arm3dDraws
        .find(d => d.t > window.arm3dChangeAt)"""
    )
    expect = _fk_pose(arm, [240, 100, 600], "front-up")
    assert first["source"] == "local", first  # drawn at once, from the browser's kinematics
    assert abs(first["frames"][-1][0] - expect[-1][0] - 5.0) < 1e-6, first  # wrong by 5 mm
    _quiet(page)
    assert _close(_drawn(page)["arm"], expect)  # corrected by the kernel's pose
    mm, note = page.evaluate(_NOTE)
    assert mm == pytest.approx(5.0, abs=1e-6) and "5.000 mm apart" in note, (mm, note)
    assert note and page.locator(".arm3d-disagree").first.is_visible()
    page.evaluate("() => { analysisArm3d.pose = analysisArm3d.truePose; }")
    _type_into(page, "x [mm]", 250)
    _quiet(page)
    assert page.evaluate(_NOTE) == [None, ""], page.evaluate(_NOTE)
    assert _close(_drawn(page)["arm"], _fk_pose(arm, [250, 100, 600], "front-up"))
    # 2. a slider dragged with the mouse: the arm follows during the drag (drawn in the browser
    # from the printed kinematics at each move, before the button is released), then the
    # kernel's message and pose follow
    before = _message(page)
    handle = x.locator(".noUi-handle")
    box = handle.bounding_box()
    hx, hy = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    n0 = page.evaluate("() => document.querySelector('.arm3d-widget').arm3dDraws.length")
    page.mouse.move(hx, hy)
    page.mouse.down()
    for k in range(1, 9):
        page.mouse.move(hx - 5 * k, hy)
        page.wait_for_timeout(60)
    during = page.evaluate(
        """n => document.querySelector('.arm3d-widget').arm3dDraws.slice(n)
        .filter(d => d.source === 'local').length""",
        n0,
    )
    page.mouse.up()
    assert during >= 3, f"the arm was redrawn {during} times during the drag"
    page.wait_for_function(
        "old => document.querySelector('.explorer-message').innerText !== old", arg=before
    )
    xs = float(x.locator(".widget-readout").inner_text())
    assert xs < 250.0  # dragged to the left
    expect = _fk_pose(arm, [xs, 100, 600], "front-up")
    assert _close(_settled(page, expect)["arm"], expect)

    step("2 slider drag")
    # 3. another branch: the drawing flips the elbow
    page.get_by_role("button", name="back-down", exact=True).first.click()
    expect = _fk_pose(arm, [xs, 100, 600], "back-down")
    drawn = _settled(page, expect)
    assert _close(drawn["arm"], expect) and "back-down" in drawn["title"], drawn
    page.get_by_role("button", name="front-up", exact=True).first.click()

    step("3 branch")
    # 4. Table 4 row 8, typed: the unreachable message (the paper's 无解), no arm drawn
    for label, v in (("x [mm]", 200), ("y [mm]", 500), ("z [mm]", 600)):
        _type_into(page, label, v)
    page.wait_for_function(
        "() => document.querySelector('.explorer-message').innerText.includes('31.849 mm beyond')"
    )
    row8 = _message(page)
    assert row8 == plain_message(pose_report(arm, [200, 500, 600])), row8  # as the site says
    assert "nearest reachable on the line" in row8
    rows = page.locator(".explorer-table tbody tr").all_inner_texts()  # kept, no numbers
    assert len(rows) == 4 and all(r.split()[-1] == "out-of-reach" for r in rows), rows
    page.wait_for_function(
        "() => document.querySelector('.arm3d-widget .js-plotly-plot')._fullLayout.title.text"
        ".includes('no solution')"
    )
    drawn = _drawn(page)
    kept = _fk_pose(arm, [200, 100, 600], "front-up")  # the last pose, kept and greyed
    assert _close(drawn["arm"], kept) and _close(drawn["target"], [[200, 500, 600]]), drawn
    plot.scroll_into_view_if_needed()
    assert_arm_on_screen(page, PLOT, kept, rgb=STALE_RGB)
    page.screenshot(path=shots / "lab-explorer-row8.png", full_page=False)

    step("4 row 8")
    # 5. the 3D view rotates with the mouse, and keeps its camera when the target changes
    plot.scroll_into_view_if_needed()
    _quiet(page)
    before = _camera(plot)
    _drag_view(page, plot, 120, 40)
    after = _camera_at_rest(page, plot)  # where the user left it (plotly may still apply the
    # drag's last mouse moves in the next frame, after the camera it saved at mouseup)
    assert max(abs(after[k] - before[k]) for k in "xyz") > 0.1, (before, after)  # it rotated
    _type_into(page, "x [mm]", 100)
    _mark(page)
    _type_into(page, "y [mm]", 100)
    drawn, ms = _drawn_after_change(page)
    latencies.append(ms)
    assert _close(drawn["arm"], row1)
    _quiet(page)  # the kernel's pose in too (it redraws if it differs from the browser's)
    kept = _camera(plot)
    assert kept == pytest.approx(after, abs=1e-9), (after, kept)
    # the arm on screen where the rotated camera puts it
    assert_arm_on_screen(page, PLOT, row1)
    page.screenshot(path=shots / "lab-explorer-rotated.png", full_page=False)

    step("5 camera")
    # 6. FK mode: the joint sliders drive the drawing
    page.get_by_role("button", name=re.compile("FK mode")).first.click()
    t1 = _slider(page, "θ1 [°]")
    t1.wait_for()
    _mark(page)
    _type_into(page, "θ1 [°]", 30)
    drawn, ms = _drawn_after_change(page)
    latencies.append(ms)
    q = np.radians([30.0, 10.21, -155.13])
    assert _close(drawn["arm"], arm.frames(q)), drawn
    assert "FK" in drawn["title"]
    assert_arm_on_screen(page, PLOT, arm.frames(q), previous=row1)
    # the FK line: the joints set, their pulses, the tool and the branch they belong to
    page.wait_for_function(
        "() => document.querySelector('.explorer-message').innerText.startsWith("
        "'FK: joints (30.00°')"
    )
    rep = pose_report(arm, arm.fk(q), "front-up", theta1_on_axis=float(q[0]))
    assert _message(page) == fk_line(arm, q, rep), _message(page)
    assert page.locator(".explorer-table caption").first.inner_text() == FK_CAPTION

    assert not page.blocked or all("127.0.0.1" not in u for u in page.blocked)
    step("6 FK")
    # make lab never changes the stored notebook: saved, the copy changed, notebooks/ did not
    saved = root / NOTEBOOK.name
    before_save = saved.stat().st_mtime
    page.get_by_role("menuitem", name="File", exact=True).click()
    # Save: wait for JupyterLab's PUT of the notebook to be answered
    with page.expect_response(
        lambda r: r.request.method == "PUT" and f"/api/contents/{NOTEBOOK.name}" in r.url,
        timeout=30_000,
    ) as put:
        page.get_by_role("menuitem", name=re.compile(r"^Save( Notebook)?(\s|$)")).first.click()
    assert put.value.ok, (put.value.status, _tail(root / "lab.log"))
    assert saved.stat().st_mtime > before_save, "JupyterLab did not save the notebook"
    assert NOTEBOOK.read_bytes() == STORED, "the stored notebook changed"
    step("save")
    # the browser's own frame interval with nothing changing (context for the latency)
    frame = page.evaluate(
        """() => new Promise(r => { const ts = []; const f = t => { ts.push(t);
        if (ts.length < 11) requestAnimationFrame(f); else r(ts.slice(1).map((v, i) => v - ts[i])
            .sort((a, b) => a - b)[5]); }; requestAnimationFrame(f); })"""
    )
    load = os.getloadavg()
    report = {
        "latency_ms": [round(v, 1) for v in latencies],
        "median_ms": round(float(np.median(latencies)), 1),
        "max_ms": round(max(latencies), 1),
        "phases_ms": [[round(v, 1) for v in p[:-2]] for p in PHASES],
        "first_draw_from": sorted({p[-1] for p in PHASES}),
        "redrawn_by": sorted({p[-2] for p in PHASES}),
        "idle_frame_ms": round(frame, 1),
        "loadavg": [round(v, 2) for v in load],
        "cpus": os.cpu_count(),
        "steps_s": steps,
    }
    (shots / "lab-latency.json").write_text(json.dumps(report, indent=1) + "\n")
    print(
        f"JupyterLab explorer: {time.perf_counter() - t0:.1f} s; change -> pose on screen {report}"
    )
    # every change is drawn first from the printed kinematics, not after a kernel round trip
    assert report["first_draw_from"] == ["local"], report
    # and redrawn in place (the arm's WebGL objects updated, the scene drawn once), never by a
    # whole Plotly.update: that is what keeps a change within the 50 ms budget. The time
    # itself is recorded here (build/browser/lab-latency.json, with the machine's load) and
    # measured in make bench against Plotly.update (benchmarks/explorer_redraw.py), not
    # asserted: a timed test fails on a loaded machine, not on slow code.
    assert report["redrawn_by"] == ["in-place"], report


def test_explorer_in_notebook7(lab, lab_page, shots):
    """The same notebook in Notebook 7's interface (``/notebooks/...``, served by the same
    Jupyter server as JupyterLab): Run All, then typed changes; each time the drawn arm must
    be where IK then FK in Python put it (a frozen plot fails), drawn first in the browser."""
    if importlib.util.find_spec("notebook") is None:
        pytest.skip("no Notebook 7 (the notebook package, pinned in requirements.lock): make venv")
    from analysis.kinematics.arm import paper_arm

    arm = paper_arm()
    url, root = lab
    page = lab_page
    t0 = time.perf_counter()
    page.goto(url + f"notebooks/{NB7_COPY}")
    page.locator(".jp-Notebook").first.wait_for()
    _run_all(page, ready=lambda: _kernel_idle(url, NB7_COPY))
    x = _slider(page, "x [mm]")
    _attached(x, "the explorer's x slider (Notebook 7)", root, shots, timeout=120_000)
    x.scroll_into_view_if_needed()
    plot = page.locator(".arm3d-widget .js-plotly-plot").first
    _attached(plot, "the 3D view (Notebook 7)", root, shots)
    row1 = _fk_pose(arm, [100, 100, 600], "front-up")
    drawn = _settled(page, row1)
    assert _close(drawn["arm"], row1), (drawn, page.console[-10:])
    latencies = []
    shown = row1
    for label, v, target in (("x [mm]", 150, [150, 100, 600]), ("z [mm]", 700, [150, 100, 700])):
        _mark(page)
        _type_into(page, label, v)
        drawn, ms = _drawn_after_change(page)
        latencies.append(round(ms, 1))
        expect = _fk_pose(arm, target, "front-up")
        assert _close(drawn["arm"], expect), (target, drawn["arm"], expect.tolist())
        assert PHASES[-1][-1] == "local", PHASES[-1]  # drawn from the printed kinematics
        assert PHASES[-1][-2] == "in-place", PHASES[-1]
        plot.scroll_into_view_if_needed()
        assert_arm_on_screen(page, PLOT, expect, previous=shown)
        shown = expect
    page.get_by_role("button", name="back-down", exact=True).first.click()
    expect = _fk_pose(arm, [150, 100, 700], "back-down")
    assert _close(_settled(page, expect)["arm"], expect)
    page.wait_for_function(
        "() => document.querySelector('.explorer-message').innerText.startsWith('ok — back-down')"
    )
    plot.scroll_into_view_if_needed()
    page.screenshot(path=shots / "notebook7-explorer.png", full_page=False)
    assert NOTEBOOK.read_bytes() == STORED, "the stored notebook changed"
    print(
        f"Notebook 7 explorer: {time.perf_counter() - t0:.1f} s; change -> pose on screen "
        f"{latencies} ms (load {os.getloadavg()[0]:.2f})"
    )
