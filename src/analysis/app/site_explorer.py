"""The explorer on a page without a kernel (notebook 09's page on the report site): a
``div.static-explorer`` that ``js/static_explorer.js`` fills with the controls and the 3D view,
and every arm that loads printed as JavaScript (:mod:`analysis.app.explore_js`), each with its
figure and start target (:func:`static_explorer_html`)."""

from __future__ import annotations

import hashlib
import json
from collections.abc import Iterable

from analysis.escape import html_text, js_json

__all__ = ["EXPLORER_NOTE", "explorer_figure", "static_explorer_html"]

EXPLORER_NOTE = (
    "The explorer, here without a kernel: the same controls drive the arm through its "
    "closed form printed as JavaScript (analysis.app.explore_js, from the recording that "
    "the numpy and compiled solvers run; the browser tests hold it to Python within 1e-9). "
    "Drag the 3D view to rotate it, scroll to zoom. With a kernel (make lab, "
    "notebooks/{name}) it also shows the pulse error and the manipulability."
)


def explorer_figure(arm) -> dict:
    """The page explorer's empty figure of ``arm`` as plotly JSON (arm and target traces kept,
    to be drawn in place by ``js/arm3d_view.js``; the title keeps its margin)."""
    from analysis.app.arm3d import arm_figure, workspace_box

    fig = arm_figure(
        arm, None, None, box=workspace_box(arm), keep_arm=True, height=480,
        title=arm.description.title,
    )
    return json.loads(fig.to_json()) | {"config": {"displaylogo": False, "responsive": True}}


def static_explorer_html(name: str, arms: Iterable[str] | None = None) -> str:
    """The explorer for a page without a kernel: a ``div.static-explorer`` that
    ``js/static_explorer.js`` (served from ``_static``) fills with the controls and the 3D
    view, and every arm that loads (:func:`~analysis.app.explore_logic.available_arms`) printed
    as JavaScript (:func:`~analysis.app.explore_js.arm_module_js`), each with its figure
    (:func:`explorer_figure`) and start target
    (:func:`~analysis.app.explore_logic.default_target`; Table 4 row 1 for the paper's arm)."""
    import numpy as np

    from analysis.app.explore_js import arm_module_js
    from analysis.app.explore_logic import available_arms, default_target
    from analysis.kinematics.arm import load_arm

    names = list(arms) if arms is not None else list(available_arms()[0])
    scripts, figures, start, left = [], {}, {}, {}
    for arm_name in names:
        arm = load_arm(arm_name)
        try:
            scripts.append(f"analysisArms[{js_json(arm_name)}] = {arm_module_js(arm)};")
        except (ValueError, TypeError, AttributeError) as exc:  # not a D-H chain
            left[arm_name] = (
                f"left out of this page ({exc}; the page prints D-H chains only); "
                f"make lab, notebooks/{name} explores it with a kernel"
            )
            continue
        t = [100.0, 100.0, 600.0] if arm_name == "grabber" else default_target(arm).tolist()
        figures[arm_name] = explorer_figure(arm)
        start[arm_name] = [float(np.round(v, 9)) for v in t]
    first = "grabber" if "grabber" in figures else next(iter(figures))
    cfg = {"id": hashlib.sha1(name.encode()).hexdigest()[:8], "arm": first,
           "arms": list(figures), "figures": figures, "start": start, "left": left}
    return (
        f'<p class="explorer-note">{html_text(EXPLORER_NOTE.format(name=name))}</p>\n'
        f"<div class=\"static-explorer\" data-explorer='{html_text(json.dumps(cfg))}'>"
        "<noscript>The explorer needs JavaScript.</noscript></div>\n"
        "<script>window.analysisArms = window.analysisArms || {};\n"
        + "\n".join(scripts)
        + "</script>\n"
    )

