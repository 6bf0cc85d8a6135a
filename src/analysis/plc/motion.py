"""Motion networks: pulse counts -> stepper moves on the CPU 224's two PTO channels.

I/O per the paper's Table 2: SB1 start I0.0, SB2 stop I0.1; pulse outputs Q0.0, Q0.1;
direction outputs Q0.2, Q0.5, Q0.7; relays KM1 Q0.3, KM2 Q0.4.

Sharing two PTO channels among three steppers (a documented choice; the paper does not
say how it does it). We read Table 2 as: PTO0 (Q0.0) drives the waist, direction Q0.2;
PTO1 (Q0.1) is switched by the relays, KM1 (Q0.3) routing it to the shoulder driver
(direction Q0.5) and KM2 (Q0.4) to the elbow driver (direction Q0.7). Sequence:

* step 0, idle: on a rising edge of SB1 with the reach flag on, the move is latched: the
  targets ``t_i := c_i`` and the relative moves ``d_i = t_i - position_i`` are stored, the
  directions set from their signs (all in that one scan, the ``start`` bit), KM1 on and
  KM2 off, and phase A starts: PTO0 = |d1| (waist) and PTO1 = |d2| (shoulder) together.
* step 1 -> 2: when both channels are idle (SM66.7, SM76.7), KM1 off, KM2 on, phase B:
  PTO1 = |d3| (elbow). (A real installation needs a relay settling delay here, e.g. a
  TON of 50 ms before PLS 1; not generated because its length depends on the relays.)
* step 2 -> 0: when PTO1 is idle, KM2 off, positions := the latched targets ``t_i``.
* SB2 (I0.1) aborts both trains (enable bit cleared + PLS) and returns to step 0; the
  positions are then unknown and the arm must be re-homed.

A new target typed while the arm moves changes c1..c3 at once (the IK runs every scan) but
nothing of the move: the pulses, directions and the positions recorded at its end come from
the values latched at the start (``tests/plc/test_motion.py`` changes the target mid-move on
awlsim and on the S7-200 evaluator).

The "done" networks come before the networks that execute PLS, so an idle bit is never
tested in the scan that started its train (whether SM66.7 drops within the PLS scan is
not documented in the sources we have). A zero move loads no pulses (the PTO needs a
count >= 1). Single-segment PTO, control byte 16#85 (enable, PTO, single segment,
microseconds, update count and cycle time), cycle time 500 us (1 kHz) by default
(STEP 7-Micro/WIN help, PTO, s7-24yeq.htm).

Start-up (:data:`MOTION_STARTUP`): the first scan (SM0.1) resets Q0.0-Q0.7, loads the PTO
control bytes and cycle times and sets the positions to 0: the arm must stand at its zero
pose (all counts 0) when the CPU starts. No homing sequence is generated.
"""

from __future__ import annotations

from analysis.plc.memmap import MemoryMap, default_map

__all__ = ["MOTION_MAP", "MOTION_STARTUP", "motion_networks", "motion_uses"]

MOTION_MAP = {
    "step": "VB120",
    "start": "V121.0",
    "pos1": "VD124",
    "pos2": "VD128",
    "pos3": "VD132",
    "d1": "VD136",
    "d2": "VD140",
    "d3": "VD144",
    "t1": "VD148",
    "t2": "VD152",
    "t3": "VD156",
}
"""The motion networks' own V memory (an HMI must not write there)."""

MOTION_STARTUP = (
    "the first scan (SM0.1) resets Q0.0-Q0.7, sets PTO0/PTO1 to single segment (SMB67 = "
    "SMB77 = 16#85, cycle SMW68/SMW78) and the positions VD124-VD132 to 0: the arm must "
    "stand at its zero pose (all counts 0) at power-up; no homing is generated"
)

_USES = {
    "VB120": "motion step (0 idle, 1 waist + shoulder, 2 elbow)",
    "V121.0": "motion start pulse (the scan a move is latched)",
    "VD124": "motion: waist position [pulses]",
    "VD128": "motion: shoulder position [pulses]",
    "VD132": "motion: elbow position [pulses]",
    "VD136": "motion: |waist move| [pulses]",
    "VD140": "motion: |shoulder move| [pulses]",
    "VD144": "motion: |elbow move| [pulses]",
    "VD148": "motion: latched waist target [pulses]",
    "VD152": "motion: latched shoulder target [pulses]",
    "VD156": "motion: latched elbow target [pulses]",
    "AC1": "motion: signed waist move (start scan only)",
    "AC2": "motion: signed shoulder move (start scan only)",
    "AC3": "motion: signed elbow move (start scan only)",
    "I0.0": "SB1 start (Table 2)",
    "I0.1": "SB2 stop (Table 2)",
    "Q0.0": "PTO0 pulses, waist (Table 2)",
    "Q0.1": "PTO1 pulses, shoulder or elbow via KM1/KM2 (Table 2)",
    "Q0.2": "waist direction (Table 2)",
    "Q0.3": "KM1: PTO1 to the shoulder driver (Table 2)",
    "Q0.4": "KM2: PTO1 to the elbow driver (Table 2)",
    "Q0.5": "shoulder direction (Table 2)",
    "Q0.7": "elbow direction (Table 2)",
    "SM66.7": "PTO0 idle",
    "SM76.7": "PTO1 idle",
    "SMB67": "PTO0 control byte",
    "SMW68": "PTO0 cycle time [us]",
    "SMD72": "PTO0 pulse count",
    "SMB77": "PTO1 control byte",
    "SMW78": "PTO1 cycle time [us]",
    "SMD82": "PTO1 pulse count",
}


