"""An S7-200 CPU that runs STEP 7-Micro/WIN STL programs, scan by scan.

:class:`S7200` holds the CPU's memory and runs the scan; its instructions come in the S7-200
System Manual's families, one module each: operands (:mod:`.operands`), the instruction
table (:mod:`.instructions`), bit logic and compares (:mod:`.bit_logic`), move, math and
conversion (:mod:`.arithmetic`), program control (:mod:`.program_control`) and the pulse
outputs (:mod:`.pulse_output`); :func:`~.loader.load_program` checks a program for it.
Sources: [S2M] the S7-200 Programmable Controller System Manual (manualslib.com/manual/801761,
its page numbers); [manualshelf] its older edition C79000-G7076-C233-01 (manualshelf.com,
page-NNN); [MWH] the STEP 7-Micro/WIN 32 help (its file names); [SMART] the S7-200 SMART
System Manual V2.3; "~" marks a rule assumed or taken from a secondary source.

The scan: OB1 every scan. SM0.0 is always on, SM0.1 and SM0.3 are on in the first scan only,
SM0.5 is a 1 s clock and SM0.4 a 1 min clock of the simulated time (``scan_ms`` per scan),
SM0.6 alternates every scan [S2M p.496]. A fatal error (a NaN in a REAL compare [S2M p.96])
puts the CPU in STOP; :attr:`S7200.fault` says where.

Watchdog. A scan that does not end holds a real CPU until its watchdog puts it in STOP; the
System Manual asks for WDR when a scan may exceed 300 ms [MWH s7-27sz5.htm; S2M A5E00066097-02
p.9-146]. The evaluator does not model instruction times: it gives a scan a budget of
statements (``watchdog``, :data:`WATCHDOG_STATEMENTS` by default, about 0.6 s of this
evaluator), charged at every jump back (JMP to an earlier label, NEXT: the statements
between the jump and its target) and every CALL (the subroutine's length), so straight
code costs nothing extra per statement. Past it the CPU goes to STOP: ``watchdog at line N``
names the jump (or call) that went over. WDR grants one new budget, up to
:data:`MAX_SCAN_FACTOR` budgets a scan.

Why hand-written (design.md asks for an established library where one fits): awlsim runs
S7-300/400 AWL, a different machine (RLO and accumulators instead of a logic stack and
in-place two-operand math, V memory, SM bits, different REAL error rules), and no S7-200
simulator is installable from the registries. The project's translation to AWL
(:mod:`analysis.plc.translate`) is cross-checked against this evaluator on random programs
(``tests/plc/test_stl_machine.py``).
"""

from __future__ import annotations

import re
import struct
from dataclasses import dataclass

from analysis.plc.stl_eval.arithmetic import Arithmetic
from analysis.plc.stl_eval.bit_logic import BitLogic
from analysis.plc.stl_eval.loader import Pou, load_program
from analysis.plc.stl_eval.operands import (
    ADDR_EXAMPLE,
    F32,
    FMT,
    I16,
    I32,
    PTR_AREA,
    PTR_NAME,
    SIZE,
    TYPES,
    U8,
    U16,
    U32,
    WIDTH_OF,
    BadPointer,
    Operand,
)
from analysis.plc.stl_eval.program_control import EndScan, ProgramControl, Stop
from analysis.plc.stl_eval.pulse_output import PtoChannel, PulseOutput
from analysis.plc.stl_eval.syntax import StlError, Stmt

__all__ = ["MAX_SCAN_FACTOR", "S7200", "WATCHDOG_STATEMENTS", "Fault"]

WATCHDOG_STATEMENTS = 1_000_000
"""The evaluator's watchdog: statements a scan may run (module docstring, Watchdog)."""
MAX_SCAN_FACTOR = 10
"""WDR retriggers the watchdog; a scan past this many budgets stops all the same."""


@dataclass(frozen=True)
class Fault:
    """Why the CPU went to STOP, and where."""

    reason: str
    line: int
    block: str
    network: int
    text: str
    prefix: str = ""
    """What stopped it, before the place (``"watchdog at "``)."""

    def __str__(self) -> str:
        return self.prefix + str(
            StlError(
                self.reason, line=self.line, block=self.block, network=self.network, text=self.text
            )
        )


