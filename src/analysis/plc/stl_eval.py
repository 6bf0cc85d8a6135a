"""Static reading and a byte-accurate float32 evaluation of S7-200 STL (the paper's Figures 3-6).

An audit aid, not a PLC simulator (awlsim runs whole programs, :mod:`analysis.plc.runner`):
it parses the listings of :data:`analysis.papers.grabber.FIGURE_STL`, finds operands that are
not S7-200 addresses, traces which V-memory bytes each instruction reads and writes
(def-use), finds operands that share bytes (:func:`overlaps`), and evaluates the
straight-line arithmetic with S7-200 semantics on a byte image of V memory: ``op IN1, OUT``
works in place (``OUT := OUT op IN1``), MOVD copies 32 bits, MOVR copies a REAL, SIN/COS take
radians, ROUND rounds halves away from zero, REAL is IEEE-754 single precision, big-endian
(S7-200 System Manual, REAL format). VD12 is bytes 12-15, so VD104 and VD106 share bytes
106-107 and a write to one changes the other, as on the PLC. Power flow
(LD/LPS/LRD/LPP/AENO) is taken as always on. ``CALL ARCTAN`` / ``CALL ARCCOS`` follow
Siemens' "Arcusfunctions" library (results in radians). The REAL arithmetic is
:class:`~analysis.kinematics.ops.Float32Ops`, the project's one float32 model.

Why hand-written: awlsim executes AWL, not Micro/WIN STL with the paper's typos (``VDD0``),
and the audit needs to run single instructions and fragments thousands of times.
"""

from __future__ import annotations

import re
import struct
from dataclasses import dataclass

import numpy as np

from analysis.kinematics.ops import Float32Ops

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
_F32 = Float32Ops("half-away")
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
    """Run straight-line STL on a byte image of V memory; returns the new image.

    Parameters
    ----------
    instrs : list of Instr
        From :func:`parse_stl`.
    memory : VMemory, optional
        The initial image (zeros if omitted; see :func:`real_memory`).
    aliases : dict, optional
        Operand substitutions, e.g. ``{"VDD0": "VD12"}`` to try a reading of Figure 6.
    ftz : bool
        Flush denormal REAL operands and results to zero (a CPU without gradual underflow;
        IEEE arithmetic, as awlsim's, keeps them). A ROUND of NaN or inf leaves its output
        unchanged (the S7-200 sets SM1.1 and writes nothing).

    Raises ``ValueError`` naming the instruction for unknown mnemonics or operands.
    """
    mem = memory.copy() if memory is not None else VMemory()
    aliases = aliases or {}
    m = _F32

    def name(a: str) -> str:
        return aliases.get(a, a)

    tiny = np.finfo(np.float32).tiny

    def flush(x):
        return np.float32(0.0) if ftz and 0 < abs(x) < tiny else np.float32(x)

    def val(a: str) -> np.float32:
        a = name(a)
        if _CONST_REAL.match(a):
            return np.float32(float(a))
        if _ADDR.match(a):
            return flush(mem.real(a))
        raise ValueError(f"operand {a!r} is not a VD address or REAL constant")

    def store(a: str, x) -> None:
        a = name(a)
        if not _ADDR.match(a):
            raise ValueError(f"cannot write to operand {a!r}")
        mem.set_real(a, flush(x))

    with np.errstate(all="ignore"):
        for ins in instrs:
            op, args = ins.op, ins.args
            if op in _LOGIC:
                continue
            if op == "MOVD":  # bit copy, no conversion
                src = name(args[0])
                bits = int(src) & 0xFFFFFFFF if _CONST_INT.match(src) else mem.bits(src)
                mem.set_bits(name(args[1]), bits)
            elif op == "MOVR":
                store(args[1], val(args[0]))
            elif op in ("+R", "-R", "*R", "/R"):
                a, b = val(args[1]), val(args[0])  # OUT := OUT op IN1
                r = {"+R": a + b, "-R": a - b, "*R": b * a, "/R": a / b}[op]
                store(args[1], r)
            elif op in ("SIN", "COS"):
                store(args[1], (m.sin if op == "SIN" else m.cos)(val(args[0])))
            elif op == "CALL ARCTAN":
                store(args[-1], m.atan(val(args[0])))
            elif op == "CALL ARCCOS":
                store(args[-1], m.acos(val(args[0])))
            elif op == "ROUND":  # REAL -> DINT, halves away from zero
                x = m.round_half_away(val(args[0]))
                if np.isfinite(x):
                    mem.set_bits(name(args[1]), int(x) & 0xFFFFFFFF)
            else:
                raise ValueError(f"line {ins.line}: unsupported instruction {op!r}")
    return mem


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
