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
check box to choose theta1 on the base axis. The 3D view is a plotly figure
(:mod:`analysis.app.arm3d`, which says why plotly) displayed under the controls with a
display id and updated in place, so it keeps the user's rotation while the sliders move.
Nothing here is specific to one arm.
"""

from __future__ import annotations

import html
import math
from dataclasses import dataclass
from typing import ClassVar

import ipywidgets as W
import numpy as np
import numpy.typing as npt
import pandas as pd

from analysis.app.arm3d import arm_figure, figure_bundle, workspace_box
from analysis.kinematics.arm import DEFAULT_TOL_MM, Arm, as_points, load_arm
from analysis.kinematics.pulses import angles_to_pulses, pulses_to_angles
from analysis.kinematics.status import STATUS_TEXT, Status
from analysis.paths import data_dir

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

POSITION_INPUTS = {"px": "x", "py": "y", "pz": "z"}
"""Closed-form inputs that are coordinates of the target point [mm]; every other input of an
arm (e.g. an orientation angle of a pose) is an angle [rad], shown in degrees."""
MANIPULABILITY_UNIT = 1e6
"""The table shows the manipulability in 10^6 mm^3/rad^3 (the paper's arm: ~3.7 at Table 4
row 1, at most ~9.5 where the elbow is square)."""


def num(value: float, decimals: int = 2) -> str:
    """``value`` with ``decimals`` decimals, never "-0.00" (a negative zero prints as 0).

    >>> num(-0.0001, 1), num(-0.05, 1), num(2.345, 2)
    ('0.0', '-0.1', '2.35')
    """
    text = f"{value:.{decimals}f}"
    return text[1:] if text.startswith("-") and float(text) == 0.0 else text


def _greek(name: str) -> str:
    """``theta1`` -> ``θ1`` (joint names of the descriptions, for labels)."""
    for word, letter in (("theta", "θ"), ("alpha", "α"), ("beta", "β"), ("gamma", "γ")):
        if name.startswith(word):
            return letter + name[len(word) :]
    return name


def available_arms() -> tuple[dict[str, str], dict[str, str]]:
    """The arms described in ``data/arms/*.toml``: ``({name: title}, {name: why not})``.

    The first dict holds every arm that :func:`~analysis.kinematics.arm.load_arm` builds
    (description and closed form), in file-name order; the second the files that do not
    load, with the error (e.g. a description that is not a D-H chain yet).
    """
    ok, skipped = {}, {}
    for path in sorted((data_dir() / "arms").glob("*.toml")):
        try:
            ok[path.stem] = load_arm(path.stem).description.title
        except ValueError as exc:
            skipped[path.stem] = str(exc)
    return ok, skipped


def _position(arm: Arm, p: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]:
    """The target point [mm] within an input vector (the inputs named px, py, pz)."""
    idx = [arm.inputs.index(k) for k in POSITION_INPUTS if k in arm.inputs]
    if len(idx) != 3:
        raise ValueError(
            f"arm {arm.name}: inputs {arm.inputs} do not name the target point (px, py, pz)"
        )
    return p[..., idx]


RPY_INPUTS = ("alpha", "beta", "gamma")
"""Closed-form inputs that are the tool's orientation as RPY angles [rad], in the convention
of :mod:`analysis.kinematics.rpy` (a pose: the GR-1 arm's inputs)."""


def target_from_joints(arm: Arm, q: npt.ArrayLike) -> npt.NDArray[np.float64] | None:
    """The closed form's inputs that joint angles ``q`` (..., n) [rad] reach, (..., k).

    The point (inputs ``px, py, pz``) is :meth:`Arm.fk`; RPY inputs (``alpha, beta, gamma``)
    come from the D-H chain's tool rotation (:func:`analysis.kinematics.rpy.pose_from_transform`).
    None if the arm has an input of another kind (its FK cannot be put as a target).
    """
    from analysis.kinematics.rpy import pose_from_transform

    known = set(POSITION_INPUTS) | set(RPY_INPUTS)
    if not set(arm.inputs) <= known:
        return None
    q = np.asarray(q, dtype=float)
    values = dict(zip(("px", "py", "pz"), np.moveaxis(arm.fk(q), -1, 0), strict=True))
    if set(RPY_INPUTS) & set(arm.inputs):
        pose = pose_from_transform(arm.table.fk(q))
        values |= dict(zip(RPY_INPUTS, np.moveaxis(pose[..., 3:], -1, 0), strict=True))
    return np.stack([values[k] for k in arm.inputs], axis=-1)


def default_target(arm: Arm, *, seed: int = 0) -> npt.NDArray[np.float64]:
    """A target the arm reaches on its first branch, to start the explorer at.

    What :func:`target_from_joints` gives for the first joint vector that solves with
    status "ok" on the default branch, trying the middle of each joint's range with the
    inner joints bent by +-30, +-60 deg, then 256 seeded draws within the joint limits;
    coordinates cleaned of round-off below 1 nm.
    """
    lim = np.array([lim if lim is not None else (-np.pi, np.pi) for lim in arm.limits])
    mid = lim.mean(axis=1)
    bends = np.zeros((4, arm.n_joints))
    k = min(arm.n_joints, 3)
    bends[:, :k] = np.radians([[0, 30, -60], [0, -30, 60], [30, 45, -90], [0, 0, 0]])[:, :k]
    rng = np.random.default_rng(seed)
    drawn = lim[:, 0] + rng.random((256, arm.n_joints)) * (lim[:, 1] - lim[:, 0])
    q = np.concatenate([np.clip(mid + bends, lim[:, 0], lim[:, 1]), drawn])
    p = target_from_joints(arm, q)
    if p is None:
        raise ValueError(
            f"arm {arm.name}: inputs {arm.inputs} are not a point (px, py, pz) or a pose "
            f"with RPY angles {RPY_INPUTS}; give the explorer a target"
        )
    good = np.flatnonzero(arm.solve(p, arm.branches[:1]).ok[:, 0])
    return np.round(p[good[0] if good.size else 0], 9) + 0.0


@dataclass(frozen=True)
class PoseReport:
    """Everything the explorer shows for one target.

    Attributes
    ----------
    target : tuple of float
        The target, one value per input of the arm (``px, py, pz`` [mm]; angles [rad]).
    branch : str
        The chosen branch (one of ``Arm.branches``).
    reachable : bool
        True if the target has a solution (status "ok"; base-axis targets only with
        ``theta1_on_axis``).
    outside_mm : float
        Signed distance outside the reachable set [mm]: > 0 unreachable by that much,
        <= 0 reachable (its magnitude is the margin to the nearer boundary).
    message : str
        One-line summary; for a bad target the library's exception message, verbatim.
    error : str or None
        The exception's class name for a bad target (``"UnreachableError"``,
        ``"BaseAxisError"``, ``"ValueError"``), else None.
    table : pandas.DataFrame
        Index = every branch of the arm. Columns ``theta<j>_deg`` [deg] and ``c<j>`` (whole
        pulses) per joint, ``error_mm`` (distance of FK(whole-pulse angles) from the target
        point), ``w_mm3`` (manipulability sqrt(det(J J^T)) [mm^3/rad^3]; for three joints
        |det J|) and ``status`` (a word of ``STATUS_TEXT``: "ok", or why the branch has no
        solution, its numbers then missing). Empty for a bad target.
    status : Status
        The target's status (:class:`~analysis.kinematics.status.Status`).
    arm : str
        The arm's name.
    """

    target: tuple[float, ...]
    branch: str
    reachable: bool
    outside_mm: float
    message: str
    error: str | None
    table: pd.DataFrame
    status: Status = Status.OK
    arm: str = ""

    @property
    def status_text(self) -> str:
        """The status as a word (``STATUS_TEXT``): "ok", "out-of-reach", "base-axis", ..."""
        return STATUS_TEXT[self.status]

    @property
    def branch_ok(self) -> bool:
        """True if the chosen branch has a solution."""
        return self.reachable and self.table.loc[self.branch, "status"] == "ok"

    def row(self) -> pd.Series:
        """The chosen branch's row of :attr:`table` (KeyError for a bad target)."""
        return self.table.loc[self.branch]

    def joint_columns(self) -> list[str]:
        return [c for c in self.table.columns if c.startswith("theta")]

    def angles_deg(self) -> npt.NDArray[np.float64]:
        """The chosen branch's joint angles [deg] (KeyError for a bad target)."""
        return self.row()[self.joint_columns()].to_numpy(float)

    def formatted(self) -> pd.DataFrame:
        """The table for people: column names with units, numbers as text (angles to
        0.01 deg, the pulse error to 1 um, the manipulability in 10^6 mm^3/rad^3; never
        "-0.00"), "—" where a branch has no solution. Empty for a bad target."""
        t = self.table
        joints = self.joint_columns()
        ok = (t["status"] == "ok").to_numpy()

        def col(values, fmt):
            return [fmt(v) if good else "—" for v, good in zip(values, ok, strict=True)]

        out = {f"{_greek(c[:-4])} [°]": col(t[c], lambda v: num(v, 2)) for c in joints}
        for j in range(1, len(joints) + 1):
            out[f"c{j} [pulses]"] = col(t[f"c{j}"], lambda v: str(int(v)))
        out["pulse error [mm]"] = col(t["error_mm"], lambda v: num(v, 3))
        out["w [10⁶ mm³/rad³]"] = col(t["w_mm3"], lambda v: num(v / MANIPULABILITY_UNIT, 3))
        out["status"] = list(t["status"])
        return pd.DataFrame(out, index=t.index)

    def to_html(self) -> str:
        """:meth:`formatted` as HTML, one line per branch (no wrapping), the chosen branch
        marked and bold, numbers right-aligned; "" for a bad target."""
        if self.table.empty:
            return ""
        f = self.formatted()
        pad = "padding:2px 10px"
        th = "".join(
            f'<th style="{pad};text-align:{"left" if k == 0 else "right"}">{h}</th>'
            for k, h in enumerate(["branch", *f.columns])
        )
        rows = []
        for b, r in f.iterrows():
            cells = [("&#9654; " if b == self.branch else "") + html.escape(str(b))]
            cells += [html.escape(str(v)) for v in r]
            last = len(cells) - 1
            tds = "".join(
                f'<td style="{pad};text-align:{"left" if k in (0, last) else "right"}">{c}</td>'
                for k, c in enumerate(cells)
            )
            style = ' style="font-weight:bold"' if b == self.branch else ""
            rows.append(f"<tr{style}>{tds}</tr>")
        return (
            '<table class="explorer-table" style="white-space:nowrap;border-collapse:'
            'collapse;font-variant-numeric:tabular-nums">'
            f"<thead><tr>{th}</tr></thead><tbody>{''.join(rows)}</tbody></table>"
        )


def _manipulability(arm: Arm, q: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]:
    """Yoshikawa's sqrt(det(J J^T)) of the positional Jacobian [mm^3/rad^3], shape (...,)."""
    J = arm.jacobian(q)
    d = np.linalg.det(J @ np.swapaxes(J, -1, -2))
    return np.sqrt(np.clip(d, 0.0, None))


def pose_report(
    arm: Arm,
    target: npt.ArrayLike,
    branch: str | None = None,
    *,
    theta1_on_axis: float | None = None,
    tol: float = DEFAULT_TOL_MM,
) -> PoseReport:
    """Every IK branch of one target: angles, pulses, pulse error, manipulability, status.

    Parameters
    ----------
    arm : Arm
    target : array_like, shape (k,)
        One value per input of the arm's closed form (``Arm.inputs``; ``px, py, pz`` [mm]).
    branch : str, optional
        The branch to highlight; default the arm's first (the paper's: front-up for the
        grabber, eq. 6, Table 4).
    theta1_on_axis : float, optional
        Waist angle [rad] for a target on the base axis (else such a target gets the status
        "base-axis" and the library's message).
    tol : float
        Distance tolerance [mm] passed to :meth:`Arm.solve`.

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
    >>> rep = pose_report(paper_arm(), [200, 500, 600])
    >>> rep.status_text, round(rep.outside_mm, 3)
    ('out-of-reach', 31.849)
    """
    names = arm.branches
    branch = names[0] if branch is None else branch
    if branch not in names:
        raise ValueError(f"unknown branch {branch!r}; expected one of {', '.join(names)}")
    p = as_points(target, inputs=arm.inputs)
    if p.shape != (len(arm.inputs),):
        raise ValueError(
            f"pose_report takes one target of shape ({len(arm.inputs)},), got {p.shape}"
        )
    key = tuple(float(v) + 0.0 for v in p)
    sol = arm.solve(p, names, theta1_on_axis=theta1_on_axis, tol=tol)
    status, outside = Status(int(sol.status)), float(sol.outside_mm)
    n = arm.n_joints
    cols = [f"theta{j}_deg" for j in range(1, n + 1)] + [f"c{j}" for j in range(1, n + 1)]
    cols += ["error_mm", "w_mm3", "status"]
    if status != Status.OK:
        try:
            arm.raise_for(p, int(status), outside, tol=tol)
        except ValueError as exc:
            message, error = str(exc), type(exc).__name__
        else:  # raise_for raises for every status but OK
            raise AssertionError(f"status {status!r} without a refusal for target {key}")
        empty = pd.DataFrame(columns=cols, index=pd.Index([], name="branch"))
        return PoseReport(key, branch, False, outside, message, error, empty, status, arm.name)
    ok = sol.ok
    q = np.where(ok[:, None], sol.theta, 0.0)  # (B, n) rad; 0 stands in where no solution
    ppr = np.asarray(arm.params.pulses_per_rev, dtype=float)
    c = angles_to_pulses(q, ppr)
    err = np.linalg.norm(arm.fk(pulses_to_angles(c, ppr)) - _position(arm, p), axis=-1)
    # why a branch has no solution: that branch solved alone gives its own status
    words = [
        "ok" if ok[i] else STATUS_TEXT[Status(int(arm.solve(p, (b,), tol=tol).status))]
        for i, b in enumerate(names)
    ]
    deg = np.where(ok[:, None], np.degrees(q), np.nan)
    table = pd.DataFrame(
        {
            **{f"theta{j + 1}_deg": deg[:, j] for j in range(n)},
            **{f"c{j + 1}": pd.array(np.where(ok, c[:, j], 0), dtype="Int64") for j in range(n)},
            "error_mm": np.where(ok, err, np.nan),
            "w_mm3": np.where(ok, _manipulability(arm, q), np.nan),
            "status": words,
        },
        index=pd.Index(names, name="branch"),
    )
    for j in range(n):  # no pulse count where there is no angle
        table.loc[~ok, f"c{j + 1}"] = pd.NA
    r = table.loc[branch]
    if r["status"] != "ok":
        message = f"{branch}: no solution on this branch ({r['status']}); pick another branch"
    else:
        angles = ", ".join(num(r[f"theta{j}_deg"], 2) for j in range(1, n + 1))
        pulses = ", ".join(str(int(r[f"c{j}"])) for j in range(1, n + 1))
        message = (
            f"{branch}: θ = ({angles})° -> pulses ({pulses}); whole pulses put the gripper "
            f"{num(r['error_mm'], 3)} mm off the target; margin to the reach boundary "
            f"{num(max(-outside, 0.0), 1)} mm"
        )
    return PoseReport(key, branch, True, outside, message, None, table, status, arm.name)


def plain_message(rep: PoseReport) -> str:
    """What the explorer says about a report: its status word, then one plain sentence.

    The library's messages are kept, except on the base axis, where it names the Python
    argument that supplies theta1: the explorer offers a check box for it instead.

    >>> from analysis.kinematics.arm import paper_arm
    >>> print(plain_message(pose_report(paper_arm(), [0, 0, 800])))  # doctest: +ELLIPSIS
    base-axis — target (0, 0, 800) mm lies on the base axis, where ... θ1 on the base axis" ...
    """
    if rep.status == Status.BASE_AXIS:
        where = ", ".join(f"{v:g}" for v in rep.target)
        text = (
            f"target ({where}) mm lies on the base axis, where the waist angle θ1 is "
            'undefined. Tick "allow θ1 on the base axis" to choose it.'
        )
    else:
        text = rep.message
    return f"{rep.status_text} — {text}"


def build_explorer(arm: Arm | str | None = None, target: npt.ArrayLike | None = None) -> Explorer:
    """The interactive explorer (see :class:`Explorer`); ``arm`` an Arm or a name (default
    the paper's grabber), ``target`` the first target (default :func:`default_target`).

    Display it as the last expression of a cell: the controls, then the 3D view.
    """
    return Explorer(arm, target)


class Explorer(W.VBox):
    """The explorer's controls (an ``ipywidgets.VBox``) and its 3D view.

    Attributes: ``arm_picker`` (Dropdown), ``branch`` (ToggleButtons), ``fk_mode``
    (ToggleButton), ``on_axis`` (Checkbox "allow θ1 on the base axis") and ``on_axis_deg``
    (its theta1 slider), ``target_sliders`` (one per arm input) and ``joint_sliders`` (one
    per joint), ``message`` and ``table`` (HTML); the last :class:`PoseReport` as
    ``report``, the plotly figure as ``figure`` and its MIME bundle as ``bundle``.

    Displayed (``_ipython_display_``), it shows the controls and then the 3D view with a
    display id, which every later change updates in place.
    """

    SLIDER_LAYOUT: ClassVar[dict] = {"width": "640px"}  # 0.1 mm steps stay precise to drag
    SLIDER_STYLE: ClassVar[dict] = {"description_width": "120px"}  # "θ1 on the axis [°]"

    def __init__(self, arm: Arm | str | None = None, target: npt.ArrayLike | None = None):
        arm = load_arm(arm) if isinstance(arm, str) else (arm or load_arm("grabber"))
        self.arms, self.skipped = available_arms()
        if arm.name not in self.arms:  # an arm built from a changed description
            self.arms = {arm.name: arm.description.title} | self.arms
        self._syncing, self._view = False, None
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
            readout_format=".2f", continuous_update=False, layout=self.SLIDER_LAYOUT,
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
            ]
        )
        self.arm_picker.observe(self._on_arm, names="value")
        for w in (self.branch, self.on_axis, self.on_axis_deg):
            w.observe(self._on_change, names="value")
        self.fk_mode.observe(self._on_mode, names="value")
        self._set_arm(arm, target)

    # --- building ----------------------------------------------------------------------
    def _slider(self, value: float, lo: float, hi: float, label: str, step: float, fmt: str):
        s = W.FloatSlider(
            value=float(np.clip(value, lo, hi)), min=lo, max=hi, step=step,
            description=label, readout_format=fmt, continuous_update=False,
            layout=self.SLIDER_LAYOUT, style=self.SLIDER_STYLE,
        )  # fmt: skip
        s.observe(self._on_change, names="value")
        return s

    def _set_arm(self, arm: Arm, target: npt.ArrayLike | None) -> None:
        """Sliders for ``arm``'s inputs and joints, its branches, and the first target."""
        self.arm = arm
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
        for j, spec in enumerate(arm.description.joints):
            lim = arm.limits[j]
            lo, hi = (-180.0, 180.0) if lim is None else (math.degrees(v) for v in lim)
            joints.append(self._slider(0.0, lo, hi, f"{_greek(spec.name)} [°]", 0.01, ".2f"))
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
        q = rep.angles_deg() if rep.branch_ok else np.zeros(len(self.joint_sliders))
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
    def refresh(self) -> None:
        """Recompute the report from the controls; redraw message, table and 3D view."""
        arm = self.arm
        axis = self.on_axis.value and not self.fk_mode.value
        self.on_axis_deg.layout.display = None if axis else "none"
        if self.fk_mode.value:
            q = np.radians([s.value for s in self.joint_sliders])
            point = arm.fk(q)
            where = ", ".join(num(v, 2) for v in point)
            head = f"FK: gripper at ({where}) mm. "
            target = target_from_joints(arm, q)
            if target is not None:
                rep = pose_report(arm, target, self.branch.value, theta1_on_axis=float(q[0]))
            else:  # an input FK cannot give: no IK table
                rep, target = None, point
        else:
            target = self._target()
            t1 = math.radians(self.on_axis_deg.value) if axis else None
            rep = pose_report(arm, target, self.branch.value, theta1_on_axis=t1)
            q = np.radians(rep.angles_deg()) if rep.branch_ok else None
            head = ""
        self.report = rep
        if rep is None:
            text, bad = head + f"(the IK of {arm.name} takes {', '.join(arm.inputs)})", False
        else:
            text, bad = head + plain_message(rep), not rep.branch_ok
        colour = "#b00020" if bad else "#1b5e20"
        self.message.value = (
            f'<div class="explorer-message" style="color:{colour};white-space:normal">'
            f"<b>{html.escape(text)}</b></div>"
        )
        self.table.value = rep.to_html() if rep is not None else ""
        title = f"{arm.description.title} · " + ("FK" if self.fk_mode.value else self.branch.value)
        if q is not None:
            title += " · θ = (" + ", ".join(num(v, 2) for v in np.degrees(q)) + ")°"
        else:
            title += " · no solution"
        self.figure = arm_figure(arm, q, target, title=title, box=self.box)
        self.bundle = figure_bundle(self.figure, f"explorer-{arm.name}", f"3D view: {title}")
        if self._view is not None:
            self._view.update(self.bundle, raw=True)

    def _ipython_display_(self) -> None:
        """The controls (a widget), then the 3D view with a display id (updated in place)."""
        from IPython.display import display

        data = super()._repr_mimebundle_()
        data = dict(data[0] if isinstance(data, tuple) else data)
        data["text/plain"] = (
            f"Explorer of the {self.arm.description.title} ({self.arm.name}): sliders, branch "
            "picker and FK mode need a running kernel (make lab)."
        )
        display(data, raw=True)
        self._view = display(self.bundle, raw=True, display_id=True)
