"""The grabber's machine on the CPU 224 (seed 000, Table 2's I/O): S7-200 STL networks that
home, move, ramp and stop three steppers on the two PTO channels, after the IK networks.

I/O (Table 2; what Table 2 does not list is an HMI bit in V memory, the paper's "人机界面或
PC 机" of sec. 3, and says so in MAP.json's ``machine`` section):

=========  =========  =========================================================================
Start      I0.0       SB1: a rising edge latches the target's counts and starts the move
StopOK     I0.1       SB2 wired normally closed (a correction: a broken wire must stop): FALSE
                      stops; the program reads "circuit closed", so an open circuit = stop
Enable     V121.0     HMI: the PTO may run (FALSE during a move stops it as StopOK does)
Home       V121.1     HMI, rising edge: home mode "set": the positions := the home counts
Reset      V121.2     HMI, rising edge, with the stop circuit closed: clears the error and
                      re-enables the PTO (control bytes 16#A0, SM66.4-.6/SM76.4-.6 cleared)
TargetX/Y/Z VD0-VD8   the IK's inputs (HMI); the program never writes them
Homed ... Status      V122.0 Homed, V122.1 Busy, V122.2 Done, V122.3 Error, VW124 Status
Q0.0/Q0.1  PTO0, PTO1 pulses; Q0.2, Q0.5, Q0.7 directions (1: counts up); Q0.3 KM1 routes
                      PTO1 to the shoulder driver, Q0.4 KM2 to the elbow driver
=========  =========  =========================================================================

Sequence (``VB120``, the step): 0 idle -> 1 phase A prepared (directions, KM1) -> 2 phase A
runs (PLS 0 waist, PLS 1 shoulder, in the step's first scan) -> 3 phase B prepared (KM1 off,
KM2 on) -> 4 phase B runs (PLS 1 elbow) -> 0. The networks run in decreasing step order, so
each step lasts at least one scan: a direction bit or a relay is written in one scan and
reaches its terminal at that scan's end, before the PLS of the next scan (the first pulse
of a train leaves at PLS, not at the end of the scan). The three joints cannot arrive
together: PTO1 is one generator switched between two drivers.

What the issue's defects became (the status codes and the meaning of Error and Done are the
ST machine's, :data:`analysis.plc.machine.spec.MACHINE_STATUS`, so an HMI reads both alike):

* ``StopOK`` FALSE (SB2 pressed, or its wire broken) latches a stop (102, ``Error``) until the
  circuit is closed and ``Reset``; during a move it aborts both trains (control byte 0 +
  PLS: the System Manual's way to stop a PTO), relays off, ``Homed`` off (without a pulse
  counter the position is lost: ``Home`` before the next ``Start``, status 101). ``Enable``
  FALSE during a move aborts it the same way, without a latch. Reset re-enables the PTO (a
  disabled control byte made every later PLS abort); every PLS is preceded by its control
  byte (16#A0: enabled, multiple segments, microseconds); a phase ends only when its
  channels are idle and no abort or delta error was flagged (else a fault latched, 103): a
  move whose PLS aborted is never "reached".
* Directions and relays one scan before PLS (above).
* The +-180 deg cut: the move is ``target - position`` in counts; for an unlimited joint
  (:attr:`~analysis.kinematics.description.JointSpec.unlimited`) it is brought into half a
  turn (+-ppr/2: the short way); a limited joint's target lies within its limits (the IK
  refuses others, status 4) and so does the straight move to it.
* Ramps: multi-segment PTO profiles from the joint's ``max_velocity`` and
  ``max_acceleration`` (:mod:`.profile`); ramp level 0..m tables per joint, written on the
  first scan, the plateau's count filled in at Start.
* Refused (Status, ``Error`` on, ``Done`` off; no axis moves): Home or Start while moving
  (104: the PTO cannot re-plan a running profile, and the position mid-move is unknown), with
  a stop (102) or a fault (103) latched, with ``Enable`` FALSE (100); Start before ``Homed``
  (101) and the IK's refusals (its own status: unreachable 1, joint limits 4, NaN 6). An
  accepted command clears ``Error``.

What needs I/O the paper does not list: a reference switch per joint for homing by switch
(the description's home mode "switch" is refused here), an E-stop circuit that removes the
drivers' power (SB2 is a program stop), the driver enable and alarm signals, a pulse
counter (HSC) to keep the position through a stop, relay contact feedback.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from analysis.kinematics.pulses import round_half_away
from analysis.plc.motion.profile import Ramp, ramp

__all__ = [
    "CONTROL",
    "MACHINE_IO",
    "MOTION_MAP",
    "STATUS",
    "MotionPlan",
    "motion_networks",
    "motion_plan",
]

CONTROL = 0xA0
"""PTO control byte: enabled, PTO, multiple segments, microseconds (S7-200 System Manual
C79000-G7076-C233-01 p.233, Table 9-17)."""

MOTION_MAP = {
    "step": "VB120",
    "Enable": "V121.0",
    "Home": "V121.1",
    "Reset": "V121.2",
    "Homed": "V122.0",
    "Busy": "V122.1",
    "Done": "V122.2",
    "Error": "V122.3",
    "entry": "V123.0",
    "start": "V123.1",
    "home": "V123.2",
    "stopped": "V123.3",
    "fault": "V123.4",
    "Status": "VW124",
    "pos": ("VD128", "VD132", "VD136"),
    "target": ("VD140", "VD144", "VD148"),
    "move": ("VD152", "VD156", "VD160"),
    "count": ("VD164", "VD168", "VD172"),
    "table": ("VW176", "VW178", "VW180"),
}
"""The motion networks' V memory in VB120-VB183 (profile tables after the IK's work area)."""

MACHINE_IO = {
    "Start": ("I0.0", "BOOL", "input", "SB1 (Table 2); rising edge: latch the target, move"),
    "StopOK": ("I0.1", "BOOL", "input",
               "SB2 (Table 2) wired normally closed: FALSE (pressed, or a broken wire) stops"),
    "Enable": ("V121.0", "BOOL", "input", "HMI bit (not in Table 2): the PTO may run"),
    "Home": ("V121.1", "BOOL", "input",
             "HMI bit (not in Table 2); rising edge: the present position is the home position "
             "(home mode 'set': Table 2 has no reference switch)"),
    "Reset": ("V121.2", "BOOL", "input",
              "HMI bit (not in Table 2); rising edge: clear the error, re-enable the PTO"),
    "Homed": ("V122.0", "BOOL", "output", "the positions are known (homed, no stopped move since)"),
    "Busy": ("V122.1", "BOOL", "output", "a move runs"),
    "Done": ("V122.2", "BOOL", "output", "the last move arrived, or Home was taken"),
    "Error": ("V122.3", "BOOL", "output",
              "the last command was refused or a stop or fault is latched: see Status"),
    "Status": ("VW124", "INT", "output", "the machine's status code (status codes below)"),
}  # fmt: skip
"""Issue 29's machine variables on the CPU 224: address, type, direction, meaning."""

