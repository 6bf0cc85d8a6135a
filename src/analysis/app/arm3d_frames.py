"""Joint axes, link frames and the tool frame of an arm, as data and as plotly traces (issue
31 item 3: "front and back branches that differ by 2,000 waist pulses draw identical
pictures and a 5-DOF orientation cannot be checked by eye" in a stick figure).

One description, two evaluators. The frames are the arm's own forward kinematics, the one
``fk`` and ``fk --json`` run: :func:`frame_transforms` evaluates the D-H chain's transforms
``T_0_i`` (:func:`analysis.kinematics.dh.chain_transforms`, what
:func:`analysis.kinematics.forward.chain_points` composes; the tool frame is the last one),
or for a closed chain the tool's pose alone (:meth:`Arm.pose`: the picker's points are not
D-H frames). What is drawn from them is said once per trace, in the trace's ``meta``
(:func:`frame_spec`): which frames, as joint axes or as x, y, z triads, and how long. Python
draws it with :func:`segments` (the notebook figures of :mod:`analysis.app.arm3d`) and the
browser with ``segments`` of ``js/arm3d_view.js`` (the explorer's redraw in place, from the
transforms that the printed kinematics, :func:`analysis.app.explore_js.frames_graph`, or the
kernel's pose give); the browser tests hold the drawn tool frame to ``fk --json``.

What is drawn
-------------
* **joint axes**: each joint's axis as a short line through its joint, along the z axis
  that the D-H convention turns or slides it about (standard D-H, ``A_i = Rz(theta_i)
  Tz(d_i) ...``: joint i acts along ``z_{i-1}`` through the origin of frame i-1; modified D-H,
  ``A_i = Rx Tx Rz(theta_i) Tz(d_i)``: along ``z_i`` through the origin of frame i), an
  arrowhead of two short lines on its positive end; revolute axes solid orange, prismatic ones
  dashed purple. Lines only: a plotly marker is a glyph mesh that took 17 ms of every redraw
  of the explorer in software WebGL (headless Chromium, load 12: 49 against 31 ms from a
  change to the pose on screen), lines about 1 ms;
* **link frames**: the x, y, z axes (red, green, blue) of the base frame and of every frame
  but the last, short; in the legend, shown by a click (hidden at first: with the joint
  axes and the tool frame they crowd a small view, and a frame's x axis runs along the next
  link of a folded arm);
* **tool frame**: the last frame's x, y, z axes (red, green, blue), longer and thicker,
  always drawn: two branches that put the tool on the same point (the grabber's front and
  back, half a waist turn apart) show different triads.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from analysis.kinematics.dh import chain_transforms
from analysis.kinematics.ops import numpy_ops
from analysis.kinematics.solution import check_joints

__all__ = [
    "AXIS_COLOURS",
    "XYZ_COLOURS",
    "frame_spec",
    "frame_traces",
    "frame_transforms",
    "segments",
]

XYZ_COLOURS = ("#e8201a", "#1c9e2c", "#1a3cff")
"""The colours of a frame's x, y and z axes (red, green, blue; the blue far enough from the
arm's #1f77b4 that the browser tests tell them apart)."""
AXIS_COLOURS = {"revolute": "#ff7f0e", "prismatic": "#9b4dca"}
"""Joint axes: revolute orange, prismatic purple (dashed)."""
HEAD = (0.16, 0.07)
"""A joint axis' arrowhead: each barb goes back ``HEAD[0]`` and aside ``HEAD[1]`` of the
axis' length from its tip."""
LENGTHS = {"axis": 0.18, "link": 0.07, "tool": 0.13}
"""Lengths drawn, as fractions of the workspace box's largest span: a joint axis, a link
frame's axes, the tool frame's axes."""
_LEGEND = " ".join(
    f'<span style="color:{c}">{a}</span>' for a, c in zip("xyz", XYZ_COLOURS, strict=True)
)
"""The legend's key of a triad: the letters x, y, z in their colours (plotly's text markup)."""


