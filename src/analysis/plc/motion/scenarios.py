"""The issue's scenarios for the S7-200 machine (issue 29 item 4), run on an engine into a
trace, with the numbers each is held to computed apart from the program.

A scenario is a list of rows ``(t_s, name, value)`` (issue 29's SCENARIO.csv: a row sets a
program variable at that time; here also ``jog``: the operator moves the arm by hand, its
value the joint counts) and a settling time after the last row. :func:`run` applies each row
before the first scan that starts at or after its time and records, after every scan, the
drives' positions and the machine's outputs (:class:`Trace`, whose :meth:`Trace.rows` are
issue 29's TRACE.csv columns: ``t_s``, ``q1..q3`` [deg], ``v1..v3`` [deg/s], the outputs).

:func:`grabber_scenarios` builds the issue's list for an arm of the grabber's machine: power
up, home, move, target change mid-move, stop mid-move, reset and resume, unreachable, NaN,
across theta1 = +-180 deg, a joint limit, a wire break on StopOK. Their targets come from
chosen joint angles through the description's forward kinematics, and ``expect`` holds the
counts the IK gives for them (float64, :meth:`~analysis.kinematics.arm.Arm.solve`, rounded
half away from zero as eqs. 20-22 by the S7-200's ROUND): the program's float32 arithmetic
must land within one pulse of them. The checks are in :mod:`.checks`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from analysis.plc.motion.drives import Drives
from analysis.plc.motion.engines import Engine
from analysis.plc.motion.networks import MACHINE_IO

__all__ = [
    "OUTPUTS",
    "Scenario",
    "Trace",
    "grabber_scenarios",
    "ik_counts",
    "limit_scenarios",
    "run",
    "signals",
]

OUTPUTS = ("Homed", "Busy", "Done", "Error", "Status")


@dataclass(frozen=True)
class Scenario:
    """Rows ``(t_s, name, value)``, the settling time [s] after the last, what it shows, and
    the independent expectations (names -> values, see :func:`grabber_scenarios`)."""

    name: str
    rows: tuple[tuple[float, str, object], ...]
    settle: float = 1.0
    note: str = ""
    expect: dict = field(default_factory=dict)

    @property
    def end(self) -> float:
        return max(t for t, _, _ in self.rows) + self.settle


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
    ppr: tuple[int, ...]
    fault: str | None = None

    def q_deg(self) -> np.ndarray:
        """Joint positions [deg], shape (scans, 3)."""
        return self.counts * (360.0 / np.asarray(self.ppr))

    def v_deg(self) -> np.ndarray:
        """Mean joint speed over each scan [deg/s], shape (scans, 3)."""
        q = self.q_deg()
        dt = np.diff(self.t, prepend=0.0)[:, None]
        return np.diff(q, axis=0, prepend=q[:1] * 0 + q[:1]) / dt

    def at(self, t: float) -> int:
        """Index of the last scan that ended at or before ``t``."""
        return int(np.searchsorted(self.t, t, side="right")) - 1

    def rows(self) -> list[dict]:
        """Issue 29's TRACE.csv rows: t_s, q1..q3 [deg], v1..v3 [deg/s], the outputs."""
        q, v = self.q_deg(), self.v_deg()
        out = []
        for i, t in enumerate(self.t):
            row = {"t_s": round(float(t), 6)}
            row |= {f"q{j + 1}": float(q[i, j]) for j in range(q.shape[1])}
            row |= {f"v{j + 1}": float(v[i, j]) for j in range(v.shape[1])}
            row |= {k: self.outputs[k][i].item() for k in self.outputs}
            out.append(row)
        return out


def signals(mmap_inputs: dict[str, str] | None = None) -> dict[str, tuple[str, str]]:
    """Machine variable -> (address, type): issue 29's names on the CPU 224 (the targets at
    the IK's inputs, VD0-VD8 by default)."""
    out = {name: (addr, typ) for name, (addr, typ, _d, _m) in MACHINE_IO.items()}
    targets = mmap_inputs or {"px": "VD0", "py": "VD4", "pz": "VD8"}
    for name, addr in zip(("TargetX", "TargetY", "TargetZ"), targets.values(), strict=True):
        out[name] = (addr, "REAL")
    return out


