"""The machine scenarios of issue 29 item 4 and the checks that hold a run to numbers computed
apart from the program: for every engine (the ST engine from ST and from PLCopen XML here; the
S7-200 evaluator and awlsim reuse the definitions and the checks).

A :class:`Scenario` is what an operator does (rows ``t_s, name, value``: the machine's inputs
by their contract names, :mod:`.spec`) and what must follow (:class:`Expect`). A :class:`Trace`
is one row per cycle: ``t`` [s], ``q`` and ``v`` (cycles, joints) in joint units (deg or mm,
per second) and the program's outputs by name; :meth:`Trace.from_csv` reads ``stl-run
--trace``. :func:`check` runs every check a scenario names and returns the failures (an empty
list: it passed); each check is also a function of its own:

- :func:`check_final`: the final joint positions equal the IK of the target (float64 closed
  form, eqs. 20-22's pulses) within one pulse (an unlimited revolute joint modulo 360 deg);
- :func:`check_limits`: velocity, acceleration and jerk, as finite differences of the
  positions (exact bounds: a divided difference is a mean of the derivative), within each
  joint's limits;
- :func:`check_sync`: each move from rest lasts at least the joint's own time-optimal
  profile (:func:`.profile.min_time`: axes that jump fail) and at most 1.5 times the
  synchronised profile (:func:`.profile.sync_time`), and the joints arrive within one cycle
  of each other;
- :func:`check_stop`: after the stop, each axis comes to rest within
  :func:`.profile.stop_distance` (the jerk-limited braking distance from its velocity and
  acceleration) plus one cycle at its velocity, and never moves again;
- :func:`check_still`: no axis moves at all in a window (a refused command);
- :func:`check_outputs`: an output has a value at a time (Status 101, Homed, ...).

The targets come from joint values (FK computed apart from the program, then the float64
IK of that target gives the expected pulses), seeded, inside the refusal bands' margins.
"""

from __future__ import annotations

import csv
import io
import math
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

from analysis.kinematics.status import Status
from analysis.plc.machine.profile import min_time, stop_distance, sync_limits, sync_time
from analysis.plc.machine.spec import MachineSpec, machine_spec

__all__ = [
    "SCENARIOS",
    "Expect",
    "Scenario",
    "Trace",
    "check",
    "check_final",
    "check_limits",
    "check_outputs",
    "check_still",
    "check_stop",
    "check_sync",
    "motion_segments",
    "scenarios",
]

SCENARIOS = ("power_home", "move", "retarget", "stop", "reset_resume", "unreachable", "nan",
             "wrap", "joint_limit", "wire_break")  # fmt: skip
"""The scenarios every arm runs (``joint_limit`` only where a joint has limits)."""

HOME_T, START_T = 0.1, 0.5
"""Home's and the first Start's rising edge [s]."""
PULSE_S = 0.1
"""How long a push button stays pressed [s]."""


@dataclass(frozen=True)
class Expect:
    """What a scenario asserts: ``final`` joint positions (None: no move), ``still`` windows
    [s] where nothing moves, ``outputs`` (t, name, value) to read, ``stop_t`` the time the
    stop circuit opens (nothing moves again before ``stop_until``, default the end), ``sync`` which moves from rest are held to the profile: "all" (but a
    stopped one), "last" (a re-planned move: the halt before it is not one), or ""."""

    final: tuple[float, ...] | None = None
    still: tuple[tuple[float, float], ...] = ()
    outputs: tuple[tuple[float, str, float], ...] = ()
    stop_t: float | None = None
    stop_until: float | None = None
    sync: str = "all"


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


