"""The checks of a machine run, each a function over a :class:`Trace` (one row per cycle: ``t``
[s], ``q`` and ``v`` (cycles, joints) in joint units, deg or mm, per second, and the outputs by
name), returning its failures, one line each (an empty list: it holds). The scenarios that
name them are :mod:`.scenarios` (:func:`~.scenarios.check` runs a scenario's); the bounds come
from :mod:`.profile`, computed apart from any engine. Used on the ST engine here and, by the
same definitions, on the S7-200 evaluator and awlsim.

The stop distance (:func:`check_stop`). Issue 29 item 4 asks for "a stop distance within
v^2/2a + v x cycle". That is the braking distance with an unlimited jerk: no jerk-limited
profile can keep it, since the deceleration itself must ramp up (v a / 2j more) and, when
the stop comes while the axis accelerates, the acceleration must first ramp down to zero.
Measured on the ST engine (pyplcopen 0.21.0 with the project's patch, 4 ms, every axis
moving at the stop of the ``stop`` scenario, which comes at cruise; :func:`stop_distances`,
the figures held by ``tests/plc/machine/test_stop_bounds.py``): the rest distance is 1.36 to
3.02 times the issue's bound on the grabber, 1.38 to 2.30 on the palletizer, 1.38 to 4.30 on
the picker, 1.38 to 2.29 on the GR-1, and 0.87 to 0.99 times the jerk-limited bound
(:func:`.profile.stop_distance` from the velocity and acceleration at the stop, with the
joint's deceleration and jerk limits, plus one cycle at that velocity). The jerk-limited
bound is the assertion; the issue's would fail on every arm however well the program
stopped. A bare MC_Stop from a cruise at 90 deg/s (360 deg/s^2, 3600 deg/s^3) comes to rest
at 15.762 deg at 4 ms and 15.75 at 1 ms, the continuous braking distance v^2/2a + v a/2j
being 15.75 deg; the issue's bound is 11.61 deg.

No overrun (:func:`check_stop`: no step back on the way to rest). pyplcopen 0.21.0's MC_Stop
and MC_Halt aim at the continuous braking distance, floor each phase of the profile to whole
cycles and let a final quintic correct the residue; that quintic runs past the rest position
and comes back: 0.04% to 3.7% of the braking distance on the machines (0.71% on the grabber,
0.87% on the palletizer, 3.67% on the picker, 1.58% on the GR-1), a bare MC_Stop from the
cruise above 0.09 deg at 4 ms, 1.5% and 3.6% with a 10 or 100 times larger jerk. A reversal
at the end of a stop is a defect on a real arm, so the engine is built with a patch
(``tools/st-engine/pyplcopen-0.21.0-motion.patch``, applied by ``make st-engine``) that
brakes on a whole-cycle jerk-limited velocity ramp to rest (of those ramps, the one that
travels least): the rest is where the ramp ends,
within the bound, and no axis moves back. The same patch ramps velocity commands, which the
homing searches use (unpatched, a search started at its velocity in one cycle: 31 times the
acceleration limit, 1562 times the jerk limit), so :func:`check_limits` holds acceleration
and jerk from power-up on, homing included.
"""

from __future__ import annotations

import csv
import io
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

from analysis.plc.machine.profile import min_time, stop_distance, sync_limits, sync_time
from analysis.plc.machine.spec import MachineSpec

__all__ = [
    "PLC_COLUMN",
    "Trace",
    "check_final",
    "check_homed",
    "check_limits",
    "check_outputs",
    "check_short_way",
    "check_still",
    "check_stop",
    "check_sync",
    "motion_segments",
    "stop_distances",
]


PLC_COLUMN = "plc_q{}"
"""A trace's column (``stl-run --trace``) of what the PLC reads of axis k: its encoder's
position (:attr:`Trace.pos`)."""


