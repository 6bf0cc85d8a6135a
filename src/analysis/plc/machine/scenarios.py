"""The machine scenarios of issue 29 item 4 and the checks that hold a run to numbers computed
apart from the program: for every engine (the ST engine from ST and from PLCopen XML here; the
S7-200 evaluator and awlsim reuse the definitions and the checks).

A :class:`Scenario` is what an operator does (rows ``t_s, name, value``: the machine's inputs
by their contract names, :mod:`.spec`) and what must follow (:class:`Expect`). A :class:`Trace`
is one row per cycle: ``t`` [s], ``q`` and ``v`` (cycles, joints) in joint units (deg or mm,
per second) and the program's outputs by name; :meth:`Trace.from_csv` reads ``stl-run
--trace``. :func:`check` runs every check a scenario names and returns the failures (an empty
list: it passed); each check is also a function of its own (:mod:`.checks`, re-exported
here):

- :func:`check_final`: the final joint positions equal the IK of the target (float64 closed
  form, eqs. 20-22's pulses) within one pulse (an unlimited revolute joint modulo 360 deg);
- :func:`check_limits`: velocity, acceleration and jerk, as finite differences of the
  positions (exact bounds: a divided difference is a mean of the derivative), within each
  joint's limits;
- :func:`check_sync`: each move from rest lasts at least the joint's own time-optimal
  profile (:func:`.profile.min_time`: axes that jump fail) and at most 1.5 times the
  synchronised profile (:func:`.profile.sync_time`), and the joints arrive within one cycle
  of each other;
- :func:`check_stop`: after the stop (and after the halt of a re-plan), each axis comes to
  rest within :func:`.profile.stop_distance` (the jerk-limited braking distance from its
  velocity and acceleration) plus one cycle at its velocity without moving back on the way,
  and (a stop) never moves again;
- :func:`check_still`: no axis moves at all in a window (a refused command);
- :func:`check_short_way`: no move turns an unlimited joint more than half a turn;
- :func:`check_outputs`: an output has a value at a time (Status 101, Homed, ...).

The targets come from joint values (FK computed apart from the program, then the float64
IK of that target gives the expected pulses), seeded, inside the refusal bands' margins.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from analysis.kinematics.status import Status
from analysis.plc.machine.checks import (
    Trace,
    check_final,
    check_homed,
    check_limits,
    check_outputs,
    check_short_way,
    check_still,
    check_stop,
    check_sync,
    motion_segments,
)
from analysis.plc.machine.plant import homing_bound
from analysis.plc.machine.profile import sync_time
from analysis.plc.machine.spec import MachineSpec, machine_spec

__all__ = [
    "SCENARIOS",
    "Expect",
    "Scenario",
    "Trace",
    "check",
    "check_final",
    "check_homed",
    "check_limits",
    "check_outputs",
    "check_short_way",
    "check_still",
    "check_stop",
    "check_sync",
    "expected_joints",
    "motion_segments",
    "scenarios",
]

SCENARIOS = (
    "handling",
    "axis_error",
    "power_home",
    "move",
    "retarget",
    "stop",
    "reset_resume",
    "unreachable",
    "nan",
    "wrap",
    "joint_limit",
    "wire_break",
)
"""The scenarios every arm runs (``joint_limit`` only where a joint has limits)."""

HOME_T = 0.1
"""Home's rising edge [s]; the first Start follows once every axis is homed
(:func:`.plant.homing_bound`, 0.1 s after it)."""
CYCLE_S = 0.004
"""The task cycle the scenarios are timed for (``stl-run``'s default)."""
PULSE_S = 0.1
"""How long a push button stays pressed [s]."""


@dataclass(frozen=True)
class Expect:
    """What a scenario asserts: ``final`` joint positions (None: no move), ``still`` windows
    [s] where nothing moves, ``outputs`` (t, name, value) to read, ``stop_t`` the time the
    stop circuit opens (nothing moves again before ``stop_until``, default the end),
    ``sync`` which moves from rest are held to the profile: "all" (but a
    stopped one), "last" (a re-planned move: the halt before it is not one), or ""."""

    final: tuple[float, ...] | None = None
    still: tuple[tuple[float, float], ...] = ()
    outputs: tuple[tuple[float, str, float], ...] = ()
    stop_t: float | None = None
    stop_until: float | None = None
    sync: str = "all"
    faulted: tuple[int, float] | None = None
    """(axis index, time): that axis' drive fails then (it stops dead: its limits and braking
    are not the program's)."""
    halt_t: float | None = None
    """A re-plan halts every axis then (MC_Halt): each comes to rest within its braking
    distance and never moves back on the way (:func:`check_stop`, up to its rest)."""
    homed_t: float | None = None
    """Every axis is homed by then (:func:`check_homed`); its homing is held to the limits as
    every move is (:func:`check_limits`), not to the synchronised profile (:func:`check_sync`)."""


@dataclass(frozen=True)
class Scenario:
    name: str
    title: str
    rows: tuple[tuple[float, str, float], ...]
    expect: Expect

    @property
    def end_s(self) -> float:
        """The last row's time (``stl-run`` adds ``--settle-s``)."""
        return max(t for t, _, _ in self.rows)

    def csv(self) -> str:
        """The scenario as ``stl-run --scenario`` reads it (``t_s,name,value``)."""
        out = ["t_s,name,value"]
        for t, name, value in self.rows:
            out.append(f"{t:.6g},{name},{_value(name, value)}")
        return "\n".join(out) + "\n"


_BOOLS = {"Enable", "Home", "Start", "StopOK", "Reset", "Grip"}


def _value(name: str, value: float) -> str:
    if name in _BOOLS:
        return "TRUE" if value else "FALSE"
    return "nan" if math.isnan(value) else repr(float(value))


# --- the scenarios -----------------------------------------------------------------------------


def _targets(arm, spec: MachineSpec, rng: np.random.Generator):
    """Two reachable configurations A, B (default branch, joints a fair way from home), the
    wrap pair across theta1 = +-180 deg, and their targets in the machine's units."""
    from analysis.kinematics.sampling import sample_q

    branch = arm.branches[0]
    qs = sample_q(arm, rng, 64, branch=branch)
    home = np.array([a.home_position for a in spec.axes])
    user = arm.joints_to_user(qs)
    far = np.max(np.abs(user - home) / np.array([a.max_velocity for a in spec.axes]), axis=1)
    order = np.argsort(-far)
    qa, qb = qs[order[0]], qs[order[1]]
    wrap = []
    step = spec.axes[0].per_pulse  # four pulses apart across the cut
    for deg in (180.0 - 2 * step, -180.0 + 2 * step):
        q = qa.copy()
        q[0] = math.radians(deg)
        wrap.append(q)
    return qa, qb, wrap


def _user_target(arm, q) -> tuple[float, ...]:
    t = arm.target(q)
    return tuple(
        float(x) for x in np.where([u == "rad" for u in arm.input_units], np.degrees(t), t)
    )


def expected_joints(arm, spec: MachineSpec, target) -> tuple[float, ...] | None:
    """The joint positions [deg | mm] the machine must reach for ``target`` (machine units):
    the float64 IK of the default branch, as pulses (eqs. 20-22) times each axis' step; None
    if the IK refuses it."""
    p = arm.from_user(np.array(target, dtype=float))
    sol = arm.solve(p, arm.branches[0])
    if int(np.asarray(sol.status).reshape(-1)[0]) != Status.OK:
        return None
    q = np.asarray(sol.theta).reshape(-1, arm.n_joints)[0]
    c = arm.pulses(q)
    return tuple(float(k) * a.per_pulse for k, a in zip(c, spec.axes, strict=True))


def _start(t: float, target, spec: MachineSpec) -> list[tuple[float, str, float]]:
    rows = [(t - 0.05, n, float(x)) for n, x in zip(spec.targets, target, strict=True)]
    return [*rows, (t, "Start", 1.0), (t + PULSE_S, "Start", 0.0)]


def _pulse(t: float, name: str) -> list[tuple[float, str, float]]:
    return [(t, name, 1.0), (t + PULSE_S, name, 0.0)]


def _move_time(spec: MachineSpec, q_from, q_to) -> float:
    d = np.asarray(q_to) - np.asarray(q_from)
    return sync_time(
        d,
        *(
            np.array([getattr(a, k) for a in spec.axes])
            for k in ("max_velocity", "max_acceleration", "max_jerk")
        ),
    )


def scenarios(arm, seed: int = 29) -> dict[str, Scenario]:
    """The scenarios of ``arm`` (:data:`SCENARIOS`; ``joint_limit`` only where it has a
    limited joint whose limit a reachable target crosses)."""
    spec = machine_spec(arm)
    rng = np.random.default_rng(seed)
    qa, qb, (qw1, qw2) = _targets(arm, spec, rng)
    home = tuple(a.home_position for a in spec.axes)
    ta, tb = _user_target(arm, qa), _user_target(arm, qb)
    ja, jb = expected_joints(arm, spec, ta), expected_joints(arm, spec, tb)
    t_move = _move_time(spec, home, ja)
    boot = [(0.0, "Enable", 1.0), (0.0, "StopOK", 1.0), *_pulse(HOME_T, "Home")]
    t_home = homing_bound(spec, CYCLE_S)
    t0 = HOME_T + t_home + 0.1
    done = t0 + t_move + 0.5
    mid = t0 + 0.4 * t_move
    out: dict[str, Scenario] = {}
    out["power_home"] = Scenario(
        "power_home",
        "power up, Start before Home refused, home",
        (
            *boot[:2],
            *_start(0.3, ta, spec),
            *_pulse(0.6, "Home"),
            (0.6 + t_home + 0.2, "Start", 0.0),
        ),
        Expect(
            still=((0.0, 0.6),),
            outputs=(
                (0.35, "Status", 101),
                (0.35, "Homed", 0),
                (0.6 + t_home, "Homed", 1),
                (0.6 + t_home, "Busy", 0),
            ),
            homed_t=0.6 + t_home,
        ),
    )
    out["move"] = Scenario(
        "move",
        "home, move to a target",
        (*boot, *_start(t0, ta, spec), (done, "Start", 0.0)),
        Expect(final=ja, outputs=((done, "Done", 1), (done, "Status", 0))),
    )
    t2 = _move_time(spec, ja, jb) + mid + 0.5 + t_move
    out["retarget"] = Scenario(
        "retarget",
        "a new target mid-move (re-planned from where the axes stop)",
        (*boot, *_start(t0, ta, spec), *_start(mid, tb, spec), (t2, "Start", 0.0)),
        Expect(final=jb, sync="last", halt_t=mid),
    )
    far = tuple(x * 10.0 if k < 3 else x for k, x in enumerate(ta))
    out["unreachable"] = _refused(
        "unreachable", "a target out of reach", boot, t0, far, spec, Status.OUT_OF_REACH
    )
    nan = (math.nan, *ta[1:])
    out["nan"] = _refused("nan", "a NaN target", boot, t0, nan, spec, Status.INVALID)
    out.update(_wrap(arm, spec, boot, t0, qw1, qw2))
    lim = _limit_target(arm, spec, rng)
    if lim is not None:
        out["joint_limit"] = _refused(
            "joint_limit", "a target beyond a joint limit", boot, t0, lim, spec, Status.JOINT_LIMITS
        )
    out.update(_stops(spec, boot, t0, ta, tb, ja, t_move, mid))
    out["handling"] = _handling(spec, boot, t0, ta, tb, ja, jb)
    homed = t0 - 0.05  # every scenario that boots: homed before its first Start
    return {
        k: s
        if s.expect.homed_t is not None
        else replace(s, expect=replace(s.expect, homed_t=homed))
        for k, s in out.items()
    }


def _stops(spec, boot, t0, ta, tb, ja, t_move: float, mid: float) -> dict[str, Scenario]:
    """The stop family: the stop circuit opened mid-move (stop, reset_resume, wire_break)
    and a drive's fault (axis_error)."""
    out: dict[str, Scenario] = {}
    stop_rows = (*boot, *_start(t0, ta, spec), (mid, "StopOK", 0.0))
    settle = mid + 1.5
    out["stop"] = Scenario(
        "stop",
        "the stop circuit opens mid-move; closed, Start without Reset is refused",
        (
            *stop_rows,
            (settle, "StopOK", 1.0),
            *_start(settle + 0.2, tb, spec),
            (settle + 1.0, "Start", 0.0),
        ),
        Expect(
            stop_t=mid,
            still=((settle, settle + 1.0),),
            outputs=((mid + 0.05, "Status", 102), (settle + 0.25, "Status", 102)),
        ),
    )
    back = settle + 0.6
    t3 = back + 0.2 + t_move + 0.5
    out["reset_resume"] = Scenario(
        "reset_resume",
        "stop mid-move, Reset, Start again: the target is reached",
        (
            *stop_rows,
            (settle, "StopOK", 1.0),
            *_pulse(settle + 0.2, "Reset"),
            *_start(back, ta, spec),
            (t3, "Start", 0.0),
        ),
        Expect(
            final=ja,
            stop_t=mid,
            stop_until=back,
            outputs=((settle + 0.45, "Status", 0), (settle + 0.45, "Error", 0)),
        ),
    )
    drive = spec.axes[1].name
    out["axis_error"] = Scenario(
        "axis_error",
        f"{drive}'s drive fails mid-move: every axis stops; after Reset the machine must be "
        "homed again (Start refused)",
        (
            *boot,
            *_start(t0, ta, spec),
            (mid, f"{drive}.PowerOK", 0.0),
            (mid + 0.3, f"{drive}.PowerOK", 1.0),
            *_pulse(settle, "Reset"),
            *_start(settle + 0.4, ta, spec),
            (settle + 1.5, "Start", 0.0),
        ),
        Expect(
            stop_t=mid,
            faulted=(1, mid),
            still=((mid + 1.0, settle + 1.5),),
            outputs=(
                (mid + 0.05, "Status", 103),
                (mid + 0.05, "Error", 1),
                (mid + 0.05, "Homed", 0),
                (settle + 0.45, "Status", 101),
                (settle + 0.45, "Error", 1),
            ),
        ),
    )
    out["wire_break"] = Scenario(
        "wire_break",
        "a broken stop wire mid-move: Reset does not clear it, Start is refused",
        (
            *stop_rows,
            *_pulse(settle, "Reset"),
            *_start(settle + 0.4, ta, spec),
            (settle + 1.5, "Start", 0.0),
        ),
        Expect(
            stop_t=mid,
            still=((settle - 0.2, settle + 1.5),),
            outputs=((settle + 0.45, "Status", 102), (settle + 0.45, "Error", 1)),
        ),
    )
    return out


def _handling(spec, boot, t0, ta, tb, ja, jb) -> Scenario:
    """A handling cycle: move to A, close the gripper (a Start during its dwell is refused,
    nothing moves), move to B, open it."""
    home = tuple(a.home_position for a in spec.axes)
    at_a = t0 + 1.3 * _move_time(spec, home, ja) + 0.3
    dwell = spec.grip_dwell_s
    go_b = at_a + dwell + 0.2
    at_b = go_b + 1.3 * _move_time(spec, ja, jb) + 0.3
    end = at_b + dwell + 0.2
    rows = (*boot, *_start(t0, ta, spec), (at_a, "Grip", 1.0), *_start(at_a + 0.1, tb, spec),
            *_start(go_b, tb, spec), (at_b, "Grip", 0.0), (end, "Start", 0.0))  # fmt: skip
    return Scenario("handling", "move, grip (a Start during the dwell refused), move, release",
        rows, Expect(final=jb, still=((at_a, go_b),), outputs=(
            (at_a + 0.01, "Gripper", 1), (at_a + 0.01, "GripperClosed", 0),
            (at_a + 0.01, "Busy", 1), (at_a + 0.15, "Status", 104),
            (at_a + dwell + 0.05, "GripperClosed", 1), (at_a + dwell + 0.05, "Done", 1),
            (end, "Gripper", 0), (end, "GripperClosed", 0), (end, "Done", 1))))  # fmt: skip


def _refused(name, title, boot, t0, target, spec, status) -> Scenario:
    rows = (*boot, *_start(t0, target, spec), (t0 + 1.0, "Start", 0.0))
    return Scenario(
        name,
        title,
        rows,
        Expect(
            still=((t0 - 0.05, t0 + 1.0),),
            outputs=((t0 + 0.05, "Status", int(status)), (t0 + 0.05, "Error", 1)),
        ),
    )


def _wrap(arm, spec, boot, t0, q1, q2) -> dict[str, Scenario]:
    t1, t2 = _user_target(arm, q1), _user_target(arm, q2)
    j1, j2 = expected_joints(arm, spec, t1), expected_joints(arm, spec, t2)
    if j1 is None or j2 is None:
        return {}
    home = tuple(a.home_position for a in spec.axes)
    first = t0 + _move_time(spec, home, j1) + 0.5
    end = first + 1.0
    rows = (*boot, *_start(t0, t1, spec), *_start(first, t2, spec), (end, "Start", 0.0))
    return {
        "wrap": Scenario(
            "wrap", "a target across theta1 = +-180 deg: the short way", rows, Expect(final=j2)
        )
    }


def _limit_target(arm, spec, rng: np.random.Generator):
    """A target the arm reaches only with a joint beyond its limits (the float64 IK of the
    default branch: JOINT_LIMITS), from joint values drawn past the limits; None if none of
    2000 draws gives one (every joint unrestricted)."""
    if all(a.unlimited for a in spec.axes):
        return None
    lo = np.array(
        [-180.0 if a.unlimited else a.lower - 0.5 * (a.upper - a.lower) for a in spec.axes]
    )
    hi = np.array(
        [180.0 if a.unlimited else a.upper + 0.5 * (a.upper - a.lower) for a in spec.axes]
    )
    q = arm.joints_from_user(lo + (hi - lo) * rng.random((2000, len(spec.axes))))
    q = q[arm.valid_q(q)]
    p = arm.target(q)
    status = np.asarray(arm.solve(p, arm.branches[0]).status)
    hits = np.flatnonzero(status == Status.JOINT_LIMITS)
    return _user_target(arm, q[hits[0]]) if len(hits) else None


def check(
    scenario: Scenario, trace: Trace, spec: MachineSpec, arrive_s: float | None = None
) -> list[str]:
    """Every check ``scenario`` names (module docstring); the failures, each one line.
    ``arrive_s``: how far apart the joints may arrive (default one cycle)."""
    e = scenario.expect
    out = check_limits(trace, spec, skip=e.faulted)
    if e.homed_t is not None:
        out += check_homed(trace, spec, e.homed_t)
    if e.final is not None:
        out += check_final(trace, spec, e.final)
    for t0, t1 in e.still:
        out += check_still(trace, spec, t0, t1)
    if e.stop_t is not None:
        out += check_stop(trace, spec, e.stop_t, e.stop_until,
                          skip=e.faulted[0] if e.faulted else None)  # fmt: skip
    if e.halt_t is not None:  # up to the halt's rest only: the re-planned move follows
        out += check_stop(trace, spec, e.halt_t, e.halt_t + trace.cycle_s)
    out += check_short_way(trace, spec)
    if e.sync:
        segs = motion_segments(trace)
        segs = segs[-1:] if e.sync == "last" else segs
        k_stop = trace.at(e.stop_t) if e.stop_t is not None else None
        for seg in segs:
            if k_stop is not None and seg[0] <= k_stop <= seg[1]:
                continue  # a stopped move
            if e.homed_t is not None and trace.t[seg[0]] < e.homed_t:
                continue  # homing (check_homed)
            if not np.all(np.abs(trace.v[seg[0]]) < 1e-9) or seg[1] >= len(trace.t) - 1:
                continue  # not from rest (a halted one continues), or still moving at the end
            out += check_sync(trace, spec, seg, arrive_s)
    out += check_outputs(trace, e.outputs)
    return [f"{scenario.name}: {m}" for m in out]