def motion_uses() -> dict[str, str]:
    """Address -> what the motion networks use it for (MAP.json ``memory``)."""
    return dict(_USES)


def _abs_to(src: str, dst: str, dirbit: str, start: str) -> list[str]:
    """In the start scan only: dst := |src| (DINT), dirbit := src >= 0."""
    return [
        f"LD     {start}",
        f"AD>=   {src}, 0",
        f"S      {dirbit}, 1",
        f"LD     {start}",
        f"AD<    {src}, 0",
        f"R      {dirbit}, 1",
        f"LD     {start}",
        f"MOVD   {src}, {dst}",
        f"AD<    {src}, 0",
        f"MOVD   0, {dst}",
        f"-D     {src}, {dst}",
    ]


def motion_networks(mmap: MemoryMap | None = None, cycle_us: int = 500) -> list[str]:
    """S7-200 STL networks (lines starting with "Network" open a network) for the sequence.

    Parameters
    ----------
    mmap : MemoryMap
        The IK program's map (c1..c3 and the reach flag are read from it).
    cycle_us : int
        PTO cycle time [us] (10..65535).
    """
    mmap = mmap or default_map("s7-200")
    if not 10 <= cycle_us <= 65535:
        raise ValueError(f"cycle_us = {cycle_us} outside the PTO range 10..65535 us")
    c1, c2, c3 = (mmap.address(k) for k in ("c1", "c2", "c3"))
    ok = mmap.address("reachable")
    m = MOTION_MAP
    taken = {b for k, b in mmap.inputs.items()} | {
        v if isinstance(v, int) else v[0] for v in mmap.outputs.values()
    }
    for b in list(taken):
        taken |= {b + 1, b + 2, b + 3}
    mine = set(range(120, 160))
    if taken & mine or mmap.work_base < 160:
        raise ValueError(
            "the motion networks use VB120-VB159; the map's inputs, outputs or work area "
            f"(from VB{mmap.work_base}) overlap them"
        )
    return [
        "Network // motion init (first scan): outputs off, PTO0/PTO1 single segment, positions 0",
        "LD     SM0.1",
        "R      Q0.0, 8",
        "MOVB   16#85, SMB67",
        "MOVB   16#85, SMB77",
        f"MOVW   {cycle_us}, SMW68",
        f"MOVW   {cycle_us}, SMW78",
        f"MOVB   0, {m['step']}",
        f"MOVD   0, {m['pos1']}",
        f"MOVD   0, {m['pos2']}",
        f"MOVD   0, {m['pos3']}",
        "Network // phase B done (PTO1 idle): KM2 off, positions := latched targets, idle",
        f"LDB=   {m['step']}, 2",
        "A      SM76.7",
        "R      Q0.4, 1",
        f"MOVD   {m['t1']}, {m['pos1']}",
        f"MOVD   {m['t2']}, {m['pos2']}",
        f"MOVD   {m['t3']}, {m['pos3']}",
        f"MOVB   0, {m['step']}",
        "Network // phase A done (both idle): KM1 off, KM2 on (PTO1 -> elbow), PLS 1 elbow",
        f"LDB=   {m['step']}, 1",
        "A      SM66.7",
        "A      SM76.7",
        "R      Q0.3, 1",
        "S      Q0.4, 1",
        f"MOVB   2, {m['step']}",
        f"LDB=   {m['step']}, 2",
        "EU",
        f"AD>    {m['d3']}, 0",
        f"MOVD   {m['d3']}, SMD82",
        "PLS    1",
        "Network // SB1 (I0.0) rising edge, reachable, idle: latch targets and relative moves",
        "LD     I0.0",
        "EU",
        f"A      {ok}",
        f"AB=    {m['step']}, 0",
        f"=      {m['start']}",
        f"MOVD   {c1}, {m['t1']}",
        f"MOVD   {c2}, {m['t2']}",
        f"MOVD   {c3}, {m['t3']}",
        f"MOVD   {m['t1']}, AC1",
        f"-D     {m['pos1']}, AC1",
        f"MOVD   {m['t2']}, AC2",
        f"-D     {m['pos2']}, AC2",
        f"MOVD   {m['t3']}, AC3",
        f"-D     {m['pos3']}, AC3",
        f"MOVB   1, {m['step']}",
        "Network // start scan: |d| and direction bits (waist Q0.2, shoulder Q0.5, elbow Q0.7)",
        *_abs_to("AC1", m["d1"], "Q0.2", m["start"]),
        *_abs_to("AC2", m["d2"], "Q0.5", m["start"]),
        *_abs_to("AC3", m["d3"], "Q0.7", m["start"]),
        "Network // phase A: KM1 on (PTO1 -> shoulder), KM2 off; PLS 0 waist, PLS 1 shoulder",
        f"LDB=   {m['step']}, 1",
        "EU",
        "R      Q0.4, 1",
        "S      Q0.3, 1",
        f"LDB=   {m['step']}, 1",
        "EU",
        f"AD>    {m['d1']}, 0",
        f"MOVD   {m['d1']}, SMD72",
        "PLS    0",
        f"LDB=   {m['step']}, 1",
        "EU",
        f"AD>    {m['d2']}, 0",
        f"MOVD   {m['d2']}, SMD82",
        "PLS    1",
        "Network // SB2 (I0.1): abort both trains, relays off, idle (re-home afterwards)",
        "LD     I0.1",
        "MOVB   16#05, SMB67",
        "PLS    0",
        "MOVB   16#05, SMB77",
        "PLS    1",
        "R      Q0.3, 2",
        f"MOVB   0, {m['step']}",
    ]
