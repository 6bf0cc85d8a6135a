"""The issue's scenarios for the S7-200 machine (issue 29 item 4), run on an engine into a
trace: the ST machine's definitions and checks (:mod:`analysis.plc.machine.scenarios`),
with what the S7-200 does differently.

A case is a :class:`~analysis.plc.machine.scenarios.Scenario` (rows ``t_s, name, value`` by
the contract's names, and its :class:`~analysis.plc.machine.scenarios.Expect`) plus what
only the S7-200 needs: the settling time, the operator bringing the arm to its home marks
(``jogs``: home mode "set" declares the present position; without a pulse counter a stopped
move loses it) and, on a joint with limits, the number of waist steps of a move (the long
way). :func:`run` applies each row before the first scan that starts at or after its time
and records, after every scan, the drives' positions and the machine's outputs
(:class:`Trace`; :meth:`Trace.machine_trace` is the ST machine's trace of it: ``t``,
``q`` and ``v`` in deg and deg/s, the outputs, issue 29's TRACE.csv columns).

What differs from the ST machine, by design of the hardware (Table 2, a CPU 224): a Start
during a move is refused (104: the PTO cannot re-plan a running profile and the position
mid-move is unknown), so a target typed mid-move changes nothing of the move; a stop aborts
the trains at once (no deceleration: the stop distance is what the trains emit until the
next scan reads the input, within ``v x scan``) and loses the position, so Reset is followed
by Home; the elbow moves after the shoulder (one generator, two drivers), so the joints do
not arrive together and the ST machine's synchronisation check does not apply; the ramps
limit velocity and acceleration at the pulses (:mod:`.checks`), not jerk.

The targets come from chosen joint angles through the description's forward kinematics;
the final positions expected are the float64 IK's (:func:`~analysis.plc.machine.scenarios.
expected_joints`): the program's float32 arithmetic must land within one pulse of them.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from analysis.plc.machine.checks import Trace as MachineTrace
from analysis.plc.machine.scenarios import Expect, Scenario, expected_joints
from analysis.plc.machine.spec import machine_spec
from analysis.plc.motion.drives import Drives
from analysis.plc.motion.engines import Engine
from analysis.plc.motion.networks import MACHINE_IO

__all__ = ["OUTPUTS", "S7Case", "Trace", "grabber_cases", "limit_cases", "run", "signals"]

OUTPUTS = ("Homed", "Busy", "Done", "Error", "Status")
PULSE_S = 0.05
"""How long a push button stays pressed [s] (two scans at 20 ms)."""


@dataclass(frozen=True)
class S7Case:
    """A scenario with the S7-200's additions (module docstring)."""

    scenario: Scenario
    settle: float
    jogs: tuple[tuple[float, tuple[int, ...]], ...] = ()
    waist_steps: tuple[float, int] | None = None
    """(from t [s], steps): the waist's steps from then on."""

    @property
    def name(self) -> str:
        return self.scenario.name

    @property
    def end(self) -> float:
        return max(self.scenario.end_s, *(t for t, _ in self.jogs), 0.0) + self.settle


@dataclass
class Trace:
    """After every scan: its end time [s], the joints' counts, the outputs; the drives and
    the engine's PTO channels for the pulse-level checks."""

    t: np.ndarray
    counts: np.ndarray
    outputs: dict[str, np.ndarray]
    drives: Drives
    pto: tuple
    engine: str
    per_pulse: np.ndarray
    fault: str | None = None

    def q_deg(self) -> np.ndarray:
        """Joint positions [deg], shape (scans, 3)."""
        return self.counts * self.per_pulse

    def machine_trace(self) -> MachineTrace:
        """The ST machine's trace of this run (``q`` [deg], ``v`` [deg/s] the mean speed over
        each scan, the outputs as numbers)."""
        q = self.q_deg()
        dt = np.diff(self.t, prepend=0.0)[:, None]
        v = np.diff(q, axis=0, prepend=q[:1]) / dt
        outs = {k: np.asarray(v_, dtype=float) for k, v_ in self.outputs.items()}
        return MachineTrace(self.t, q, v, outs)


def signals(mmap_inputs: dict[str, str] | None = None) -> dict[str, tuple[str, str]]:
    """Machine variable -> (address, type): issue 29's names on the CPU 224 (the targets at
    the IK's inputs, VD0-VD8 by default)."""
    out = {name: (addr, typ) for name, (addr, typ, _d, _m) in MACHINE_IO.items()}
    targets = mmap_inputs or {"px": "VD0", "py": "VD4", "pz": "VD8"}
    for name, addr in zip(("TargetX", "TargetY", "TargetZ"), targets.values(), strict=True):
        out[name] = (addr, "REAL")
    return out


