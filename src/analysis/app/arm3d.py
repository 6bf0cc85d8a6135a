"""The arm as an interactive 3D figure (plotly): rotate, zoom and pan in JupyterLab and in
the static report site, with no network.

Why plotly (``plotly`` on PyPI, pinned in ``requirements.lock``)
-----------------------------------------------------------------
* One figure description (JSON) is rendered by plotly.js in both places the explorer must
  work: JupyterLab 4 renders the ``application/vnd.plotly.v1+json`` output with the
  ``jupyterlab-plotly`` renderer that the ``plotly`` wheel installs (plotly.js bundled in the
  extension, nothing fetched), and the report site renders the ``text/html`` output of the
  same bundle (MyST-NB picks ``text/html``; it skips the plotly mimetype) with the
  ``plotly.min.js`` of the same wheel served from the site's ``_static``
  (``docs/site/conf.py`` adds it to the pages that hold a plotly figure).
* Its 3D scenes (WebGL) rotate, zoom and pan with the mouse out of the box, and keep the
  user's camera when the figure is redrawn with the same ``layout.uirevision``: the
  explorer (:mod:`analysis.app.explore`) updates its view in place through a display id, so
  moving a slider does not reset the rotation.
* The alternatives were weighed: matplotlib's 3D (the old explorer) is a static PNG in a
  notebook and in a static page; three.js or pythreejs need a widget manager, which a
  static page only gets from a CDN; plotly's ``FigureWidget`` needs ``anywidget`` and puts
  its 5 MB script into the notebook's stored widget state.

The explorer's view in JupyterLab and Notebook 7 is :class:`Arm3DWidget`, an ``anywidget``
of this package (``js/arm3d_view.js`` and ``js/arm3d_widget.js``, a few kB): it draws the
figure with plotly.js and redraws the arm in place on every change of the explorer's
controls, from the arm's kinematics printed as JavaScript (:mod:`analysis.app.explore_js`),
so a slider change reaches the screen without a round trip to the kernel; the kernel's own
pose (:meth:`Arm.frames`) follows and is drawn for the controls' current values. Why not
plotly's ``FigureWidget`` (an anywidget too, in plotly 6+): its widget state carries the
whole plotly.js bundle (4.8 MB) as the module's source, which nbclient and JupyterLab store in
the notebook's metadata; here the kernel sends plotly.js once per page as a binary message,
which is never stored. Why not ``display(..., display_id=True)`` and ``update()`` (the
previous explorer): JupyterLab does not render display updates sent from widget callbacks
(ipywidgets #1844), so the view stayed at its first pose.

Everything else here is a pure function of the arm and the joint angles: :func:`arm_figure`
builds a ``plotly.graph_objects.Figure`` (coordinates rounded to 1 µm, so stored notebook
outputs that nbval compares do not depend on round-off), :func:`figure_bundle` the MIME
bundle a notebook displays, with a deterministic ``div`` id (no random ids in stored
outputs), and :func:`workspace_box` the axis ranges, from a seeded sample of the arm's
forward kinematics.
"""

from __future__ import annotations

import hashlib
import html
import json
from collections.abc import Sequence
from dataclasses import dataclass
from functools import cache
from pathlib import Path

import numpy as np
import numpy.typing as npt
import plotly.graph_objects as go

from analysis.app.arm3d_frames import frame_spec, frame_traces, frame_transforms, segments

try:  # the widget needs anywidget (pinned in requirements.lock); the figures do not
    import anywidget
    import traitlets
except ImportError:  # pragma: no cover
    anywidget = None

__all__ = [
    "Arm3DWidget", "Box", "arm_figure", "figure_bundle", "trajectory_figure", "workspace_box",
]  # fmt: skip

