"""A program loaded on an engine, one interface for ``stl-run``: write, scan, read, fault.

A dialect's printer class names its engine (:meth:`analysis.plc.printer.PlcPrinter.session`):
S7-200 STL runs on the project's S7-200 evaluator (:class:`S7200Session`, the paper's
symbols known), S7-300 AWL on awlsim (:class:`AwlSession`). A session is what the command
needs and nothing more: :meth:`write` a typed value before the first scan, :meth:`scan` N
times, :meth:`read` typed values, :attr:`fault` (why the CPU went to STOP, or None).
"""

from __future__ import annotations

import re
import struct
import time

from analysis.plc.cpus import target_cpu

__all__ = ["BUDGET_S", "WATCHDOG_S", "AwlSession", "S7200Session"]

S7200_AREAS = "SM|V|M|I|Q|S"


class S7200Session:
    """An S7-200 program on the evaluator (:class:`analysis.plc.stl_eval.S7200`)."""

    def __init__(self, text: str, *, cpu: str | None = None, source: str = "program") -> None:
        from analysis.plc.stl_eval import S7200, load_program
        from analysis.plc.stl_eval.legacy import PAPER_SYMBOLS

        self.loaded = load_program(text, symbols=PAPER_SYMBOLS, cpu=cpu, source=source)
        self.plc = S7200(self.loaded)

    def write(self, typ: str, addr: str, value, explicit: bool = True) -> None:
        """Write ``value`` as ``typ`` at ``addr``; an integer the program reads only as a
        REAL, its type not given (``explicit``), is refused (its bits are not its value)."""
        if typ == "DINT" and not explicit and self.read_as_real(addr):
            raise ValueError(
                f"--set {addr}={value}: the program reads {addr} as a REAL; write {value}.0 (an "
                f"integer would store its bit pattern, {value} -> a REAL of about "
                f"{_bits_as_real(value):.3g}), or {addr}={value}:DINT to store those bits"
            )
        self.plc.write(typ, addr, value)

    def scan(self, n: int = 1) -> None:
        self.plc.scan(n)

    def read(self, typ: str, addr: str):
        return self.plc.read(typ, addr)

    @property
    def fault(self) -> str | None:
        """Why the CPU went to STOP (a fault, else a STOP instruction), or None."""
        if self.plc.fault is not None:
            return str(self.plc.fault)
        return self.plc.stopped_by

    def read_as_real(self, addr: str) -> bool:
        """Whether the program reads the double word ``addr`` as a REAL anywhere (an integer
        written there is then most likely a mistake: its bits are not its value)."""
        m = re.fullmatch(rf"({S7200_AREAS})D(\d+)", addr)
        if not m:
            return False
        area, off = m.group(1), int(m.group(2))
        for pou in self.loaded.pous.values():
            for _, classes, opnds, builder in pou.code:
                if builder == "call":
                    _, _, params, ops = opnds
                    pairs = [("r" if p[2] == "REAL" else "d", o)
                             for p, o in zip(params, ops, strict=True)]  # fmt: skip
                else:
                    pairs = list(zip(classes, opnds, strict=False))
                for cls, o in pairs:
                    if getattr(o, "kind", None) == "mem" and o.area == area and o.off == off:
                        if cls[0] == "r" and not cls.endswith(">"):
                            return True
        return False


WATCHDOG_S = 6.0
"""The scan watchdog of an S7-300 session [s]: the longest scan cycle monitoring time an
S7-300 CPU can be set to (6,000 ms; the default is 150 ms): a scan that runs longer sends
the CPU to STOP."""
BUDGET_S = 300.0
"""The cap on scans x watchdog [s]: ``--scans N`` runs at most min(N x :data:`WATCHDOG_S`,
this) seconds of awlsim, then the CPU goes to STOP, saying how many scans it ran."""


class AwlSession:
    """An S7-300 AWL program on awlsim (:class:`analysis.plc.runner.AwlRunner`), its M memory
    the target CPU's (default the CPU 315-2 DP's 2,048 bytes, awlsim's own; a program that
    addresses more is refused), the first scan the first :meth:`scan`; every scan watched
    (:data:`WATCHDOG_S`) and all of them capped (:data:`BUDGET_S`)."""

    def __init__(self, text: str, *, cpu: str | None = None, source: str = "program",
                 watchdog_s: float = WATCHDOG_S, budget_s: float = BUDGET_S) -> None:  # fmt: skip
        from analysis.plc.memmap import default_map
        from analysis.plc.runner import AwlRunner

        target = target_cpu(cpu, "s7-300")
        self.watchdog_s, self.budget_s = watchdog_s, budget_s
        self.runner = AwlRunner(text, default_map("s7-300"), name=source, first_scan=False,
                                m_bytes=target.areas["M"], cpu_name=f"the {target.name}",
                                cycle_limit_us=int(watchdog_s * 1e6))  # fmt: skip
        self.fault: str | None = None

    def write(self, typ: str, addr: str, value, explicit: bool = True) -> None:
        self.runner.write(typ, addr, value)

    def scan(self, n: int = 1) -> None:
        """``n`` scans, or fewer: a scan past the watchdog or all of them past the cap on
        scans x watchdog stop the CPU (:attr:`fault` says which, where, after how many)."""
        from awlsim.common.exceptions import AwlSimError

        budget = min(n * self.watchdog_s, self.budget_s)
        start = time.monotonic()
        for k in range(n):
            if time.monotonic() - start > budget:
                self.fault = (
                    f"{k:,} of {n:,} scans ran in the {budget:g} s that --scans x the "
                    f"{self.watchdog_s:g} s watchdog allows (at most {self.budget_s:g} s)"
                )
                return
            try:
                self.runner.cycle()
            except AwlSimError as exc:
                self.fault = _awlsim_stop(exc, k)
                return

    def read(self, typ: str, addr: str):
        return self.runner.read(typ, addr)


def _awlsim_stop(exc, k: int) -> str:
    """awlsim's error (several lines and a CPU dump) as one line: what, the statement and
    its line, the scan."""
    head = str(exc).split("[S7-CPU]", 1)[0]
    lines = [ln.strip() for ln in head.splitlines() if ln.strip()]
    what = lines[-1] if lines else type(exc).__name__
    m = re.search(r"at line (\d+):\s*\n\s*\n?\s*(.+)", head)
    where = f" at line {m.group(1)} ({' '.join(m.group(2).split())})" if m else ""
    return f"{what[:200]}{where[:200]} in scan {k + 1:,}"


def _bits_as_real(v: int) -> float:
    return struct.unpack(">f", struct.pack(">I", v & 0xFFFFFFFF))[0]
