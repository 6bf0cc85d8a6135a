"""The paper's listings (Figures 3-6) as the audit reads them: parse, def-use, overlaps, run.

:func:`parse_stl` reads a bare listing of :data:`analysis.papers.grabber.FIGURE_STL` (and
fragments of it, ``;``-separated in the audit) into :class:`Instr`, keeping the paper's
typos readable (``CALLARCTAN,``, ``ROUNDVD122``) and a ``// ?`` uncertainty mark. The static
helpers find operands that are not S7-200 addresses (:func:`invalid_operands`), the V bytes
each instruction reads and writes (:func:`defs_uses`) and operands that share bytes
(:func:`overlaps`: VD104 and VD106 share bytes 106-107). :func:`evaluate` runs a listing
on the S7-200 evaluator (:class:`~analysis.plc.stl_eval.cpu.S7200`) as one network
that begins with power flow on (the figures begin with ``LD 上电置1``, read as SM0.0),
with ``CALL ARCTAN`` / ``CALL ARCCOS`` as Siemens' "Arcusfunctions" library subroutines
(results in radians) and the whole V memory of a CPU 226 (VB0-VB10239): power flow, ENO and
AENO, SM1.1/SM1.3 and "the output is not altered" all as on the CPU.
"""

from __future__ import annotations

import math
import re
import struct
from dataclasses import dataclass

import numpy as np

from analysis.plc.stl_eval.cpu import S7200
from analysis.plc.stl_eval.loader import Library, load_program

__all__ = [
    "Instr",
    "VMemory",
    "defs_uses",
    "dint",
    "evaluate",
    "invalid_operands",
    "overlaps",
    "parse_stl",
    "real",
    "real_from_bits",
    "real_memory",
    "span",
]

_ADDR = re.compile(r"^V([BWD])(\d+)$")
_WIDTH = {"B": 1, "W": 2, "D": 4}
V_BYTES = 10240
"""V memory of the CPU 224 (VB0-VB10239 in the later firmware; 8192 in the first)."""
_CONST_REAL = re.compile(r"^[+-]?\d+\.\d*(E[+-]?\d+)?$", re.IGNORECASE)
_CONST_INT = re.compile(r"^[+-]?\d+$")
_LOGIC = {"LD", "LPS", "LRD", "LPP", "AENO"}


@dataclass(frozen=True)
class Instr:
    """One STL instruction: mnemonic, operands, source line, uncertainty flag (``// ?``)."""

    op: str
    args: tuple[str, ...]
    line: int
    uncertain: bool


def parse_stl(text: str) -> list[Instr]:
    """Parse a listing of :data:`analysis.papers.grabber.FIGURE_STL` into instructions.

    Comments (``// ...``) are dropped; a comment starting with ``?`` marks the line as
    uncertain. ``CALL ARCTAN, A, B`` becomes ``Instr("CALL ARCTAN", (A, B))``.
    """
    out = []
    for lineno, raw in enumerate(text.splitlines(), start=1):
        code, _, comment = raw.partition("//")
        code = code.strip()
        if not code:
            continue
        op, _, rest = code.partition(" ")
        args = tuple(a.strip() for a in rest.split(",") if a.strip())
        if op == "CALL":  # "CALL ARCTAN, IN, OUT" (also accepted without the first comma)
            parts = [a for a in re.split(r"[,\s]+", rest.strip()) if a]
            op, args = f"CALL {parts[0]}", tuple(parts[1:])
        out.append(Instr(op, args, lineno, comment.strip().startswith("?")))
    return out


def invalid_operands(instrs: list[Instr]) -> list[tuple[Instr, str]]:
    """Operands that are neither a VD address, a REAL/INT constant nor a contact symbol."""
    bad = []
    for ins in instrs:
        if ins.op in _LOGIC:
            continue
        for a in ins.args:
            if not (_ADDR.match(a) or _CONST_REAL.match(a) or _CONST_INT.match(a)):
                bad.append((ins, a))
    return bad


def span(addr: str) -> range:
    """The V-memory bytes an address covers: ``span("VD104") == range(104, 108)``."""
    m = _ADDR.match(addr)
    if not m:
        raise ValueError(f"operand {addr!r} is not a V-memory address (VB/VW/VD)")
    start = int(m.group(2))
    end = start + _WIDTH[m.group(1)]
    if end > V_BYTES:
        raise ValueError(f"address {addr!r} ends beyond V memory (VB{V_BYTES - 1})")
    return range(start, end)


def defs_uses(ins: Instr) -> tuple[set[str], set[str]]:
    """(written, read) V addresses of one instruction (in-place ops read their OUT too)."""
    if ins.op in _LOGIC or not ins.args:
        return set(), set()
    src, out = ins.args[0], ins.args[-1]
    reads = set() if (_CONST_REAL.match(src) or _CONST_INT.match(src)) else {src}
    if ins.op in ("+R", "-R", "*R", "/R"):
        reads.add(out)
    return {out}, reads


def overlaps(instrs: list[Instr]) -> list[tuple[str, str, range]]:
    """Pairs of distinct addresses in a listing that share bytes (e.g. VD104 and VD106).

    Returns ``(a, b, shared bytes)`` for each pair, sorted. On the PLC a write to one
    changes the other; in a listing that uses both for different quantities, that is a
    bug. Invalid operands (see :func:`invalid_operands`) are skipped.
    """
    addrs = sorted(
        {a for ins in instrs if ins.op not in _LOGIC for a in ins.args if _ADDR.match(a)},
        key=lambda a: (span(a).start, a),
    )
    out = []
    for i, a in enumerate(addrs):
        for b in addrs[i + 1 :]:
            shared = range(max(span(a).start, span(b).start), min(span(a).stop, span(b).stop))
            if len(shared):
                out.append((a, b, shared))
    return out