PLOTLY_MIME = "application/vnd.plotly.v1+json"
ROUND_MM = 3
"""Decimals [mm] of the coordinates in a figure: 1 µm, far below what a figure can show and
far above float64 round-off (~1e-13 mm), so stored outputs are reproducible."""
CONFIG = {"displaylogo": False, "responsive": True, "scrollZoom": True}
PATH_POINTS = 600
"""The most samples a trajectory's tool path is drawn through (evenly spread)."""
_FONT = {"family": "DejaVu Sans, Arial, sans-serif", "size": 13}


@dataclass(frozen=True)
class Box:
    """Axis-aligned box [mm]: ``lo`` and ``hi``, 3 values each (x, y, z)."""

    lo: tuple[float, float, float]
    hi: tuple[float, float, float]

    @property
    def span(self) -> npt.NDArray[np.float64]:
        return np.subtract(self.hi, self.lo)


def workspace_box(
    arm, *, samples: int = 4096, seed: int = 0, pad: float = 0.08, grid_mm: float = 10.0
) -> Box:
    """A box around everything the arm's links can reach [mm], for axis and slider ranges.

    Joint angles are drawn uniformly within the joint limits (a full turn where a joint is
    unrestricted), seeded; the box holds every frame origin of those poses (the base, each
    link's end, the tool), padded by ``pad`` of its span on each side, rounded outwards
    to ``grid_mm``, made symmetric in x and y about the base axis, and cut at z = 0 when
    no link goes below the base. Generic over arms: it uses only :meth:`Arm.frames`.

    Examples
    --------
    The paper's arm (Table 3: L1 = 660, L2 + L3 = 510 mm) reaches 510 mm around the shoulder
    at (0, 0, 660) mm; the padded box holds that sphere:

    >>> from analysis.kinematics.arm import paper_arm
    >>> b = workspace_box(paper_arm())
    >>> b.lo[0] <= -510 and b.hi[0] >= 510 and b.lo[2] <= 150 and b.hi[2] >= 1170
    True
    """
    if not (isinstance(samples, int) and samples >= 2):
        raise ValueError(f"samples = {samples!r}: need a whole number >= 2")
    if not (0.0 <= pad <= 1.0):
        raise ValueError(f"pad = {pad!r}: must be within 0 .. 1 (a fraction of the span)")
    if not grid_mm > 0:
        raise ValueError(f"grid_mm = {grid_mm!r} mm must be > 0 mm")
    lim = np.array([lim if lim is not None else (-np.pi, np.pi) for lim in arm.limits])
    rng = np.random.default_rng(seed)
    q = lim[:, 0] + rng.random((samples, arm.n_joints)) * (lim[:, 1] - lim[:, 0])
    q = np.concatenate([q, np.zeros((1, arm.n_joints))])
    pts = arm.frames(q[arm.valid_q(q)]).reshape(-1, 3)  # a closed chain: poses that assemble
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    margin = pad * np.maximum(hi - lo, grid_mm)
    lo = np.floor((lo - margin) / grid_mm) * grid_mm
    hi = np.ceil((hi + margin) / grid_mm) * grid_mm
    r = np.maximum(-lo[:2], hi[:2]).max()  # x and y symmetric about the base axis
    lo[:2], hi[:2] = -r, r
    if pts[:, 2].min() >= 0.0:  # nothing below the base: the floor is z = 0
        lo[2] = 0.0
    return Box(tuple(float(v) + 0.0 for v in lo), tuple(float(v) + 0.0 for v in hi))


def _round(a: npt.ArrayLike) -> list:
    """Coordinates as plain lists rounded to :data:`ROUND_MM` decimals, -0.0 as 0.0."""
    return (np.round(np.asarray(a, dtype=float), ROUND_MM) + 0.0).tolist()