STATUS = {
    100: ("not-powered", "Home or Start refused: Enable is FALSE",
          "Axes not enabled: switch Enable on"),
    101: ("not-homed", "Start refused: the positions are not known (not homed since power-up or "
          "since a stopped move)", "Arm not homed: bring it to its home marks, press Home"),
    102: ("stopped", "the stop circuit is open or was (StopOK FALSE: SB2 or a broken wire): a "
          "move is aborted and its position lost; nothing moves until the circuit is closed, "
          "Reset, Home, then Start", "Stop circuit open: close it, press Reset, then Home"),
    103: ("axis-error", "a pulse train ended early (SM66.4/.5, SM76.4/.5: a delta error or an "
          "abort): the position is lost; Reset, Home, then Start",
          "Pulse output fault: press Reset, then Home"),
    104: ("busy", "Home or Start refused during a move (the PTO cannot re-plan a running "
          "profile): the move goes on to its latched target", "Machine busy: wait for Done"),
}  # fmt: skip
"""The machine's own status codes (beside the IK's, which Status repeats when the IK refuses
a Start's target): name, meaning, alarm text. The codes and their words are the ST machine's
(:data:`analysis.plc.machine.spec.MACHINE_STATUS`); the meanings say what the S7-200 does
differently (a stopped move loses the position)."""

_WIRING = (  # joint: PTO channel, relay output (None: its own channel), direction output
    (0, None, "Q0.2"),
    (1, "Q0.3", "Q0.5"),
    (1, "Q0.4", "Q0.7"),
)
_SKIP_INIT = 250  # the first-scan networks are jumped over after the first scan


