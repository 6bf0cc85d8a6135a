"""One S7-200 program, scan by scan, on the S7-200 evaluator or on awlsim, with its pulse
trains in time: the same interface for both, so that one scenario runs on each.

Both engines run the program at the start of a scan and the PTO generators for the scan's
``scan_ms`` after it (:mod:`analysis.plc.stl_eval.pulse_output`, the S7-200 System Manual's
generator). The evaluator executes PLS itself. On awlsim the translation
(:func:`analysis.plc.translate.translate_s7200`) logs what each PLS found in the SM registers
(:meth:`~analysis.plc.translate.Layout.pls_record`); :class:`AwlsimEngine` feeds that log to
the same :class:`~analysis.plc.stl_eval.PtoChannel` after the scan and writes its status
back into the translated SMB66/SMB76 and SMB166/SMB176. A CPU in STOP (a fault or the STOP
instruction) ends its pulse trains and turns its outputs off on both.

Each :meth:`Engine.scan` returns an :class:`Interval`: its time span, the output terminals
during it (the process image the previous scan wrote: the image reaches the terminals at the
end of a scan) and the pulses each channel emitted in it, with the train each belongs to.
"""

from __future__ import annotations

import re
import struct
from dataclasses import dataclass

from analysis.plc.stl_eval import S7200, PtoChannel, load_program
from analysis.plc.stl_eval.legacy import PAPER_SYMBOLS

__all__ = ["AwlsimEngine", "Engine", "EvaluatorEngine", "Interval"]

_FMT = {"BOOL": None, "BYTE": ">B", "INT": ">h", "WORD": ">H", "DINT": ">i", "DWORD": ">I",
        "REAL": ">f"}  # fmt: skip
_BIT = re.compile(r"^(SM|V|M|I|Q|S)(\d+)\.([0-7])$")
_WORD = re.compile(r"^(SM|V|M|I|Q|S)([BWD])(\d+)$")


@dataclass(frozen=True)
class Interval:
    """One scan's time span [s], the output terminals during it (Q bytes), and per PTO
    channel the pulses' rising edges in it and the index of the train each belongs to."""

    t0: float
    t1: float
    terminals: bytes
    pulses: tuple[tuple[float, ...], tuple[float, ...]]
    trains: tuple[tuple[int, ...], tuple[int, ...]]

    def q(self, bit: str) -> bool:
        """Output terminal ``bit`` ("Q0.2") during the interval."""
        byte, b = bit[1:].split(".")
        return bool(self.terminals[int(byte)] >> int(b) & 1)


class Engine:
    """A program running scan by scan (subclasses: the evaluator, awlsim)."""

    name = ""
    pto: list[PtoChannel]
    scan_ms: float
    time: float

    def scan(self) -> Interval:
        raise NotImplementedError

    def read(self, typ: str, addr: str):
        raise NotImplementedError

    def write(self, typ: str, addr: str, value) -> None:
        raise NotImplementedError

    @property
    def fault(self) -> str | None:
        """Why the CPU went to STOP, or None."""
        raise NotImplementedError

    def _interval(self, t0: float, terminals: bytes, counts: list[int]) -> Interval:
        pulses = tuple(tuple(p.pulses[n:]) for p, n in zip(self.pto, counts, strict=True))
        trains = tuple(tuple(p.pulse_train[n:]) for p, n in zip(self.pto, counts, strict=True))
        return Interval(t0, self.time, terminals, pulses, trains)  # type: ignore[arg-type]


class EvaluatorEngine(Engine):
    """The program on :class:`~analysis.plc.stl_eval.S7200` (a CPU 224 by default)."""

    name = "S7-200 evaluator"

    def __init__(
        self,
        text: str,
        *,
        scan_ms: float = 10.0,
        cpu: str | None = None,
        symbols=None,
        libraries=None,
    ) -> None:
        loaded = load_program(text, symbols=symbols or PAPER_SYMBOLS, cpu=cpu, libraries=libraries)
        self.cpu = S7200(loaded, scan_ms=scan_ms)
        self.pto = self.cpu.pto
        self.scan_ms = scan_ms

    @property
    def time(self) -> float:
        return self.cpu.time

    def scan(self) -> Interval:
        t0, terminals = self.cpu.time, self.cpu.terminals
        counts = [len(p.pulses) for p in self.pto]
        self.cpu.scan()
        return self._interval(t0, terminals, counts)

    def read(self, typ: str, addr: str):
        return self.cpu.read(typ, addr)

    def write(self, typ: str, addr: str, value) -> None:
        self.cpu.write(typ, addr, value)

    @property
    def fault(self) -> str | None:
        cpu = self.cpu
        return str(cpu.fault) if cpu.fault is not None else cpu.stopped_by