def _arm_traces(
    arm, q, target, box: Box, keep_arm: bool = False, links: bool = True
) -> list[go.Scatter3d]:
    """The base axis (dashed), the arm through its frame origins at ``q`` [rad] (none if
    ``q`` is None, or an empty one with ``keep_arm``), the target's cross (x, y, z [mm]), then
    the joint axes, link frames and tool frame at ``q`` (:mod:`analysis.app.arm3d_frames`;
    present, empty, with ``keep_arm`` and no ``q``; the link frames only with ``links``)."""
    traces = [
        go.Scatter3d(
            x=[0.0, 0.0],
            y=[0.0, 0.0],
            z=_round([box.lo[2], box.hi[2]]),
            mode="lines",
            line={"color": "#888888", "width": 3, "dash": "dash"},
            name="base axis",
            hoverinfo="skip",
        )
    ]
    if q is not None or keep_arm:
        pts = arm.frames(np.asarray(q, dtype=float)) if q is not None else np.zeros((0, 3))
        keep = np.r_[True, np.any(np.abs(np.diff(pts, axis=0)) > 1e-9, axis=1)][: len(pts)]
        pts = pts[keep]  # frames that coincide (a zero-length link) drawn once
        x, y, z = (_round(pts[:, k]) for k in range(3))
        traces.append(
            go.Scatter3d(
                x=x,
                y=y,
                z=z,
                mode="lines+markers",
                line={"color": "#1f77b4", "width": 9},
                marker={"size": 5, "color": "#0b3c5d"},
                name="arm",
                hovertemplate="(%{x:.1f}, %{y:.1f}, %{z:.1f}) mm<extra></extra>",
            )
        )
    if target is not None or keep_arm:
        t = np.asarray(target, dtype=float)[:3] if target is not None else np.zeros(0)
        traces.append(
            go.Scatter3d(
                x=_round(t[:1]),
                y=_round(t[1:2]),
                z=_round(t[2:3]),
                mode="markers",
                # "cross", not "x": WebGL draws the "x" symbol as an empty square
                marker={"symbol": "cross", "size": 7, "color": "#d62728"},
                name="target",
                hovertemplate="target (%{x:.1f}, %{y:.1f}, %{z:.1f}) mm<extra></extra>",
            )
        )
    if q is not None or keep_arm:
        T = frame_transforms(arm, np.asarray(q, dtype=float)) if q is not None else None
        spec = frame_spec(arm, float(box.span.max()))
        spec = spec if links else [s for s in spec if not s["name"].startswith("link")]
        traces += frame_traces(spec, T, _round)
    return traces


def _layout(arm, title: str, box: Box, height: int) -> dict:
    """The figure's layout: axes of one scale in the box's proportions, ``uirevision`` the
    arm's name (a redraw of the same arm keeps the user's camera)."""
    span = box.span
    ratio = span / span.max()
    # no filled back planes: in a browser without a GPU (headless Chromium renders WebGL in
    # software) they cost half the time of every redraw; the grid lines stay
    # five ticks an axis at most: where the x and y axes meet, their end labels ("-600" of one,
    # "600" of the other) no longer print over each other
    axis = {"showbackground": False, "gridcolor": "#c8ccd0", "nticks": 5}
    scene = {
        f"{k}axis": axis | {"title": {"text": f"{k} [mm]"}, "range": [box.lo[i], box.hi[i]]}
        for i, k in enumerate("xyz")
    }
    return {
        "template": go.layout.Template(),  # no 10 kB default template in every output
        "title": {"text": title, "font": _FONT | {"size": 15}, "x": 0.02},
        "font": _FONT,
        "height": height,
        "margin": {"l": 0, "r": 0, "t": 40 if title else 10, "b": 0},
        # the tool buttons down the right edge, clear of a long title
        "modebar": {"orientation": "v"},
        "showlegend": True,
        "legend": {"x": 0.01, "y": 0.95, "bgcolor": "rgba(255,255,255,0.7)"},
        "paper_bgcolor": "white",
        "uirevision": arm.name,
        "scene": scene
        | {
            "aspectmode": "manual",
            "aspectratio": dict(zip("xyz", _round(ratio), strict=True)),
            # a step further back than plotly's default: the axis titles stay inside the view
            "camera": {"eye": {"x": 1.45, "y": -1.55, "z": 0.8}},
            "uirevision": arm.name,
        },
    }


