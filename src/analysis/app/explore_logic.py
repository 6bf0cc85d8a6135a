"""The plain logic of the explorer (:mod:`analysis.app.explore`, notebook ``09_explore``),
tested without a kernel: the arms that load (:func:`available_arms`), a start target
(:func:`default_target`, :func:`target_from_joints`), every IK branch of one target with its
status, whole pulse counts (eqs. 20-22 for the paper's arm), the gripper error those pulses
leave and the manipulability (:func:`pose_report`, :class:`PoseReport`), and the sentence the
explorer shows (:func:`plain_message`). Nothing here is specific to one arm; every name is
importable from :mod:`analysis.app.explore` too."""

from __future__ import annotations

import html
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt
import pandas as pd

from analysis.kinematics.arm import DEFAULT_TOL_MM, Arm, as_points, load_arm  # noqa: F401
from analysis.kinematics.joints import NO_DRIVE
from analysis.kinematics.status import STATUS_TEXT, Status

POSITION_INPUTS = {"px": "x", "py": "y", "pz": "z"}
"""Closed-form inputs that are coordinates of the target point [mm]; every other input of an
arm (e.g. an orientation angle of a pose) is an angle [rad], shown in degrees."""
IK_CAPTION = "every branch for this target"
FK_CAPTION = "other solutions for this point"
"""The captions of the explorer's table: in IK mode the target's branches; in FK mode the IK
solutions of the point the set joints reach (the set joints may be one of them, or none)."""
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


def greek(name: str) -> str:
    """``theta1`` -> ``θ1`` (joint names of the descriptions, for labels)."""
    for word, letter in (("theta", "θ"), ("alpha", "α"), ("beta", "β"), ("gamma", "γ")):
        if name.startswith(word):
            return letter + name[len(word) :]
    return name


def available_arms() -> tuple[dict[str, str], dict[str, str]]:
    """The arms described in ``data/arms/*.toml``: ``({name: title}, {name: why not})``.

    The first dict holds every arm that :func:`~analysis.kinematics.arm.load_arm` builds
    (description and closed form), in file-name order; the second the files that do not
    load, with the error (:func:`analysis.kinematics.catalog.list_arms`).
    """
    from analysis.kinematics.catalog import list_arms

    docs = list_arms()
    ok = {d["name"]: d["title"] for d in docs if "error" not in d}
    return ok, {d["name"]: d["error"] for d in docs if "error" in d}


def _position_error(arm: Arm, q: npt.NDArray[np.float64], p) -> npt.NDArray[np.float64]:
    """Distance [mm] of the tool point at joint values ``q`` from the target's coordinates
    (the inputs named px, py, pz that the arm has: a planar arm's px, py compare in-plane)."""
    idx = [k for k, name in enumerate(POSITION_INPUTS) if name in arm.inputs]
    if not idx:
        raise ValueError(f"arm {arm.name}: inputs {arm.inputs} name no coordinate (px, py, pz)")
    given = p[..., [arm.inputs.index(n) for n in POSITION_INPUTS if n in arm.inputs]]
    return np.linalg.norm(arm.fk(q)[..., idx] - given, axis=-1)


RPY_INPUTS = ("alpha", "beta", "gamma")
"""Closed-form inputs that are the tool's orientation as RPY angles [rad], in the convention
of :mod:`analysis.kinematics.rpy` (a pose: the GR-1 arm's inputs)."""


def target_from_joints(arm: Arm, q: npt.ArrayLike) -> npt.NDArray[np.float64] | None:
    """The closed form's inputs that joint angles ``q`` (..., n) [rad] reach, (..., k).

    The point (inputs ``px, py, pz``) is :meth:`Arm.fk`; RPY inputs (``alpha, beta, gamma``)
    come from the D-H chain's tool rotation (:func:`analysis.kinematics.rpy.pose_from_transform`).
    None if the arm has an input of another kind (its FK cannot be put as a target).
    """
    known = set(POSITION_INPUTS) | set(RPY_INPUTS)
    if not set(arm.inputs) <= known:
        return None
    return arm.target(q)