@dataclass(frozen=True)
class Trace:
    """One row per cycle (module docstring)."""

    t: npt.NDArray[np.float64]
    q: npt.NDArray[np.float64]
    v: npt.NDArray[np.float64]
    outputs: dict = field(default_factory=dict)

    @property
    def cycle_s(self) -> float:
        return float(self.t[1] - self.t[0]) if len(self.t) > 1 else 0.0

    def at(self, t_s: float) -> int:
        """The row of time ``t_s`` (the first at or after it)."""
        return int(min(np.searchsorted(self.t, t_s - 1e-9), len(self.t) - 1))

    @classmethod
    def from_run(cls, run) -> Trace:
        """From an :class:`analysis.plc.st_engine.MachineRun`."""
        return cls(run.t, run.q, run.v, {n: run.values[:, k] for k, n in enumerate(run.names)})

    @classmethod
    def from_csv(cls, text: str) -> Trace:
        """From the text of ``stl-run --trace`` (``t_s, q1..qN, v1..vN``, then outputs)."""
        rows = list(csv.reader(io.StringIO(text)))
        head, body = rows[0], np.array(rows[1:], dtype=object)
        n = sum(1 for h in head if h[:1] == "q" and h[1:].isdigit())

        def num(col):
            return np.array([_cell(c) for c in body[:, col]], dtype=float)

        outs = {h: num(k) for k, h in enumerate(head) if k > 2 * n}
        q = np.stack([num(1 + k) for k in range(n)], axis=1)
        v = np.stack([num(1 + n + k) for k in range(n)], axis=1)
        return cls(num(0), q, v, outs)


def _cell(c: str) -> float:
    word = c.strip().upper()
    return 1.0 if word == "TRUE" else 0.0 if word == "FALSE" else float(c)


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
    for deg in (179.96, -179.96):
        q = qa.copy()
        q[0] = math.radians(deg)
        wrap.append(q)
    return qa, qb, wrap


def _user_target(arm, q) -> tuple[float, ...]:
    t = arm.target(q)
    return tuple(float(x) for x in np.where([u == "rad" for u in arm.input_units],
                                            np.degrees(t), t))  # fmt: skip


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
    return rows + [(t, "Start", 1.0), (t + PULSE_S, "Start", 0.0)]


def _pulse(t: float, name: str) -> list[tuple[float, str, float]]:
    return [(t, name, 1.0), (t + PULSE_S, name, 0.0)]


def _move_time(spec: MachineSpec, q_from, q_to) -> float:
    d = np.asarray(q_to) - np.asarray(q_from)
    return sync_time(d, *(np.array([getattr(a, k) for a in spec.axes])
                          for k in ("max_velocity", "max_acceleration", "max_jerk")))  # fmt: skip


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
    done = START_T + t_move + 0.5
    mid = START_T + 0.4 * t_move
    out: dict[str, Scenario] = {}
    out["power_home"] = Scenario("power_home", "power up, Start before Home refused, home", (
        *boot[:2], *_start(0.3, ta, spec), *_pulse(0.6, "Home"), (1.2, "Start", 0.0)),
        Expect(still=((0.0, 1.2),), outputs=((0.35, "Status", 101), (0.35, "Homed", 0),
                                              (1.0, "Homed", 1), (1.0, "Busy", 0))))  # fmt: skip
    out["move"] = Scenario("move", "home, move to a target", (*boot, *_start(START_T, ta, spec),
        (done, "Start", 0.0)), Expect(final=ja, outputs=((done, "Done", 1),
                                                         (done, "Status", 0))))  # fmt: skip
    t2 = _move_time(spec, ja, jb) + mid + 0.5 + t_move
    out["retarget"] = Scenario("retarget", "a new target mid-move (re-planned from where the "
        "axes stop)", (*boot, *_start(START_T, ta, spec), *_start(mid, tb, spec),
                       (t2, "Start", 0.0)), Expect(final=jb, sync="last"))  # fmt: skip
    stop_rows = (*boot, *_start(START_T, ta, spec), (mid, "StopOK", 0.0))
    settle = mid + 1.5
    out["stop"] = Scenario("stop", "the stop circuit opens mid-move; closed, Start without "
        "Reset is refused", (*stop_rows, (settle, "StopOK", 1.0), *_start(settle + 0.2, tb, spec),
        (settle + 1.0, "Start", 0.0)), Expect(stop_t=mid, still=((settle, settle + 1.0),),
        outputs=((mid + 0.05, "Status", 102), (settle + 0.25, "Status", 102))))  # fmt: skip
    back = settle + 0.6
    t3 = back + 0.2 + t_move + 0.5
    out["reset_resume"] = Scenario("reset_resume", "stop mid-move, Reset, Start again: the "
        "target is reached", (*stop_rows, (settle, "StopOK", 1.0), *_pulse(settle + 0.2, "Reset"),
        *_start(back, ta, spec), (t3, "Start", 0.0)), Expect(final=ja, stop_t=mid, stop_until=back,
        outputs=((settle + 0.45, "Status", 0), (settle + 0.45, "Error", 0))))  # fmt: skip
    far = tuple(x * 10.0 if k < 3 else x for k, x in enumerate(ta))
    out["unreachable"] = _refused("unreachable", "a target out of reach", boot, far, spec,
                                  Status.OUT_OF_REACH)
    nan = (math.nan, *ta[1:])
    out["nan"] = _refused("nan", "a NaN target", boot, nan, spec, Status.INVALID)
    out.update(_wrap(arm, spec, boot, qw1, qw2))
    lim = _limit_target(arm, spec, qa)
    if lim is not None:
        out["joint_limit"] = _refused("joint_limit", "a target beyond a joint limit", boot, lim,
                                      spec, Status.JOINT_LIMITS)  # fmt: skip
    out["wire_break"] = Scenario("wire_break", "a broken stop wire mid-move: Reset does not "
        "clear it, Start is refused", (*stop_rows, *_pulse(settle, "Reset"),
        *_start(settle + 0.4, ta, spec), (settle + 1.5, "Start", 0.0)),
        Expect(stop_t=mid, still=((settle - 0.2, settle + 1.5),),
               outputs=((settle + 0.45, "Status", 102),
                        (settle + 0.45, "Error", 1))))  # fmt: skip
    return out


