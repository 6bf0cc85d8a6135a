"""Trajectories played on the report site (notebook 09's page, no kernel), in Debian's Chromium
(issue 31 item 3: "a trajectory (the GR-1's cubic, and the machine runs ...) playable with a
time slider"). A click on the time slider's rail, as a user's, moves the arm; what is drawn
then (the arm, its tool frame, the outputs under the title) must be the forward kinematics of
the joints at the slider's time, computed here apart from the page: the GR-1's cubic from the
thesis's joints, the machine run by running the GR-1's program on the ST engine again."""

from __future__ import annotations

import numpy as np
import pytest

from analysis.kinematics.arm import load_arm

PATH = "notebooks/09_explore.html"

_FIND = """title => { const gd = [...document.querySelectorAll('.js-plotly-plot')]
    .find(g => g.layout && g.layout.title && String(g.layout.title.text).includes(title));
    if (gd) gd.scrollIntoView({block: 'center'});
    return Boolean(gd); }"""

_STATE = """title => { const gd = [...document.querySelectorAll('.js-plotly-plot')]
    .find(g => g.layout && g.layout.title && String(g.layout.title.text).includes(title));
    const s = gd._fullLayout.sliders[0];
    const pts = t => t.x.map((x, i) => [x, t.y[i], t.z[i]]);
    const tool = gd._fullData.find(t => t.meta && t.meta.arm3d && t.name.startsWith('tool'));
    const ann = gd._fullLayout.annotations || [];
    return {active: s.active, label: s.steps[s.active].label,
            arm: pts(gd._fullData.find(t => t.name === 'arm')),
            tool: pts(tool), length: tool.meta.arm3d.length,
            note: ann.length ? ann[0].text : null}; }"""


@pytest.fixture(scope="module")
def page09(context, site_url, site_dir, blocked):
    if not (site_dir / PATH).exists():
        pytest.skip(f"{PATH} is not part of this build")
    page = context.new_page()
    errors: list[str] = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.js_errors = errors
    page.goto(site_url + PATH, wait_until="load")
    yield page
    page.close()


def _play_to(page, title: str, fraction: float) -> dict:
    """Click the time slider of the figure titled ``title`` at ``fraction`` of its rail; what
    is drawn once the slider has moved there."""
    assert page.evaluate(_FIND, title), f"no figure titled {title!r} on {PATH}"
    page.wait_for_function(
        """title => [...document.querySelectorAll('.js-plotly-plot')].some(g => g.layout
            && String((g.layout.title || {}).text).includes(title) && g._fullLayout
            && g._fullLayout.sliders && g._fullLayout.sliders.length)""",
        arg=title,
    )
    plot = page.locator(".js-plotly-plot").filter(has=page.locator(f"text={title}")).first
    rail = plot.locator(".slider-rail-rect").first
    box = rail.bounding_box()
    before = page.evaluate(_STATE, title)
    page.mouse.click(box["x"] + fraction * box["width"], box["y"] + box["height"] / 2)
    page.wait_for_function(
        """([title, k]) => { const gd = [...document.querySelectorAll('.js-plotly-plot')]
            .find(g => String((g.layout.title || {}).text).includes(title));
            return gd._fullLayout.sliders[0].active !== k && !gd._transitioning; }""",
        arg=[title, before["active"]],
    )
    page.wait_for_timeout(300)  # the frame's redraw
    return page.evaluate(_STATE, title)


def _rows(t: np.ndarray, label: str) -> np.ndarray:
    """The samples whose time the slider's label (s, 2 decimals) names."""
    return np.flatnonzero(np.abs(t - float(label)) <= 0.005 + 1e-9)


def _assert_pose(arm, drawn: dict, q_user: np.ndarray, rows: np.ndarray) -> int:
    """The drawn arm and tool frame are FK's at one of ``rows`` (joint values in deg | mm);
    that row."""
    assert len(rows), drawn["label"]
    arm_pts = np.asarray(drawn["arm"], dtype=float)
    tool = np.array([[np.nan if v is None else v for v in p] for p in drawn["tool"]], dtype=float)
    o, R = tool[0], (tool[[1, 4, 7]] - tool[0]).T / drawn["length"]
    for r in rows:
        q = arm.joints_from_user(q_user[r])
        T = arm.tool_transform(q)
        if (np.abs(arm_pts[-1] - arm.fk(q)).max() <= 2e-3 and np.abs(o - T[:3, 3]).max() <= 2e-3
                and np.abs(R - T[:3, :3]).max() <= 1e-4):  # fmt: skip
            return int(r)
    raise AssertionError(f"t = {drawn['label']} s: the drawn pose is no sample's ({rows})")


def test_the_gr1_cubic_plays_from_the_time_slider(page09):
    from analysis.audit.papers.gr1.thesis import DURATION_S, printed_joints
    from analysis.studies.trajectories import cubic_trajectory

    arm = load_arm("gr1")
    q0, qf = printed_joints()
    t = np.linspace(0.0, DURATION_S, 201)
    q = cubic_trajectory(q0, qf, DURATION_S, t)[0]
    drawn = _play_to(page09, "GR-1 on the cubic", 0.6)
    assert drawn["active"] > 0
    _assert_pose(arm, drawn, arm.joints_to_user(q), _rows(t, drawn["label"]))
    assert page09.js_errors == [], page09.js_errors


def test_the_machine_run_plays_with_its_outputs(page09, machine_engine, tmp_path):
    """The GR-1's handling run, as notebook 09 makes it (stl, stl-run on the ST engine),
    read back by the strict reader; the page at the slider's time draws that row's pose and
    prints that row's outputs."""
    from analysis.app.arm3d_trace import read_trace
    from analysis.app.cli import main
    from analysis.plc.machine.scenarios import scenarios

    arm = load_arm("gr1")
    prog, mp, scen, out = (tmp_path / n for n in ("g.st", "g.json", "s.csv", "t.csv"))
    scen.write_text(scenarios(arm)["handling"].csv(), encoding="utf-8")
    assert main(["stl", "--arm", "gr1", "--dialect", "st", "-o", str(prog), "--map", str(mp)]) == 0
    assert main(["stl-run", str(prog), "--dialect", "st", "--map", str(mp), "--scenario",
                 str(scen), "--trace", str(out)]) == 0  # fmt: skip
    run = read_trace(out, arm)
    for fraction in (0.3, 0.45):
        drawn = _play_to(page09, "machine run", fraction)
        row = _assert_pose(arm, drawn, run.q, _rows(run.t, drawn["label"]))
        busy = "TRUE" if run.outputs["Busy"][row] else "FALSE"
        assert drawn["note"].startswith(f"t = {run.t[row]:.2f} s · Status "), drawn["note"]
        assert f"Busy {busy}" in drawn["note"], drawn["note"]
    assert page09.js_errors == [], page09.js_errors