def frame_transforms(arm, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """The frames drawn at joint values ``q`` (..., n) [rad | mm], shape (..., k, 4, 4), in
    the base frame [mm]: for a D-H chain the base frame (identity) and ``T_0_i`` of every row
    (:func:`~analysis.kinematics.dh.chain_transforms`, the forward kinematics that ``fk``
    runs, so the last one is ``fk --json``'s rotation and position bit for bit); for a closed
    chain the tool's pose alone (:meth:`Arm.pose`).

    >>> from analysis.kinematics.arm import paper_arm
    >>> T = frame_transforms(paper_arm(), np.radians([45.0, 10.2087, -155.1291]))
    >>> T.shape, T[-1, :3, 3].round(2).tolist()
    ((4, 4, 4), [100.0, 100.0, 600.0])
    """
    q = check_joints(q, arm.n_joints, units=arm.joint_units)
    shape = q.shape[:-1]
    if not arm.description.has_rows:
        p = arm.pose(q)
        out = np.zeros((*shape, 1, 4, 4))
        out[..., 0, :3, :3], out[..., 0, :3, 3], out[..., 0, 3, 3] = p.rotation, p.position, 1.0
        return out
    blocks = chain_transforms(numpy_ops, arm.table, list(np.moveaxis(q, -1, 0)))
    out = np.zeros((*shape, len(blocks) + 1, 4, 4))
    out[..., :, 3, 3] = 1.0
    out[..., 0, :3, :3] = np.eye(3)
    for i, T in enumerate(blocks, start=1):  # a loop over the chain's rows, not over points
        for r in range(3):
            for c in range(4):
                out[..., i, r, c] = T[r][c]
    return out


def frame_spec(arm, span_mm: float) -> list[dict]:
    """What is drawn, one dict per trace: ``name``, ``kind`` ("axes" or "triads"),
    ``frames`` (indices into :func:`frame_transforms`), ``length`` [mm] (from ``span_mm``,
    the workspace box's largest span) and its style. Joint axes by the D-H convention (module
    docstring); a closed chain has the tool frame only."""
    if not span_mm > 0:
        raise ValueError(f"span_mm = {span_mm!r}: must be > 0 mm")
    tool = {"name": f"tool frame {_LEGEND}", "kind": "triads", "width": 8,
            "length": LENGTHS["tool"] * span_mm}  # fmt: skip
    if not arm.description.has_rows:
        return [tool | {"frames": [0]}]
    table = arm.table
    shift = 0 if table.convention == "standard" else 1  # the frame whose z is joint i's axis
    spec = []
    for kind in ("revolute", "prismatic"):
        frames = [i + shift for i, row in enumerate(table.rows) if row.kind == kind]
        if frames:
            spec.append({"name": f"joint axes ({kind})", "kind": "axes", "joint": kind,
                         "frames": frames, "length": LENGTHS["axis"] * span_mm, "head": list(HEAD),
                         "width": 6})  # fmt: skip
    n = len(table.rows)
    spec.append({"name": f"link frames {_LEGEND}", "kind": "triads", "frames": list(range(n)),
                 "length": LENGTHS["link"] * span_mm, "width": 4,
                 "visible": "legendonly"})  # fmt: skip
    spec.append(tool | {"frames": [n]})
    return spec


def segments(spec: dict, T: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """The points of one trace of :func:`frame_spec` for frames ``T`` (..., k, 4, 4), shape
    (..., m, 3), NaN rows between segments (a gap in the line): per joint axis ``o - L/2 z``,
    the tip ``o + L/2 z`` and the arrowhead's barbs ``tip - HEAD[0] L z +- HEAD[1] L x`` (its
    frame's x and z), as ``start, tip, barb+, gap, tip, barb-, gap``; per triad ``o, o + L x,
    gap, o, o + L y, gap, o, o + L z, gap``. ``js/arm3d_view.js``'s ``segments`` computes the
    same."""
    T = np.asarray(T, dtype=float)[..., spec["frames"], :, :]  # (..., f, 4, 4)
    o, L = T[..., :3, 3], float(spec["length"])
    gap = np.full(o.shape, np.nan)
    if spec["kind"] == "axes":
        x, z = T[..., :3, 0], T[..., :3, 2]
        tip, back, side = o + 0.5 * L * z, HEAD[0] * L * z, HEAD[1] * L * x
        pts = np.stack(
            [o - 0.5 * L * z, tip, tip - back + side, gap, tip, tip - back - side, gap], axis=-2
        )  # (..., f, 7, 3) fmt: skip
    else:
        ends = [o + L * T[..., :3, k] for k in range(3)]
        pts = np.stack([p for e in ends for p in (o, e, gap)], axis=-2)  # (..., f, 9, 3)
    return pts.reshape(*pts.shape[:-3], -1, 3)


def _colours(spec: dict) -> str | list[str]:
    """The line colour of a trace: a joint axis one colour; a triad red, green, blue by axis,
    per point (the gap points included)."""
    if spec["kind"] == "axes":
        return AXIS_COLOURS[spec["joint"]]
    return [c for c in XYZ_COLOURS for _ in range(3)] * len(spec["frames"])


def frame_traces(spec: list[dict], T: npt.ArrayLike | None, rounding) -> list:
    """The plotly traces of ``spec`` for the frames ``T`` (k, 4, 4) of one pose (None: empty
    traces, for a view that draws them in place later); ``rounding`` the figure's rounding
    of coordinates (lists, NaN kept as a gap). Each trace carries its spec as ``meta``."""
    import plotly.graph_objects as go

    out = []
    for s in spec:
        pts = segments(s, T) if T is not None else np.zeros((0, 3))
        style = _colours(s)
        xyz = [[None if v != v else v for v in rounding(pts[:, k])] for k in range(3)]
        out.append(
            go.Scatter3d(
                x=xyz[0], y=xyz[1], z=xyz[2], name=s["name"], meta={"arm3d": s},
                mode="lines",
                line={"color": style, "width": s["width"],
                      "dash": "dash" if s.get("joint") == "prismatic" else "solid"},
                connectgaps=False, hoverinfo="skip", visible=s.get("visible", True),
            )
        )  # fmt: skip
    return out