def _refused(name, title, boot, target, spec, status) -> Scenario:
    rows = (*boot, *_start(START_T, target, spec), (START_T + 1.0, "Start", 0.0))
    return Scenario(name, title, rows, Expect(still=((0.0, START_T + 1.0),), outputs=(
        (START_T + 0.05, "Status", int(status)), (START_T + 0.05, "Error", 1))))  # fmt: skip


def _wrap(arm, spec, boot, q1, q2) -> dict[str, Scenario]:
    t1, t2 = _user_target(arm, q1), _user_target(arm, q2)
    j1, j2 = expected_joints(arm, spec, t1), expected_joints(arm, spec, t2)
    if j1 is None or j2 is None:
        return {}
    home = tuple(a.home_position for a in spec.axes)
    first = START_T + _move_time(spec, home, j1) + 0.5
    end = first + 1.0
    rows = (*boot, *_start(START_T, t1, spec), *_start(first, t2, spec), (end, "Start", 0.0))
    return {"wrap": Scenario("wrap", "a target across theta1 = +-180 deg: the short way",
                             rows, Expect(final=j2))}


def _limit_target(arm, spec, q):
    """A reachable target (limits ignored) whose default-branch IK leaves a joint's limits,
    or None."""
    for k, a in enumerate(spec.axes):
        if a.unlimited:
            continue
        for beyond in (a.upper + 10.0, a.lower - 10.0):
            qq = arm.joints_to_user(q).copy()
            qq[k] = beyond
            t = _user_target(arm, arm.joints_from_user(qq))
            p = arm.from_user(np.array(t))
            free = arm.solve(p, arm.branches[0], limits=False)
            held = arm.solve(p, arm.branches[0])
            if (int(np.ravel(free.status)[0]) == Status.OK
                    and int(np.ravel(held.status)[0]) == Status.JOINT_LIMITS):  # fmt: skip
                return t
    return None


# --- the checks --------------------------------------------------------------------------------


def _limits(spec: MachineSpec):
    return tuple(np.array([getattr(a, k) for a in spec.axes])
                 for k in ("max_velocity", "max_acceleration", "max_jerk"))  # fmt: skip


def _wrapped(d, spec: MachineSpec):
    """Differences [deg | mm]; an unlimited revolute joint's modulo 360 deg, in (-180, 180]."""
    d = np.array(d, dtype=float)
    for k, a in enumerate(spec.axes):
        if a.unlimited:
            d[..., k] = d[..., k] - 360.0 * np.round(d[..., k] / 360.0)
    return d


def check_final(trace: Trace, spec: MachineSpec, expected) -> list[str]:
    """The last row's joint positions equal ``expected`` within one pulse (module docstring)."""
    err = np.abs(_wrapped(trace.q[-1] - np.asarray(expected), spec))
    step = np.array([a.per_pulse for a in spec.axes])
    bad = np.flatnonzero(err > step * (1 + 1e-9))
    return [f"final {spec.axes[k].joint} = {trace.q[-1, k]:.6g} {spec.axes[k].unit}, the IK "
            f"gives {expected[k]:.6g} (off {err[k] / step[k]:.3g} pulses)" for k in bad]