def arm_figure(
    arm,
    q: npt.ArrayLike | None,
    target: npt.ArrayLike | None = None,
    *,
    title: str = "",
    box: Box | None = None,
    height: int = 520,
    keep_arm: bool = False,
    link_frames: bool = True,
) -> go.Figure:
    """The arm at joint angles ``q`` [rad] as a rotatable 3D stick figure [mm].

    Links run through the chain's frame origins (:meth:`Arm.frames`: base, each link's end,
    the tool); the base axis is dashed; ``target`` (its first three values, x, y, z [mm]) is
    a red cross. ``q=None`` draws no arm (a target without a solution). Axes share one
    scale (``aspectmode="manual"`` with the box's proportions), and ``uirevision`` is the
    arm's name, so a redraw of the same arm keeps the user's camera.

    Parameters
    ----------
    arm : analysis.kinematics.arm.Arm
    q : array_like, shape (n,), or None
        Joint angles [rad].
    target : array_like, optional
        The target; its first three values are x, y, z [mm].
    title : str
    box : Box, optional
        Axis ranges [mm]; default :func:`workspace_box` of the arm.
    keep_arm : bool
        Draw the arm and target traces even when empty (the widget redraws them in place).
    link_frames : bool
        Draw the link frames too (hidden at first, shown from the legend); the joint axes
        and the tool frame are always drawn (:mod:`analysis.app.arm3d_frames`).

    Examples
    --------
    Table 4 row 1: the corrected front-up angles (45, 10.21, -155.13) deg end on the target:

    >>> from analysis.kinematics.arm import paper_arm
    >>> arm = paper_arm()
    >>> fig = arm_figure(arm, np.radians([45, 10.2087, -155.1291]), [100, 100, 600])
    >>> [round(v[-1]) for v in (fig.data[1].x, fig.data[1].y, fig.data[1].z)]
    [100, 100, 600]
    """
    box = box or workspace_box(arm)
    traces = _arm_traces(arm, q, target, box, keep_arm, link_frames)
    return go.Figure(data=traces, layout=_layout(arm, title, box, height))


def _spread(m: int, k: int) -> npt.NDArray[np.intp]:
    """At most ``k`` indices spread evenly over ``m`` samples, the first and the last kept."""
    return np.unique(np.linspace(0, m - 1, min(k, m)).round().astype(int))


