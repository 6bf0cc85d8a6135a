"""The numbers a scenario's trace is held to (issue 29 item 4), computed apart from the
program: the IK's counts (:func:`~.scenarios.ik_counts`), the joints' limits from the arm
description, the scan time. :func:`check` returns what failed, one line each (empty: all
held).

* final positions equal the IK within one pulse (modulo a turn for an unlimited joint);
* no step where no motion is allowed; a stop: no step after the first scan that reads it
  (the S7-200 aborts the trains at PLS: the stop distance is at most ``v x scan``, what the
  trains emit between the input's change and that scan);
* every train within ``max_velocity`` and ``max_acceleration``, from its pulse times: the
  rate between two pulses ``1/p`` and the change of rate between two pulse intervals
  ``2 (p_k - p_k+1) / (p_k p_k+1 (p_k + p_k+1))``;
* no step in the wrong direction (a direction that changed under a running train), no pulse
  lost between open relays or sent to two drivers;
* the status and the outputs at the times the scenario names.
"""

from __future__ import annotations

import math

import numpy as np

from analysis.plc.motion.scenarios import Scenario, Trace

__all__ = ["check", "ramp_extremes"]


def ramp_extremes(trace: Trace, joint: int) -> tuple[float, float]:
    """The largest step rate [pulses/s] and rate change [pulses/s^2] of ``joint``'s trains."""
    steps = [(t, ch, k) for t, j, _s, ch, k in trace.drives.steps if j == joint]
    f_max = a_max = 0.0
    for key in {(ch, k) for _t, ch, k in steps}:
        t = np.array([s[0] for s in steps if (s[1], s[2]) == key])
        if len(t) < 2:
            continue
        p = np.diff(t)
        f_max = max(f_max, float((1 / p).max()))
        if len(p) > 1:
            a = 2 * (p[:-1] - p[1:]) / (p[:-1] * p[1:] * (p[:-1] + p[1:]))
            a_max = max(a_max, float(np.abs(a).max()))
    return f_max, a_max


def _steps_between(trace: Trace, t0: float, t1: float) -> int:
    return sum(t0 <= s[0] < t1 for s in trace.drives.steps)


def check(trace: Trace, sc: Scenario, arm, scan_s: float) -> list[str]:
    """What ``trace`` of scenario ``sc`` on ``arm`` gets wrong (module docstring)."""
    bad, e = [], sc.expect
    joints = arm.description.joints
    ppr = np.array([j.pulses_per_rev for j in joints])
    final = trace.counts[-1]
    if trace.fault:
        bad.append(f"{sc.name}: the CPU went to STOP: {trace.fault}")
    if "final" in e:
        off = np.abs(final - np.array(e["final"]))
        unl = np.array([j.unlimited for j in joints])
        off = np.where(unl, np.minimum(off % ppr, ppr - off % ppr), off)
        if (off > 1).any():
            bad.append(f"{sc.name}: final counts {final.tolist()}, the IK's {list(e['final'])}")
    if "final_mod" in e:
        off = (final - np.array(e["final_mod"])) % ppr
        if (np.minimum(off, ppr - off) > 1).any():
            bad.append(f"{sc.name}: final counts {final.tolist()} are not the IK's "
                       f"{list(e['final_mod'])} modulo a turn")  # fmt: skip
    for t, want in e.get("final_at", ()):
        got = trace.counts[trace.at(t)]
        if (np.abs(got - np.array(want)) > 1).any():
            bad.append(f"{sc.name}: counts {got.tolist()} at {t} s, expected {list(want)}")
    if "no_motion" in e:
        t0, t1 = e["no_motion"]
        n = _steps_between(trace, t0, t1)
        if n:
            bad.append(f"{sc.name}: {n} steps between {t0} and {t1} s, where none may move")
    if "stop_at" in e:
        t_stop, t_until = e["stop_at"]
        t_read = math.ceil(t_stop / scan_s - 1e-9) * scan_s
        n = _steps_between(trace, t_read + 1e-9, t_until)
        if n:
            bad.append(f"{sc.name}: {n} steps after the scan that read the stop ({t_read:.3f} s)")
    if "waist_pulses_after" in e:
        t0, want = e["waist_pulses_after"]
        got = sum(1 for t, j, *_ in trace.drives.steps if j == 0 and t >= t0)
        if abs(got - want) > 1:
            bad.append(f"{sc.name}: the waist stepped {got} times after {t0} s, expected {want}")
    for key, out in (("status", "Status"), ("error", "Error"), ("homed", "Homed"),
                     ("done", "Done")):  # fmt: skip
        if key in e and trace.outputs[out][-1] != e[key]:
            bad.append(f"{sc.name}: {out} = {trace.outputs[out][-1]} at the end, expected {e[key]}")
    for key, out in (("status_at", "Status"), ("done_at", "Done")):
        for t, want in e.get(key, ()):
            got = trace.outputs[out][trace.at(t)]
            if got != want:
                bad.append(f"{sc.name}: {out} = {got} at {t} s, expected {want}")
    for j, spec in enumerate(joints):
        f, a = ramp_extremes(trace, j)
        f_lim = spec.max_velocity * spec.pulses_per_rev / (2 * math.pi)
        a_lim = spec.max_acceleration * spec.pulses_per_rev / (2 * math.pi)
        if f > f_lim * (1 + 1e-9):
            bad.append(f"{sc.name}: joint {spec.name} stepped at {f:.1f} pulses/s, "
                       f"max_velocity is {f_lim:.1f}")  # fmt: skip
        if a > a_lim * (1 + 1e-9):
            bad.append(f"{sc.name}: joint {spec.name} accelerated by {a:.0f} pulses/s^2, "
                       f"max_acceleration is {a_lim:.0f}")  # fmt: skip
    d = trace.drives
    if d.wrong_direction():
        bad.append(f"{sc.name}: {d.wrong_direction()} steps in the wrong direction")
    if d.lost or d.doubled:
        bad.append(f"{sc.name}: {d.lost} PTO1 pulses reached no driver, {d.doubled} two")
    return bad
