"""The S7-200's pulse train outputs (PTO0 on Q0.0, PTO1 on Q0.1) and the PLS instruction
(mixed into :class:`~.cpu.S7200`).

``PLS 0|1`` starts a single-segment pulse train of SMD72/SMD82 pulses when the control byte
SMB67/SMB77 enables it and clears the idle bit SM66.7/SM76.7; :meth:`~.cpu.S7200.pto_done`
(or ``pto_scans``) finishes it. With the enable bit cleared, PLS aborts the train [MWH
s7-24yeq.htm]. The pulses themselves are not simulated.
"""

from __future__ import annotations

from analysis.plc.stl_eval.operands import U32

__all__ = ["Pto", "PulseOutput"]


class Pto:
    """One pulse train output: the pulse counts started (``log``), a one-entry pipeline."""

    def __init__(self) -> None:
        self.log: list[int] = []
        self.busy = False
        self.queued: int | None = None
        self.scans = 0


class PulseOutput:
    """The builder of PLS."""

    def _b_pls(self, st, classes, o, pou, idx):
        ch = o[0].value
        ctl, cnt, idle = 67 + 10 * ch, 72 + 10 * ch, 66 + 10 * ch
        sm = self.mem["SM"]
        p = self.pto[ch]
        cpu = self

        def body():
            c = sm[ctl]
            if not c & 0x80:  # enable bit cleared: abort the train
                if p.busy:
                    sm[idle] |= 0x20  # aborted by the user
                p.busy, p.queued = False, None
                sm[idle] |= 0x80
                cpu.eno = 1
                return
            if c & 0x40:
                cpu.eno = 1  # PWM is not modelled
                return
            n = U32.unpack_from(sm, cnt)[0]
            if not p.busy:
                p.busy, p.scans = True, 0
                p.log.append(n)
                sm[idle] &= ~0x80
            elif p.queued is None:
                p.queued = n
            else:
                sm[idle] |= 0x40  # pipeline overflow
            cpu.eno = 1

        return self._box(body, st, pou)

    def pto_done(self, ch: int) -> None:
        """The pulse train on channel ``ch`` (0: Q0.0, 1: Q0.1) has finished: the queued
        one starts, or the channel becomes idle (SM66.7 / SM76.7)."""
        p = self.pto[ch]
        sm = self.mem["SM"]
        idle = 66 + 10 * ch
        if p.queued is not None:
            p.log.append(p.queued)
            p.queued, p.scans = None, 0
            return
        p.busy = False
        sm[idle] |= 0x80