def run(engine: Engine, case: S7Case, per_pulse=(0.09, 0.09, 0.09), io=None) -> Trace:
    """Run ``case`` on ``engine`` (module docstring); ``io`` the variables' addresses
    (:func:`signals` by default), ``per_pulse`` each joint's step [deg]."""
    io = io or signals()
    rows = sorted([*case.scenario.rows, *((t, "jog", c) for t, c in case.jogs)],
                  key=lambda r: r[0])  # fmt: skip
    drives = Drives()
    ts, counts, outs = [], [], {k: [] for k in OUTPUTS}
    i, fault = 0, None
    while engine.time < case.end - 1e-9:
        while i < len(rows) and rows[i][0] <= engine.time + 1e-9:
            _t, name, value = rows[i]
            if name == "jog":
                drives.jog(value)
            elif name in io:
                addr, typ = io[name]
                engine.write(typ, addr, bool(value) if typ == "BOOL" else value)
            i += 1
        drives.apply(engine.scan())
        ts.append(engine.time)
        counts.append(drives.counts.copy())
        for k in OUTPUTS:
            addr, typ = io[k]
            outs[k].append(engine.read(typ, addr))
        fault = fault or engine.fault
    return Trace(np.array(ts), np.array(counts), {k: np.array(v) for k, v in outs.items()},
                 drives, tuple(engine.pto), engine.name, np.asarray(per_pulse), fault)  # fmt: skip


# --------------------------------------------------------------------------------------------
def _point(arm, deg) -> tuple[float, float, float]:
    """The target that joint angles ``deg`` reach (the description's forward kinematics)."""
    return tuple(float(v) for v in arm.fk(np.radians(np.asarray(deg, dtype=float))))


def _target(t: float, p) -> list:
    return [(t, n, float(v)) for n, v in zip(("TargetX", "TargetY", "TargetZ"), p, strict=True)]


def _pulse(t: float, name: str) -> list:
    return [(t, name, 1.0), (t + PULSE_S, name, 0.0)]


def _boot(target, home: bool = True, stop_ok: float = 1.0) -> list:
    rows = [(0.0, "Enable", 1.0), (0.0, "StopOK", stop_ok), *_target(0.0, target)]
    return rows + (_pulse(0.05, "Home") if home else [])


def _case(name, title, rows, expect: Expect, settle, **s7) -> S7Case:
    return S7Case(Scenario(name, title, tuple(rows), expect), settle, **s7)