@dataclass(frozen=True)
class MotionPlan:
    """What the networks need of the arm: per joint its ramp, home count, pulses/rev and
    whether it is unlimited (the short way); the profile tables' offsets."""

    ramps: tuple[Ramp, ...]
    home: tuple[int, ...]
    ppr: tuple[int, ...]
    unlimited: tuple[bool, ...]
    tables: tuple[tuple[int, ...], ...]
    """``tables[j][k]``: V offset of joint j's profile at ramp level k."""

    @property
    def end(self) -> int:
        """One past the last byte of the profile tables."""
        j = len(self.ramps) - 1
        return self.tables[j][-1] + 1 + 8 * (2 * self.ramps[j].levels + 1)


def motion_plan(arm, table_base: int, levels: int = 5) -> MotionPlan:
    """The plan of ``arm``'s machine (three revolute joints, Table 2's wiring), its tables
    from V offset ``table_base``. ValueError naming the joint and the key for what the arm
    description lacks (:meth:`~analysis.kinematics.description.JointSpec.require`)."""
    joints = arm.description.joints
    if len(joints) != 3 or any(j.kind != "revolute" for j in joints):
        raise ValueError(
            f"arm {arm.description.name}: the S7-200 motion networks drive three revolute "
            "joints (Table 2's wiring)"
        )
    ramps, home, tables = [], [], []
    base = table_base + (-table_base) % 4
    for j in joints:
        if j.require("home_mode") != "set":
            raise ValueError(
                f"joint {j.name}: home mode {j.home_mode!r}: a reference switch per joint needs "
                "inputs Table 2 does not list; the S7-200 networks home by 'set' only"
            )
        r = ramp(j.name, j.require("max_velocity"), j.require("max_acceleration"),
                 j.pulses_per_rev, levels)  # fmt: skip
        ramps.append(r)
        deg = math.degrees(j.require("home_position"))
        home.append(int(round_half_away(deg / 360.0 * j.pulses_per_rev)))
        offs = []
        for k in range(r.levels + 1):
            offs.append(base)
            base += 1 + 8 * (2 * k + 1)
        tables.append(tuple(offs))
    return MotionPlan(tuple(ramps), tuple(home), tuple(j.pulses_per_rev for j in joints),
                      tuple(j.unlimited for j in joints), tuple(tables))  # fmt: skip


def _table_writes(plan: MotionPlan) -> list[str]:
    """First scan: every profile table's constant part (its plateau count is set at Start)."""
    out = []
    for j, (r, offs) in enumerate(zip(plan.ramps, plan.tables, strict=True)):
        for k, off in enumerate(offs):
            segs = r.table(2 * r.cum[k] + 1)  # level k's segments (plateau count placeholder)
            out.append(f"Network // joint {j + 1}: profile at ramp level {k} (VB{off})")
            out += ["LD     SM0.0", f"MOVB   {len(segs)}, VB{off}"]
            for i, (c0, d, n) in enumerate(segs):
                s = off + 1 + 8 * i
                out += [f"MOVW   {c0}, VW{s}", f"MOVW   {d}, VW{s + 2}"]
                if i != k:  # the plateau's count is written at Start
                    out.append(f"MOVD   {n}, VD{s + 4}")
    return out


def _abort(latch: str | None) -> list[str]:
    """Boxes (under the stack's top): end the move, the position lost (Homed, Busy off),
    relays off; ``latch`` the stop or fault latch to set (None: none)."""
    m = MOTION_MAP
    out = [f"MOVB   0, {m['step']}", f"R      {m['Homed']}, 2", "R      Q0.3, 2"]
    return out + ([f"S      {m[latch]}, 1"] if latch else [])


def _phase_done(step: int, channels: tuple[int, ...], then: list[str], what: str) -> list[str]:
    m = MOTION_MAP
    flags = [f"SM{66 + 10 * c}.{b}" for c in channels for b in (4, 5)]
    return [
        f"Network // {what} over (PTO{'/PTO'.join(map(str, channels))} idle): a train that "
        "ended early (delta error, abort) is an error, never 'reached'",
        f"LDB=   {m['step']}, {step}",
        f"AN     {m['entry']}",
        *(f"A      SM{66 + 10 * c}.7" for c in channels),
        "LPS",
        f"LD     {flags[0]}", *(f"O      {f}" for f in flags[1:]), "ALD",
        *_abort("fault"),
        "LPP",
        *(f"AN     {f}" for f in flags),
        *then,
    ]  # fmt: skip