@dataclass(frozen=True)
class Trace:
    """One row per cycle (module docstring)."""

    t: npt.NDArray[np.float64]
    q: npt.NDArray[np.float64]
    v: npt.NDArray[np.float64]
    outputs: dict = field(default_factory=dict)
    pos: npt.NDArray[np.float64] | None = None
    """The encoders' positions (what the PLC reads); None: not recorded (a CSV trace)."""

    @property
    def cycle_s(self) -> float:
        return float(self.t[1] - self.t[0]) if len(self.t) > 1 else 0.0

    def at(self, t_s: float) -> int:
        """The row of time ``t_s`` (the first at or after it)."""
        return int(min(np.searchsorted(self.t, t_s - 1e-9), len(self.t) - 1))

    @classmethod
    def from_run(cls, run) -> Trace:
        """From an :class:`analysis.plc.st_engine.MachineRun`."""
        outs = {n: run.values[:, k] for k, n in enumerate(run.names)}
        return cls(run.t, run.q, run.v, outs, run.pos)

    @classmethod
    def from_csv(cls, text: str) -> Trace:
        """From the text of ``stl-run --trace`` (``t_s, q1..qN, v1..vN``, then outputs, then
        ``plc_q1..plc_qN`` when it has them: :attr:`pos`)."""
        rows = list(csv.reader(io.StringIO(text)))
        head, body = rows[0], np.array(rows[1:], dtype=object)
        n = sum(1 for h in head if h[:1] == "q" and h[1:].isdigit())
        plc = [PLC_COLUMN.format(k + 1) for k in range(n)]

        def num(col):
            return np.array([_cell(c) for c in body[:, col]], dtype=float)

        outs = {h: num(k) for k, h in enumerate(head) if k > 2 * n and h not in plc}
        q = np.stack([num(1 + k) for k in range(n)], axis=1)
        v = np.stack([num(1 + n + k) for k in range(n)], axis=1)
        pos = (np.stack([num(head.index(h)) for h in plc], axis=1)
               if n and all(h in head for h in plc) else None)  # fmt: skip
        return cls(num(0), q, v, outs, pos)


def _cell(c: str) -> float:
    word = c.strip().upper()
    return 1.0 if word == "TRUE" else 0.0 if word == "FALSE" else float(c)


# --- the checks --------------------------------------------------------------------------------


def _limits(spec: MachineSpec):
    return tuple(
        np.array([getattr(a, k) for a in spec.axes])
        for k in ("max_velocity", "max_acceleration", "max_jerk")
    )


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
    return [
        f"final {spec.axes[k].joint} = {trace.q[-1, k]:.6g} {spec.axes[k].unit}, the IK "
        f"gives {expected[k]:.6g} (off {err[k] / step[k]:.3g} pulses)"
        for k in bad
    ]


def check_limits(trace: Trace, spec: MachineSpec, rel: float = 1e-6, skip=None) -> list[str]:
    """Velocity, acceleration and jerk from the positions' divided differences within each
    joint's limits (a relative ``rel`` for round-off), from power-up on: homing included (its
    searches start and stop as every move does); ``skip`` (axis, t): that axis from t on is
    not held (its drive failed and stopped it dead)."""
    dt, out = trace.cycle_s, []
    for order, lim, word in zip(
        (1, 2, 3), _limits(spec), ("velocity", "acceleration", "jerk"), strict=True
    ):
        if len(trace.q) <= order:
            continue
        d = np.abs(np.diff(trace.q, n=order, axis=0)) / dt**order
        if skip is not None:
            d[max(trace.at(skip[1]) - order, 0) :, skip[0]] = 0.0
        peak = d.max(axis=0)
        for k in np.flatnonzero(peak > lim * (1 + rel) + 1e-9):
            at = trace.t[int(np.argmax(d[:, k]))]
            out.append(
                f"{spec.axes[k].joint}: {word} {peak[k]:.6g} {spec.axes[k].unit}/s"
                f"{'' if order == 1 else order} at t = {at:.3f} s exceeds {lim[k]:g}"
            )
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