def trajectory_figure(
    arm,
    t: npt.ArrayLike,
    q: npt.ArrayLike,
    *,
    title: str = "",
    box: Box | None = None,
    height: int = 560,
    frames: int = 41,
    notes: Sequence[str] | None = None,
) -> go.Figure:
    """A joint trajectory played in the 3D view: :func:`arm_figure` at the first sample, the
    tool's whole path (dashed), the arm with its joint axes and tool frame at ``frames``
    times spread evenly over the samples as plotly animation frames, a time slider (one step
    per frame, labelled in s) and play / pause buttons. Works in JupyterLab and on the static
    site (plotly.js alone).

    Parameters
    ----------
    t : array_like, shape (m,)
        Times [s], increasing.
    q : array_like, shape (m, n)
        Joint values [rad | mm] at ``t`` (e.g. seed 004's cubic, eqs. 5.3-5.4).
    notes : sequence of str, optional
        One line per sample (m,), shown under the title at each frame (a machine run's
        outputs: :func:`analysis.app.arm3d_trace.machine_run_figure`); plain text, escaped.

    >>> from analysis.kinematics.arm import load_arm
    >>> fig = trajectory_figure(load_arm("gr1"), [0.0, 1.0], np.zeros((2, 5)), frames=2)
    >>> len(fig.frames), [s.label for s in fig.layout.sliders[0].steps]
    (2, ['0.00', '1.00'])
    """
    t, q = np.asarray(t, dtype=float), np.asarray(q, dtype=float)
    if t.ndim != 1 or len(t) < 2 or not np.all(np.diff(t) > 0):
        raise ValueError(f"t: {t.shape} times; expected at least 2, increasing")
    if q.shape != (len(t), arm.n_joints):
        raise ValueError(f"q: shape {q.shape}; expected ({len(t)}, {arm.n_joints})")
    if not 2 <= frames <= 400:
        raise ValueError(f"frames={frames}: 2 .. 400 animation frames")
    if notes is not None and len(notes) != len(t):
        raise ValueError(f"notes: {len(notes)} lines; expected one per sample ({len(t)})")
    idx = _spread(len(t), frames)
    pts = arm.frames(q[idx])  # (k, n_frames, 3): every pose in one call
    # the tool's path through at most PATH_POINTS samples (a machine run has one per cycle)
    path = arm.fk(q[_spread(len(t), PATH_POINTS)])
    box = box or workspace_box(arm)
    # no link frames: 41 poses of them would triple the figure for traces hidden at first
    fig = arm_figure(arm, q[0], None, title=title, box=box, height=height, link_frames=False)
    fig.add_trace(
        go.Scatter3d(
            x=_round(path[:, 0]), y=_round(path[:, 1]), z=_round(path[:, 2]), mode="lines",
            line={"color": "#2ca02c", "width": 4, "dash": "dot"}, name="tool path",
            hoverinfo="skip",
        )
    )  # fmt: skip
    arm_at = [k for k, tr in enumerate(fig.data) if tr.name == "arm"]
    # the joint axes, link frames and tool frame move with the arm (arm3d_frames)
    drawn = [(k, tr.meta["arm3d"]) for k, tr in enumerate(fig.data) if tr.meta]
    T = frame_transforms(arm, q[idx])  # (k, frames, 4, 4)
    extra = [segments(spec, T) for _, spec in drawn]  # (k, m, 3) each

    labels = [f"{v:.2f}" for v in t[idx]]
    fig.frames = [
        go.Frame(
            data=[go.Scatter3d(**_xyz(p)), *(go.Scatter3d(**_xyz(e[i])) for e in extra)],
            traces=arm_at + [k for k, _ in drawn],
            name=label,
            layout=_note(notes[idx[i]]) if notes is not None else None,
        )
        for i, (p, label) in enumerate(zip(pts, labels, strict=True))
    ]
    if notes is not None:
        fig.update_layout(_note(notes[idx[0]]))
        fig.update_layout(legend={"y": 0.9})  # below the note
    fig.update_layout(_player(labels))
    return fig


def _xyz(p) -> dict:
    """Points (m, 3) as a trace's x, y, z lists, rounded (:func:`_round`), NaN as a gap."""
    return dict(zip("xyz", ([None if v != v else v for v in _round(p[:, c])]
                            for c in range(3)), strict=True))  # fmt: skip


def _note(text: str) -> dict:
    """The layout of a line under the title (plain text, escaped for plotly's markup)."""
    return {"annotations": [{"text": html.escape(str(text), quote=False), "x": 0.02, "y": 1.0,
                             "xref": "paper", "yref": "paper", "xanchor": "left",
                             "yanchor": "top", "showarrow": False}]}  # fmt: skip


def _player(labels: list[str]) -> dict:
    """A time slider (a step per animation frame, by its label) and play / pause buttons."""
    still = {"mode": "immediate", "frame": {"duration": 0, "redraw": True},
             "transition": {"duration": 0}}  # fmt: skip
    return dict(
        sliders=[{
            "active": 0, "currentvalue": {"prefix": "t = ", "suffix": " s"},
            "pad": {"t": 10}, "len": 0.75, "x": 0.25,
            "steps": [{"method": "animate", "label": label, "args": [[label], still]}
                      for label in labels],
        }],
        updatemenus=[{
            "type": "buttons", "direction": "left", "x": 0.0, "y": 0.0, "xanchor": "left",
            "yanchor": "top", "pad": {"t": 10},
            "buttons": [
                {"label": "▶ play", "method": "animate",
                 "args": [None, {"frame": {"duration": 60, "redraw": True},
                                 "fromcurrent": True, "transition": {"duration": 0}}]},
                {"label": "❚❚ pause", "method": "animate", "args": [[None], still]},
            ],
        }],
    )  # fmt: skip


