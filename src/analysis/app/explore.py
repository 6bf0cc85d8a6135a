"""Interactive exploration of the arms in ``data/arms`` (notebook ``09_explore``, JupyterLab).

The plain logic, tested without a kernel:

* :func:`available_arms`: the arms ``data/arms/*.toml`` describes that load (name -> title),
  and those that do not, with the reason;
* :func:`pose_report`: for one target, every IK branch of the arm (its closed form,
  :mod:`analysis.kinematics.arm`) with a status word per branch
  (:data:`~analysis.kinematics.status.STATUS_TEXT`), whole pulse counts (eqs. 20-22 for the
  paper's arm), the gripper error those whole pulses leave, the manipulability; for a bad
  target its status and the library's own message (:meth:`Arm.raise_for`);
* :func:`plain_message`: the sentence the explorer shows (plain words: no Python argument
  or command-line flag, no "-0.0");
* :meth:`PoseReport.to_html`: the table with column names and units, one line per branch.

:class:`Explorer` wires them to ``ipywidgets`` 8 controls: an arm picker (every arm of
:func:`available_arms`), one slider per input of the arm's closed form (``Arm.inputs``:
``px, py, pz`` in mm; any other input, e.g. an orientation angle, in degrees), a branch
picker (``Arm.branches``, the paper's first), an FK mode with one slider per joint, and a
check box to choose theta1 on the base axis. The 3D view is
:class:`~analysis.app.arm3d.Arm3DWidget`, the last child of the box: it listens to these
controls in the browser and redraws the arm from its kinematics printed as JavaScript
(:mod:`analysis.app.explore_js`) at every change, and draws the kernel's pose
(:meth:`Arm.frames`) when it arrives; a redraw keeps the user's rotation.
Nothing here is specific to one arm.

The plain logic lives in :mod:`analysis.app.explore_logic` and is importable from here.
"""

from __future__ import annotations

import html
import json
import math
from typing import ClassVar

import ipywidgets as W
import numpy as np
import numpy.typing as npt

from analysis.app.arm3d import Arm3DWidget, arm_figure, figure_bundle, workspace_box
from analysis.app.arm3d_frames import frame_transforms
from analysis.app.explore_js import arm_module_js
from analysis.app.explore_logic import (
    FK_CAPTION,
    IK_CAPTION,
    POSITION_INPUTS,
    PoseReport,
    available_arms,
    default_target,
    fk_line,
    num,
    plain_message,
    pose_report,
    target_from_joints,
)

# the ``X as X`` imports: the logic's other public names, importable from here as before
from analysis.app.explore_logic import MANIPULABILITY_UNIT as MANIPULABILITY_UNIT
from analysis.app.explore_logic import RPY_INPUTS as RPY_INPUTS
from analysis.app.explore_logic import greek as _greek
from analysis.kinematics.arm import Arm, as_points, load_arm

__all__ = [
    "Explorer",
    "PoseReport",
    "available_arms",
    "build_explorer",
    "default_target",
    "num",
    "plain_message",
    "pose_report",
    "target_from_joints",
]


def build_explorer(arm: Arm | str | None = None, target: npt.ArrayLike | None = None) -> Explorer:
    """The interactive explorer (see :class:`Explorer`); ``arm`` an Arm or a name (default
    the paper's grabber), ``target`` the first target (default :func:`default_target`).

    Display it as the last expression of a cell: the controls, then the 3D view.
    """
    return Explorer(arm, target)