def check_limits(trace: Trace, spec: MachineSpec, rel: float = 1e-6) -> list[str]:
    """Velocity, acceleration and jerk from the positions' divided differences within each
    joint's limits (a relative ``rel`` for round-off)."""
    dt, out = trace.cycle_s, []
    for order, lim, word in zip((1, 2, 3), _limits(spec), ("velocity", "acceleration", "jerk"),
                                strict=True):  # fmt: skip
        if len(trace.q) <= order:
            continue
        d = np.abs(np.diff(trace.q, n=order, axis=0)) / dt**order
        peak = d.max(axis=0)
        for k in np.flatnonzero(peak > lim * (1 + rel) + 1e-9):
            at = trace.t[int(np.argmax(d[:, k]))]
            out.append(f"{spec.axes[k].joint}: {word} {peak[k]:.6g} {spec.axes[k].unit}/s"
                       f"{'' if order == 1 else order} at t = {at:.3f} s exceeds {lim[k]:g}")
    return out


def motion_segments(trace: Trace, tol: float = 1e-9) -> list[tuple[int, int]]:
    """(first, last) rows of each stretch of motion: rows where some axis changes position,
    separated by at least one row at rest."""
    moving = np.any(np.abs(np.diff(trace.q, axis=0)) > tol, axis=1)
    segs, start = [], None
    for k, m in enumerate(moving):
        if m and start is None:
            start = k
        elif not m and start is not None:
            segs.append((start, k))
            start = None
    if start is not None:
        segs.append((start, len(moving)))
    return segs


def check_sync(trace: Trace, spec: MachineSpec, seg: tuple[int, int],
               arrive_s: float | None = None) -> list[str]:  # fmt: skip
    """A move from rest (rows ``seg``, distances ``d``): each joint takes at least its own
    time-optimal profile (:func:`.profile.min_time`: an axis that jumps fails) and at most
    1.5 times the synchronised one (:func:`.profile.sync_time`) plus two cycles; its peak
    velocity is at most the synchronised profile's ``Vn |d_i|`` (:func:`.profile.
    sync_limits`) and the peaks are in proportion to the distances within 2% (the velocities
    scaled to the longest move); the joints arrive within ``arrive_s`` (default one cycle)."""
    i0, i1 = seg
    dt, (v, a, j) = trace.cycle_s, _limits(spec)
    arrive_s = dt if arrive_s is None else arrive_s
    d = trace.q[i1] - trace.q[i0]
    steps = np.abs(np.diff(trace.q[i0 : i1 + 1], axis=0)) > 1e-9
    moving = np.flatnonzero(np.abs(d) > 1e-9)
    if len(moving) == 0:
        return []
    arrive = {k: int(np.flatnonzero(steps[:, k])[-1]) + 1 for k in moving}
    out = []
    t_sync = sync_time(d, v, a, j)
    vn = sync_limits(d, v, a, j)[0]
    peaks = np.abs(trace.v[i0 : i1 + 1]).max(axis=0)
    for k in moving:
        took, joint, unit = arrive[k] * dt, spec.axes[k].joint, spec.axes[k].unit
        own = min_time(d[k], v[k], a[k], j[k])
        if took < own - dt:
            out.append(f"{joint} moved {d[k]:.6g} {unit} in {took:.3f} s, faster than its "
                       f"limits allow ({own:.3f} s)")
        if took > 1.5 * t_sync + 2 * dt:
            out.append(f"{joint} took {took:.3f} s, the synchronised profile {t_sync:.3f} s")
        if peaks[k] > vn * abs(d[k]) * (1 + 1e-6) + 1e-9:
            out.append(f"{joint} peaked at {peaks[k]:.6g} {unit}/s, above the synchronised "
                       f"profile's {vn * abs(d[k]):.6g}")
    ratio = peaks[moving] / np.abs(d[moving])
    if ratio.max() > 1.02 * ratio.min():
        hi, lo = moving[np.argmax(ratio)], moving[np.argmin(ratio)]
        out.append(f"velocities not in proportion to the distances: {spec.axes[hi].joint} "
                   f"peaks at {ratio.max():.4g}/s of its move, {spec.axes[lo].joint} at "
                   f"{ratio.min():.4g}/s")
    spread = max(arrive.values()) - min(arrive.values())
    if spread * dt > arrive_s + 1e-9:
        late = max(arrive, key=arrive.get)
        out.append(f"the joints arrive {spread} cycles apart ({spec.axes[late].joint} last, at "
                   f"t = {trace.t[i0 + arrive[late]]:.3f} s)")
    return out


