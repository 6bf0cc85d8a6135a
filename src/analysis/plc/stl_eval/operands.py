"""S7-200 operands: addresses, constants, locals and pointers, resolved for one CPU.

Memory (the areas :class:`Resolver` accepts): V, M, SM, I, Q, S, L (64 bytes per call level),
AC0-AC3, sized by the target CPU (:data:`analysis.plc.memmap.CPUS`, CPU 224 by default).
Big-endian: VD100 is VB100 (most significant) .. VB103; V100.0 is the least significant bit
of VB100 [S2M p.42]. An accumulator read as a byte or word is its low 8 or 16 bits; a byte
or word written to it changes only those bits (~ the manual's "accumulators can be accessed
as bytes, words or double words"; what happens to the high bits is assumed). SMB0-SMB29 are
read-only for the program [S2M appendix D, SM memory]. Timers, counters, high-speed counters
and analog I/O are not modelled: an instruction naming T, C, HC, AIW or AQW is refused with
its line. A pointer is ``*VDn``, ``*ACn`` or ``*LDn`` holding an address made by ``&VBn``
(one level: a pointer to a pointer is no S7-200 operand).

Sources are named as in :mod:`analysis.plc.stl_eval.cpu`.
"""

from __future__ import annotations

import re
import struct
from dataclasses import dataclass

from analysis.plc.stl_eval.syntax import Block, clip

TYPES = ("BOOL", "BYTE", "INT", "WORD", "DINT", "DWORD", "REAL")
U8 = struct.Struct(">B")
U16 = struct.Struct(">H")
I16 = struct.Struct(">h")
U32 = struct.Struct(">I")
I32 = struct.Struct(">i")
F32 = struct.Struct(">f")
FMT = {"B": U8, "W": U16, "I": I16, "D": U32, "L": I32, "R": F32}
SIZE = {"B": 1, "W": 2, "I": 2, "D": 4, "L": 4, "R": 4}
TINY = 1.1754943508222875e-38
FLT_MAX = 3.4028234663852886e38


_AREAS = {"V", "M", "SM", "I", "Q", "S", "L"}
_REFUSED_AREAS = {
    "T": "timers are not modelled by this evaluator",
    "C": "counters are not modelled by this evaluator",
    "HC": "high-speed counters are not modelled by this evaluator",
    "AIW": "analog inputs are not modelled by this evaluator",
    "AQW": "analog outputs are not modelled by this evaluator",
}
PTR_AREA = {"V": 1, "M": 2, "I": 3, "Q": 4, "SM": 5, "S": 6}
PTR_NAME = {v: k for k, v in PTR_AREA.items()}
_INT_RE = r"[+-]?\d+"
_REAL_RE = r"[+-]?(?:\d+\.\d*|\.\d+)(?:[Ee][+-]?\d+)?|[+-]?\d+[Ee][+-]?\d+"


def parse_const(a: str):
    """(kind, value) of a constant, or None. kind: "int", "real", "hex", "bin"."""
    if re.fullmatch(_REAL_RE, a):
        return "real", float(a)
    if re.fullmatch(_INT_RE, a):
        return "int", int(a)
    m = re.fullmatch(r"16#([0-9A-Fa-f]+)", a)
    if m:
        return "hex", int(m.group(1), 16)
    m = re.fullmatch(r"2#([01]+)", a)
    if m:
        return "bin", int(m.group(1), 2)
    return None


@dataclass(frozen=True)
class Operand:
    """A resolved operand: kind in {"mem", "bit", "ac", "const", "ptr", "addr", "num"}."""

    kind: str
    area: str = ""
    off: int = 0
    bit: int = 0
    width: str = ""
    value: object = None
    ptr: Operand | None = None
    text: str = ""


# operand classes an instruction takes: letter = data type, suffix ">" written, "^" both
WIDTH_OF = {"b": "B", "w": "W", "i": "I", "d": "D", "l": "L", "r": "R"}


