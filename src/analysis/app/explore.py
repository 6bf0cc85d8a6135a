"""Interactive exploration of the paper's arm (notebook ``09_explore``, JupyterLab).

:func:`pose_report` is the plain, tested logic: for one target it gives all four IK
branches (corrected eqs. 6-19, :mod:`analysis.kinematics.arm`), their whole pulse counts (eqs.
20-22),
the gripper error those whole pulses leave, the manipulability, and for a bad target the
library's own :class:`~analysis.kinematics.arm.UnreachableError` /
:class:`~analysis.kinematics.arm.BaseAxisError`
message. :func:`build_explorer` wires it to ``ipywidgets`` 8 controls; the figure is
rendered to PNG off-screen (no pyplot state) and put into an ``Output`` widget, so the
explorer also works, and is tested, without a kernel.
"""

from __future__ import annotations

import base64
import html
import io
from dataclasses import dataclass

import ipywidgets as W
import numpy as np
import numpy.typing as npt
import pandas as pd

from analysis.kinematics.arm import (
    BRANCHES,
    DEFAULT_TOL_MM,
    Arm,
    BaseAxisError,
    UnreachableError,
    as_points,
)
from analysis.kinematics.pulses import angles_to_pulses, pulses_to_angles
from analysis.studies.workspace import manipulability

__all__ = ["Explorer", "PoseReport", "build_explorer", "pose_report"]

_COLUMNS = ["theta1_deg", "theta2_deg", "theta3_deg", "c1", "c2", "c3", "error_mm", "w_mm3"]


@dataclass(frozen=True)
class PoseReport:
    """Everything the explorer shows for one target.

    Attributes
    ----------
    target : tuple of 3 float
        (Px, Py, Pz) [mm].
    branch : str
        The chosen branch (one of :data:`~analysis.kinematics.arm.BRANCHES`).
    reachable : bool
        True if the target has IK solutions (base-axis targets only with ``theta1_on_axis``).
    outside_mm : float
        Signed distance outside the reachable shell [mm]: > 0 unreachable by that much,
        <= 0 reachable (its magnitude is the margin to the nearer shell boundary).
    message : str
        One-line summary; for a bad target the library exception's message.
    error : str or None
        ``"UnreachableError"`` / ``"BaseAxisError"`` for a bad target, else None.
    table : pandas.DataFrame
        Index = branch names (all four, in :data:`BRANCHES` order), columns ``theta1_deg,
        theta2_deg, theta3_deg`` (wrapped to (-180, 180]), ``c1, c2, c3`` (whole pulses,
        eqs. 20-22), ``error_mm`` (distance of FK(whole-pulse angles) from the target) and
        ``w_mm3`` (manipulability |det J| [mm^3/rad^3]). Empty (no NaN) for a bad target.
    """

    target: tuple[float, float, float]
    branch: str
    reachable: bool
    outside_mm: float
    message: str
    error: str | None
    table: pd.DataFrame

    def row(self) -> pd.Series:
        """The chosen branch's row of :attr:`table` (KeyError for a bad target)."""
        return self.table.loc[self.branch]

    def to_html(self) -> str:
        """The table as HTML with the chosen branch marked, or "" for a bad target."""
        if self.table.empty:
            return ""
        t = self.table.copy()
        t.index = [f"&#9654; {b}" if b == self.branch else b for b in t.index]
        fmt = {c: "{:.2f}".format for c in _COLUMNS[:3]} | {"error_mm": "{:.3f}".format}
        return t.to_html(formatters=fmt | {"w_mm3": "{:.4g}".format}, escape=False, border=0)


