"""The S7-200's pulse train outputs (PTO0 on Q0.0, PTO1 on Q0.1) and the PLS instruction
(mixed into :class:`~.cpu.S7200`), simulated in time.

:class:`PtoChannel` is one generator as the S7-200 System Manual documents it; it knows
nothing of the evaluator, so that the awlsim side (:mod:`analysis.plc.motion.engines`) runs
the same model on the PLS records the AWL translation logs. Sources: [S2M-A] the S7-200
Programmable Controller System Manual A5E00066097-02 (manualslib.com/manual/1303220), [S2M-C]
its edition C79000-G7076-C233-01 (manualshelf.com, page-NNN), [S2M-6] the edition whose PTO
section is 6 (scribd.com/document/599073354), [SMART] the S7-200 SMART System Manual; "~"
marks an assumption.

Registers (per channel; PTO1 adds 10 to every SM byte) [S2M-C p.233, Table 9-17]:

=========  ==============================================================================
SMB67      control byte: .7 enable, .6 PWM (not modelled: PLS refused at run time), .5 multiple
           segments, .3 time base (0 us, 1 ms), .2 update the pulse count, .0 update the
           cycle time
SMW68      cycle time, 2-65535 units; SMD72 pulse count, 1-4,294,967,295 (single segment)
SMB66      status: .4 profile aborted by a delta calculation error, .5 aborted by the user,
           .6 pipeline overflow, .7 idle
SMB166     the segment in progress (multiple segments; ~ numbered from 1)
SMW168     the profile table's offset from VB0 (multiple segments)
=========  ==============================================================================

Behaviour modelled:

* PLS with the enable bit cleared disables the generator: a train in progress is aborted
  (SM66.5 set), the pipeline emptied, the channel idle; the output reverts to the process
  image [S2M-C p.226: "disable ... by writing zero to the enable bit ... and then executing
  PLS"; S2M-A p.9-53 (user abort bit)]. It never starts a train, whatever else the control
  byte says: a PLS after a disabling control byte aborts, every time.
* Single segment [S2M-C p.228]: PLS copies SMW68/SMD72 into the generator when the update
  bits ask for it (the registers start at 0 [S2M-C p.226]); a cycle time under 2 units is 2,
  a count of 0 is 1 [S2M-6 Table 6-33]. An idle channel starts the train at once; a busy
  one holds it in a one-entry pipeline that starts when the running train ends; a PLS with
  the pipeline full sets SM66.6 and is ignored [S2M-C p.228; SMART 7.7.2].
* Multiple segments [S2M-A p.9-53, Table 9-15]: PLS reads the profile table at SMW168: a
  byte, the number of segments (1-255; 0: no output, a non-fatal error), then 8 bytes a
  segment: the initial cycle time (word, 2-65535 units), the cycle time delta per pulse
  (signed word) and the pulse count (double word). The k-th pulse of a segment (k = 0, 1,
  ...) lasts ``initial + k * delta`` units (~ the delta applied from the second pulse on,
  as the Position Control Wizard's ``(final - initial) / count`` reads); a cycle time that
  leaves 2..65535 ends the profile with SM66.4 set [S2M-A p.9-53]. The table is read when
  PLS runs (~ the manual says the CPU reads it "automatically"; a program that rewrites the
  table while its profile runs is not modelled). A PLS while a profile runs sets SM66.6 and
  is ignored (~ as the single-segment pipeline when full: a profile fills the pipeline).
* The idle bit: cleared by the PLS that starts a train, set when the last pulse's cycle has
  ended [S2M-C p.233]. SM66.4-.6 stay set until the program resets them (~ as the manual
  says of SM66.6, "you must clear this bit manually").
* Time: the evaluator runs each scan's program at the scan's start and then lets the
  generators run for ``scan_ms`` (:meth:`~.cpu.S7200.scan`); a train started by PLS begins at
  the scan's start. Each pulse is a time (its rising edge, seconds from power-up); what a
  pulse does at a driver (direction, relays) is the machine's business
  (:mod:`analysis.plc.motion`), read from the output terminals of the scan it falls in.
"""

from __future__ import annotations

import struct
from dataclasses import dataclass, field

from analysis.plc.stl_eval.operands import U16, U32

__all__ = ["PtoChannel", "PulseOutput", "Train"]

IDLE, OVERFLOW, ABORTED, DELTA_ERROR = 0x80, 0x40, 0x20, 0x10
_SEG = struct.Struct(">HhI")


@dataclass
class Train:
    """One pulse train (a single segment, or a profile): when PLS started it and its
    segments ``(initial cycle, delta, count)`` in time-base units, ``unit`` seconds each."""

    start: float
    segments: list[tuple[int, int, int]]
    unit: float
    control: int
    pulses: int = 0
    """Pulses emitted so far."""
    end: str = ""
    """How it ended: "done", "aborted", "delta error" (empty while it runs)."""


