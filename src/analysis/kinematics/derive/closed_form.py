"""The derived closed form of the waist families: one object with the contract of
:mod:`analysis.kinematics.arms`.

:class:`DerivedClosedForm` is what :func:`analysis.kinematics.derive.derive` returns for a
description of a family with a waist and parallel axes (3R, 4R-kept, 5R, 6R-wrist,
6R-parallel): ``BRANCHES``, ``INPUTS``, ``check``, ``geometry``, ``ik(m, p, P, ...)`` and
``refusal`` as a hand-written closed-form module has them, so the shared solver, the compiled
kernel, the float32 model, SymPy and the PLC programs run it unchanged. ``ik`` is the
subproblem decomposition of :mod:`analysis.kinematics.derive` (its docstring gives the
steps; :mod:`.positioning` and :mod:`.wrist` write them), against the math namespace ``m``;
the lengths come from ``P`` through the description's D-H rows at every call, so a changed
parameter (``Arm.with_``) or a traced one (the compiled kernel) is used as it is.

Branches: ``<side>-<elbow>`` (front/back, up/down: four), and for a six-axis arm
``<side>-<elbow>-<wrist>`` (noflip/flip, :data:`.wrist.WRISTS`: eight).
"""

from __future__ import annotations

import math

import numpy as np

from analysis.kinematics.derive import subproblems as sp
from analysis.kinematics.derive import wrist as wr
from analysis.kinematics.derive.base import POINT, POSE, fmt
from analysis.kinematics.derive.positioning import WaistArm, apply_columns, mat_vec
from analysis.kinematics.ops import numpy_ops
from analysis.kinematics.status import Status

__all__ = ["BRANCHES", "BRANCHES_6", "DerivedClosedForm"]

BRANCHES = ("front-up", "front-down", "back-up", "back-down")
"""The waist facing the target (front) or turned by about pi (back), the elbow up or down
(:mod:`analysis.kinematics.derive`: how up is seen is the description's ``elbow``)."""
BRANCHES_6 = tuple(f"{b}-{w}" for b in BRANCHES for w in wr.WRISTS)
"""A six-axis arm's: each of :data:`BRANCHES` with the wrist not flipped or flipped."""
PROJECTION_HINT = "orientation_tol=None gives the nearest reachable orientation"
SIX = ("6R-wrist", "6R-parallel")
FLIP_MESSAGE_RAD = 1e-2
"""A six-axis arm refused as ``degenerate`` is said to be at its wrist flip where a branch's
wrist lies within this of it (wider than any flip band, :func:`.wrist.wrist_band`), else
on the shoulder axis."""