def _pls(j: int, plan: MotionPlan) -> list[str]:
    m = MOTION_MAP
    ch = _WIRING[j][0]
    return [f"AD>    {m['count'][j]}, 0", f"MOVW   {m['table'][j]}, SMW{168 + 10 * ch}",
            f"MOVB   16#{CONTROL:02X}, SMB{67 + 10 * ch}", f"PLS    {ch}"]  # fmt: skip


def _refuse(req: str, cond: list[str], status: str) -> list[str]:
    """A request bit refused when ``cond`` holds: Status := ``status`` (a code, or the IK's
    status double word: DTI), Error on, Done off, the request dropped."""
    m = MOTION_MAP
    move = f"DTI    {status}, " if status.startswith("VD") else f"MOVW   {status}, "
    return [f"LD     {req}", *cond, move + m["Status"], f"S      {m['Error']}, 1",
            f"R      {m['Done']}, 1", f"R      {req}, 1"]  # fmt: skip


def _refusals(req: str) -> list[str]:
    """Home's and Start's common refusals: moving 104, a stop latched 102, a fault latched
    103, Enable off 100."""
    m = MOTION_MAP
    return [*_refuse(req, [f"AB<>   {m['step']}, 0"], "104"),
            *_refuse(req, [f"A      {m['stopped']}"], "102"),
            *_refuse(req, [f"A      {m['fault']}"], "103"),
            *_refuse(req, [f"AN     {m['Enable']}"], "100")]  # fmt: skip


def _start(plan: MotionPlan, mmap) -> list[str]:
    m = MOTION_MAP
    c = [mmap.address(f"c{j + 1}") for j in range(3)]
    ok = mmap.address("reachable")
    ik_status = mmap.address("status")
    out = [
        "Network // Start (SB1, I0.0): a rising edge asks for a move",
        "LD     I0.0", "EU", f"=      {m['start']}",
        "Network // Start refused (Status, Error; no axis moves): moving 104, a stop latched "
        "102, a fault latched 103, Enable off 100, not homed 101, the IK's refusal (its status)",
        *_refusals(m["start"]),
        *_refuse(m["start"], [f"AN     {m['Homed']}"], "101"),
        *_refuse(m["start"], [f"AN     {ok}"], ik_status),
        "Network // Start: latch the targets (c1..c3: a target typed later changes nothing of "
        "this move) and the moves d = target - position",
        f"LD     {m['start']}",
    ]  # fmt: skip
    for j in range(3):
        out += [f"MOVD   {c[j]}, {m['target'][j]}", f"MOVD   {m['target'][j]}, {m['move'][j]}",
                f"-D     {m['pos'][j]}, {m['move'][j]}"]  # fmt: skip
    for j in range(3):
        if not plan.unlimited[j]:
            continue
        d, half = m["move"][j], plan.ppr[j] // 2
        out += [
            f"Network // joint {j + 1} turns without limit: the short way (|d| <= {half})",
            f"LD     {m['start']}", f"AD>    {d}, {half}", f"-D     {plan.ppr[j]}, {d}",
            f"LD     {m['start']}", f"AD<    {d}, {-half}", f"+D     {plan.ppr[j]}, {d}",
        ]  # fmt: skip
    out.append("Network // Start: directions now (a scan before PLS), |d| (the pulse counts)")
    for j in range(3):
        d, n, q = m["move"][j], m["count"][j], _WIRING[j][2]
        out += [
            f"LD     {m['start']}", f"AD>=   {d}, 0", f"S      {q}, 1",
            f"LD     {m['start']}", f"AD<    {d}, 0", f"R      {q}, 1",
            f"LD     {m['start']}", f"MOVD   {d}, {n}", f"AD<    {d}, 0", f"MOVD   0, {n}",
            f"-D     {d}, {n}",
        ]  # fmt: skip
    for j, (r, offs) in enumerate(zip(plan.ramps, plan.tables, strict=True)):
        n, sel = m["count"][j], m["table"][j]
        out += [
            f"Network // joint {j + 1}: ramp level k (the largest with 2 x cum_k < |d|), its "
            "plateau's count |d| - 2 x cum_k, its table",
            f"LD     {m['start']}", f"MOVW   {offs[0]}, {sel}", f"MOVD   {n}, VD{offs[0] + 5}",
        ]  # fmt: skip
        for k in range(1, r.levels + 1):
            slot = f"VD{offs[k] + 1 + 8 * k + 4}"
            two = 2 * r.cum[k]
            out += [f"LD     {m['start']}", f"AD>    {n}, {two}", f"MOVW   {offs[k]}, {sel}",
                    f"MOVD   {n}, {slot}", f"-D     {two}, {slot}"]  # fmt: skip
    out += [
        "Network // Start accepted: phase A prepared (KM1 on: PTO1 -> shoulder; KM2 off), busy",
        f"LD     {m['start']}", "S      Q0.3, 1", "R      Q0.4, 1", f"MOVB   1, {m['step']}",
        f"S      {m['Busy']}, 1", f"R      {m['Done']}, 1", f"R      {m['Error']}, 1",
        f"MOVW   0, {m['Status']}", f"R      {m['start']}, 1",
    ]  # fmt: skip
    return out