def check_sync(
    trace: Trace, spec: MachineSpec, seg: tuple[int, int], arrive_s: float | None = None
) -> list[str]:
    """A move from rest (rows ``seg``, distances ``d``): each joint takes at least its own
    time-optimal profile (:func:`.profile.min_time`: an axis that jumps fails) and at most
    1.5 times the synchronised one (:func:`.profile.sync_time`) plus two cycles; its peak
    velocity is at most the synchronised profile's ``Vn |d_i|`` (:func:`.profile.
    sync_limits`) and the peaks are in proportion to the distances within 2% (the velocities
    scaled to the longest move); no joint moves back (no overshoot); the joints arrive within
    ``arrive_s`` (default one cycle)."""
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
            out.append(
                f"{joint} moved {d[k]:.6g} {unit} in {took:.3f} s, faster than its "
                f"limits allow ({own:.3f} s)"
            )
        if took > 1.5 * t_sync + 2 * dt:
            out.append(f"{joint} took {took:.3f} s, the synchronised profile {t_sync:.3f} s")
        back = np.diff(trace.q[i0 : i1 + 1, k]) * np.sign(d[k])
        if back.min() < -1e-9:
            out.append(
                f"{joint} moved back {-back.min():.3g} {unit} in one cycle during its "
                "move (an overshoot)"
            )
        if peaks[k] > vn * abs(d[k]) * (1 + 1e-6) + 1e-9:
            out.append(
                f"{joint} peaked at {peaks[k]:.6g} {unit}/s, above the synchronised "
                f"profile's {vn * abs(d[k]):.6g}"
            )
    ratio = peaks[moving] / np.abs(d[moving])
    if ratio.max() > 1.02 * ratio.min():
        hi, lo = moving[np.argmax(ratio)], moving[np.argmin(ratio)]
        out.append(
            f"velocities not in proportion to the distances: {spec.axes[hi].joint} "
            f"peaks at {ratio.max():.4g}/s of its move, {spec.axes[lo].joint} at "
            f"{ratio.min():.4g}/s"
        )
    spread = max(arrive.values()) - min(arrive.values())
    if spread * dt > arrive_s + 1e-9:
        late = max(arrive, key=arrive.get)
        out.append(
            f"the joints arrive {spread} cycles apart ({spec.axes[late].joint} last, at "
            f"t = {trace.t[i0 + arrive[late]]:.3f} s)"
        )
    return out


def _rest_row(trace: Trace, k: int, end: int) -> tuple[int, list]:
    segs = [s for s in motion_segments(trace) if s[1] > k and s[0] < end]
    return (segs[0][1] if segs and segs[0][0] <= k + 1 else k), segs


def stop_distances(trace: Trace, spec: MachineSpec, t_stop: float, t_until=None) -> list[dict]:
    """Per axis after the stop at ``t_stop``: its velocity ``v0`` and acceleration ``a0`` then,
    the distance to its ``rest`` position and to its ``farthest`` point, the jerk-limited
    bound (:func:`.profile.stop_distance` plus one cycle at ``v0``) and the issue's
    (``v0^2 / 2a`` plus one cycle): module docstring."""
    k = trace.at(t_stop)
    end = trace.at(t_until) if t_until is not None else len(trace.t) - 1
    dt, (_, a, j) = trace.cycle_s, _limits(spec)
    rest, _ = _rest_row(trace, k, end)
    out = []
    for i, ax in enumerate(spec.axes):
        v0 = float(trace.v[k, i])
        a0 = float((trace.v[k, i] - trace.v[k - 1, i]) / dt) if k > 0 else 0.0
        out.append({
            "joint": ax.joint, "v0": v0, "a0": a0,
            "rest": float(abs(trace.q[rest, i] - trace.q[k, i])),
            "farthest": float(np.abs(trace.q[k : rest + 1, i] - trace.q[k, i]).max()),
            "jerk_bound": stop_distance(v0, a0, a[i], j[i]) + abs(v0) * dt,
            "issue_bound": v0 * v0 / (2.0 * a[i]) + abs(v0) * dt,
        })  # fmt: skip
    return out