@dataclass
class PtoChannel:
    """One PTO generator (module docstring). ``pulses``: the rising edges emitted [s];
    ``flags``: the status bits (SM66.4-.6) raised since the CPU last copied them."""

    ch: int
    idle: bool = True
    flags: int = 0
    segment_no: int = 0
    cycle: int = 0
    count: int = 0
    trains: list[Train] = field(default_factory=list)
    pulses: list[float] = field(default_factory=list)
    pulse_train: list[int] = field(default_factory=list)
    """The index in :attr:`trains` of each pulse's train."""
    _run: Train | None = None
    _queued: Train | None = None
    _seg: int = 0
    _k: int = 0
    _next: int = 0
    """The next rising edge [ns] (integer: cycle times add up exactly)."""

    @property
    def busy(self) -> bool:
        return self._run is not None

    def pls(self, t: float, control: int, cycle: int, count: int, table=None) -> str:
        """Execute PLS at time ``t`` [s]: ``control`` the control byte, ``cycle`` SMW68 (or,
        for a profile, SMW168: the table's offset), ``count`` SMD72; ``table(offset, n)``
        returns ``n`` bytes of V memory from ``offset``. Returns what happened: "abort",
        "idle" (disabled, nothing ran), "start", "queued", "overflow", "no segments",
        "pwm"."""
        if not control & 0x80:
            aborted = self._run is not None
            if aborted:
                self._run.end = "aborted"
                self.flags |= ABORTED
            self._run = self._queued = None
            self.idle, self.segment_no = True, 0
            return "abort" if aborted else "idle"
        if control & 0x40:
            return "pwm"
        unit = 1e-3 if control & 0x08 else 1e-6
        if control & 0x20:
            n = table(cycle, 1)[0]
            if n == 0:
                return "no segments"
            raw = table(cycle + 1, 8 * n)
            segs = [_SEG.unpack_from(raw, 8 * i) for i in range(n)]
            segs = [(c, d, max(k, 1)) for c, d, k in segs]
            if self._run is not None:
                self.flags |= OVERFLOW
                return "overflow"
        else:
            if control & 0x01:
                self.cycle = cycle
            if control & 0x04:
                self.count = count
            segs = [(max(self.cycle, 2), 0, max(self.count, 1))]
            if self._run is not None:
                if self._queued is not None or self._run.control & 0x20:
                    self.flags |= OVERFLOW
                    return "overflow"
                self._queued = Train(t, segs, unit, control)
                return "queued"
        self._begin(Train(t, segs, unit, control), round(t * 1e9))
        return "start"

    def _begin(self, train: Train, t_ns: int) -> None:
        self._run, self._seg, self._k, self._next = train, 0, 0, t_ns
        train.start = t_ns / 1e9
        self.trains.append(train)
        self.idle, self.segment_no = False, 1

    def advance(self, t_end: float) -> int:
        """Emit the pulses whose rising edge falls before ``t_end`` [s] and end the trains
        whose last cycle is over by then. Returns the number of pulses emitted."""
        n0, t_end = len(self.pulses), round(t_end * 1e9)
        while self._run is not None:
            run = self._run
            if self._seg == len(run.segments):  # every pulse out: done when its cycle ends
                if self._next > t_end:
                    break
                run.end = "done"
                self._finish(self._next)
                continue
            if self._next >= t_end:
                break
            c0, d, n = run.segments[self._seg]
            c = c0 + self._k * d
            if not 2 <= c <= 65535:  # the delta left the legal cycle times: SM66.4
                run.end = "delta error"
                self.flags |= DELTA_ERROR
                self._finish(None)
                break
            self.pulses.append(self._next / 1e9)
            self.pulse_train.append(len(self.trains) - 1)
            run.pulses += 1
            self._next += c * (1_000_000 if run.unit == 1e-3 else 1_000)
            self._k += 1
            if self._k == n:
                self._seg, self._k = self._seg + 1, 0
                self.segment_no = min(self._seg + 1, len(run.segments))
        return len(self.pulses) - n0

    def _finish(self, t: int | None) -> None:
        queued, self._run, self._queued = self._queued, None, None
        self.segment_no = 0
        if queued is not None and t is not None:  # the pipeline starts at once [S2M-C p.228]
            self._begin(queued, t)
        else:
            self.idle = True

    def status_byte(self, old: int) -> int:
        """SMB66 from its ``old`` value: the idle bit, the flags raised since the last call
        added (the program clears them), bits 0-3 kept; the flags are then consumed."""
        new = (old & 0x7F) | self.flags | (IDLE if self.idle else 0)
        self.flags = 0
        return new


class PulseOutput:
    """The builder of PLS and the generators' time step (mixed into the CPU)."""

    def _b_pls(self, st, classes, o, pou, idx):
        ch = o[0].value
        b = 10 * ch
        sm = self.mem["SM"]
        v = self.mem["V"]
        p = self.pto[ch]
        cpu = self

        def table(offset, n):
            if offset + n > len(v):
                raise _TableOutside(offset, n)
            return bytes(v[offset : offset + n])

        def body():
            c = sm[67 + b]
            if c & 0x80 and c & 0x40:
                cpu._fatal(st, pou, "PLS in PWM mode (SM67.6 / SM77.6): PWM is not modelled")
            cycle = U16.unpack_from(sm, 168 + b)[0] if c & 0x20 else U16.unpack_from(sm, 68 + b)[0]
            try:
                p.pls(cpu.time, c, cycle, U32.unpack_from(sm, 72 + b)[0], table)
            except _TableOutside as exc:
                cpu._fatal(st, pou, f"PLS {ch}: the profile table at VB{exc.args[0]} "
                           f"({exc.args[1]} bytes) is beyond V memory")  # fmt: skip
            cpu.pto_sync(ch)
            cpu.eno = 1

        return self._box(body, st, pou)

    def pto_sync(self, ch: int) -> None:
        """Copy channel ``ch``'s state into SMB66/SMB76 and SMB166/SMB176."""
        p, sm = self.pto[ch], self.mem["SM"]
        sm[66 + 10 * ch] = p.status_byte(sm[66 + 10 * ch])
        sm[166 + 10 * ch] = p.segment_no

    def pto_advance(self, t_end: float) -> None:
        """Let both generators run until ``t_end`` [s] (after a scan's program)."""
        for ch, p in enumerate(self.pto):
            p.advance(t_end)
            self.pto_sync(ch)


class _TableOutside(Exception):
    pass