def pose_report(
    arm: Arm,
    target: npt.ArrayLike,
    branch: str = "front-up",
    *,
    theta1_on_axis: float | None = None,
    tol: float = DEFAULT_TOL_MM,
) -> PoseReport:
    """All four IK branches of one target with pulses, pulse error and manipulability.

    Parameters
    ----------
    arm : Arm
    target : array_like, shape (3,)
        (Px, Py, Pz) [mm].
    branch : str
        The branch to highlight; default the paper's front-up (eq. 6, Table 4).
    theta1_on_axis : float, optional
        Waist angle [rad] for a target on the base axis (else such a target is reported
        with the library's :class:`BaseAxisError` message).
    tol : float
        Distance tolerance [mm] passed to :meth:`Arm.solve` / :meth:`Arm.check_target`.

    Returns
    -------
    PoseReport

    Examples
    --------
    Table 4 row 1, (100, 100, 600) mm: front-up (45.00, 10.21, -155.13) deg, pulses
    (500, 113, -1724); row 8 (200, 500, 600) is 31.849 mm beyond the reach:

    >>> from analysis.kinematics.arm import paper_arm
    >>> pose_report(paper_arm(), [100, 100, 600]).table[["c1", "c2", "c3"]].loc["front-up"].tolist()
    [500, 113, -1724]
    >>> round(pose_report(paper_arm(), [200, 500, 600]).outside_mm, 3)
    31.849
    """
    if branch not in BRANCHES:
        raise ValueError(f"unknown branch {branch!r}; expected one of {', '.join(BRANCHES)}")
    p = as_points(target)
    if p.shape != (3,):
        raise ValueError(f"pose_report takes one target of shape (3,), got {p.shape}")
    sol = arm.solve(p, BRANCHES, theta1_on_axis=theta1_on_axis, tol=tol)
    outside = float(sol.outside_mm)
    key = tuple(float(v) for v in p)
    try:
        arm.check_target(p, tol=tol, allow_axis=theta1_on_axis is not None)
    except (UnreachableError, BaseAxisError) as exc:
        empty = pd.DataFrame(columns=_COLUMNS, index=pd.Index([], name="branch"))
        return PoseReport(key, branch, False, outside, str(exc), type(exc).__name__, empty)
    if not sol.ok.all():  # check_target and solve share one decision; this cannot happen
        raise AssertionError(f"solve() and check_target() disagree on target {key}")
    ppr = np.asarray(arm.params.pulses_per_rev, dtype=float)
    q = sol.theta  # (4, 3) rad
    c = angles_to_pulses(q, ppr)
    err = np.linalg.norm(arm.fk(pulses_to_angles(c, ppr)) - p, axis=-1)
    deg = np.degrees(q)
    table = pd.DataFrame(
        {
            **{f"theta{j + 1}_deg": deg[:, j] for j in range(3)},
            **{f"c{j + 1}": c[:, j] for j in range(3)},
            "error_mm": err,
            "w_mm3": manipulability(arm, q),
        },
        index=pd.Index(BRANCHES, name="branch"),
    )
    r = table.loc[branch]
    angles = ", ".join(f"{r[k]:.2f}" for k in _COLUMNS[:3])
    pulses = ", ".join(str(int(r[k])) for k in ("c1", "c2", "c3"))
    msg = (
        f"{branch}: theta = ({angles}) deg -> pulses ({pulses}); whole pulses put the "
        f"gripper {r['error_mm']:.3f} mm off the target; margin to the reach "
        f"boundary {max(-outside, 0.0):.1f} mm"
    )
    return PoseReport(key, branch, True, outside, msg, None, table)


def _arm_png(arm: Arm, q: npt.ArrayLike, target: npt.ArrayLike | None, title: str = "") -> bytes:
    """PNG of :func:`analysis.app.plotting.plot_arm`, drawn on a pyplot-free Figure (Agg)."""
    from matplotlib.figure import Figure

    from analysis.app.plotting import plot_arm, style

    with style():
        fig = Figure(figsize=(5.0, 4.6))
        plot_arm(arm, q, ax=fig.add_subplot(projection="3d"), target=target).set_title(title)
        buf = io.BytesIO()
        fig.savefig(buf, format="png", metadata={"Software": None})
    return buf.getvalue()


def _html_message(text: str, bad: bool) -> str:
    colour = "#b00020" if bad else "#1b5e20"
    return f'<div style="color:{colour}"><b>{html.escape(text)}</b></div>'


def build_explorer(arm: Arm, target: npt.ArrayLike = (100.0, 100.0, 600.0)) -> Explorer:
    """The interactive explorer: an ``ipywidgets.VBox`` (see :class:`Explorer`).

    IK mode: sliders x, y, z [mm] spanning the reachable shell's bounding box, a branch
    picker (front-up, the paper's, by default). "FK mode": three joint sliders [deg]
    instead; the gripper point is FK of them and the table lists the IK branches of that
    point (base-axis points use the slider's theta1). Bad targets show the library's
    exception message and no numbers. Starts at Table 4 row 1, (100, 100, 600) mm.
    """
    return Explorer(arm, target)