def motion_networks(arm, mmap, work: dict | None = None, levels: int = 5) -> list[str]:
    """S7-200 STL networks (lines starting with "Network" open one) of ``arm``'s machine,
    to follow the IK networks of the same OB1 (module docstring).

    Parameters
    ----------
    arm : Arm
        Three revolute joints with ``max_velocity``, ``max_acceleration`` and ``home``.
    mmap : MemoryMap
        The IK program's map (c1..c3, the reach flag and the status are read from it).
    work : dict, optional
        The IK's work area (name -> V offset): the profile tables follow it.
    levels : int
        Acceleration segments of a full ramp (:func:`~.profile.ramp`).
    """
    m = MOTION_MAP
    _check_room(mmap)
    plan = motion_plan(arm, _table_base(mmap, work), levels)
    mmap.check_end(plan.end - 1, "the motion networks' profile tables")
    home = [f"MOVD   {h}, {p}" for h, p in zip(plan.home, m["pos"], strict=True)]
    arrived = [f"MOVD   {t}, {p}" for t, p in zip(m["target"], m["pos"], strict=True)]
    arrived += [f"MOVB   0, {m['step']}", f"R      {m['Busy']}, 1", f"S      {m['Done']}, 1",
                "R      Q0.4, 1"]  # fmt: skip
    return [
        "Network // first scan only (SM0.1); later scans jump over these networks",
        "LDN    SM0.1", f"JMP    {_SKIP_INIT}",
        "Network // outputs off (pulses, directions, relays), PTO0/PTO1 enabled for multiple "
        "segments in us (16#A0), idle, not homed, no error",
        "LD     SM0.0", "R      Q0.0, 8", f"MOVB   16#{CONTROL:02X}, SMB67",
        f"MOVB   16#{CONTROL:02X}, SMB77", f"MOVB   0, {m['step']}", "MOVB   0, VB122",
        "MOVB   0, VB123", f"MOVW   0, {m['Status']}",
        *(f"MOVD   0, {p}" for p in m["pos"]),
        *_table_writes(plan),
        "Network // every scan from here",
        f"LBL    {_SKIP_INIT}",
        "Network // the stop circuit open (StopOK = I0.1, SB2 normally closed) or Enable off "
        "during a move: abort both trains (enable bit 0 + PLS), relays off, position lost",
        "LDN    I0.1", f"ON     {m['Enable']}", f"AB<>   {m['step']}, 0",
        "MOVB   0, SMB67", "PLS    0", "MOVB   0, SMB77", "PLS    1", *_abort(None),
        "Network // the stop circuit open (pressed, or a broken wire): latched until Reset",
        "LDN    I0.1", f"S      {m['stopped']}, 1",
        *_phase_done(4, (1,), arrived, "phase B"),
        "Network // phase B prepared a scan ago (KM2 on): its first scan",
        f"LDB=   {m['step']}, 3", f"MOVB   4, {m['step']}", f"S      {m['entry']}, 1",
        *_phase_done(2, (0, 1), ["R      Q0.3, 1", "S      Q0.4, 1", f"MOVB   3, {m['step']}"],
                     "phase A"),
        "Network // phase A prepared a scan ago (directions, KM1): its first scan",
        f"LDB=   {m['step']}, 1", f"MOVB   2, {m['step']}", f"S      {m['entry']}, 1",
        "Network // phase A's first scan: PLS 0 (waist), PLS 1 (shoulder through KM1), each "
        "with its profile and its control byte",
        f"LDB=   {m['step']}, 2", f"A      {m['entry']}", "LPS", *_pls(0, plan), "LPP",
        *_pls(1, plan),
        "Network // phase B's first scan: PLS 1 (elbow through KM2)",
        f"LDB=   {m['step']}, 4", f"A      {m['entry']}", *_pls(2, plan),
        "Network // Reset (HMI, rising edge) with the stop circuit closed: the latches and "
        "Error cleared, the PTO re-enabled (16#A0), its abort, overflow and delta bits cleared",
        f"LD     {m['Reset']}", "EU", "A      I0.1", f"R      {m['stopped']}, 2",
        f"R      {m['Error']}, 1", f"MOVB   16#{CONTROL:02X}, SMB67",
        f"MOVB   16#{CONTROL:02X}, SMB77", "R      SM66.4, 3", "R      SM76.4, 3",
        f"MOVW   0, {m['Status']}",
        "Network // a stop (102) or a fault (103) latched: Error, every scan until Reset",
        f"LD     {m['stopped']}", f"O      {m['fault']}", f"S      {m['Error']}, 1",
        f"MOVW   102, {m['Status']}", f"LD     {m['fault']}", f"MOVW   103, {m['Status']}",
        "Network // Home (HMI, rising edge): refused while moving 104, a stop latched 102, a "
        "fault latched 103, Enable off 100",
        f"LD     {m['Home']}", "EU", f"=      {m['home']}", *_refusals(m["home"]),
        "Network // homed (mode 'set'): the arm stands at its home pose, the positions := its "
        "counts",
        f"LD     {m['home']}", *home, f"S      {m['Homed']}, 1", f"S      {m['Done']}, 1",
        f"R      {m['Error']}, 1", f"MOVW   0, {m['Status']}", f"R      {m['home']}, 1",
        *_start(plan, mmap),
        "Network // end of the scan: a step's first scan is over",
        "LD     SM0.0", f"R      {m['entry']}, 1",
    ]  # fmt: skip