def grabber_cases(arm, move_s: float = 0.4) -> dict[str, S7Case]:
    """The issue's scenarios for ``arm`` (the grabber's machine), by name (module docstring);
    ``move_s`` [s]: when "mid-move" is after the Start."""
    spec = machine_spec(arm)
    a = _point(arm, (30.0, 20.0, -40.0))  # a move of (333, 222, -444) pulses from home
    b = _point(arm, (-20.0, 35.0, -60.0))
    level = _point(arm, (0.0, 20.0, -40.0))
    w1 = (-level[0], 0.001, level[2])  # theta1 = 180 deg - 1e-4 deg
    w2 = (-level[0], -0.001, level[2])  # 2 um away, across the cut
    ja, jb, jw = (expected_joints(arm, spec, p) for p in (a, b, w2))
    mid, end = 0.2 + move_s, 1e9
    cases = [
        ("power_home", "power up, Start before Home refused (101), Home",
         [*_boot(a, home=False), *_pulse(0.2, "Start"), *_pulse(0.4, "Home")],
         Expect(still=((0.0, end),), outputs=((0.3, "Status", 101), (0.3, "Error", 1),
                                              (0.3, "Homed", 0), (0.5, "Homed", 1),
                                              (0.5, "Status", 0), (0.5, "Error", 0))), 0.5, {}),
        ("move", "home, move to a target", [*_boot(a), *_pulse(0.2, "Start")],
         Expect(final=ja, outputs=((2.6, "Done", 1), (2.6, "Status", 0), (2.6, "Busy", 0))),
         2.5, {}),
        ("retarget", "a target typed mid-move changes nothing of the move; a Start during it is "
         "refused (104); a Start after Done moves to it",
         [*_boot(a), *_pulse(0.2, "Start"), *_target(mid, b), *_pulse(mid + 0.1, "Start"),
          *_pulse(2.9, "Start")],
         Expect(final=jb, outputs=((mid + 0.2, "Status", 104), (mid + 0.2, "Busy", 1),
                                   (2.85, "Done", 1), (2.85, "Error", 1))), 3.0, {}),
        ("stop", "the stop circuit opens mid-move (102, the position lost); closed, Start "
         "without Reset is refused",
         [*_boot(a), *_pulse(0.2, "Start"), (mid, "StopOK", 0.0), (mid + 0.3, "StopOK", 1.0),
          *_pulse(mid + 0.5, "Start")],
         Expect(stop_t=mid, still=((mid + 0.05, end),),
                outputs=((mid + 0.05, "Status", 102), (mid + 0.05, "Homed", 0),
                         (mid + 0.6, "Status", 102), (mid + 0.6, "Error", 1))), 0.5, {}),
        ("reset_resume", "stop mid-move, close, Reset (0), Start refused until Home (101); the "
         "operator brings the arm to its home marks, Home, Start: the target is reached",
         [*_boot(a), *_pulse(0.2, "Start"), (mid, "StopOK", 0.0), (mid + 0.3, "StopOK", 1.0),
          *_pulse(mid + 0.4, "Reset"), *_pulse(mid + 0.6, "Start"), *_pulse(mid + 0.8, "Home"),
          *_pulse(mid + 0.9, "Start")],
         Expect(final=ja, stop_t=mid, stop_until=mid + 0.7,
                outputs=((mid + 0.5, "Status", 0), (mid + 0.5, "Error", 0),
                         (mid + 0.7, "Status", 101))), 2.5, {"jogs": ((mid + 0.7, (0, 0, 0)),)}),
        ("unreachable", "Table 4 row 8 (printed 无解): the IK's status 1, nothing moves",
         [*_boot((200.0, 500.0, 600.0)), *_pulse(0.2, "Start")],
         Expect(still=((0.0, end),), outputs=((0.3, "Status", 1), (0.3, "Error", 1))), 0.5, {}),
        ("nan", "a NaN target: the IK's status 6 (no REAL compare sees it), nothing moves",
         [*_boot((float("nan"), 100.0, 600.0)), *_pulse(0.2, "Start")],
         Expect(still=((0.0, end),), outputs=((0.3, "Status", 6), (0.3, "Error", 1))), 0.5, {}),
        ("wrap", "theta1 +179.9999 -> -179.9999 deg (a 2 um target change): the short way, "
         "not a turn", [*_boot(w1), *_pulse(0.2, "Start"), *_target(4.2, w2),
                        *_pulse(4.25, "Start")],
         Expect(final=jw, outputs=((4.15, "Done", 1), (4.35, "Status", 0))), 1.0,
         {"waist_steps": (4.2, 0)}),
        ("wire_break", "the stop wire broken at power-up: 102; Home, Reset, Start refused, "
         "nothing moves", [*_boot(a, home=False, stop_ok=0.0), *_pulse(0.1, "Home"),
                           *_pulse(0.2, "Reset"), *_pulse(0.3, "Start")],
         Expect(still=((0.0, end),), outputs=((0.15, "Status", 102), (0.35, "Status", 102),
                                              (0.35, "Error", 1), (0.35, "Homed", 0))), 0.5, {}),
    ]  # fmt: skip
    return {n: _case(n, title, rows, e, settle, **s7) for n, title, rows, e, settle, s7 in cases}


def limit_cases(arm, limited: bool) -> dict[str, S7Case]:
    """A joint limit: the waist from +120 to -120 deg. ``limited`` (theta1 within
    [-170, 170] deg): the long way, 240 deg through 0; unlimited: the short way, 120 deg
    through 180. A target at theta1 = 175 deg is the IK's 'joint limits' (4) on the limited
    arm."""
    spec = machine_spec(arm)
    p1, p2 = _point(arm, (120.0, 20.0, -40.0)), _point(arm, (-120.0, 20.0, -40.0))
    j1, j2 = expected_joints(arm, spec, p1), expected_joints(arm, spec, p2)
    per = spec.axes[0].per_pulse
    d = round((j2[0] - j1[0]) / per)
    if not limited:
        ppr = spec.axes[0].pulses_per_rev
        d = (d + ppr // 2) % ppr - ppr // 2
    rows = [*_boot(p1), *_pulse(0.2, "Start"), *_target(3.4, p2), *_pulse(3.45, "Start")]
    expect = Expect(final=j2, outputs=((3.35, "Done", 1), (3.55, "Status", 0)))
    cases = {"limit_path": _case("limit_path", "theta1 +120 -> -120 deg", rows, expect,
                                 3.6 if limited else 2.2, waist_steps=(3.4, abs(d)))}  # fmt: skip
    if limited:
        p3 = _point(arm, (175.0, 20.0, -40.0))
        cases["joint_limit"] = _case(
            "joint_limit", "theta1 = 175 deg beyond the limit: the IK's status 4, nothing moves",
            [*_boot(p3), *_pulse(0.2, "Start")],
            Expect(still=((0.0, 1e9),), outputs=((0.3, "Status", 4), (0.3, "Error", 1))), 0.5,
        )  # fmt: skip
    return cases