class Explorer(W.VBox):
    """VBox with the controls as attributes: ``x, y, z, branch, fk_mode, t1, t2, t3``
    (sliders / pickers), ``message`` and ``table`` (HTML), ``plot`` (Output), and the
    last :class:`PoseReport` as ``report``."""

    def __init__(self, arm: Arm, target: npt.ArrayLike):
        p = as_points(target)
        P, R = arm.params, arm.params.reach_outer
        self.arm, self._syncing = arm, False
        opts = {"step": 1.0, "continuous_update": False, "readout_format": ".0f"}
        self.x = W.FloatSlider(value=p[0], min=-R, max=R, description="x [mm]", **opts)
        self.y = W.FloatSlider(value=p[1], min=-R, max=R, description="y [mm]", **opts)
        zmin = max(0.0, P.L1 - R)
        self.z = W.FloatSlider(value=p[2], min=zmin, max=P.L1 + R, description="z [mm]", **opts)
        self.branch = W.ToggleButtons(options=BRANCHES, value="front-up", description="branch")
        self.fk_mode = W.ToggleButton(value=False, description="FK mode", icon="sliders")
        jopts = opts | {"step": 0.01, "min": -180.0, "max": 180.0, "readout_format": ".2f"}
        self.t1, self.t2, self.t3 = (
            W.FloatSlider(value=0.0, description=f"theta{j} [deg]", **jopts) for j in (1, 2, 3)
        )
        self.message, self.table, self.plot = W.HTML(), W.HTML(), W.Output()
        self.xyz_box = W.VBox([self.x, self.y, self.z])
        self.joint_box = W.VBox([self.t1, self.t2, self.t3])
        self.joint_box.layout.display = "none"
        super().__init__(
            [
                W.HBox([self.branch, self.fk_mode]),
                self.xyz_box,
                self.joint_box,
                self.message,
                W.HBox([self.plot, self.table]),
            ]
        )
        for w in (self.x, self.y, self.z, self.branch, self.t1, self.t2, self.t3):
            w.observe(self._on_change, names="value")
        self.fk_mode.observe(self._on_mode, names="value")
        self.refresh()

    def _on_change(self, _change=None) -> None:
        if not self._syncing:
            self.refresh()

    def _on_mode(self, change) -> None:
        """Switch modes keeping the arm where it is (as far as the slider steps allow)."""
        self._syncing = True
        try:
            if change["new"]:
                rep = self.report
                q = rep.row()[_COLUMNS[:3]].to_numpy(float) if rep.reachable else (0, 0, 0)
                self.t1.value, self.t2.value, self.t3.value = (round(float(v), 2) for v in q)
            else:
                p = self.arm.fk(np.radians([self.t1.value, self.t2.value, self.t3.value]))
                for s, v in zip((self.x, self.y, self.z), p, strict=True):
                    s.value = float(np.clip(round(float(v)), s.min, s.max))
        finally:
            self._syncing = False
        self.xyz_box.layout.display = "none" if change["new"] else None
        self.joint_box.layout.display = None if change["new"] else "none"
        self.refresh()

    def refresh(self) -> None:
        """Recompute the report from the controls and redraw message, table and plot."""
        if self.fk_mode.value:
            q = np.radians([self.t1.value, self.t2.value, self.t3.value])
            p = self.arm.fk(q)
            rep = pose_report(self.arm, p, self.branch.value, theta1_on_axis=float(q[0]))
            head = "FK: gripper at (" + ", ".join(f"{v:.2f}" for v in p) + ") mm. "
        else:
            p = np.array([self.x.value, self.y.value, self.z.value])
            rep = pose_report(self.arm, p, self.branch.value)
            q = np.radians(rep.row()[_COLUMNS[:3]].to_numpy(float)) if rep.reachable else None
            head = ""
        self.report = rep
        hint = " (switch on FK mode to choose theta1)" if rep.error == "BaseAxisError" else ""
        self.message.value = _html_message(head + rep.message + hint, not rep.reachable)
        self.table.value = rep.to_html()
        if q is None:  # no solution: draw nothing rather than a made-up pose
            self.plot.outputs = ()
            return
        title = ("FK, " if self.fk_mode.value else "") + self.branch.value
        png = base64.b64encode(_arm_png(self.arm, q, p, title)).decode("ascii")
        data = {"image/png": png, "text/plain": "<3D view of the arm>"}
        self.plot.outputs = ({"output_type": "display_data", "data": data, "metadata": {}},)
