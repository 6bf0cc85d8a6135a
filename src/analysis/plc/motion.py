"""Motion networks: pulse counts -> stepper moves on the CPU 224's two PTO channels.

I/O per the paper's Table 2: SB1 start I0.0, SB2 stop I0.1; pulse outputs Q0.0, Q0.1;
direction outputs Q0.2, Q0.5, Q0.7; relays KM1 Q0.3, KM2 Q0.4.

Sharing two PTO channels among three steppers (a documented choice; the paper does not
say how it does it). We read Table 2 as: PTO0 (Q0.0) drives the waist, direction Q0.2;
PTO1 (Q0.1) is switched by the relays, KM1 (Q0.3) routing it to the shoulder driver
(direction Q0.5) and KM2 (Q0.4) to the elbow driver (direction Q0.7). Sequence:

* step 0, idle: on a rising edge of SB1 with the reach flag on, the relative moves
  ``d_i = c_i - position_i`` are computed, directions set from their signs, KM1 on and
  KM2 off, and phase A starts: PTO0 = |d1| (waist) and PTO1 = |d2| (shoulder) together.
* step 1 -> 2: when both channels are idle (SM66.7, SM76.7), KM1 off, KM2 on, phase B:
  PTO1 = |d3| (elbow). (A real installation needs a relay settling delay here, e.g. a
  TON of 50 ms before PLS 1; not generated because its length depends on the relays.)
* step 2 -> 0: when PTO1 is idle, KM2 off, positions := c.
* SB2 (I0.1) aborts both trains (enable bit cleared + PLS) and returns to step 0; the
  positions are then unknown and the arm must be re-homed.

The "done" networks come before the networks that execute PLS, so an idle bit is never
tested in the scan that started its train (whether SM66.7 drops within the PLS scan is
not documented in the sources we have). A zero move loads no pulses (the PTO needs a
count >= 1). Single-segment PTO, control
byte 16#85 (enable, PTO, single segment, microseconds, update count and cycle time),
cycle time 500 us (1 kHz) by default.
"""

from __future__ import annotations

from analysis.plc.memmap import MemoryMap, default_map

__all__ = ["MOTION_MAP", "motion_networks"]

MOTION_MAP = {
    "step": "VB120",
    "pos1": "VD124",
    "pos2": "VD128",
    "pos3": "VD132",
    "d1": "VD136",
    "d2": "VD140",
    "d3": "VD144",
}


def _abs_to(src: str, dst: str, dirbit: str) -> list[str]:
    """dst := |src| (DINT), dirbit := src >= 0."""
    return [
        f"LDD>=  {src}, 0",
        f"=      {dirbit}",
        "LD     SM0.0",
        f"MOVD   {src}, {dst}",
        f"LDD<   {src}, 0",
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
    return [
        "Network // motion init (first scan): PTO0/PTO1 single segment, 16#85, positions 0",
        "LD     SM0.1",
        "R      Q0.0, 2",
        "MOVB   16#85, SMB67",
        "MOVB   16#85, SMB77",
        f"MOVW   {cycle_us}, SMW68",
        f"MOVW   {cycle_us}, SMW78",
        f"MOVB   0, {m['step']}",
        f"MOVD   0, {m['pos1']}",
        f"MOVD   0, {m['pos2']}",
        f"MOVD   0, {m['pos3']}",
        "Network // phase B done (PTO1 idle): KM2 off, positions := targets, idle",
        f"LDB=   {m['step']}, 2",
        "A      SM76.7",
        "R      Q0.4, 1",
        f"MOVD   {c1}, {m['pos1']}",
        f"MOVD   {c2}, {m['pos2']}",
        f"MOVD   {c3}, {m['pos3']}",
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
        "Network // SB1 (I0.0) rising edge, reachable, idle: relative moves and directions",
        "LD     I0.0",
        "EU",
        f"A      {ok}",
        f"AB=    {m['step']}, 0",
        f"MOVD   {c1}, AC1",
        f"-D     {m['pos1']}, AC1",
        f"MOVD   {c2}, AC2",
        f"-D     {m['pos2']}, AC2",
        f"MOVD   {c3}, AC3",
        f"-D     {m['pos3']}, AC3",
        f"MOVB   1, {m['step']}",
        "Network // |d| and direction bits (waist Q0.2, shoulder Q0.5, elbow Q0.7)",
        *_abs_to("AC1", m["d1"], "Q0.2"),
        *_abs_to("AC2", m["d2"], "Q0.5"),
        *_abs_to("AC3", m["d3"], "Q0.7"),
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