def check_stop(trace: Trace, spec: MachineSpec, t_stop: float,
               t_until: float | None = None) -> list[str]:  # fmt: skip
    """After the stop circuit opens at ``t_stop``: each axis comes to rest within its
    jerk-limited braking distance from its velocity and acceleration then (:func:`.profile.
    stop_distance`) plus one cycle at that velocity, has braked at all (an axis that stops
    dead would need more deceleration than its limit: :func:`check_limits`), and does not
    move again before ``t_until``. The rest position counts, not the farthest point: the ST
    engine's MC_Stop/MC_Halt overshoot it and come back (its correction quintic)."""
    k = trace.at(t_stop)
    end = trace.at(t_until) if t_until is not None else len(trace.t) - 1
    dt, (_, a, j) = trace.cycle_s, _limits(spec)
    segs = [s for s in motion_segments(trace) if s[1] > k and s[0] < end]
    rest = segs[0][1] if segs and segs[0][0] <= k + 1 else k
    out = []
    for i, ax in enumerate(spec.axes):
        v0 = trace.v[k, i]
        a0 = (trace.v[k, i] - trace.v[k - 1, i]) / dt if k > 0 else 0.0
        bound = stop_distance(v0, a0, a[i], j[i]) + abs(v0) * dt
        went = abs(trace.q[rest, i] - trace.q[k, i])
        if went > bound * (1 + 1e-6) + 1e-9:
            out.append(f"{ax.joint}: came to rest {went:.6g} {ax.unit} after the stop from "
                       f"{v0:.4g} {ax.unit}/s; the braking distance is {bound:.6g}")
    again = [s for s in segs if s[0] > rest]
    if again:
        out.append(f"moved again after the stop at t = {trace.t[again[0][0]]:.3f} s")
    return out


def check_still(trace: Trace, spec: MachineSpec, t0: float, t1: float) -> list[str]:
    """No axis moves at all between ``t0`` and ``t1``."""
    k0, k1 = trace.at(t0), trace.at(t1)
    moved = np.abs(trace.q[k0 : k1 + 1] - trace.q[k0]).max(axis=0)
    return [f"{spec.axes[k].joint} moved {moved[k]:.6g} {spec.axes[k].unit} between "
            f"t = {t0:g} and {t1:g} s" for k in np.flatnonzero(moved > 0)]


def check_outputs(trace: Trace, expected) -> list[str]:
    """Each ``(t, name, value)``: the output ``name`` holds ``value`` at ``t``."""
    out = []
    for t, name, value in expected:
        got = trace.outputs[name][trace.at(t)]
        if got != value:
            out.append(f"{name} = {got:g} at t = {t:g} s, expected {value:g}")
    return out


def check(scenario: Scenario, trace: Trace, spec: MachineSpec,
          arrive_s: float | None = None) -> list[str]:  # fmt: skip
    """Every check ``scenario`` names (module docstring); the failures, each one line.
    ``arrive_s``: how far apart the joints may arrive (default one cycle)."""
    e = scenario.expect
    out = check_limits(trace, spec)
    if e.final is not None:
        out += check_final(trace, spec, e.final)
    for t0, t1 in e.still:
        out += check_still(trace, spec, t0, t1)
    if e.stop_t is not None:
        out += check_stop(trace, spec, e.stop_t, e.stop_until)
    if e.sync:
        segs = motion_segments(trace)
        segs = segs[-1:] if e.sync == "last" else segs
        k_stop = trace.at(e.stop_t) if e.stop_t is not None else None
        for seg in segs:
            if k_stop is not None and seg[0] <= k_stop <= seg[1]:
                continue  # a stopped move
            if not np.all(np.abs(trace.v[seg[0]]) < 1e-9):
                continue  # not from rest (a halted one continues)
            out += check_sync(trace, spec, seg, arrive_s)
    out += check_outputs(trace, e.outputs)
    return [f"{scenario.name}: {m}" for m in out]