class DerivedClosedForm(WaistArm):
    """A closed form derived from a D-H table (see the module docstring); the parameters
    are :class:`~.base.FamilyForm`'s."""

    def __init__(self, name: str, description, structure) -> None:
        super().__init__(name, description, structure)
        st = structure
        six = st.family in SIX
        self.BRANCHES = BRANCHES_6 if six else BRANCHES
        self.INPUTS = POSE if self.pose_input else POINT
        self.STATUSES = (
            Status.OUT_OF_REACH,
            Status.INSIDE_REACH,
            Status.BASE_AXIS,
            Status.DEGENERATE,
            *((Status.ORIENTATION,) if st.family == "5R" else ()),
        )
        """The refusals ``ik`` can give (joint limits and non-finite inputs are the shared
        solver's)."""
        if st.family == "5R":
            self.ORIENTATION_TOL_RAD = st.orientation_tol
            self.PROJECTION_HINT = PROJECTION_HINT
            self.ik = self.ik_pose
        if st.family == "4R-kept":
            self.sample_q = self._sample_kept

    # --- the contract ---------------------------------------------------------------------
    def _kept_q4(self, q):
        s, psi = self.structure.sigma, self.structure.keep[0]
        return s[2] * (psi - s[0] * q[:, 1] - s[1] * q[:, 2])

    def _adjust_q(self, q):
        if self.family == "4R-kept":
            q = q.copy()
            q[:, 3] = self._kept_q4(q)
        return q

    def _sample_kept(self, rng, n: int, P, bounds):
        """Candidate configurations (n, 4) [rad] of a 4R-kept arm (the contract's
        ``sample_q`` hook): joints 1-3 uniform within ``bounds`` (n_joints, 2), joint 4 the
        kept pitch, ``q4 = s4 (psi - s2 q2 - s3 q3)``, wrapped to (-pi, pi]."""
        b = np.asarray(bounds, dtype=float)
        q = b[:3, 0] + rng.random((n, 3)) * (b[:3, 1] - b[:3, 0])
        q4 = self._kept_q4(np.concatenate([q, q[:, :1]], axis=1))
        return np.concatenate([q, (np.mod(q4 + np.pi, 2 * np.pi) - np.pi)[:, None]], axis=1)

    def check(self, P) -> None:
        """Reject lengths the closed form cannot use (ValueError naming the value)."""
        g = self._points(numpy_ops, P)
        for key, what in (("la", "upper arm (axis 2 to axis 3)"), ("lb", "forearm")):
            v = float(g[key])
            if not v > 1e-9:
                raise ValueError(
                    f"arm {self.description.name}: the {what} has length {v:g} mm across the "
                    "parallel axes; the derived closed form needs it > 0 mm"
                )

    def geometry(self, P) -> dict:
        """The shoulder (axis 2 nearest the waist axis), the reach radii of the solved point
        in the arm plane and the largest distance of the tool from the box centre [mm]; a
        pose arm: the tool point's distance from the solved point (``tool_offset``)."""
        g = self._points(numpy_ops, P)
        la, lb = float(g["la"]), float(g["lb"])
        centre, half = self._box(numpy_ops, g)
        out = {
            "shoulder": tuple(float(v) for v in g["S"]),
            "reach_outer": la + lb,
            "reach_inner": abs(la - lb),
            "reach_tool": max(float(v) for v in half),
            "box_centre": tuple(float(v) for v in centre),
            "box_half": tuple(float(v) for v in half),
        }
        if "tool" in g:
            out["tool_offset"] = float(np.sqrt(float(sp.norm_sq(g["tool"]))))
        return out

    def ik(
        self, m, p, P, *, tol, axis_tol=None, margin_rad=0.0, theta1_on_axis=None, precise=False
    ):
        """The closed form (:meth:`solve_target`); a 5R arm's ``ik`` is :meth:`ik_pose`
        (set in ``__init__``: the contract reads an arm's options off the signature of its
        ``ik``). ``margin_rad`` widens a six-axis wrist's flip band (:mod:`.wrist`)."""
        return self.solve_target(m, p, P, tol=tol, axis_tol=axis_tol, margin_rad=margin_rad,
                                 theta1_on_axis=theta1_on_axis, precise=precise)  # fmt: skip

    def ik_pose(
        self,
        m,
        p,
        P,
        *,
        tol,
        axis_tol=None,
        margin_rad=0.0,
        theta1_on_axis=None,
        orientation_tol="default",
        precise=False,
    ):
        """The closed form of a 5R arm (a pose): :meth:`solve_target`."""
        return self.solve_target(
            m, p, P, tol=tol, axis_tol=axis_tol, margin_rad=margin_rad,
            theta1_on_axis=theta1_on_axis, orientation_tol=orientation_tol, precise=precise,
        )  # fmt: skip

    def solve_target(
        self,
        m,
        p,
        P,
        *,
        tol,
        axis_tol=None,
        margin_rad=0.0,
        theta1_on_axis=None,
        orientation_tol="default",
        precise=False,
    ):
        """Every branch for target ``p`` (a point [mm]; a pose arm: a pose, position [mm]
        and RPY angles [rad] of seed 004's eq. 3.14), in namespace ``m``.

        Returns ``branches`` {name: (q1..qn)} [rad], ``refusals`` [(Status, condition)] in
        priority order, ``branch_refusals`` {name: [...]} where branches differ,
        ``outside`` (signed distance outside the reach [mm]), ``wrist`` {"front"/"back":
        the solved point turned back to theta1 = 0} and, for a six-axis arm, ``flip``
        {branch: the sine of the wrist's angle from its flip}. ``tol``, ``axis_tol``,
        ``margin_rad`` and ``theta1_on_axis`` as for every closed form
        (:mod:`analysis.kinematics.arms`); ``orientation_tol`` (5R) [rad]: the largest
        accepted angle of the roll axis out of reach, None to project onto the nearest;
        ``precise``: the bend from 1 -/+ cos in factored form (:func:`.subproblems.pk3_cos`).
        """
        axis_tol = tol if axis_tol is None else axis_tol
        g = self._points(m, P)
        pos, w, cols = self._solved_point(m, p, g)
        refusals, ctx = self._reach(m, g, pos, w, tol)
        sides, cyl = self._waist(m, g, w, tol, axis_tol, theta1_on_axis, refusals, ctx)
        limit = None
        if self.family == "5R":
            limit = self._orientation(m, sides, cols, margin_rad, orientation_tol, refusals)
        ctx.update(cols=cols, tol=tol, axis_tol=axis_tol, precise=precise, limit=limit,
                   band=wr.wrist_band(margin_rad))  # fmt: skip
        branches, conds, outsides, flips = {}, {}, [], {}
        for side, v in sides.items():
            for _, arm in self._arms(m, g, v, side, ctx):
                outsides.append(arm.get("outside"))
                for name, (q, extra) in arm["branches"].items():
                    branches[name] = (v["theta1"], *q)
                    conds[name] = [*arm["conds"], *extra]
                    if "flip" in arm:
                        flips[name] = arm["flip"][name]
        branches = {b: branches[b] for b in self.BRANCHES}
        out = {"branches": branches, "refusals": refusals}
        if any(conds.values()):
            out["branch_refusals"] = {b: conds[b] for b in self.BRANCHES}
        if ctx["d"] is not None:
            outside = m.select(m.gt(ctx["beyond"], ctx["within"]), ctx["beyond"], ctx["within"])
        else:
            outside = outsides[0]
            for o in outsides[1:]:
                outside = m.select(m.lt(outside, o), outside, o)
        if cyl is not None:
            outside = m.select(m.gt(cyl, tol), cyl, outside)
        out["outside"] = outside
        out["wrist"] = {s: (v["w"]) for s, v in sides.items()}
        if self.family == "5R":
            out["off_plane"] = sides["front"]["off"]
        if flips:
            out["flip"] = flips
        return out

    def _orientation(self, m, sides, cols, margin_rad, orientation_tol, refusals):
        """5R: where the pose puts the roll axis, turned back by each side's waist (``a``)
        and its offset from the arm plane (``off``); the largest accepted sine of that
        offset (None: project), refused here where the plane is the same for both sides."""
        st, u, w1 = self.structure, self._u, self._w1
        a_req = apply_columns(cols, mat_vec(self._R0T, self._w5))  # where the pose puts it
        for side, v in sides.items():
            v["a"] = sp.rotate(w1, a_req, v["c1"], -v["s1"])
            v["off"] = m.let(f"off_{side}", sp.dot(u, v["a"]) - self._c5)
        tol_o = st.orientation_tol if orientation_tol == "default" else orientation_tol
        limit = None
        if tol_o is not None:
            narrowed = float(tol_o) - float(margin_rad)
            if not narrowed > 0:
                raise ValueError(
                    f"orientation_tol = {tol_o} rad leaves nothing after the margin "
                    f"{margin_rad} rad"
                )
            limit = math.sin(min(narrowed, math.pi / 2))
        if self.orient_global and limit is not None:
            m.section("orientation: the roll axis must lie in the arm plane")
            refusals.append((Status.ORIENTATION, m.gt(m.abs(sides["front"]["off"]), limit)))
        return limit

    def _arms(self, m, g, v, side, ctx):
        """The arm branches of one waist side: ``(tag, arm)`` with ``arm["branches"]``
        {name: (joints 2.., extra refusals)}, ``arm["conds"]`` (what the arm part cannot do)
        and ``arm["outside"]``; one per side, a six-axis arm of the UR family one per side
        and wrist (the pitch depends on the wrist)."""
        fam, cols = self.family, ctx["cols"]
        if fam == "6R-parallel":
            a6 = apply_columns(cols, mat_vec(self._R0T, self.structure.axes[5]))
            a6_1 = sp.rotate(self._w1, a6, v["c1"], -v["s1"])
            q5s, flip = wr.ur_q5(m, self._u, self._w5, tuple(self.structure.axes[5]), a6_1, side)
            turned = None
            for wrist, (q5, c5, s5) in zip(wr.WRISTS, q5s, strict=True):
                tag = f"{side}_{wrist}"
                q5 = m.let(f"theta5_{tag}", q5)
                if turned is None:
                    q6, a5_1 = wr.ur_pitch(m, self, cols, v["c1"], v["s1"], (c5, s5), tag)
                    psi, cp, spsi, _ = self._pitch(m, a5_1, tag)
                    turned = (q6, psi, cp, spsi)
                else:  # the flipped wrist: q6 and the pitch half a turn on (wr.flipped)
                    q6 = m.let(f"theta6_{tag}", wr.half_turn(m, turned[0]))
                    psi = m.let(f"psi_{tag}", wr.half_turn(m, turned[1]))
                    cp, spsi = -turned[2], -turned[3]
                arm = {**v, "psi": psi, "cp": cp, "sp": spsi, "conds": []}
                elbows = self._plane_elbows(m, g, arm, side, tag, ctx)
                extra = [(Status.DEGENERATE, m.le(flip, ctx["band"]))]
                arm["branches"] = {f"{side}-{e}-{wrist}": ((*q, q5, q6), extra)
                                   for e, q in elbows.items()}  # fmt: skip
                arm["flip"] = dict.fromkeys(arm["branches"], flip)
                yield tag, arm
            return
        arm = {**v, "conds": []}
        if fam == "5R":
            m.section(f"{side}: the pitch about the parallel axes (PK1), the roll (PK1)")
            if ctx["limit"] is not None and not self.orient_global:
                arm["conds"].append((Status.ORIENTATION, m.gt(m.abs(v["off"]), ctx["limit"])))
            psi, cp, spsi, r5 = self._pitch(m, v["a"], side)
            n_req = apply_columns(cols, mat_vec(self._R0T, self._n5))
            n1 = sp.rotate(self._u, sp.rotate(self._w1, n_req, v["c1"], -v["s1"]), cp, -spsi)
            arm.update(psi=psi, cp=cp, sp=spsi, r5=r5,
                       q5=m.wrap(sp.pk1(m, self._w5, self._n5, n1)))  # fmt: skip
        elif fam == "4R-kept":
            arm["psi"], arm["cp"], arm["sp"] = self.structure.keep
        turns = {"up": [], "down": []} if fam == "6R-wrist" else None
        elbows = self._plane_elbows(m, g, arm, side, side, ctx, turns)
        if fam == "6R-wrist":
            arm["branches"], arm["flip"] = {}, {}
            for e, (q2, q3) in elbows.items():
                sols, flip = wr.spherical(m, self.structure.axes, self._R0T, cols,
                                          [(v["c1"], v["s1"]), *turns[e]], f"{side}_{e}")
                extra = [(Status.DEGENERATE, m.le(flip, ctx["band"]))]
                for wrist, q in sols.items():
                    arm["branches"][f"{side}-{e}-{wrist}"] = ((q2, q3, *q), extra)
                    arm["flip"][f"{side}-{e}-{wrist}"] = flip
        else:
            tail = (arm["q5"],) if fam == "5R" else ()
            arm["branches"] = {f"{side}-{e}": ((*q, *tail), []) for e, q in elbows.items()}
        yield side, arm

    def _plane_elbows(self, m, g, arm, side, tag, ctx, turns=None) -> dict:
        """The arm plane's reach and both elbows: {"up": joints 2.., "down": ...}; ``turns``
        {"up": [], "down": []} receives each elbow's joint 2 and 3 cosines and sines."""
        t, c, gam, sg = self._plane(m, g, arm, tag, ctx, ctx["tol"], ctx["axis_tol"],
                                    ctx["precise"])  # fmt: skip
        out = {}
        for elbow in ("up", "down"):
            s = self.s_up[side] * (1.0 if elbow == "up" else -1.0)
            out[elbow] = self._elbow(m, g, t, c, gam, sg, s, arm, tag, elbow,
                                     None if turns is None else turns[elbow])  # fmt: skip
        return out

    def refusal(self, status: Status, p, P, *, tol: float, distance: float) -> tuple[str, float]:
        """The one-line reason a target is refused, naming it and the limit crossed, and
        the limit [mm] (NaN where no length is crossed)."""
        geo = self.geometry(P)
        pose = tuple(float(v) for v in p)
        where = self.where(pose)
        sh = fmt(geo["shoulder"])
        if status == Status.OUT_OF_REACH:
            rel = np.abs(np.subtract(pose[:3], geo["box_centre"]))
            over = rel - np.asarray(geo["box_half"])
            if over.max() > tol:
                k = int(np.argmax(over))
                return (
                    f"{where} is {over[k]:.3f} mm beyond the reach of {geo['box_half'][k]:g} mm "
                    f"in {'xyz'[k]} around {fmt(geo['box_centre'])} mm: no configuration "
                    "reaches it"
                ), geo["box_half"][k]
            return (
                f"{where} puts the wrist {distance:.3f} mm beyond the reach of "
                f"{geo['reach_outer']:g} mm (the two links across the parallel axes) around "
                f"the shoulder at {sh} mm"
            ), geo["reach_outer"]
        if status == Status.INSIDE_REACH:
            return self._inside_reason(where, pose, P, geo, tol, distance)
        if status == Status.BASE_AXIS:
            what = "puts the wrist centre on" if self.family in SIX else "lies on"
            return (
                f"{where} {what} the waist axis (within {tol:g} mm): theta1 is undefined "
                "there; choose the waist angle to use (theta1_on_axis)"
            ), float("nan")
        if status == Status.DEGENERATE:
            return self._degenerate_reason(where, pose, P, tol), 0.0
        if status == Status.ORIENTATION:
            with np.errstate(all="ignore"):
                sol = self.solve_target(numpy_ops, pose, dict(P), tol=tol, orientation_tol=None)
            off = abs(float(sol["off_plane"]))
            return (
                f"{where} asks for a roll axis {math.degrees(math.asin(min(1.0, off))):.3f} deg "
                "out of the set a 5-DOF arm can turn it to (accepted: "
                f"{math.degrees(self.structure.orientation_tol):.2g} deg); {PROJECTION_HINT}"
            ), float("nan")
        raise ValueError(f"no message for status {status!r}")

    def _inside_reason(self, where, pose, P, geo, tol, distance):
        if not self.lateral_zero:
            g = self._points(numpy_ops, P)
            with np.errstate(all="ignore"):
                w = self._solved_point(numpy_ops, pose, g)[1]
            x = np.subtract([float(c) for c in w], [float(c) for c in g["q1"]])
            rho = float(np.hypot(np.dot(x, self._g1), np.dot(x, self._e)))
            lat = float(abs((float(g["hq1"]) - self._uw1 * float(np.dot(x, self._w1))) / self._nu))
            if rho < lat - tol:
                return (
                    f"{where} is {lat - rho:.3f} mm inside the cylinder of radius "
                    f"{lat:g} mm around the waist axis that the arm's lateral offset "
                    "keeps every reachable point out of"
                ), lat
        sh = fmt(geo["shoulder"])
        return (
            f"{where} puts the wrist {distance:.3f} mm inside the inner reach of "
            f"{geo['reach_inner']:g} mm (|La - Lb|) around the shoulder at {sh} mm"
        ), geo["reach_inner"]

    def _degenerate_reason(self, where, pose, P, tol) -> str:
        if self.family in SIX:
            with np.errstate(all="ignore"):
                sol = self.solve_target(numpy_ops, pose, dict(P), tol=tol)
            flip = min(float(np.asarray(f)) for f in sol["flip"].values())
            if flip <= FLIP_MESSAGE_RAD:
                axes = "4 and 6" if self.family == "6R-wrist" else "6 and 2-4"
                return (
                    f"{where} puts the wrist at its flip (axes {axes} aligned, "
                    f"{math.degrees(math.asin(min(1.0, flip))):.3g} deg apart): the pose sets "
                    "only the sum of their turns, not each"
                )
        return (
            f"{where} puts the wrist on the shoulder axis (the two links are equal): "
            "theta2 is undefined"
        )
