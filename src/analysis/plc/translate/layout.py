"""Where a translation keeps each S7-200 area in awlsim's M memory (:class:`Layout`).

V n -> M n for the whole of the CPU's V memory (VB0-VB8191 on a CPU 224): a program's V
addresses and the memory map's byte offsets are the same in both dialects. Everything else
lives above it: SM, AC0-AC3, the process images I and Q, S, the S7-200 M area, then the
translation's own bits and scratch (logic stacks, ENO, the first-scan and STOP bits, ROUND
and CALL scratch, the PLS log: what each PLS found in the SM registers, for the runner's
pulse generators, :meth:`Layout.pls_record`). :func:`analysis.plc.runner.AwlRunner` sizes
awlsim's M area to fit (its default is 2048 bytes).
"""

from __future__ import annotations

from dataclasses import dataclass

from analysis.plc.memmap import CPUS, DEFAULT_CPU

__all__ = [
    "FIRST_SCAN_DONE",
    "I_BASE",
    "PLS_LOG",
    "PLS_RECORDS",
    "Q_BASE",
    "SM_BASE",
    "STOP_BIT",
    "Layout",
]


PLS_RECORDS = 4
"""PLS executions a channel may log in one scan (a fifth stops the run, saying so)."""
PLS_RECORD_BYTES = 10
PLS_CHANNEL_BYTES = 2 + PLS_RECORDS * PLS_RECORD_BYTES


@dataclass(frozen=True)
class Layout:
    """Where a translation keeps each S7-200 area in awlsim's M memory (module docstring).

    ``byte(area, n)`` is the M byte of S7-200 ``area`` byte ``n`` (``"V"``, ``"SM"``,
    ``"AC"`` (4 bytes per accumulator), ``"I"``, ``"Q"``, ``"S"``, ``"M"``).
    """

    cpu: str
    v: int
    sm: int
    ac: int
    i: int
    q: int
    s: int
    m: int
    first_scan_done: tuple[int, int]
    stop_bit: tuple[int, int]
    eno: tuple[int, int]
    cmp_scratch: tuple[int, int]
    round_scratch: int
    pls_log: int
    logic: int

    @classmethod
    def for_cpu(cls, cpu: str | None = None) -> Layout:
        c = CPUS[cpu or DEFAULT_CPU["s7-200"]]
        if c.dialect != "s7-200":
            raise ValueError(f"{c.name} is not an S7-200 CPU")
        v = c.areas["V"]
        sm = v
        ac = sm + c.areas["SM"]
        i = ac + 16
        q = i + c.areas["I"]
        s = q + c.areas["Q"]
        m = s + c.areas["S"]
        bits = m + c.areas["M"]  # one byte of the translation's own bits
        round_scratch = bits + 4  # 3 double words
        pls = round_scratch + 12  # the PLS log: PLS_RECORDS records a channel (pls_record)
        logic = pls + 2 * PLS_CHANNEL_BYTES  # 4 bytes per block
        return cls(
            c.name,
            v,
            sm,
            ac,
            i,
            q,
            s,
            m,
            (bits, 0),
            (bits, 1),
            (bits, 2),
            (bits, 7),
            round_scratch,
            pls,
            logic,
        )

    def pls_record(self, ch: int, k: int = 0) -> int:
        """M byte of PLS record ``k`` of channel ``ch`` in a scan: the control byte, a spare
        byte, the cycle time (word), the pulse count (double word) and the profile table's
        offset (word), as SMB67, SMW68, SMD72, SMW168 held when PLS ran. The byte at
        ``pls_record(ch) - 2`` counts the records of the scan (the runner empties it), the
        one after it is set when a scan ran more than :data:`PLS_RECORDS` PLS."""
        return self.pls_log + PLS_CHANNEL_BYTES * ch + 2 + PLS_RECORD_BYTES * k

    def byte(self, area: str, n: int) -> int:
        if area == "V":
            return n
        return {"SM": self.sm, "AC": self.ac, "I": self.i, "Q": self.q, "S": self.s, "M": self.m}[
            area
        ] + n

    def header(self) -> str:
        """The AWL comment the runner reads (M area size and STOP bit)."""
        return (
            f"// analysis.plc.translate: {self.cpu}; STOP bit M {self.stop_bit[0]}."
            f"{self.stop_bit[1]}"
        )


DEFAULT_LAYOUT = Layout.for_cpu()
SM_BASE = DEFAULT_LAYOUT.sm
"""M byte of SMB0 in a translation for the default CPU (CPU 224)."""
I_BASE = DEFAULT_LAYOUT.i
Q_BASE = DEFAULT_LAYOUT.q
PLS_LOG = DEFAULT_LAYOUT.pls_log
STOP_BIT = DEFAULT_LAYOUT.stop_bit
FIRST_SCAN_DONE = DEFAULT_LAYOUT.first_scan_done