class S7200(BitLogic, Arithmetic, ProgramControl, PulseOutput):
    """An S7-200 CPU in RUN with one program loaded (:func:`load_program`).

    Parameters
    ----------
    program : Loaded or str
        The program (text is loaded with the other keyword arguments' defaults).
    ftz : bool
        Flush denormal REAL operands and results to zero (default: IEEE gradual underflow).
    scan_ms : float
        Simulated scan time [ms]: the clock bits SM0.4 and SM0.5, and how long the pulse
        generators run after each scan's program (:mod:`.pulse_output`).
    fragment : bool
        Run a listing that is one network without its first contact: the scan begins with
        power flow on, as after ``LD SM0.0`` (the paper's figures and the audit's pieces).

    Use :meth:`write` / :meth:`read` (type and address, as in ``--set VD0=100.0``) and
    :meth:`scan`. After a fatal error :attr:`fault` says where and the CPU stays in STOP.
    """

    def __init__(
        self,
        program,
        *,
        ftz: bool = False,
        scan_ms: float = 10.0,
        symbols=None,
        libraries=None,
        cpu=None,
        fragment: bool = False,
        watchdog: int = WATCHDOG_STATEMENTS,
    ) -> None:
        if isinstance(program, str):
            program = load_program(program, symbols=symbols, libraries=libraries, cpu=cpu)
        self.loaded = program
        c = program.cpu
        self.mem = {a: bytearray(c.areas[a]) for a in ("V", "M", "SM", "I", "Q", "S")}
        self.mem["AC"] = bytearray(16)
        self.frames = [bytearray(64) for _ in range(9)]  # main + 8 nested subroutine levels
        self.depth = 0
        self.s = 0  # logic stack, bit 0 = top
        self.eno = 0
        self.ftz = ftz
        self.fragment = fragment
        self.scan_ms = scan_ms
        self.scans = 0
        if not 1 <= watchdog <= 10**9:
            raise ValueError(f"watchdog = {watchdog}: a statement budget of 1..1e9 a scan")
        self.watchdog = watchdog
        self._budget, self._renewals, self._wdr = watchdog, 0, False
        self.fault: Fault | None = None
        self.stopped_by: str | None = None
        self.events = {"denormal": 0, "overflow": 0}
        self.pto = [PtoChannel(0), PtoChannel(1)]
        self.time = 0.0
        """Simulated time [s]: the start of the next scan."""
        self.terminals = bytes(len(self.mem["Q"]))
        """The outputs at the terminals now: the process image the last scan wrote (the
        image reaches the terminals at the end of the scan)."""
        self._edges: dict[int, int] = {}
        self._first = True
        self._for: list = []
        self._code = {k: self._bind(p) for k, p in program.pous.items()}
        self.pto_sync(0)  # both PTO channels idle at power-up
        self.pto_sync(1)

    # --- public memory access ---------------------------------------------------------
    def _addr(self, typ: str, addr: str) -> tuple[str, int, int | None]:
        typ = typ.upper()
        if typ not in TYPES:
            raise ValueError(f"type {typ!r} is not one of {', '.join(TYPES)}")
        a = addr.strip().upper()
        if typ == "BOOL":
            m = re.fullmatch(r"(SM|V|M|I|Q|S)(\d+)\.([0-7])", a)
            if not m:
                raise ValueError(f"{addr!r} is not a bit address (e.g. V116.0, I0.0, Q0.1)")
            area, off, bit = m.group(1), int(m.group(2)), int(m.group(3))
            size = 1
        else:
            w = {"BYTE": "B", "INT": "W", "WORD": "W", "DINT": "D", "DWORD": "D", "REAL": "D"}[typ]
            m = re.fullmatch(r"AC([0-3])", a)
            if m:
                n = int(m.group(1))
                return "AC", 4 * n + 4 - {"B": 1, "W": 2, "D": 4}[w], None
            m = re.fullmatch(r"(SM|V|M|I|Q|S)([BWD])(\d+)", a)
            if not m or m.group(2) != w:
                raise ValueError(f"{addr!r} is not a {typ} address (e.g. {ADDR_EXAMPLE[typ]})")
            area, off, bit = m.group(1), int(m.group(3)), None
            size = {"B": 1, "W": 2, "D": 4}[w]
        n = len(self.mem[area])
        if off + size > n:
            raise ValueError(
                f"{addr} is beyond the {self.loaded.cpu.name}'s {area} memory "
                f"({area}B0-{area}B{n - 1})"
            )
        return area, off, bit

    def read(self, typ: str, addr: str):
        """The value at ``addr`` as ``typ`` (BOOL, BYTE, INT, WORD, DINT, DWORD, REAL)."""
        area, off, bit = self._addr(typ, addr)
        buf = self.mem[area]
        typ = typ.upper()
        if typ == "BOOL":
            return bool(buf[off] >> bit & 1)
        fmt = {"BYTE": U8, "INT": I16, "WORD": U16, "DINT": I32, "DWORD": U32, "REAL": F32}[typ]
        return fmt.unpack_from(buf, off)[0]

    def write(self, typ: str, addr: str, value) -> None:
        """Store ``value`` at ``addr`` as ``typ`` (ValueError if it does not fit)."""
        area, off, bit = self._addr(typ, addr)
        buf = self.mem[area]
        typ = typ.upper()
        if typ == "BOOL":
            if value not in (0, 1, True, False):
                raise ValueError(f"{addr} = {value!r}: a BOOL is 0 or 1")
            buf[off] = (buf[off] | 1 << bit) if value else (buf[off] & ~(1 << bit) & 0xFF)
            return
        fmt = {"BYTE": U8, "INT": I16, "WORD": U16, "DINT": I32, "DWORD": U32, "REAL": F32}[typ]
        try:
            if typ == "REAL":
                fmt.pack_into(buf, off, float(value))
            else:
                if isinstance(value, float) and not value.is_integer():
                    raise struct.error
                fmt.pack_into(buf, off, int(value))
        except (struct.error, OverflowError, ValueError):
            raise ValueError(f"{addr} = {value!r} does not fit a {typ}") from None

    # --- running ----------------------------------------------------------------------
    @property
    def stopped(self) -> bool:
        return self.fault is not None or self.stopped_by is not None

    def scan(self, n: int = 1) -> None:
        """Run ``n`` scans of the main program (nothing once the CPU is in STOP)."""
        for _ in range(n):
            if self.stopped:
                return
            sm = self.mem["SM"]
            t = self.scans * self.scan_ms
            b0 = 0x01 | (0x80)  # SM0.0 always on, SM0.7 RUN switch position
            if self._first:
                b0 |= 0x02 | 0x08  # SM0.1 first scan, SM0.3 power-up
            if (t % 60000.0) >= 30000.0:
                b0 |= 0x10  # SM0.4: 1 min clock
            if (t % 1000.0) >= 500.0:
                b0 |= 0x20  # SM0.5: 1 s clock
            if self.scans % 2:
                b0 |= 0x40  # SM0.6: scan clock
            sm[0] = b0
            self.s = 1 if self.fragment else 0
            self.depth = 0
            self._budget, self._renewals, self._wdr = self.watchdog, 0, False
            try:
                self._run("OB1")
            except EndScan:
                pass
            except Stop:
                pass
            self._first = False
            self.scans += 1
            self.time = self.scans * self.scan_ms / 1000.0
            if self.stopped:  # ~ in STOP the outputs take their STOP state (off): no pulses
                for ch, p in enumerate(self.pto):
                    p.pls(self.time, 0, 0, 0)
                    self.pto_sync(ch)
                self.mem["Q"][:] = bytes(len(self.mem["Q"]))
            else:
                self.pto_advance(self.time)  # the generators run while the next scan does
            self.terminals = bytes(self.mem["Q"])

    def _run(self, key: str) -> None:
        code, _labels = self._code[key]
        pc, n = 0, len(code)
        loops, self._for = self._for, []  # FOR/NEXT loops are per block invocation
        try:
            while pc < n:
                r = code[pc]()
                if r is None:
                    pc += 1
                    continue
                if r <= pc:  # a jump back (JMP to an earlier label, NEXT): the loop's body
                    self.spend(pc - r + 1, key, pc)
                pc = r
        finally:
            self._for = loops

    def spend(self, n: int, key: str, idx: int) -> None:
        """Count ``n`` statements against the scan's watchdog budget; past it, the CPU goes
        to STOP naming statement ``idx`` of block ``key`` (module docstring, Watchdog)."""
        self._budget -= n
        if self._budget >= 0:
            return
        if self._wdr and self._renewals + 1 < MAX_SCAN_FACTOR:
            self._wdr = False  # WDR retriggered the watchdog: a new budget
            self._renewals += 1
            self._budget = self.watchdog
            return
        pou = self.loaded.pous[key]
        budget = f"{self.watchdog:,} statements"
        if self._renewals:
            budget = f"{self._renewals + 1} x {budget} (WDR retriggered it {self._renewals} times)"
        self.fault = Fault(
            f"the scan did not end within {budget}, the evaluator's watchdog: a loop that "
            "never ends holds the CPU in one scan",
            *self._where(pou.code[idx][0], pou),
            prefix="watchdog at ",
        )
        raise Stop

    # --- binding the compiled program to this CPU's memory ----------------------------
    def _bind(self, pou: Pou):
        code = []
        for idx, (st, classes, opnds, builder) in enumerate(pou.code):
            fn = getattr(self, "_b_" + builder)(st, classes, opnds, pou, idx)
            code.append(fn)
        return code, pou.labels

    def _where(self, st: Stmt, pou: Pou):
        return st.line, pou.block.label, st.network, st.text

    def _buf(self, o: Operand):
        """(callable returning the buffer, offset) of a memory operand."""
        if o.area == "L":
            frames = self.frames
            return (lambda: frames[self.depth]), o.off
        buf = self.mem[o.area if o.kind != "ac" else "AC"]
        return (lambda: buf), o.off

    def getter(self, o: Operand, t: str):
        """A function returning operand ``o`` read as type letter ``t``."""
        if o.kind == "const":
            v = o.value
            return lambda: v
        if o.kind == "bit":
            getb, off = self._buf(o)
            bit = o.bit
            if o.area == "L":
                return lambda: getb()[off] >> bit & 1
            buf = getb()
            return lambda: buf[off] >> bit & 1
        w = WIDTH_OF.get(t, t)
        fmt = FMT[w]
        if o.kind == "addr":
            v = PTR_AREA[o.area] << 24 | o.off
            return lambda: v
        if o.kind == "ptr":
            pget = self.getter(o.ptr, "D")
            size = SIZE[w]
            mem = self.mem

            def read_ptr():
                p = pget()
                area = PTR_NAME.get(p >> 24)
                off = p & 0xFFFFFF
                if area is None or off + size > len(mem[area]):
                    raise BadPointer(p)
                return fmt.unpack_from(mem[area], off)[0]

            return read_ptr
        off = o.off
        if o.kind == "ac":
            off = o.off + 4 - SIZE[w]
        if o.area == "L":
            getb, _ = self._buf(o)
            unpack = fmt.unpack_from
            return lambda: unpack(getb(), off)[0]
        buf = self.mem["AC" if o.kind == "ac" else o.area]
        unpack = fmt.unpack_from
        return lambda: unpack(buf, off)[0]

    def setter(self, o: Operand, t: str):
        """A function storing a value of type letter ``t`` into operand ``o``; REAL values
        are rounded to binary32 (OverflowError beyond its range)."""
        if o.kind == "bit":
            getb, off = self._buf(o)
            bit = o.bit
            mask, inv = 1 << bit, ~(1 << bit) & 0xFF

            def set_bit(v):
                b = getb()
                b[off] = b[off] | mask if v else b[off] & inv

            return set_bit
        w = WIDTH_OF.get(t, t)
        fmt = FMT[w]
        if o.kind == "ptr":
            pget = self.getter(o.ptr, "D")
            size = SIZE[w]
            mem = self.mem

            def write_ptr(v):
                p = pget()
                area = PTR_NAME.get(p >> 24)
                off = p & 0xFFFFFF
                if area is None or off + size > len(mem[area]) or (area == "SM" and off < 30):
                    raise BadPointer(p)
                fmt.pack_into(mem[area], off, v)

            return write_ptr
        off = o.off
        if o.kind == "ac":
            off = o.off + 4 - SIZE[w]
        pack = fmt.pack_into
        if o.area == "L":
            getb, _ = self._buf(o)
            return lambda v: pack(getb(), off, v)
        buf = self.mem["AC" if o.kind == "ac" else o.area]
        return lambda v: pack(buf, off, v)

    # SM1.x status bits
    def _status(self, zero: bool, neg: bool) -> None:
        sm = self.mem["SM"]
        sm[1] = (sm[1] & ~0x0F) | (0x01 if zero else 0) | (0x04 if neg else 0)

    def _overflow(self, clear_div: bool = True) -> None:
        sm = self.mem["SM"]
        sm[1] = (sm[1] & ~(0x0F if clear_div else 0x07)) | 0x02
        self.eno = 0

    def _sm11(self) -> None:
        """An error of an instruction that affects SM1.1 only (ROUND, TRUNC, DTI, ITB: S2M
        p.115 lists no other SM bit): SM1.1 on, ENO = 0, the other bits as they were."""
        self.mem["SM"][1] |= 0x02
        self.eno = 0

    def _divzero(self) -> None:
        self.mem["SM"][1] |= 0x08
        self.eno = 0

    def _fatal(self, st, pou, reason) -> None:
        self.fault = Fault(reason, *self._where(st, pou))
        raise Stop

    def _box(self, fn, st, pou):
        """Wrap a box body: runs with power flow, ENO = 0 when skipped, pointer faults."""
        cpu = self

        def run():
            if not cpu.s & 1:
                cpu.eno = 0
                return None
            try:
                fn()
            except BadPointer as exc:
                # non-fatal error 0006: ENO = 0, nothing written (S2M: indirect address)
                cpu.eno = 0
                cpu.events.setdefault("bad pointer", 0)
                cpu.events["bad pointer"] += 1
                cpu.last_error = f"line {st.line}: bad pointer {exc.args[0]:#010x} (error 0006)"
            return None

        return run

    # --- builders: one per kind of instruction ----------------------------------------
