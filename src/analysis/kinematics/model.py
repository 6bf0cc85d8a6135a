"""The arm model: its description, its closed form and its numbers, and the kinematics derived
from them (the public import is :mod:`analysis.kinematics.arm`).

:class:`Arm` holds one description (``data/arms/<name>.toml``, read by
:mod:`analysis.kinematics.description`), the closed-form object the loader picked for it
(:mod:`analysis.kinematics.arms`; None for a chain no closed form solves, which still has its
FK) and plain-number parameters (:class:`~analysis.kinematics.params.Params`). Build it with
:func:`analysis.kinematics.loader.load_arm` (by name or path), the one place that reads a
description, picks the closed form, checks it and probes it; nothing here looks anything up
again. Nothing here is specific to an arm:

- forward kinematics and frame origins come from the D-H chain, or, for an arm that is not
  a D-H chain (the picker's closed chain), from its closed form's ``fk``
  (:func:`analysis.kinematics.forward.chain_points`: the one place that chooses);
- the Jacobian is that chain differentiated by forward-mode duals
  (:class:`~analysis.kinematics.ops.DualOps`), not written by hand;
- joint values are radians (revolute) or millimetres (prismatic, :attr:`Arm.joint_units`);
  :meth:`Arm.pulses` converts both to drive pulses (eqs. 20-22; a screw's lead);
- :meth:`Arm.sample_q` draws valid configurations (:mod:`analysis.kinematics.sampling`),
  :meth:`Arm.target` gives the closed form's inputs that a configuration reaches;
- :meth:`Arm.solve` runs the closed form and the shared solver body
  (:func:`~analysis.kinematics.solution.solve_body`: statuses, joint limits, NaN where no
  solution) with numpy, or the compiled kernel generated from the very same body
  (:mod:`analysis.kinematics.compiled`). The body, the tolerances, the errors and the result
  record live in :mod:`analysis.kinematics.solution` and are re-exported here.

Angles in radians, lengths in mm; joint arrays have shape ``(..., n)``, targets
``(..., k)``.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path

import numpy as np
import numpy.typing as npt

from analysis import validate
from analysis.kinematics import consistency
from analysis.kinematics.arms import ClosedForm
from analysis.kinematics.consistency import POSITION_INPUTS, RPY_INPUTS
from analysis.kinematics.description import ArmDescription
from analysis.kinematics.dh import DHTable
from analysis.kinematics.forward import chain_points
from analysis.kinematics.ops import DualOps, numpy_ops
from analysis.kinematics.params import Params
from analysis.kinematics.pose import Pose, pose
from analysis.kinematics.pulses import angles_to_pulses, pulse_values, pulses_to_angles
from analysis.kinematics.rpy import rpy_from_matrix
from analysis.kinematics.sampling import sample_q
from analysis.kinematics.solution import (
    DEFAULT_TOL_MM,
    IKSolutions,
    as_points,
    check_joints,
    check_theta1_on_axis,
    check_tol,
    collect,
    raise_refusal,
    refusal_options,
    solve_body,
)
from analysis.kinematics.status import Status

__all__ = ["BRANCHES", "Arm", "NoClosedForm"]

BRANCHES: tuple[str, ...] = ("front-up", "front-down", "back-up", "back-down")
"""The paper's arm's branches (``analysis.kinematics.arms.grabber.BRANCHES``)."""


def _frozen(values) -> np.ndarray:
    arr = np.array(values, dtype=float)
    arr.setflags(write=False)
    return arr


class NoClosedForm(ValueError):
    """The arm has no closed form (a chain outside the derived families, and none named):
    its FK, Jacobian, URDF and Pinocchio model work; asking for IK raises this, with the
    reason."""


@dataclass(frozen=True, eq=False)
class Arm:
    """One arm: its ``description``, its ``closed_form`` (None where no closed form solves
    the chain: ``no_ik`` says why) and its ``params``, numbers. Compared and hashed by
    identity.

    Build it with :func:`analysis.kinematics.loader.load_arm` (by name or path) or
    :func:`~analysis.kinematics.loader.paper_arm` (the paper's Table 3 arm); change its
    numbers with :meth:`with_`.
    """

    description: ArmDescription
    closed_form: ClosedForm | None
    params: Params
    no_ik: str = ""
    """Why the arm has no closed form (empty where it has one)."""

    # --- identity -----------------------------------------------------------------------
    @property
    def name(self) -> str:
        return self.description.name

    @property
    def cf(self) -> ClosedForm:
        """The closed form, or :class:`NoClosedForm` with the reason there is none."""
        if self.closed_form is None:
            raise NoClosedForm(self.no_ik or f"arm {self.name} has no closed form")
        return self.closed_form

    def with_(self, **changes) -> Arm:
        """The same arm with some parameter values (or ``pulses_per_rev``) changed, checked
        again as the loader checks them: by :mod:`analysis.validate`, the closed form's
        ``check`` and against the description's chain (:mod:`.consistency`)."""
        params = self.params.with_(**changes)
        if params.has_drive and len(params.pulses_per_rev) != self.n_joints:
            raise ValueError(
                f"pulses_per_rev = {changes.get('pulses_per_rev')!r}: need {self.n_joints} "
                "whole numbers, one per joint"
            )
        if self.closed_form is not None:
            self.closed_form.check(params)
            if self.description.has_rows:
                consistency.check(self.description, self.closed_form, params)
        return dataclasses.replace(self, params=params)

    @property
    def input_files(self) -> tuple[Path, ...]:
        """Every file the arm was built from: the description, the tables it read, and a
        closed form's ``.py`` file (what no output of a command may overwrite)."""
        desc = self.description
        code = (Path(self.closed_form.name),) if desc.closed_form.endswith(".py") else ()
        return (*desc.files, *code)

    @property
    def branches(self) -> tuple[str, ...]:
        """Branch names; the first is the default (the paper's choice)."""
        return self.cf.branches

    @property
    def inputs(self) -> tuple[str, ...]:
        """Names of the closed form's inputs (the target: px, py, pz; more for a pose)."""
        return self.cf.inputs

    @property
    def input_units(self) -> tuple[str, ...]:
        """Units of the inputs: "mm" for a coordinate, "rad" for an angle (the closed form's
        ``INPUT_UNITS``)."""
        return self.cf.input_units

    @property
    def joint_names(self) -> tuple[str, ...]:
        """The joints' names, in order (the description's ``[[joints]]``)."""
        return tuple(j.name for j in self.description.joints)

    @property
    def joint_units(self) -> tuple[str, ...]:
        """Units of the joint values: "rad" (revolute) or "mm" (prismatic)."""
        return tuple(j.unit for j in self.description.joints)

    @property
    def joint_labels(self) -> tuple[str, ...]:
        """Column names of the joint values in user units: ``<joint>_deg`` (revolute) or
        ``<joint>_mm`` (prismatic), e.g. ``theta1_deg`` (batch CSV, the explorer's table).

        >>> from analysis.kinematics.arm import load_arm
        >>> load_arm("picker").joint_labels
        ('theta1_deg', 'theta2_mm', 'theta6_deg', 'theta7_deg', 'theta8_deg', 'theta9_mm')
        """
        return tuple(f"{n}_{u}" for n, u in zip(self.joint_names, self.joint_user_units,
                                               strict=True))  # fmt: skip

    @property
    def joint_user_units(self) -> tuple[str, ...]:
        """Units a user gives joint values in (``fk`` on the command line): "deg" or "mm"."""
        return tuple("deg" if u == "rad" else u for u in self.joint_units)

    def joints_from_user(self, values: npt.ArrayLike) -> np.ndarray:
        """``(..., n)`` joint values in :attr:`joint_user_units` -> :attr:`joint_units`."""
        v = np.asarray(values, dtype=float)
        angle = np.array([u == "rad" for u in self.joint_units])
        if v.shape[-1:] != angle.shape:
            raise ValueError(f"{self.name} has {len(angle)} joints, got {v.shape}")
        return np.where(angle, np.radians(v), v)

    def joints_to_user(self, q: npt.ArrayLike) -> np.ndarray:
        """``(..., n)`` joint values in :attr:`joint_units` -> :attr:`joint_user_units`."""
        q = np.asarray(q, dtype=float)
        return np.where(np.array([u == "rad" for u in self.joint_units]), np.degrees(q), q) + 0.0

    @property
    def statuses(self) -> tuple[Status, ...]:
        """Every status a target of this arm can get: ok, the closed form's refusals, the
        joint limits where some joint has them."""
        limited = any(lim is not None for lim in self.limits)
        return (Status.OK, *self.cf.statuses, *((Status.JOINT_LIMITS,) * limited))

    @property
    def startup_target(self) -> tuple[float, ...] | None:
        """The target a generated PLC program writes on its first scan (the closed form's
        ``STARTUP_TARGET``, in :attr:`input_units`), or None."""
        return self.cf.startup_target(self.params)

    @property
    def user_units(self) -> tuple[str, ...]:
        """Units a user gives the inputs in (command line, CSV columns): an angle in degrees,
        a coordinate in mm; :meth:`from_user` converts.

        >>> from analysis.kinematics.arm import load_arm
        >>> load_arm("gr1").user_units
        ('mm', 'mm', 'mm', 'deg', 'deg', 'deg')
        """
        return tuple("deg" if u == "rad" else u for u in self.input_units)

    def from_user(self, values: npt.ArrayLike) -> np.ndarray:
        """``(..., k)`` inputs in :attr:`user_units` -> in :attr:`input_units` (degrees
        reduced exactly to (-180, 180], :func:`analysis.validate.reduce_deg`, then radians;
        coordinates unchanged).

        >>> from analysis.kinematics.arm import load_arm
        >>> load_arm("gr1").from_user([100, 0, 600, 0, 90, 180]).round(4).tolist()
        [100.0, 0.0, 600.0, 0.0, 1.5708, 3.1416]
        """
        v = validate.real_array(values, "target")
        angle = np.array([u == "rad" for u in self.input_units])
        if v.shape[-1:] != angle.shape:
            raise ValueError(f"{self.name} takes {len(angle)} inputs per target, got {v.shape}")
        if not angle.any():
            return v
        # degrees reduced exactly to (-180, 180] before the conversion (analysis.validate)
        return np.where(angle, np.radians(validate.reduce_deg(v)), v)

    @property
    def n_joints(self) -> int:
        return len(self.description.joints)

    @cached_property
    def table(self) -> DHTable:
        """The D-H chain with this arm's parameter values."""
        return self.description.dh_table(self.params.data)

    def dh_table(self, symbolic: bool = False) -> DHTable:
        """The D-H chain with these values, or with the parameters' SymPy symbols."""
        return self.table if not symbolic else self.description.dh_table(symbolic=True)

    @cached_property
    def geometry(self) -> dict:
        """Named points and radii of the closed form (e.g. the shoulder, the reach)."""
        return self.cf.geometry(self.params)

    @property
    def shoulder(self) -> npt.NDArray[np.float64]:
        """The shoulder point [mm] (arms whose closed form names one)."""
        return np.array(self.geometry["shoulder"], dtype=float)

    @cached_property
    def limits(self) -> tuple[tuple[float, float] | None, ...]:
        """Joint limits [rad | mm] per joint, None where unrestricted."""
        return tuple(None if j.unlimited else (j.lower, j.upper) for j in self.description.joints)

    @cached_property
    def bounds(self) -> npt.NDArray[np.float64]:
        """(n, 2) lower and upper bound of every joint [rad | mm]: its limits, or one turn
        (-pi, pi) where unrestricted (where :meth:`sample_q` draws). Read-only (the arm is
        shared: :func:`~analysis.kinematics.loader.load_arm` loads it once)."""
        return _frozen([lim if lim is not None else (-np.pi, np.pi) for lim in self.limits])

    @cached_property
    def lead_mm(self) -> npt.NDArray[np.float64]:
        """Per joint a prismatic joint's lead [mm per motor revolution], NaN if revolute."""
        joints = self.description.joints
        return _frozen([np.nan if j.lead_mm is None else j.lead_mm for j in joints])

    # --- drive pulses (eqs. 20-22): NoDrive (the joint, the key) where none is given ------
    @property
    def has_drive(self) -> bool:
        """True if the description gives every joint's drive (else no pulse counts)."""
        return self.params.has_drive

    def pulses(self, q: npt.ArrayLike, *, rounding: str = "half-away") -> npt.NDArray[np.int64]:
        """Whole drive pulses (..., n) for joint values (..., n) [rad | mm]: eqs. 20-22 for
        a revolute joint, ``q / lead * pulses_per_rev`` for a prismatic one.

        >>> from analysis.kinematics.arm import paper_arm
        >>> paper_arm().pulses(np.radians([45.0, 10.2087, -155.1291])).tolist()
        [500, 113, -1724]
        """
        return angles_to_pulses(
            q, self.params.pulses_per_rev, rounding=rounding, lead_mm=self.lead_mm
        )

    def pulse_values(self, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Unrounded pulse counts (..., n) for joint values (..., n) [rad | mm]."""
        return pulse_values(q, self.params.pulses_per_rev, lead_mm=self.lead_mm)

    def from_pulses(self, c: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Joint values (..., n) [rad | mm] commanded by whole pulse counts (..., n)."""
        return pulses_to_angles(c, self.params.pulses_per_rev, lead_mm=self.lead_mm)

    # --- forward kinematics, from the chain ----------------------------------------------
    def _q(self, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Joint values checked (shape, finite, magnitude per unit) and, for a closed chain,
        that the closed form has a configuration for them (its ``fk_refusal``)."""
        q = check_joints(q, self.n_joints, units=self.joint_units)
        cf = self.closed_form
        if not self.description.has_rows and hasattr(cf.module, "fk_refusal"):
            bad = ~self.valid_q(q)
            if bad.any():
                first = q[tuple(np.argwhere(bad)[0])]
                raise ValueError(cf.fk_refusal(first, self.params))
        return q

    def valid_q(self, q: npt.ArrayLike) -> npt.NDArray[np.bool_]:
        """Mask (...,) of joint values the arm has a configuration for (always True for a
        D-H chain; the picker's sliders must let link 5 close)."""
        q = check_joints(q, self.n_joints, units=self.joint_units)
        if self.description.has_rows:
            return np.ones(q.shape[:-1], dtype=bool)
        with np.errstate(invalid="ignore"):
            valid = self._points(numpy_ops, q)["valid"]
        return np.broadcast_to(np.asarray(valid, dtype=bool), q.shape[:-1]).copy()

    def _points(self, m, q: npt.NDArray[np.float64] | list) -> dict:
        qs = list(np.moveaxis(q, -1, 0)) if isinstance(q, np.ndarray) else q
        table = self.table if self.description.has_rows else None
        return chain_points(m, self.description, self.closed_form, self.params, qs, table)

    def frames(self, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Points of the arm [mm], shape (..., k, 3), in drawing order: for a D-H chain the
        origins of its frames 0..n (the base, each link's end, the tool); for a closed
        chain the closed form's points (the picker's linkage). The tool point is last."""
        q = self._q(q)
        origins = self._points(numpy_ops, q)["frames"]
        shape = q.shape[:-1]
        return np.stack(
            [np.stack([np.broadcast_to(c, shape) for c in o], axis=-1) for o in origins], axis=-2
        ).astype(float)

    def fk(self, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """End point [mm], shape (..., 3), for joint values (..., n) [rad | mm]: the position
        column of the chain's product of link transforms (for the paper's arm, eq. 2; for
        the picker the product of exponentials of its main chain).

        Examples
        --------
        Table 4 row 1, corrected angles (45, 10.21, -155.13) deg, lands on (100, 100, 600):

        >>> from analysis.kinematics.arm import paper_arm
        >>> paper_arm().fk(np.radians([45.0, 10.2087, -155.1291])).round(2).tolist()
        [100.0, 100.0, 600.0]
        """
        q = self._q(q)
        end = self._points(numpy_ops, q)["frames"][-1]
        return np.stack([np.broadcast_to(c, q.shape[:-1]) for c in end], axis=-1).astype(float)

    def tool_transform(self, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """The tool's pose (..., 4, 4) [mm] in the base frame for joint values (..., n)."""
        q = self._q(q)
        if self.description.has_rows:
            return self.table.fk(q)
        out = self._points(numpy_ops, q)
        shape = q.shape[:-1]
        T = np.zeros((*shape, 4, 4))
        for i, row in enumerate(out["rotation"]):
            for j, v in enumerate(row):
                T[..., i, j] = v
        for i, v in enumerate(out["frames"][-1]):
            T[..., i, 3] = v
        T[..., 3, 3] = 1.0
        return T

    def pose(self, q: npt.ArrayLike) -> Pose:
        """The full pose at joint values (..., n) [rad | mm]: tool point, rotation, RPY in
        the convention ``ik`` takes and every joint, a closed chain's passive ones too
        (:func:`analysis.kinematics.pose.pose`)."""
        return pose(self, q)

    def target(self, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """The closed form's inputs (..., k) that joint values (..., n) reach, in
        :attr:`input_units`: the tool point for ``px, py, pz``, its orientation's RPY angles
        (:func:`analysis.kinematics.rpy.pose_from_transform`) for ``alpha, beta, gamma``.

        Raises ValueError for an input of another kind (the arm's FK cannot name it).

        >>> from analysis.kinematics.arm import paper_arm
        >>> paper_arm().target(np.radians([45.0, 10.2087, -155.1291])).round(2).tolist()
        [100.0, 100.0, 600.0]
        """
        other = [k for k in self.inputs if k not in POSITION_INPUTS + RPY_INPUTS]
        if other:
            raise ValueError(
                f"arm {self.name}: inputs {other} are neither the tool point {POSITION_INPUTS} "
                f"nor RPY angles {RPY_INPUTS}: no target follows from joint values"
            )
        q = np.asarray(q, dtype=float)
        values = dict(zip(POSITION_INPUTS, np.moveaxis(self.fk(q), -1, 0), strict=True))
        if set(RPY_INPUTS) & set(self.inputs):
            rpy = rpy_from_matrix(self.tool_transform(q)[..., :3, :3])
            values |= dict(zip(RPY_INPUTS, np.moveaxis(rpy, -1, 0), strict=True))
        return np.stack([values[k] for k in self.inputs], axis=-1)

    def sample_q(
        self, rng: np.random.Generator, n: int, *, branch: str | None = None, **margins
    ) -> npt.NDArray[np.float64]:
        """``n`` seeded configurations (n, n_joints) [rad | mm] that the closed form solves
        back: within the joint limits, outside every refusal band, each one of the IK
        solutions of its own target (of ``branch`` if given). See
        :func:`analysis.kinematics.sampling.sample_q` (``margin_mm``, ``margin_rad``).
        """
        return sample_q(self, rng, n, branch=branch, **margins)

    def elbow(self, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Origin of frame 2 (the paper's arm: the elbow) [mm], shape (..., 3)."""
        return self.frames(q)[..., 2, :]

    def jacobian(self, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Positional Jacobian dP/dq [mm/rad | mm/mm], shape (..., 3, n); column j is dP/dq_j.

        The chain of :meth:`fk` differentiated by forward-mode duals (exact to round-off).
        """
        q = self._q(q)
        m = DualOps(numpy_ops)
        qs = m.seed(list(np.moveaxis(q, -1, 0)))
        end = self._points(m, qs)["frames"][-1]
        shape = q.shape[:-1]
        cols = [
            np.stack(
                [np.broadcast_to(c.d[j] if hasattr(c, "d") else 0.0, shape) for c in end], axis=-1
            )
            for j in range(self.n_joints)
        ]
        return np.stack(cols, axis=-1).astype(float)

    # --- reach ---------------------------------------------------------------------------
    def is_reachable(self, p: npt.ArrayLike, tol: float = DEFAULT_TOL_MM) -> npt.NDArray[np.bool_]:
        """Mask of targets within ``tol`` mm of the reachable set (..., )."""
        return self.solve(p, self.branches[:1], tol=tol).reachable

    # --- inverse kinematics --------------------------------------------------------------
    def branch_names(self, branches: str | Sequence[str]) -> tuple[str, ...]:
        """Validated branch names (``"all"`` for every branch)."""
        if isinstance(branches, str):
            branches = self.branches if branches == "all" else (branches,)
        if not isinstance(branches, (list, tuple)) or not all(
            isinstance(b, str) for b in branches
        ):
            raise ValueError(
                f"branches = {branches!r}: expected 'all', a branch name or a sequence of them "
                f"({', '.join(self.branches)})"
            )
        names = tuple(branches)
        unknown = [b for b in names if b not in self.branches]
        if unknown or not names:
            raise ValueError(
                f"unknown branch {unknown or names!r}; expected 'all' or from "
                f"{', '.join(self.branches)}"
            )
        return names

    def solve(
        self,
        p: npt.ArrayLike,
        branches: str | Sequence[str] = "all",
        *,
        theta1_on_axis: npt.ArrayLike | None = None,
        tol: float = DEFAULT_TOL_MM,
        limits: bool = True,
        backend: str = "numpy",
        out: IKSolutions | None = None,
        margin_mm: float = 0.0,
        margin_rad: float = 0.0,
    ) -> IKSolutions:
        """Batch closed-form IK; never raises for unreachable targets.

        Parameters
        ----------
        p : array_like, shape (..., 3)
            Targets [mm].
        branches : str or sequence of str
            Branch names or ``"all"``.
        theta1_on_axis : array_like, optional
            Waist angle [rad] for targets on the base axis (broadcast against
            ``p[..., 0]``; real, within ten turns, wrapped to (-pi, pi]). Without it such
            targets get ``Status.BASE_AXIS``.
        tol : float
            Distance tolerance [mm] (0 .. :data:`MAX_TOL_MM`).
        limits : bool
            Apply the description's joint limits (branches outside them are not ok).
        backend : {"numpy", "compiled"}
            "compiled" runs the kernel generated from the same closed form
            (:mod:`analysis.kinematics.compiled`); it needs Numba and ``theta1_on_axis=None``.
        out : IKSolutions, optional
            Preallocated result (compiled backend; see :func:`~analysis.kinematics.compiled.
            allocate`), reused to avoid touching fresh memory.
        margin_mm, margin_rad : float
            Refuse a band around the boundaries, as the generated PLC programs do: within
            ``margin_mm`` inside a reach shell or of a singular set, within ``margin_rad`` of
            the arm's angular tolerance (:func:`~analysis.kinematics.solution.
            refusal_options`; numpy backend). Joint limits stay as described.
        """
        names = self.branch_names(branches)
        # the compiled kernel counts non-finite inputs in its input copy (one pass, not two)
        p = as_points(p, inputs=self.inputs, finite=backend != "compiled", units=self.input_units)
        tol = check_tol(tol)
        options = refusal_options(tol, margin_mm, margin_rad)
        lim = self.limits if limits else ()
        if theta1_on_axis is not None:
            theta1_on_axis = check_theta1_on_axis(theta1_on_axis)
        if backend == "compiled":
            if theta1_on_axis is not None:
                raise ValueError("the compiled backend takes no theta1_on_axis; use numpy")
            if margin_mm or margin_rad:
                raise ValueError("the compiled backend takes no margin; use numpy")
            from analysis.kinematics import compiled  # Numba: imported only when asked for

            return compiled.solve(self, p, names, tol=tol, limits=lim, out=out)
        if backend != "numpy":
            raise ValueError(f"backend {backend!r}: expected 'numpy' or 'compiled'")
        opts = {} if theta1_on_axis is None else {"theta1_on_axis": theta1_on_axis}
        if margin_mm or margin_rad:
            opts.update(options)
            del opts["tol"]
            tol = options["tol"]
        with np.errstate(invalid="ignore", divide="ignore"):
            r = solve_body(numpy_ops, self.cf, tuple(p[..., k] for k in range(p.shape[-1])),
                           self.params, names, tol=tol, limits=lim, **opts)  # fmt: skip
        return collect(r, names, p.shape[:-1], self.n_joints)

    def ik(
        self,
        p: npt.ArrayLike,
        branch: str | None = None,
        *,
        theta1_on_axis: float | None = None,
        tol: float = DEFAULT_TOL_MM,
    ) -> npt.NDArray[np.float64]:
        """Closed-form IK for one target and one branch (default: the paper's); raises.

        Returns
        -------
        ndarray, shape (n,)
            Joint angles [rad].

        Raises
        ------
        UnreachableError
            The target is outside the reachable set; the message says by how much.
        BaseAxisError
            The target is on the base axis and ``theta1_on_axis`` was not given.
        OrientationError
            A pose whose orientation the arm cannot take (the GR-1).

        Examples
        --------
        Table 4 row 1 (100, 100, 600) mm -> (45.00, 10.21, -155.13) deg; the paper prints
        190.20 for theta2 (see the errata register):

        >>> from analysis.kinematics.arm import paper_arm
        >>> np.degrees(paper_arm().ik([100, 100, 600])).round(2).tolist()
        [45.0, 10.21, -155.13]
        """
        branch = branch or self.branches[0]
        if branch not in self.branches:
            raise ValueError(
                f"unknown branch {branch!r}; expected one of {', '.join(self.branches)}"
            )
        return self.ik_all(p, theta1_on_axis=theta1_on_axis, tol=tol, branches=(branch,))[branch]

    def ik_all(
        self,
        p: npt.ArrayLike,
        *,
        theta1_on_axis: float | None = None,
        tol: float = DEFAULT_TOL_MM,
        branches: Sequence[str] | None = None,
    ) -> dict[str, npt.NDArray[np.float64]]:
        """All IK solutions of one target, ``{branch: angles}`` [rad]; raises like :meth:`ik`.

        Branches outside the joint limits are left out; if none is left, ValueError.
        """
        p = as_points(p, inputs=self.inputs, units=self.input_units)
        if p.shape != (len(self.inputs),):
            raise ValueError(
                f"ik takes one target of shape ({len(self.inputs)},), got {p.shape}; "
                "use solve() for batches"
            )
        names = self.branch_names(branches or "all")
        sol = self.solve(p, names, theta1_on_axis=theta1_on_axis, tol=tol)
        self.raise_for(p, int(sol.status), float(sol.outside_mm), tol=tol)
        return {b: sol.theta[i] for i, b in enumerate(names) if sol.ok[i]}

    def raise_for(self, p, status: int, outside: float, *, tol: float) -> None:
        """Raise the error that ``status`` means for target ``p`` (nothing if OK):
        :func:`~analysis.kinematics.solution.raise_refusal`."""
        raise_refusal(self.cf, self.name, self.params, p, status, outside, tol=tol)