def _check_room(mmap) -> None:
    """VB120-VB183 must be free of the map's inputs, outputs and work area."""
    taken = set()
    for v in (*mmap.inputs.values(), *mmap.outputs.values()):
        b = v if isinstance(v, int) else v[0]
        taken |= set(range(b, b + 4))
    if taken & set(range(120, 184)) or mmap.work_base < 184:
        raise ValueError(
            "the motion networks use VB120-VB183; the map's inputs, outputs or work area (from "
            f"VB{mmap.work_base}) overlap them"
        )


def _table_base(mmap, work: dict | None) -> int:
    """The profile tables' first V byte: after the IK's work area (and every map address)."""
    ends = [v + 4 for v in (work or {}).values()]
    ends += [mmap.work_base, 184]
    return max(ends)


def motion_uses(arm, mmap, work: dict | None = None) -> dict[str, str]:
    """Address -> what the motion networks use it for (MAP.json ``memory``)."""
    m = MOTION_MAP
    plan = motion_plan(arm, _table_base(mmap, work))
    uses = {m["step"]: "motion step (0 idle, 1/2 phase A prepared/running, 3/4 phase B)",
            m["entry"]: "motion: a step's first scan", m["start"]: "motion: Start requested",
            m["home"]: "motion: Home requested",
            m["stopped"]: "motion: a stop latched (StopOK was FALSE) until Reset",
            m["fault"]: "motion: a pulse-train fault latched until Reset"}  # fmt: skip
    for j in range(3):
        uses[m["pos"][j]] = f"motion: joint {j + 1} position [pulses]"
        uses[m["target"][j]] = f"motion: joint {j + 1} latched target [pulses]"
        uses[m["move"][j]] = f"motion: joint {j + 1} move [pulses, signed]"
        uses[m["count"][j]] = f"motion: joint {j + 1} |move| [pulses]"
        uses[m["table"][j]] = f"motion: joint {j + 1} profile table offset"
    for j, offs in enumerate(plan.tables):
        for k, off in enumerate(offs):
            what = f"motion: joint {j + 1}'s PTO profile at ramp level {k} (Table 9-15)"
            uses[f"VB{off}"] = what + ": segments"
            for i in range(2 * k + 1):
                s = off + 1 + 8 * i
                uses[f"VW{s}"] = f"{what}: segment {i + 1} initial cycle [us]"
                uses[f"VW{s + 2}"] = f"{what}: segment {i + 1} cycle delta [us/pulse]"
                uses[f"VD{s + 4}"] = f"{what}: segment {i + 1} pulses"
    for ch in (0, 1):
        for bit, what in ((4, "profile aborted: delta error"), (5, "aborted by the user"),
                          (6, "pipeline overflow"), (7, "idle")):  # fmt: skip
            uses[f"SM{66 + 10 * ch}.{bit}"] = f"PTO{ch} status: {what}"
    uses["VB122"] = "motion: Homed, Busy, Done, Error (cleared together at start-up)"
    uses["VB123"] = "motion: a step's first scan, the requests, the latches (cleared at start-up)"
    for name, (addr, _t, _d, meaning) in MACHINE_IO.items():
        uses[addr] = f"{name}: {meaning}"
    uses.update({
        "Q0.0": "PTO0 pulses, waist (Table 2)", "Q0.1": "PTO1 pulses, shoulder or elbow (Table 2)",
        "Q0.2": "waist direction (Table 2)", "Q0.3": "KM1: PTO1 to the shoulder driver (Table 2)",
        "Q0.4": "KM2: PTO1 to the elbow driver (Table 2)", "Q0.5": "shoulder direction (Table 2)",
        "Q0.7": "elbow direction (Table 2)",
        "SMB66": "PTO0 status (.4 delta error, .5 aborted, .6 overflow, .7 idle)",
        "SMB67": "PTO0 control byte", "SMW168": "PTO0 profile offset",
        "SMB76": "PTO1 status (.4 delta error, .5 aborted, .6 overflow, .7 idle)",
        "SMB77": "PTO1 control byte", "SMW178": "PTO1 profile offset",
    })  # fmt: skip
    return uses