class Explorer(W.VBox):
    """The explorer's controls and its 3D view (an ``ipywidgets.VBox``).

    Attributes: ``arm_picker`` (Dropdown), ``branch`` (ToggleButtons), ``fk_mode``
    (ToggleButton), ``on_axis`` (Checkbox "allow θ1 on the base axis") and ``on_axis_deg``
    (its theta1 slider), ``target_sliders`` (one per arm input) and ``joint_sliders`` (one
    per joint), ``message`` and ``table`` (HTML), ``view`` (the 3D view,
    :class:`~analysis.app.arm3d.Arm3DWidget`); the last :class:`PoseReport` as ``report``,
    and the pose on screen as a plotly figure, ``figure``, with its MIME bundle, ``bundle``
    (built on request).
    """

    SLIDER_LAYOUT: ClassVar[dict] = {"width": "640px"}  # 0.1 mm steps stay precise to drag
    SLIDER_STYLE: ClassVar[dict] = {"description_width": "120px"}  # "θ1 on the axis [°]"

    def __init__(self, arm: Arm | str | None = None, target: npt.ArrayLike | None = None):
        arm = load_arm(arm) if isinstance(arm, str) else (arm or load_arm("grabber"))
        self.arms, self.skipped = available_arms()
        if arm.name not in self.arms:  # an arm built from a changed description
            self.arms = {arm.name: arm.description.title} | self.arms
        self._syncing = False
        self._last_q = None  # the last pose drawn with a solution [rad | mm]
        self._pose: tuple = (None, None, "")  # q [rad] or None, target, title: the drawn pose
        self.view = Arm3DWidget(layout={"width": "100%"})
        self.arm_picker = W.Dropdown(
            options=[(f"{title} ({name})", name) for name, title in self.arms.items()],
            value=arm.name,
            description="arm",
            layout={"width": "460px"},
            style=self.SLIDER_STYLE,
        )
        self.branch = W.ToggleButtons(
            options=arm.branches, value=arm.branches[0], description="branch",
            style=self.SLIDER_STYLE,
        )  # fmt: skip
        self.fk_mode = W.ToggleButton(
            value=False, description="FK mode: set the joints", icon="sliders",
            layout={"width": "220px"},
        )  # fmt: skip
        self.on_axis = W.Checkbox(value=False, description="allow θ1 on the base axis",
                                  indent=False, layout={"width": "240px"})  # fmt: skip
        self.on_axis_deg = W.FloatSlider(
            value=0.0, min=-180.0, max=180.0, step=0.01, description="θ1 on the axis [°]",
            readout_format=".2f", continuous_update=True, layout=self.SLIDER_LAYOUT,
            style=self.SLIDER_STYLE,
        )  # fmt: skip
        self.message = W.HTML(layout={"width": "100%"})
        self.table = W.HTML()
        self.target_box, self.joint_box = W.VBox(), W.VBox()
        self.joint_box.layout.display = "none"
        super().__init__(
            [
                self.arm_picker,
                W.HBox([self.fk_mode, self.on_axis]),
                self.branch,
                self.target_box,
                self.joint_box,
                self.on_axis_deg,
                self.message,
                self.table,
                self.view,
            ]
        )
        self.arm_picker.observe(self._on_arm, names="value")
        for w in (self.branch, self.on_axis, self.on_axis_deg):
            w.observe(self._on_change, names="value")
        self.fk_mode.observe(self._on_mode, names="value")
        self._set_arm(arm, target)

    # --- building ----------------------------------------------------------------------
    def _slider(self, value: float, lo: float, hi: float, label: str, step: float, fmt: str):
        # continuous_update: the value reaches the browser's model at every move of a drag,
        # where the 3D view draws it at once from the printed kinematics (arm3d_widget.js);
        # the kernel gets the moves ipywidgets lets through (one message in flight at a
        # time) and confirms the pose it computes for the latest
        s = W.FloatSlider(
            value=float(np.clip(value, lo, hi)), min=lo, max=hi, step=step,
            description=label, readout_format=fmt, continuous_update=True,
            layout=self.SLIDER_LAYOUT, style=self.SLIDER_STYLE,
        )  # fmt: skip
        s.observe(self._on_change, names="value")
        return s

    def _set_arm(self, arm: Arm, target: npt.ArrayLike | None) -> None:
        """Sliders for ``arm``'s inputs and joints, its branches, and the first target."""
        self.arm = arm
        self._last_q = None
        self.box = workspace_box(arm)
        p = default_target(arm) if target is None else as_points(target, inputs=arm.inputs)
        sliders = []
        for k, name in enumerate(arm.inputs):
            if name in POSITION_INPUTS:
                i = "xyz".index(POSITION_INPUTS[name])
                lo, hi = self.box.lo[i], self.box.hi[i]
                label = f"{POSITION_INPUTS[name]} [mm]"
                sliders.append(self._slider(p[k], lo, hi, label, 0.1, ".1f"))
            else:
                label = f"{_greek(name)} [°]"
                sliders.append(self._slider(math.degrees(p[k]), -180, 180, label, 0.01, ".2f"))
        joints = []
        lows, highs = arm.joints_to_user(arm.bounds[:, 0]), arm.joints_to_user(arm.bounds[:, 1])
        for spec, lo, hi, u in zip(
            arm.description.joints, lows, highs, arm.joint_user_units, strict=True
        ):
            label = f"{_greek(spec.name)} [{'°' if u == 'deg' else u}]"
            joints.append(self._slider(0.0, float(lo), float(hi), label, 0.01, ".2f"))
        self._syncing = True
        try:
            self.target_sliders, self.joint_sliders = sliders, joints
            self.target_box.children, self.joint_box.children = sliders, joints
            self.branch.options = arm.branches
            self.branch.value = arm.branches[0]
            if self.fk_mode.value:
                self._joints_from_report(pose_report(arm, self._target()))
        finally:
            self._syncing = False
        try:
            kinematics = arm_module_js(arm)
        except (ValueError, TypeError, AttributeError):  # no D-H chain: the kernel draws
            kinematics = ""
        with self.view.hold_sync():
            title = arm.description.title
            first = arm_figure(arm, None, None, box=self.box, keep_arm=True, title=title)
            self.view.figure = json.loads(first.to_json())  # a title: its margin is kept
            self.view.kinematics = kinematics
            self.view.controls = {
                "inputs": [f"IPY_MODEL_{s.model_id}" for s in sliders],
                "units": list(arm.input_units),
                "joints": [f"IPY_MODEL_{s.model_id}" for s in joints],
                **{
                    k: f"IPY_MODEL_{w.model_id}"
                    for k, w in (
                        ("branch", self.branch),
                        ("fk", self.fk_mode),
                        ("on_axis", self.on_axis),
                        ("on_axis_deg", self.on_axis_deg),
                    )
                },
            }
        self.refresh()

    # --- events --------------------------------------------------------------------------
    def _on_arm(self, change) -> None:
        self._set_arm(load_arm(change["new"]), None)

    def _on_change(self, _change=None) -> None:
        if not self._syncing:
            self.refresh()

    def _target(self) -> npt.NDArray[np.float64]:
        vals = []
        for s, name in zip(self.target_sliders, self.arm.inputs, strict=True):
            vals.append(s.value if name in POSITION_INPUTS else math.radians(s.value))
        return np.array(vals)

    def _joints_from_report(self, rep: PoseReport) -> None:
        """The joint sliders at the report's chosen branch, or, for a target without a
        solution there, at the last pose drawn (the one shown greyed): the arm stays put."""
        if rep.branch_ok:
            q = rep.angles_deg()
        elif self._last_q is not None:
            q = self.arm.joints_to_user(self._last_q)
        else:
            q = np.zeros(len(self.joint_sliders))
        for s, v in zip(self.joint_sliders, q, strict=True):
            s.value = float(np.clip(round(float(v), 2), s.min, s.max))

    def _on_mode(self, change) -> None:
        """Switch modes keeping the arm where it is (as far as the slider steps allow)."""
        self._syncing = True
        try:
            if change["new"]:
                self._joints_from_report(self.report or pose_report(self.arm, self._target()))
            elif self.report is not None:
                for s, v, name in zip(
                    self.target_sliders, self.report.target, self.arm.inputs, strict=True
                ):
                    v = v if name in POSITION_INPUTS else math.degrees(v)
                    s.value = float(np.clip(v, s.min, s.max))  # exactly where FK put it
        finally:
            self._syncing = False
        self.target_box.layout.display = "none" if change["new"] else None
        self.joint_box.layout.display = None if change["new"] else "none"
        self.refresh()

    # --- the view ------------------------------------------------------------------------
    def pose_key(self) -> list:
        """The controls' values a pose is drawn for: FK mode, branch, every target and joint
        slider, the base-axis box and its angle (the order ``js/arm3d_widget.js`` reads)."""
        return [
            self.fk_mode.value,
            self.branch.value,
            *(s.value for s in self.target_sliders),
            *(s.value for s in self.joint_sliders),
            self.on_axis.value,
            self.on_axis_deg.value,
        ]

    def _draw(self, q, target, title: str) -> None:
        """Send the pose to the 3D view: the frame origins at ``q`` [rad] and the frames'
        transforms (joint axes, link and tool frames: :mod:`analysis.app.arm3d_frames`); None:
        no solution, the view keeps the last pose, greyed."""
        self._pose = (q, target, title)
        if q is not None:
            self._last_q = np.asarray(q, dtype=float)
        frames = None if q is None else self.arm.frames(q)
        t = None if target is None else np.asarray(target, dtype=float)[:3]
        T = None if q is None else frame_transforms(self.arm, q)[:, :3, :]  # axes, frames
        self.view.pose = {
            "key": self.pose_key(),
            "frames": None if frames is None else np.round(frames, 6).tolist(),
            "transforms": None if T is None else (np.round(T, 6) + 0.0).tolist(),
            "target": None if t is None else np.round(t, 6).tolist(),
            "title": title,
        }

    @property
    def figure(self):
        """The pose on screen as a plotly figure (:func:`~analysis.app.arm3d.arm_figure`)."""
        q, target, title = self._pose
        return arm_figure(self.arm, q, target, title=title, box=self.box)

    @property
    def bundle(self) -> dict:
        """:attr:`figure` as a MIME bundle (:func:`~analysis.app.arm3d.figure_bundle`)."""
        title = self._pose[2]
        return figure_bundle(self.figure, f"explorer-{self.arm.name}", f"3D view: {title}")

    def _title(self, q) -> str:
        title = f"{self.arm.description.title} · " + (
            "FK" if self.fk_mode.value else self.branch.value
        )
        if q is None:
            return title + " · no solution"
        arm = self.arm
        if set(arm.joint_user_units) == {"deg"}:
            return title + " · θ = (" + ", ".join(num(v, 2) for v in np.degrees(q)) + ")°"
        return title + " · q = (" + ", ".join(
            f"{num(v, 2)} {'°' if u == 'deg' else u}"
            for v, u in zip(arm.joints_to_user(q), arm.joint_user_units, strict=True)
        ) + ")"  # fmt: skip

    def refresh(self) -> None:
        """Recompute from the controls: the 3D view's pose first (what the eye follows),
        then the report, message and table (the table keeps its place for a target without
        a solution: no layout shift)."""
        arm = self.arm
        axis = self.on_axis.value and not self.fk_mode.value
        self.on_axis_deg.layout.display = None if axis else "none"
        t1 = math.radians(self.on_axis_deg.value) if axis else None
        if self.fk_mode.value:
            q = self.arm.joints_from_user([s.value for s in self.joint_sliders])
            self._draw(q, arm.fk(q), self._title(q))
            target = target_from_joints(arm, q)
            rep = None
            if target is not None:
                rep = pose_report(arm, target, self.branch.value, theta1_on_axis=float(q[0]))
            text, bad, caption = fk_line(arm, q, rep), False, FK_CAPTION
        else:
            target = self._target()
            sol = arm.solve(target, (self.branch.value,), theta1_on_axis=t1)
            q = sol.theta[0] if sol.ok[0] else None
            self._draw(q, target, self._title(q))
            rep = pose_report(arm, target, self.branch.value, theta1_on_axis=t1)
            text, bad, caption = plain_message(rep, t1), not rep.branch_ok, IK_CAPTION
        self.report = rep
        colour = "#b00020" if bad else "#1b5e20"
        self.message.value = (
            f'<div class="explorer-message" style="color:{colour};white-space:normal;'
            f'min-height:4.5em">{html.escape(text)}</div>'
        )
        self.table.value = rep.to_html(caption) if rep is not None else ""

    def _repr_mimebundle_(self, **kwargs):
        """The widget, with a plain-text line for readers without a kernel (the stored
        notebook, nbval, the report site)."""
        data = super()._repr_mimebundle_(**kwargs)
        data = dict(data[0] if isinstance(data, tuple) else data)
        data["text/plain"] = (
            f"Explorer of the {self.arm.description.title} ({self.arm.name}): sliders, branch "
            "picker, FK mode and a 3D view that need a running kernel (make lab)."
        )
        return data
