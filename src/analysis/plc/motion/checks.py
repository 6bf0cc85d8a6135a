"""The numbers an S7-200 scenario's trace is held to (issue 29 item 4), computed apart from
the program. :func:`check` returns what failed, one line each (empty: all held).

From the ST machine's checks (:mod:`analysis.plc.machine.checks`, on
:meth:`~.scenarios.Trace.machine_trace`): the final positions equal the float64 IK within one
pulse (an unlimited joint modulo a turn), nothing moves where nothing may, a stop comes to
rest within the braking distance plus ``v x cycle`` (the S7-200 aborts its trains: only what
they emit until the scan that reads the stop) and never moves again, no move turns an
unlimited joint more than half a turn, the outputs at the scenario's times.

The S7-200's own, at the pulses (the scan-averaged positions the ST checks see step by
whole pulses, too coarse for a ramp):

* every train within ``max_velocity`` and ``max_acceleration``: the rate between two pulses
  ``1/p`` and its change between two pulse intervals ``2 (p_k - p_k+1) / (p_k p_k+1 (p_k +
  p_k+1))`` (:func:`ramp_extremes`);
* no step in the wrong direction (a direction that changed under a running train), no pulse
  lost between open relays or sent to two drivers;
* the waist's steps in a window (the long way round a limited joint).
"""

from __future__ import annotations

import numpy as np

from analysis.plc.machine.checks import (
    check_final,
    check_outputs,
    check_short_way,
    check_still,
    check_stop,
)
from analysis.plc.machine.spec import machine_spec
from analysis.plc.motion.scenarios import S7Case, Trace

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


def check(trace: Trace, case: S7Case, arm) -> list[str]:
    """What ``trace`` of ``case`` on ``arm`` gets wrong (module docstring)."""
    spec, e = machine_spec(arm), case.scenario.expect
    mt = trace.machine_trace()
    bad = [f"the CPU went to STOP: {trace.fault}"] if trace.fault else []
    if e.final is not None:
        bad += check_final(mt, spec, e.final)
    for t0, t1 in e.still:
        bad += check_still(mt, spec, t0, t1)
    if e.stop_t is not None:
        bad += check_stop(mt, spec, e.stop_t, e.stop_until)
    bad += check_short_way(mt, spec)
    bad += check_outputs(mt, e.outputs)
    for j, ax in enumerate(spec.axes):
        f, a = ramp_extremes(trace, j)
        f_lim, a_lim = ax.max_velocity / ax.per_pulse, ax.max_acceleration / ax.per_pulse
        if f > f_lim * (1 + 1e-9):
            bad.append(f"{ax.joint} stepped at {f:.1f} pulses/s, max_velocity is {f_lim:.1f}")
        if a > a_lim * (1 + 1e-9):
            bad.append(f"{ax.joint} accelerated by {a:.0f} pulses/s^2, max_acceleration is "
                       f"{a_lim:.0f}")  # fmt: skip
    d = trace.drives
    if d.wrong_direction():
        bad.append(f"{d.wrong_direction()} steps in the wrong direction")
    if d.lost or d.doubled:
        bad.append(f"{d.lost} PTO1 pulses reached no driver, {d.doubled} two")
    if case.waist_steps is not None:
        t0, want = case.waist_steps
        got = sum(1 for t, j, *_ in d.steps if j == 0 and t >= t0)
        if abs(got - want) > 1:
            bad.append(f"the waist stepped {got} times after {t0} s, expected {want}")
    return [f"{case.name}: {m}" for m in bad]