def real_from_bits(bits: int) -> float:
    """The REAL a 32-bit pattern denotes (S7 REAL = IEEE-754 single, big-endian)."""
    return struct.unpack(">f", struct.pack(">I", bits & 0xFFFFFFFF))[0]


class VMemory:
    """A byte image of V memory with REAL/DINT access by address (big-endian)."""

    def __init__(self, data: bytes | None = None) -> None:
        self.data = bytearray(data if data is not None else V_BYTES)

    def copy(self) -> VMemory:
        return VMemory(self.data)

    def __getitem__(self, addr: str) -> int:
        """The raw bits at an address (unsigned)."""
        return self.bits(addr)

    def bits(self, addr: str) -> int:
        r = span(addr)
        return int.from_bytes(self.data[r.start : r.stop], "big")

    def set_bits(self, addr: str, value: int) -> None:
        r = span(addr)
        self.data[r.start : r.stop] = (value & ((1 << (8 * len(r))) - 1)).to_bytes(len(r), "big")

    def real(self, addr: str) -> np.float32:
        if len(span(addr)) != 4:
            raise ValueError(f"{addr}: a REAL is a double word (VD)")
        return np.float32(real_from_bits(self.bits(addr)))

    def set_real(self, addr: str, x) -> None:
        self.set_bits(addr, struct.unpack(">I", struct.pack(">f", np.float32(x)))[0])

    def dint(self, addr: str) -> int:
        v = self.bits(addr)
        return v - (1 << 32) if v & 0x80000000 else v


def evaluate(
    instrs: list[Instr],
    memory: VMemory | None = None,
    *,
    aliases: dict[str, str] | None = None,
    ftz: bool = False,
) -> VMemory:
    """Run a listing on the S7-200 evaluator; returns the new V-memory image.

    Parameters
    ----------
    instrs : list of Instr
        From :func:`parse_stl`: one network, run once with power flow on at its start.
    memory : VMemory, optional
        The initial image (zeros if omitted; see :func:`real_memory`).
    aliases : dict, optional
        Operand substitutions, e.g. ``{"VDD0": "VD12"}`` to try a reading of Figure 6.
    ftz : bool
        Flush denormal REAL operands and results to zero (a CPU without gradual underflow;
        IEEE arithmetic, as awlsim's, keeps them). Moves copy bits either way.

    Raises ``ValueError`` naming the line and the instruction for unknown mnemonics or
    operands (``VDD0``), and for a NaN reaching a REAL compare (the CPU would stop).
    """
    mem = memory.copy() if memory is not None else VMemory()
    aliases = aliases or {}
    last = max((i.line for i in instrs), default=0)
    lines = [""] * last
    for ins in instrs:
        args = [aliases.get(a, a) for a in ins.args]
        if ins.op.startswith("CALL "):
            text = f"CALL {ins.op[5:]}" + "".join(f", {a}" for a in args)
        else:
            text = f"{ins.op} {', '.join(args)}".strip()
        lines[ins.line - 1] = text  # on its own line number: errors name the listing's line
    prog = load_program(
        "\n".join(lines),
        symbols=PAPER_SYMBOLS,
        libraries=arcus_library(ftz),
        cpu="CPU 226",
        source="listing",
    )
    cpu = S7200(prog, ftz=ftz, fragment=True)
    cpu.mem["V"][:] = mem.data
    cpu.scan()
    if cpu.fault is not None:
        raise ValueError(str(cpu.fault))
    return VMemory(bytes(cpu.mem["V"]))


PAPER_SYMBOLS = {"上电置1": "SM0.0"}
"""The paper's contact symbol "power-on set to 1", read as SM0.0 (always on)."""


def arcus_library(ftz: bool = False) -> dict:
    """ARCTAN(X) and ARCCOS(X) [rad] as library subroutines (Siemens FAQ 19308841,
    "Arcusfunctions"), computed in float64 and rounded to REAL (the library's own
    algorithm is not published); ``ftz`` flushes a denormal argument to zero first."""

    def arg(x: float) -> float:
        return 0.0 if ftz and x != 0.0 and abs(x) < 1.1754943508222875e-38 else x

    def atan(x):
        return math.atan(arg(x)) if math.isfinite(x) else math.nan

    def acos(x):
        x = arg(x)
        return math.acos(x) if -1.0 <= x <= 1.0 else math.nan

    src = "Siemens FAQ 19308841 (Arcusfunctions library, radians)"
    return {
        "ARCTAN": Library(("X",), ("R",), atan, src),
        "ARCCOS": Library(("X",), ("R",), acos, src),
    }


def real_memory(**values: float) -> VMemory:
    """A V-memory image holding REALs, e.g. ``real_memory(VD0=100.0, VD4=100.0)``."""
    mem = VMemory()
    for k, v in values.items():
        mem.set_real(k, v)
    return mem


def dint(mem: VMemory, addr: str) -> int:
    """Read a DINT (two's complement) from a memory image."""
    return mem.dint(addr)


def real(mem: VMemory, addr: str) -> float:
    """Read a REAL from a memory image."""
    return float(mem.real(addr))