def run(engine: Engine, scenario: Scenario, ppr=(4000, 4000, 4000), io=None) -> Trace:
    """Run ``scenario`` on ``engine`` (module docstring); ``io`` the variables' addresses
    (:func:`signals` by default)."""
    io = io or signals()
    rows = sorted(scenario.rows, key=lambda r: r[0])
    drives = Drives()
    ts, counts, outs = [], [], {k: [] for k in OUTPUTS}
    i, fault = 0, None
    while engine.time < scenario.end - 1e-9:
        while i < len(rows) and rows[i][0] <= engine.time + 1e-9:
            _t, name, value = rows[i]
            if name == "jog":
                drives.jog(value)
            else:
                addr, typ = io[name]
                engine.write(typ, addr, value)
            i += 1
        drives.apply(engine.scan())
        ts.append(engine.time)
        counts.append(drives.counts.copy())
        for k in OUTPUTS:
            addr, typ = io[k]
            outs[k].append(engine.read(typ, addr))
        fault = fault or engine.fault
    return Trace(np.array(ts), np.array(counts), {k: np.array(v) for k, v in outs.items()},
                 drives, tuple(engine.pto), engine.name, tuple(ppr), fault)  # fmt: skip


# --------------------------------------------------------------------------------------------
def ik_counts(arm, target) -> np.ndarray:
    """The counts the float64 IK gives for ``target`` (the arm's first branch), rounded half
    away from zero (eqs. 20-22; S7-200 ROUND), or None if it refuses the target."""
    sol = arm.solve(np.asarray(target, dtype=float)[None, :], arm.branches[:1])
    if not sol.ok[0, 0]:
        return None
    deg = np.degrees(sol.theta[0, 0])
    x = deg / 360.0 * np.array([j.pulses_per_rev for j in arm.description.joints])
    return (np.sign(x) * np.floor(np.abs(x) + 0.5)).astype(np.int64)


def _point(arm, deg) -> tuple[float, float, float]:
    """The target that joint angles ``deg`` reach (the description's forward kinematics)."""
    p = arm.fk(np.radians(np.asarray(deg, dtype=float)))
    return tuple(float(v) for v in p)


def _set_target(t: float, p) -> list[tuple[float, str, object]]:
    return [(t, n, float(v)) for n, v in zip(("TargetX", "TargetY", "TargetZ"), p, strict=True)]


def _pulse(t: float, name: str, width: float = 0.05) -> list[tuple[float, str, object]]:
    return [(t, name, True), (t + width, name, False)]


def _powered(target, homed: bool = True, stop_ok: bool = True) -> list:
    rows = [(0.0, "StopOK", stop_ok), (0.0, "Enable", True), *_set_target(0.0, target)]
    return rows + (_pulse(0.05, "Home") if homed else [])