def figure_bundle(fig: go.Figure, key: str, text: str) -> dict[str, object]:
    """The MIME bundle that shows ``fig``: for JupyterLab, the report site and plain text.

    * ``application/vnd.plotly.v1+json``: the figure, rendered by JupyterLab's plotly
      extension (installed with the ``plotly`` wheel);
    * ``text/html``: a ``div`` and ``Plotly.newPlot`` for the static report, where
      ``plotly.min.js`` is served from ``_static`` (no script is inlined or fetched); the
      ``div`` id is ``arm3d-`` + a hash of ``key`` and the figure, so a stored output is
      the same on every run;
    * ``text/plain``: ``text``, what the figure shows, for a reader without JavaScript.
    """
    spec = json.loads(fig.to_json())
    digest = hashlib.sha1((key + json.dumps(spec, sort_keys=True)).encode()).hexdigest()[:12]
    html = fig.to_html(
        include_plotlyjs=False,
        full_html=False,
        auto_play=False,  # a trajectory (trajectory_figure) waits for its play button
        div_id=f"arm3d-{digest}",
        config=CONFIG,
        default_width="100%",
        default_height=f"{fig.layout.height or 520}px",
    )
    return {
        PLOTLY_MIME: spec | {"config": CONFIG},
        "text/html": html,
        "text/plain": text,
    }


# --------------------------------------------------------------------------------------------
# the widget
# --------------------------------------------------------------------------------------------
JS_DIR = Path(__file__).with_name("js")
PLOTLY_JS = Path(go.__file__).resolve().parents[1] / "package_data" / "plotly.min.js"
"""plotly.js of the pinned plotly wheel (what the report site serves from ``_static``)."""


@cache
def _plotly_js() -> bytes:
    return PLOTLY_JS.read_bytes()


def widget_esm() -> str:
    """The widget's JavaScript module: the shared view (``js/arm3d_view.js``, also used by
    the static site) followed by the widget's glue (``js/arm3d_widget.js``)."""
    return (JS_DIR / "arm3d_view.js").read_text() + "\n" + (JS_DIR / "arm3d_widget.js").read_text()


if anywidget is not None:

    class Arm3DWidget(anywidget.AnyWidget):
        """The explorer's 3D view as a widget: it redraws on every change, in JupyterLab and
        Notebook 7 (see the module docstring).

        Traits (synced with the browser): ``figure`` (the plotly figure of
        :func:`arm_figure`, as JSON), ``kinematics`` (the arm printed as JavaScript by
        :func:`analysis.app.explore_js.arm_module_js`, or "" to draw only what the kernel
        sends), ``controls`` (the model ids of the explorer's sliders, branch picker, FK
        toggle and base-axis box, which the browser listens to) and ``pose`` (the kernel's
        pose: ``key`` the controls' values it was computed for, ``frames`` [[x, y, z] mm] or
        None, ``target``, ``title``).
        """

        _esm = traitlets.Unicode(widget_esm()).tag(sync=True)
        figure = traitlets.Dict().tag(sync=True)
        kinematics = traitlets.Unicode("").tag(sync=True)
        controls = traitlets.Dict().tag(sync=True)
        pose = traitlets.Dict().tag(sync=True)

        def __init__(self, **kwargs) -> None:
            super().__init__(**kwargs)
            self.on_msg(self._on_message)

        def _on_message(self, _widget, content, _buffers) -> None:
            # the browser asks for plotly.js once per page: sent, never stored in the state
            if isinstance(content, dict) and content.get("type") == "plotly?":
                self.send({"type": "plotly"}, buffers=[_plotly_js()])

else:  # pragma: no cover
    Arm3DWidget = None