class Resolver:
    """Turns operand text into :class:`Operand` for one block (its locals) and one CPU."""

    def __init__(self, cpu, block: Block, frame: dict[str, tuple]):
        self.cpu, self.block, self.frame = cpu, block, frame

    def area_size(self, area: str) -> int:
        return 64 if area == "L" else self.cpu.areas[area]

    def check_range(self, area: str, off: int, size: int, a: str) -> None:
        n = self.area_size(area)
        if off + size > n:
            raise ValueError(
                f"operand {a} is beyond the {self.cpu.name}'s {area} memory "
                f"({area}B0-{area}B{n - 1})"
            )

    def operand(self, a: str, cls: str) -> Operand:
        t = cls[0]
        write = len(cls) > 1
        au = a.upper()
        if not a:
            raise ValueError("an operand is missing (two commas, or a comma at the end)")
        if a.startswith("#"):
            name = a[1:]
            if name not in self.frame:
                raise ValueError(f"{a} is not a local variable of {self.block.label}")
            vtype, off, bit = self.frame[name]
            if t == "x":
                if vtype != "BOOL":
                    raise ValueError(f"{a} is {vtype}; this operand is a bit (BOOL)")
                return Operand("bit", "L", off, bit, text=a)
            want = WIDTH_OF[t]
            size = {"BYTE": 1, "WORD": 2, "INT": 2, "DWORD": 4, "DINT": 4, "REAL": 4}.get(vtype)
            if (
                size != SIZE[want]
                or (t == "r" and vtype != "REAL")
                or (t in "li" and vtype in ("REAL", "WORD", "DWORD"))
            ):
                raise ValueError(f"{a} is {vtype}; this operand needs a {TYPE_WORD[t]}")
            return Operand("mem", "L", off, width=want, text=a)
        for area, why in _REFUSED_AREAS.items():
            if re.fullmatch(area + r"\d+", au) or (
                area in ("T", "C") and re.fullmatch(area + r"\d+", au)
            ):
                raise ValueError(f"operand {a}: {why}")
        c = parse_const(a)
        if c is not None:
            if write:
                raise ValueError(f"operand {a} is a constant; this operand is written")
            return self.const(a, c, t)
        if a.startswith("&"):
            if t not in "dl" or write:
                raise ValueError(f"{a} (an address) can only be read as a double word")
            m = re.fullmatch(r"&(V|M|I|Q|SM|S)B(\d+)", au)
            if not m:
                raise ValueError(f"{a}: an address is &VBn, &MBn, &IBn, &QBn, &SMBn or &SBn")
            self.check_range(m.group(1), int(m.group(2)), 1, a)
            return Operand("addr", m.group(1), int(m.group(2)), text=a)
        if a.startswith("*"):
            if a[1:].startswith("*"):
                raise ValueError(
                    f"{clip(a)}: a pointer to a pointer is no S7-200 operand (a pointer is "
                    "*VDn, *ACn or *LDn)"
                )
            if t == "x":
                raise ValueError(f"{a}: a pointer addresses bytes, words or double words")
            ptr = self.operand(a[1:], "d")
            if (
                ptr.kind not in ("mem", "ac")
                or ptr.width != "D"
                or ptr.area not in ("V", "L", "AC")
            ):
                raise ValueError(f"{a}: a pointer is *VDn, *ACn or *LDn")
            return Operand("ptr", width=WIDTH_OF[t], ptr=ptr, text=a)
        m = re.fullmatch(r"AC([0-3])", au)
        if m:
            if t == "x":
                raise ValueError(f"{a}: an accumulator is not a bit")
            return Operand("ac", "AC", int(m.group(1)) * 4, width=WIDTH_OF[t], text=a)
        m = re.fullmatch(r"(SM|V|M|I|Q|S|L)(\d+)\.(\d+)", au)
        if m:
            if t != "x":
                raise ValueError(f"operand {a} is a bit; this operand needs a {TYPE_WORD[t]}")
            if int(m.group(3)) > 7:
                raise ValueError(f"operand {a}: bit numbers are 0..7")
            area, off = m.group(1), int(m.group(2))
            self.check_range(area, off, 1, a)
            if write:
                self.check_writable(area, off, a)
            return Operand("bit", area, off, int(m.group(3)), text=a)
        m = re.fullmatch(r"(SM|V|M|I|Q|S|L)([BWD])(\d+)", au)
        if m:
            area, w, off = m.group(1), m.group(2), int(m.group(3))
            if t == "x":
                raise ValueError(
                    f"operand {a} is a {_WIDTH_WORD[w]}; this operand is a bit (e.g. {area}{off}.0)"
                )
            want = WIDTH_OF[t]
            if SIZE[want] != {"B": 1, "W": 2, "D": 4}[w]:
                raise ValueError(
                    f"operand {a} is a {_WIDTH_WORD[w]}; this operand needs a "
                    f"{TYPE_WORD[t]} ({_EXAMPLE[t]})"
                )
            self.check_range(area, off, SIZE[want], a)
            if write:
                self.check_writable(area, off, a)
            return Operand("mem", area, off, width=want, text=a)
        if re.fullmatch(r"VDD\d+", au):
            raise ValueError(f"operand {a} is not an S7-200 address (VD, VW, VB or V n.b)")
        raise ValueError(
            f"operand {a!r} is not an address, a constant or a local (#name) of {self.block.label}"
        )

    def check_writable(self, area: str, off: int, a: str) -> None:
        if area == "SM" and off < 30:
            raise ValueError(f"operand {a}: SMB0-SMB29 are read-only for the program")

    def const(self, a: str, c, t: str) -> Operand:
        kind, v = c
        if t == "x":
            raise ValueError(f"operand {a} is a constant; this operand is a bit address")
        if t == "r":
            if kind != "real":
                raise ValueError(
                    f"operand {a} is an integer constant; a REAL operand needs a REAL "
                    f"constant ({a}.0): a REAL and a DINT of the same number have "
                    "different bits"
                    if kind == "int"
                    else f"operand {a}: a REAL operand needs a REAL constant"
                )
            if v != 0 and not (TINY <= abs(v) <= FLT_MAX):
                raise ValueError(f"REAL constant {a} is outside +-1.175495E-38..3.402823E+38")
            return Operand("const", value=F32.unpack(F32.pack(v))[0], text=a)
        if kind == "real":
            raise ValueError(f"operand {a} is a REAL constant; this operand needs a {TYPE_WORD[t]}")
        lo, hi = {
            "b": (0, 255),
            "w": (-32768, 65535),
            "i": (-32768, 65535),
            "d": (-(2**31), 2**32 - 1),
            "l": (-(2**31), 2**32 - 1),
        }[t]
        if kind in ("hex", "bin"):
            lo = 0
        if not lo <= v <= hi:
            raise ValueError(f"constant {a} does not fit a {TYPE_WORD[t]} ({lo}..{hi})")
        bits = v & ((1 << (8 * SIZE[WIDTH_OF[t]])) - 1)
        # store the value as the type reads it
        width = WIDTH_OF[t]
        fmt = FMT[width]
        raw = bits.to_bytes(SIZE[width], "big")
        return Operand("const", value=fmt.unpack(raw)[0], text=a)


TYPE_WORD = {
    "x": "bit",
    "b": "byte (B)",
    "w": "word (W)",
    "i": "word (INT)",
    "d": "double word (D)",
    "l": "double word (DINT)",
    "r": "double word (REAL)",
}
_WIDTH_WORD = {"B": "byte", "W": "word", "D": "double word"}
_EXAMPLE = {
    "b": "e.g. VB0",
    "w": "e.g. VW0",
    "i": "e.g. VW0",
    "d": "e.g. VD0",
    "l": "e.g. VD0",
    "r": "e.g. VD0",
}


class BadPointer(Exception):
    pass


def flush(x: float) -> float:
    return 0.0 if x != 0.0 and abs(x) < TINY else x


ADDR_EXAMPLE = {
    "BYTE": "VB0",
    "INT": "VW0",
    "WORD": "VW0",
    "DINT": "VD0",
    "DWORD": "VD0",
    "REAL": "VD0",
}