def grabber_scenarios(arm, move_s: float = 0.4) -> dict[str, Scenario]:
    """The issue's scenarios for ``arm`` (the grabber's machine), by name (module docstring);
    ``move_s`` [s]: when "mid-move" is after the Start."""
    a = _point(arm, (30.0, 20.0, -40.0))  # a move of (333, 222, -444) counts from home
    b = _point(arm, (-20.0, 35.0, -60.0))
    horizontal = _point(arm, (0.0, 20.0, -40.0))
    c1 = (-horizontal[0], 0.001, horizontal[2])  # theta1 = 180 deg - 1e-4 deg
    c2 = (-horizontal[0], -0.001, horizontal[2])  # 2 um away, across the cut
    ca, cb, cc = ik_counts(arm, a), ik_counts(arm, b), ik_counts(arm, c2)
    mid = 0.2 + move_s
    still = (0.0, math.inf)
    specs = [
        ("power_up", [*_powered(a, homed=False), *_pulse(0.2, "Start")], 0.5,
         "Start before Home: refused (100), nothing moves",
         {"final": (0, 0, 0), "status": 100, "no_motion": still}),
        ("home", _powered(a), 0.5, "Home (mode set): Homed, nothing moves",
         {"final": (0, 0, 0), "status": 0, "homed": True, "no_motion": still}),
        ("move", [*_powered(a), *_pulse(0.2, "Start")], 2.5, "a move to (30, 20, -40) deg",
         {"final": tuple(ca), "status": 0, "done": True}),
        ("target_change",
         [*_powered(a), *_pulse(0.2, "Start"), *_set_target(mid, b), *_pulse(mid + 0.1, "Start"),
          *_pulse(2.9, "Start")], 3.0,
         "the target changed mid-move: the move goes on to the latched target; a Start during "
         "the move is refused (104); a Start after Done moves to the new one",
         {"final_at": ((2.85, tuple(ca)),), "final": tuple(cb),
          "status_at": ((mid + 0.2, 104),), "status": 0, "done": True}),
        ("stop", [*_powered(a), *_pulse(0.2, "Start"), (mid, "StopOK", False),
                  *_pulse(mid + 0.3, "Start")], 0.8,
         "SB2 mid-move: both trains aborted, position lost (102); a Start with the circuit "
         "still open is refused (101)",
         {"stop_at": (mid, math.inf), "status_at": ((mid + 0.1, 102),), "status": 101,
          "error": True, "homed": False}),
        ("reset_resume",
         [*_powered(a), *_pulse(0.2, "Start"), (mid, "StopOK", False),
          (mid + 0.3, "StopOK", True), *_pulse(mid + 0.4, "Start"), *_pulse(mid + 0.5, "Reset"),
          *_pulse(mid + 0.6, "Start"), (mid + 0.7, "jog", (0, 0, 0)),
          *_pulse(mid + 0.75, "Home"), *_pulse(mid + 0.85, "Start")], 2.5,
         "after a stop: Start refused until Reset (105), then until Home (100); the operator "
         "brings the arm to its home marks, Home, Start: it arrives",
         {"stop_at": (mid, mid + 0.85), "status_at": ((mid + 0.45, 105), (mid + 0.65, 100)),
          "final": tuple(ca), "status": 0, "done": True}),
        ("unreachable", [*_powered((200.0, 500.0, 600.0)), *_pulse(0.2, "Start")], 0.5,
         "Table 4 row 8 (printed 无解): the IK's status 1, nothing moves",
         {"final": (0, 0, 0), "status": 1, "no_motion": still}),
        ("nan", [*_powered((math.nan, 100.0, 600.0)), *_pulse(0.2, "Start")], 0.5,
         "a NaN target: the IK's status 6 (no REAL compare sees it), nothing moves",
         {"final": (0, 0, 0), "status": 6, "no_motion": still}),
        ("across_180",
         [*_powered(c1), *_pulse(0.2, "Start"), *_set_target(4.2, c2), *_pulse(4.25, "Start")],
         1.0, "theta1 +179.9999 -> -179.9999 deg (a 2 um target change): the short way, not a "
         "turn", {"final_mod": tuple(cc), "waist_pulses_after": (4.2, 1),
                  "status_at": ((4.15, 0), (4.35, 0)), "done_at": ((4.15, True),),
                  "status": 0, "done": True}),
        ("wire_break", [*_powered(a, stop_ok=False), *_pulse(0.1, "Home"), *_pulse(0.2, "Start")],
         0.5, "the stop input's wire broken at power-up (StopOK FALSE): an error, Home and "
         "Start refused, nothing moves",
         {"final": (0, 0, 0), "status": 101, "error": True, "no_motion": still}),
    ]  # fmt: skip
    return {name: Scenario(name, tuple(rows), settle, note, expect)
            for name, rows, settle, note, expect in specs}  # fmt: skip


def limit_scenarios(arm, limited: bool) -> dict[str, Scenario]:
    """A joint limit: the waist from +120 to -120 deg. ``limited`` (theta1 within
    [-170, 170] deg): the long way, 240 deg through 0; unlimited: the short way, 120 deg
    through 180. A target at theta1 = 175 deg is the IK's 'joint limits' (4) on the limited
    arm."""
    p1, p2 = _point(arm, (120.0, 20.0, -40.0)), _point(arm, (-120.0, 20.0, -40.0))
    c1, c2 = ik_counts(arm, p1), ik_counts(arm, p2)
    ppr = arm.description.joints[0].pulses_per_rev
    d = int(c2[0] - c1[0])
    if not limited:
        d = (d + ppr // 2) % ppr - ppr // 2
    rows = [*_powered(p1), *_pulse(0.2, "Start"), *_set_target(3.4, p2), *_pulse(3.45, "Start")]
    expect = {"waist_pulses_after": (3.4, abs(d)), "final_mod": tuple(c2), "done": True,
              "status_at": ((3.35, 0), (3.55, 0)), "done_at": ((3.35, True),)}  # fmt: skip
    sc = {"limit_path": Scenario("limit_path", tuple(rows), 3.6 if limited else 2.2,
                                 "theta1 +120 -> -120 deg", expect)}  # fmt: skip
    if limited:
        p3 = _point(arm, (175.0, 20.0, -40.0))
        sc["limit_refused"] = Scenario(
            "limit_refused",
            tuple([*_powered(p3), *_pulse(0.2, "Start")]),
            0.5,
            "theta1 = 175 deg beyond the limit: the IK's status 4, nothing moves",
            {"final": (0, 0, 0), "status": 4, "no_motion": (0.0, math.inf)},
        )
    return sc