def check_stop(
    trace: Trace, spec: MachineSpec, t_stop: float, t_until: float | None = None, skip=None
) -> list[str]:
    """After the stop circuit opens at ``t_stop``: each axis comes to rest within its
    jerk-limited braking distance from its velocity and acceleration then (:func:`.profile.
    stop_distance`) plus one cycle at that velocity, has braked at all (an axis that stops
    dead would need more deceleration than its limit: :func:`check_limits`), never moves
    back on its way to rest (its velocity keeps its sign: no overrun and return), and does
    not move again before ``t_until`` (module docstring: the bound, not the issue's
    v^2/2a + v x cycle, and why)."""
    k = trace.at(t_stop)
    end = trace.at(t_until) if t_until is not None else len(trace.t) - 1
    rest, segs = _rest_row(trace, k, end)
    out = []
    for i, (ax, d) in enumerate(zip(spec.axes, stop_distances(trace, spec, t_stop, t_until),
                                    strict=True)):  # fmt: skip
        if i == skip:
            continue  # its drive failed: stopped dead, not braked by the program
        if d["rest"] > d["jerk_bound"] * (1 + 1e-6) + 1e-9:
            out.append(
                f"{ax.joint}: came to rest {d['rest']:.6g} {ax.unit} after the stop from "
                f"{d['v0']:.4g} {ax.unit}/s; the braking distance is {d['jerk_bound']:.6g}"
            )
        back = _moved_back(trace.q[k : rest + 1, i], d["v0"])
        if back is not None:
            out.append(
                f"{ax.joint}: moved back {back[1]:.3g} {ax.unit} at t = "
                f"{trace.t[k + back[0]]:.3f} s while stopping from {d['v0']:.4g} {ax.unit}/s "
                f"(it ran {d['farthest'] - d['rest']:.3g} {ax.unit} past its rest position)"
            )
    again = [s for s in segs if s[0] > rest]
    if again:
        out.append(f"moved again after the stop at t = {trace.t[again[0][0]]:.3f} s")
    return out


def _moved_back(q, v0: float, tol: float = 1e-9) -> tuple[int, float] | None:
    """(row, distance) of the largest step of ``q`` against the direction of ``v0`` (the
    velocity at the stop; 0: the direction of the first step), None if it never moves back."""
    steps = np.diff(q)
    sign = np.sign(v0) or np.sign(steps[np.flatnonzero(np.abs(steps) > tol)][:1]).sum()
    back = -steps * sign
    k = int(np.argmax(back)) if len(back) else 0
    return (k + 1, float(back[k])) if sign and len(back) and back[k] > tol else None


def check_homed(trace: Trace, spec: MachineSpec, t_s: float) -> list[str]:
    """At ``t_s`` (homing done) every axis stands on its home position within one pulse (the
    physical position) and its encoder reads the home position (to 1e-9; the PLC's position:
    a stale count not re-referenced fails)."""
    k, out = trace.at(t_s), []
    for i, a in enumerate(spec.axes):
        off = trace.q[k, i] - a.home_position
        if abs(off) > a.per_pulse * (1 + 1e-9):
            out.append(
                f"{a.joint} homed at {trace.q[k, i]:.6g} {a.unit}, "
                f"{off / a.per_pulse:.3g} pulses off its home {a.home_position:g}"
            )
        if trace.pos is not None and abs(trace.pos[k, i] - a.home_position) > 1e-9:
            out.append(
                f"{a.joint}: the PLC reads {trace.pos[k, i]:.6g} {a.unit} after homing, "
                f"not its home position {a.home_position:g}"
            )
    return out


def check_still(trace: Trace, spec: MachineSpec, t0: float, t1: float) -> list[str]:
    """No axis moves at all between ``t0`` and ``t1``."""
    k0, k1 = trace.at(t0), trace.at(t1)
    moved = np.abs(trace.q[k0 : k1 + 1] - trace.q[k0]).max(axis=0)
    return [
        f"{spec.axes[k].joint} moved {moved[k]:.6g} {spec.axes[k].unit} between "
        f"t = {t0:g} and {t1:g} s"
        for k in np.flatnonzero(moved > 0)
    ]


def check_short_way(trace: Trace, spec: MachineSpec) -> list[str]:
    """No move turns an unlimited revolute joint by more than half a turn (the short way:
    never a spurious revolution)."""
    out = []
    for i0, i1 in motion_segments(trace):
        for k, a in enumerate(spec.axes):
            went = abs(trace.q[i1, k] - trace.q[i0, k])
            if a.unlimited and went > 180.0 + a.per_pulse:
                out.append(
                    f"{a.joint} turned {went:.6g} deg in one move from t = "
                    f"{trace.t[i0]:.3f} s: not the short way"
                )
    return out


def check_outputs(trace: Trace, expected) -> list[str]:
    """Each ``(t, name, value)``: the output ``name`` holds ``value`` at ``t``."""
    out = []
    for t, name, value in expected:
        got = trace.outputs[name][trace.at(t)]
        if got != value:
            out.append(f"{name} = {got:g} at t = {t:g} s, expected {value:g}")
    return out