class AwlsimEngine(Engine):
    """The program translated to AWL on awlsim (:mod:`analysis.plc.translate`), its PLS log
    run on the System Manual's generator after every scan (module docstring)."""

    name = "awlsim"

    def __init__(self, text: str, *, scan_ms: float = 10.0, cpu: str | None = None) -> None:
        from analysis.plc.memmap import default_map
        from analysis.plc.runner import AwlRunner
        from analysis.plc.translate import translate_s7200

        self.tr = translate_s7200(text, cpu=cpu)
        self.lay = self.tr.layout
        self.r = AwlRunner(self.tr.awl, default_map("s7-200"), first_scan=False)
        self.mem = self.r.mem
        self.pto = [PtoChannel(0), PtoChannel(1)]
        self.scan_ms = scan_ms
        self.scans = 0
        self.time = 0.0
        n_q = self.lay.s - self.lay.q
        self.terminals = bytes(n_q)
        for ch in (0, 1):  # idle at power-up
            self._sync(ch)

    def _loc(self, area: str, off: int) -> int:
        return self.lay.byte(area, off)

    def _sync(self, ch: int) -> None:
        sm = self.lay.sm + 10 * ch
        self.mem[sm + 66] = self.pto[ch].status_byte(self.mem[sm + 66])
        self.mem[sm + 166] = self.pto[ch].segment_no

    def _table(self, offset: int, n: int) -> bytes:
        if offset + n > self.lay.sm:
            raise ValueError(f"PLS: the profile table at VB{offset} ({n} bytes) is beyond V memory")
        return bytes(self.mem[offset : offset + n])

    def scan(self) -> Interval:
        t0, terminals = self.time, self.terminals
        counts = [len(p.pulses) for p in self.pto]
        self.r.cycle()
        for ch, p in enumerate(self.pto):
            rec = self.lay.pls_record(ch)
            if self.mem[rec - 1] & 1:
                raise ValueError(f"PLS {ch} ran more than 4 times in one scan (scan {self.scans}): "
                                 "the awlsim runner logs 4")  # fmt: skip
            for k in range(self.mem[rec - 2]):
                ctl, _, cycle, count, table = struct.unpack_from(
                    ">BBHIH", self.mem, self.lay.pls_record(ch, k)
                )
                if ctl & 0x80 and ctl & 0x40:
                    raise ValueError(f"PLS {ch} in PWM mode: PWM is not modelled")
                p.pls(t0, ctl, table if ctl & 0x20 else cycle, count, self._table)
            self.mem[rec - 2] = 0
            self._sync(ch)
        self.scans += 1
        self.time = self.scans * self.scan_ms / 1000.0
        if self.r.stopped:
            for ch, p in enumerate(self.pto):
                p.pls(self.time, 0, 0, 0)
                self._sync(ch)
            q = self.lay.q
            self.mem[q : self.lay.s] = bytes(self.lay.s - q)
        else:
            for ch, p in enumerate(self.pto):
                p.advance(self.time)
                self._sync(ch)
        self.terminals = bytes(self.mem[self.lay.q : self.lay.s])
        return self._interval(t0, terminals, counts)

    def _addr(self, typ: str, addr: str) -> tuple[int, int | None, int]:
        a = addr.strip().upper()
        m = _BIT.match(a)
        if typ.upper() == "BOOL":
            if not m:
                raise ValueError(f"{addr!r} is not a bit address")
            return self._loc(m.group(1), int(m.group(2))), int(m.group(3)), 1
        m = _WORD.match(a)
        if not m:
            raise ValueError(f"{addr!r} is not a byte, word or double word address")
        size = {"B": 1, "W": 2, "D": 4}[m.group(2)]
        return self._loc(m.group(1), int(m.group(3))), None, size

    def read(self, typ: str, addr: str):
        off, bit, size = self._addr(typ, addr)
        if bit is not None:
            return bool(self.mem[off] >> bit & 1)
        return struct.unpack(_FMT[typ.upper()], bytes(self.mem[off : off + size]))[0]

    def write(self, typ: str, addr: str, value) -> None:
        off, bit, size = self._addr(typ, addr)
        if bit is not None:
            if value:
                self.mem[off] |= 1 << bit
            else:
                self.mem[off] &= ~(1 << bit) & 0xFF
            return
        self.mem[off : off + size] = struct.pack(_FMT[typ.upper()], value)

    @property
    def fault(self) -> str | None:
        return "the CPU went to STOP (a NaN in a REAL compare)" if self.r.stopped else None