def default_target(arm: Arm, *, seed: int = 0) -> npt.NDArray[np.float64]:
    """A target the arm reaches on its first branch, to start the explorer at.

    What :func:`target_from_joints` gives for the first joint vector that solves with
    status "ok" on the default branch, with the tool not below the base where one does,
    trying the middle of each joint's range with the inner joints bent by +-30, +-60 deg,
    then 256 seeded draws within the joint limits; coordinates cleaned of round-off below
    1 nm.
    """
    lim = arm.bounds
    mid = lim.mean(axis=1)
    bends = np.zeros((4, arm.n_joints))
    k = min(arm.n_joints, 3)
    bends[:, :k] = np.radians([[0, 30, -60], [0, -30, 60], [30, 45, -90], [0, 0, 0]])[:, :k]
    rng = np.random.default_rng(seed)
    drawn = lim[:, 0] + rng.random((256, arm.n_joints)) * (lim[:, 1] - lim[:, 0])
    q = np.concatenate([np.clip(mid + bends, lim[:, 0], lim[:, 1]), drawn])
    q = q[arm.valid_q(q)]  # a closed chain: configurations that assemble
    p = target_from_joints(arm, q)
    if p is None:
        raise ValueError(
            f"arm {arm.name}: inputs {arm.inputs} are not a point (px, py, pz) or a pose "
            f"with RPY angles {RPY_INPUTS}; give the explorer a target"
        )
    ok = arm.solve(p, arm.branches[:1]).ok[:, 0]
    # first a pose whose tool is not below the base (the palletizer's middle of its ranges
    # hung its gripper under the base, a small folded arm at the bottom of its box)
    above = ok & (arm.fk(q)[:, 2] >= 0.0)
    good = np.flatnonzero(above if above.any() else ok)
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
        Index = every branch of the arm. Columns ``Arm.joint_labels`` (``theta<j>_deg``
        [deg]; a prismatic joint's ``<name>_mm`` [mm]) and ``c<j>`` (whole
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
    model: Arm | None = field(default=None, repr=False, compare=False)
    """The arm itself (what :func:`plain_message` explains with)."""

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
        """The joint value columns (``Arm.joint_labels``: ``<joint>_deg`` or ``_mm``), which
        come first (then the pulse counts ``c1 .. cn``, where the arm has a drive)."""
        cols = list(self.table.columns)
        return cols[: cols.index("error_mm") - sum(c[:1] == "c" and c[1:].isdigit()
                                                   for c in cols)]  # fmt: skip

    def angles_deg(self) -> npt.NDArray[np.float64]:
        """The chosen branch's joint values in user units (KeyError for a bad target):
        angles [deg], a prismatic joint's value [mm] (``Arm.joint_user_units``)."""
        return self.row()[self.joint_columns()].to_numpy(float)

    def _shown(self) -> pd.DataFrame:
        """:attr:`table`, or for a bad target every branch of the arm with no numbers and the
        target's status (the explorer keeps its table's place: no layout shift)."""
        if not self.table.empty or self.model is None:
            return self.table
        t = pd.DataFrame(np.nan, index=pd.Index(self.model.branches, name="branch"),
                         columns=self.table.columns)  # fmt: skip
        t["status"] = self.status_text
        return t

    def formatted(self) -> pd.DataFrame:
        """The table for people: column names with units, numbers as text (angles to
        0.01 deg, the pulse error to 1 um, the manipulability in 10^6 mm^3/rad^3; never
        "-0.00"), "—" where a branch has no solution; for a bad target every branch with
        "—" and the target's status."""
        t = self._shown()
        joints = self.joint_columns()
        ok = (t["status"] == "ok").to_numpy()

        def col(values, fmt):
            return [fmt(v) if good else "—" for v, good in zip(values, ok, strict=True)]

        unit = {"deg": "°", "mm": "mm"}
        out = {
            f"{greek(c.rsplit('_', 1)[0])} [{unit[c.rsplit('_', 1)[1]]}]": col(
                t[c], lambda v: num(v, 2)
            )
            for c in joints
        }
        for j in range(1, len(joints) + 1):
            if f"c{j}" in t:  # none where no drive is given
                out[f"c{j} [pulses]"] = col(t[f"c{j}"], lambda v: str(int(v)))
        if "c1" in t:
            out["pulse error [mm]"] = col(t["error_mm"], lambda v: num(v, 3))
        out["w [10⁶ mm³/rad³]"] = col(t["w_mm3"], lambda v: num(v / MANIPULABILITY_UNIT, 3))
        out["status"] = list(t["status"])
        return pd.DataFrame(out, index=t.index)

    def to_html(self, caption: str = "") -> str:
        """:meth:`formatted` as HTML, one line per branch (no wrapping), the chosen branch
        marked and bold, numbers right-aligned, ``caption`` above it."""
        if self._shown().empty:
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
        cap = (f'<caption style="caption-side:top;text-align:left;padding:2px 10px">'
               f"{html.escape(caption)}</caption>") if caption else ""  # fmt: skip
        return (
            '<table class="explorer-table" style="white-space:nowrap;border-collapse:'
            f'collapse;font-variant-numeric:tabular-nums">{cap}'
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
    if "theta1_on_axis" not in arm.closed_form.options:
        theta1_on_axis = None  # an arm whose waist angle on the axis cannot be chosen
    sol = arm.solve(p, names, theta1_on_axis=theta1_on_axis, tol=tol)
    status, outside = Status(int(sol.status)), float(sol.outside_mm)
    n = arm.n_joints
    drive = arm.has_drive  # no drive given: no pulse columns, no whole-pulse error
    cols = [*arm.joint_labels, *(f"c{j}" for j in range(1, (n if drive else 0) + 1))]
    cols += ["error_mm", "w_mm3", "status"]
    if status != Status.OK:
        try:
            arm.raise_for(p, int(status), outside, tol=tol)
        except ValueError as exc:
            message, error = str(exc), type(exc).__name__
        else:  # raise_for raises for every status but OK
            raise AssertionError(f"status {status!r} without a refusal for target {key}")
        empty = pd.DataFrame(columns=cols, index=pd.Index([], name="branch"))
        return PoseReport(
            key, branch, False, outside, message, error, empty, status, arm.name, arm
        )
    ok = sol.ok
    q = np.where(ok[:, None], sol.theta, 0.0)  # (B, n) rad; 0 stands in where no solution
    c = arm.pulses(q) if drive else np.zeros((len(names), 0), dtype=np.int64)
    err = _position_error(arm, arm.from_pulses(c), p) if drive else np.full(len(names), np.nan)
    # why a branch has no solution: that branch solved alone gives its own status
    words = [
        "ok" if ok[i] else STATUS_TEXT[Status(int(arm.solve(p, (b,), tol=tol).status))]
        for i, b in enumerate(names)
    ]
    deg = np.where(ok[:, None], arm.joints_to_user(q), np.nan)  # degrees | mm
    table = pd.DataFrame(
        {
            **{label: deg[:, j] for j, label in enumerate(arm.joint_labels)},
            **{f"c{j + 1}": pd.array(np.where(ok, c[:, j], 0), dtype="Int64")
               for j in range(c.shape[1])},
            "error_mm": np.where(ok, err, np.nan),
            "w_mm3": np.where(ok, _manipulability(arm, q), np.nan),
            "status": words,
        },
        index=pd.Index(names, name="branch"),
    )
    for j in range(c.shape[1]):  # no pulse count where there is no angle
        table.loc[~ok, f"c{j + 1}"] = pd.NA
    message = _branch_message(arm, table.loc[branch], branch, outside)
    return PoseReport(key, branch, True, outside, message, None, table, status, arm.name, arm)


def _branch_message(arm: Arm, r: pd.Series, branch: str, outside: float) -> str:
    """:attr:`PoseReport.message` of a solved target: the chosen branch's row ``r`` in
    words (its joints, pulses, the whole pulses' error and the reach margin), or why that
    branch has no solution."""
    if r["status"] != "ok":
        return f"{branch}: no solution on this branch ({r['status']}); pick another branch"
    if set(arm.joint_user_units) == {"deg"}:
        angles = "θ = (" + ", ".join(num(r[label], 2) for label in arm.joint_labels) + ")°"
    else:  # prismatic joints: each value with its unit
        angles = "q = (" + ", ".join(
            num(r[label], 2) + ("°" if u == "deg" else f" {u}")
            for label, u in zip(arm.joint_labels, arm.joint_user_units, strict=True)
        ) + ")"  # fmt: skip
    margin = (f"reach margin {num(max(-outside, 0.0), 1)} mm (the largest over the branches' "
              "wrists)")  # fmt: skip
    if not arm.has_drive:
        return f"{branch}: {angles}; pulses: {NO_DRIVE}; {margin}"
    pulses = ", ".join(str(int(r[f"c{j}"])) for j in range(1, arm.n_joints + 1))
    return (
        f"{branch}: {angles} -> pulses ({pulses}); whole pulses put the gripper "
        f"{num(r['error_mm'], 3)} mm off the target; {margin}"
    )


def plain_message(rep: PoseReport, theta1_on_axis: float | None = None) -> str:
    """What the explorer says about a report: its status word, then one plain sentence.

    For a target without a solution, or whose chosen branch has none, the sentence of
    :func:`analysis.app.explain.explain` (the static page's, from the same templates), with
    the nearest reachable target; else the report's message.

    >>> from analysis.kinematics.arm import paper_arm
    >>> print(plain_message(pose_report(paper_arm(), [0, 0, 800])))
    base-axis — target (0, 0, 800) mm lies on the base axis, where the waist angle θ1 is undefined: tick “allow θ1 on the base axis” to choose it
    """  # noqa: E501
    from analysis.app.explain import explain

    arm = rep.model
    if (rep.status == Status.OK and rep.branch_ok) or arm is None:
        return f"{rep.status_text} — {rep.message}"
    why = rep.table.loc[rep.branch, "status"] if rep.status == Status.OK else ""
    return str(explain(arm, rep.target, rep.status, rep.outside_mm, rep.branch, why=why,
                       theta1_on_axis=theta1_on_axis))  # fmt: skip


def branch_of(arm: Arm, q: npt.ArrayLike, rep: PoseReport, tol_rad: float = 1e-6) -> tuple:
    """Which IK branch gives joint values ``q`` (n,) [rad | mm] back for the point they reach
    (``rep``: its :func:`pose_report`): ``(name, "")``, or ``(None, why)`` naming the nearest
    branch and the joint that differs (the palletizer's IK holds its tool level, so a wrist
    set otherwise belongs to no branch)."""
    q = np.asarray(q, dtype=float)
    t = rep.table
    if t.empty:
        return None, f"the point has no IK solution ({rep.status_text})"
    user = arm.joints_to_user(q)
    cols = rep.joint_columns()
    best, worst_j, diff = None, 0, np.inf
    for b, row in t.iterrows():
        if row["status"] != "ok":
            continue
        got = row[cols].to_numpy(float)
        d = np.abs((got - user + 180.0) % 360.0 - 180.0)
        d = np.where(np.asarray(arm.joint_user_units) == "deg", d, np.abs(got - user))
        if d.max() <= np.degrees(tol_rad):
            return b, ""
        if d.max() < diff:
            best, worst_j, diff = b, int(np.argmax(d)), float(d.max())
    if best is None:
        return None, "no branch solves the point"
    label = cols[worst_j].rsplit("_", 1)
    unit = "°" if label[1] == "deg" else f" {label[1]}"
    set_v, ik_v = user[worst_j], t.loc[best, cols[worst_j]]
    return None, (f"the nearest, {best}, has {greek(label[0])} = {num(ik_v, 2)}{unit} where it "
                  f"is set to {num(set_v, 2)}{unit}")  # fmt: skip


def fk_line(arm: Arm, q: npt.ArrayLike, rep: PoseReport | None) -> str:
    """The explorer's FK line for joint values ``q`` [rad | mm]: the joints and their whole
    pulses, the full pose of ``fk --json`` (:func:`analysis.kinematics.pose.fk_document`: the
    tool point, its RPY angles in the convention ``ik`` takes, a closed chain's passive
    joints) to two decimals, and the branch they belong to (:func:`branch_of`)."""
    from analysis.kinematics.pose import fk_document

    q = np.asarray(q, dtype=float)
    doc = fk_document(arm, arm.joints_to_user(q))
    joints = ", ".join(
        num(v, 2) + ("°" if u == "deg" else f" {u}")
        for v, u in zip(doc["joint_values"], doc["joint_units"], strict=True)
    )
    pulses = (f"pulses ({', '.join(str(int(c)) for c in arm.pulses(q))})" if arm.has_drive
              else f"pulses: {NO_DRIVE}")  # fmt: skip
    point = ", ".join(num(v, 2) for v in doc["position_mm"])
    rpy = ", ".join(num(v, 2) for v in doc["rpy_deg"])
    text = f"FK: joints ({joints}) → {pulses}; tool at ({point}) mm, RPY ({rpy})°"
    passive = {k: v for k, v in doc["joint_states"].items() if k not in doc["joint_names"]}
    if passive:
        text += "; passive joints " + ", ".join(
            f"{greek(k)} = {num(v, 2)}°" for k, v in passive.items()
        )
    if rep is not None:
        b, why = branch_of(arm, q, rep)
        text += f"; branch: {b}" if b else f"; branch: none ({why})"
    return text