def supports(arm) -> bool:
    """Whether the S7-200 program of ``arm`` gets the motion networks: an arm of the grabber's
    closed form (three revolute joints, Table 2's machine) whose description gives every
    joint's ``max_velocity``, ``max_acceleration`` and ``home`` (another arm gets the IK
    alone, as before)."""
    desc = arm.description
    if getattr(desc, "closed_form", None) != "grabber" or len(desc.joints) != 3:
        return False
    keys = ("max_velocity", "max_acceleration", "home_mode", "home_position")
    return all(getattr(j, k) is not None for j in desc.joints for k in keys)


def machine_document(arm, mmap) -> dict:
    """MAP.json's ``machine`` section: issue 29's variables with their addresses, types and
    meanings (the targets are the IK's inputs), and every status code with its alarm text."""
    signals = {}
    for name, (addr, typ, direction, meaning) in MACHINE_IO.items():
        signals[name] = {"address": addr, "type": typ, "direction": direction, "meaning": meaning}
    for name, key in zip(("TargetX", "TargetY", "TargetZ"), list(mmap.inputs)[:3], strict=True):
        meaning = f"target {key} [mm] (the IK's input; latched by Start)"
        signals[name] = {"address": mmap.address(key), "type": "REAL", "direction": "input",
                         "meaning": meaning}  # fmt: skip
    codes = {str(k): {"name": n, "meaning": meaning, "alarm": alarm}
             for k, (n, meaning, alarm) in STATUS.items()}  # fmt: skip
    codes["ik"] = {
        "name": "the IK's status",
        "meaning": "a Start whose target the IK refuses: Status repeats the IK's status code "
        "(status_codes above: out of reach, inside reach, base axis, joint limits, not finite)",
        "alarm": "Target refused: see the IK status",
    }
    wiring = {
        "Q0.0": "PTO0 pulses: waist driver", "Q0.1": "PTO1 pulses: through KM1 or KM2",
        "Q0.2": "waist direction (1: counts up)", "Q0.3": "KM1: PTO1 to the shoulder",
        "Q0.4": "KM2: PTO1 to the elbow", "Q0.5": "shoulder direction (1: counts up)",
        "Q0.7": "elbow direction (1: counts up)",
    }  # fmt: skip
    return {
        "signals": signals,
        "status_codes": codes,
        "wiring": wiring,
        "needs": "I/O Table 2 does not list: the HMI bits Enable, Home, Reset (V121.0-.2); for a "
        "deployment a reference switch per joint (homing by switch), an E-stop circuit that "
        "removes the drivers' power, driver enable and alarm signals, a pulse counter to keep the "
        "position through a stop, relay contact feedback and a settling time before PLS",
        "ramp": "multi-segment PTO profiles within max_velocity and max_acceleration; jerk not "
        "limited (analysis.plc.motion.profile)",
        "arm": arm.description.name,
    }
