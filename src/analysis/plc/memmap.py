"""Memory map of the generated PLC program (``stl --map MAP.json``, see the README).

Addresses are written in each dialect's own notation: V memory on the S7-200 (``VD0``,
``V112.0``), M memory on the S7-300 (``MD0``, ``M112.0``). The byte offsets are the same
in both dialects, so the S7-200 program translated to AWL (V -> M) uses the same map.
Inputs default to the paper's Figure 3 (VD0, VD4, VD8 = Px, Py, Pz).
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass, field
from pathlib import Path

__all__ = ["DIALECTS", "MemoryMap", "default_map", "parse_address"]

DIALECTS = ("s7-200", "s7-300")
INPUTS = ("px", "py", "pz")

_ADDR = re.compile(r"^(?P<area>[VM])(?P<width>[DWB]?)(?P<byte>\d+)(?:\.(?P<bit>[0-7]))?$")
# highest usable byte: awlsim's default M area is 2048 bytes; a CPU 224 has VB0-VB8191
_MAX_BYTE = {"s7-200": 2047, "s7-300": 2047}


def parse_address(addr: str, dialect: str) -> tuple[str, int, int | None]:
    """Split ``"VD12"``/``"M112.0"`` into (width, byte, bit); raise ValueError if invalid.

    ``width`` is "D" for a 32-bit double word, "X" for a bit.
    """
    area = "V" if dialect == "s7-200" else "M"
    m = _ADDR.match(addr.replace(" ", ""))
    if not m or m.group("area") != area:
        raise ValueError(
            f"address {addr!r} is not a {dialect} {area}-memory address "
            f"(e.g. {area}D0, {area}112.0)"
        )
    width, byte, bit = m.group("width"), int(m.group("byte")), m.group("bit")
    if bit is not None and width:
        raise ValueError(f"address {addr!r}: a bit address has no width letter (e.g. {area}112.0)")
    if bit is None and width != "D":
        raise ValueError(
            f"address {addr!r}: expected a double word ({area}D<n>) or a bit ({area}<n>.<b>)"
        )
    last = byte + (3 if width == "D" else 0)
    if last > _MAX_BYTE[dialect]:
        raise ValueError(f"address {addr!r} ends at byte {last}, beyond byte {_MAX_BYTE[dialect]}")
    if width == "D" and byte % 4:
        raise ValueError(f"address {addr!r}: double words must start on a multiple of 4 bytes")
    return ("D" if width else "X"), byte, (int(bit) if bit is not None else None)


@dataclass(frozen=True)
class MemoryMap:
    """Where the program's inputs, outputs and work variables live.

    Attributes
    ----------
    dialect : {"s7-200", "s7-300"}
    inputs : dict
        Input name (``px, py, pz``) -> byte of a REAL double word [mm].
    outputs : dict
        ``c1 .. cn`` and ``status`` -> byte of a DINT double word (pulses; status code);
        ``reachable`` -> (byte, bit).
    work_base : int
        First byte of the work area (REAL temporaries, allocated upward, 4 bytes each).
    """

    dialect: str = "s7-300"
    inputs: dict = field(default_factory=lambda: dict(zip(INPUTS, (0, 4, 8), strict=True)))
    outputs: dict = field(
        default_factory=lambda: {
            "c1": 100,
            "c2": 104,
            "c3": 108,
            "reachable": (112, 0),
            "status": 116,
        }
    )
    work_base: int = 200

    def __post_init__(self) -> None:
        if self.dialect not in DIALECTS:
            raise ValueError(f"dialect {self.dialect!r} is not one of {', '.join(DIALECTS)}")
        if "reachable" not in self.outputs:
            raise ValueError("outputs must name the reach flag 'reachable' (a bit)")
        for k in self.outputs:
            if k != "reachable" and k != "status" and not re.fullmatch(r"c[1-9]\d*", k):
                raise ValueError(f"output {k!r} is not c1..cn, status or reachable")
        dwords = [*self.inputs.values(), *(v for k, v in self.outputs.items() if k != "reachable")]
        used: set[int] = set()
        for b in dwords:
            if not isinstance(b, int) or b < 0 or b % 4 or b + 3 > _MAX_BYTE[self.dialect]:
                raise ValueError(
                    f"double-word offset {b!r} must be a multiple of 4 "
                    f"in 0..{_MAX_BYTE[self.dialect] - 3}"
                )
            span = set(range(b, b + 4))
            if span & used:
                raise ValueError(f"double word at byte {b} overlaps another input/output")
            used |= span
        byte, bit = self.outputs["reachable"]
        if byte in used:
            raise ValueError(f"reachable bit byte {byte} overlaps a double word")
        if not (0 <= bit <= 7):
            raise ValueError(f"bit number {bit} must be 0..7")
        if self.work_base % 4 or self.work_base <= max(used | {byte}):
            raise ValueError(
                f"work_base {self.work_base} must be a multiple of 4 above the I/O area"
            )

    def check_program(self, inputs, outputs) -> None:
        """Raise ValueError unless this map names exactly the program's I/O."""
        need_out = {*outputs, "reachable", "status"}
        if set(self.inputs) != set(inputs) or set(self.outputs) != need_out:
            raise ValueError(
                f"the map names inputs {sorted(self.inputs)} and outputs {sorted(self.outputs)};"
                f" the program needs inputs {sorted(inputs)} and outputs {sorted(need_out)}"
            )

    # --- notation --------------------------------------------------------------------
    @property
    def area(self) -> str:
        return "V" if self.dialect == "s7-200" else "M"

    def dword(self, byte: int) -> str:
        return f"{self.area}D{byte}"

    def bit(self, byte: int, bit: int) -> str:
        return f"{self.area}{byte}.{bit}"

    def address(self, name: str) -> str:
        """Address text of an input/output name."""
        if name in self.inputs:
            return self.dword(self.inputs[name])
        if name == "reachable":
            return self.bit(*self.outputs["reachable"])
        if name in self.outputs:
            return self.dword(self.outputs[name])
        raise KeyError(name)

    def with_dialect(self, dialect: str) -> MemoryMap:
        return MemoryMap(dialect, dict(self.inputs), dict(self.outputs), self.work_base)

    def to_dict(self, work: dict[str, int] | None = None) -> dict:
        """MAP.json content: every input, output and (optionally) work address."""
        d = {
            "dialect": self.dialect,
            "inputs": {k: self.address(k) for k in self.inputs},
            "outputs": {k: self.address(k) for k in self.outputs},
            "units": {
                "inputs": "mm (REAL)",
                "outputs": "pulses (DINT); reachable: BOOL; status: DINT code "
                "(0 ok, 1 out of reach, 2 inside reach, 3 base axis, 4 joint limits, "
                "6 not finite)",
            },
        }
        if work:
            d["work"] = {k: self.dword(v) for k, v in sorted(work.items(), key=lambda kv: kv[1])}
        return d

    def to_json(self, work: dict[str, int] | None = None) -> str:
        return json.dumps(self.to_dict(work), indent=2) + "\n"

    @classmethod
    def from_dict(cls, d: dict) -> MemoryMap:
        """Read a MAP.json (as written by :meth:`to_dict`); ``work`` entries are ignored."""
        try:
            dialect = d["dialect"]
            ins = {k: parse_address(v, dialect) for k, v in d["inputs"].items()}
            outs = {k: parse_address(v, dialect) for k, v in d["outputs"].items()}
        except KeyError as exc:
            raise ValueError(f"map is missing the key {exc}") from None
        except AttributeError:
            raise ValueError("map inputs and outputs must be objects of addresses") from None
        for k, (w, _, _) in ins.items():
            if w != "D":
                raise ValueError(f"input {k} must be a double word")
        for k, (w, _, _) in outs.items():
            if (w == "X") != (k == "reachable"):
                raise ValueError(
                    f"output {k}: expected {'a bit' if k == 'reachable' else 'a double word'}"
                )
        outputs = {k: (b if w == "D" else (b, bit)) for k, (w, b, bit) in outs.items()}
        top = max(b for _, b, _ in [*ins.values(), *outs.values()])
        if "status" not in outputs:  # maps written before the status word existed
            taken = {b + i for k, b in outputs.items() if k != "reachable" for i in range(4)}
            taken |= {b + i for _, b, _ in ins.values() for i in range(4)}
            taken.add(outputs.get("reachable", (0, 0))[0])
            free = (b for b in range(0, 2048, 4) if not set(range(b, b + 4)) & taken)
            outputs["status"] = next(free)
            top = max(top, outputs["status"])
        # work area: from byte 200, or above the I/O area if that reaches further
        work_base = int(d.get("work_base", max(200, (top // 4 + 1) * 4)))
        return cls(dialect, {k: b for k, (_, b, _) in ins.items()}, outputs, work_base)

    @classmethod
    def from_json(cls, path: str | Path) -> MemoryMap:
        try:
            d = json.loads(Path(path).read_text())
        except json.JSONDecodeError as exc:
            raise ValueError(f"{path}: not valid JSON ({exc})") from None
        except OSError as exc:
            raise ValueError(f"cannot read {path}: {exc.strerror}") from None
        return cls.from_dict(d)


def default_map(dialect: str = "s7-300", inputs=INPUTS, n_outputs: int = 3) -> MemoryMap:
    """The default map: inputs from byte 0 (Figure 3: VD0, VD4, VD8), pulses c1..cn from
    byte 100, then the reach flag (its own byte) and the status double word."""
    ins = {k: 4 * i for i, k in enumerate(inputs)}
    outs: dict = {f"c{j + 1}": 100 + 4 * j for j in range(n_outputs)}
    flag = 100 + 4 * n_outputs
    outs["reachable"] = (flag, 0)
    outs["status"] = flag + 4
    return MemoryMap(dialect, ins, outs, max(200, flag + 8))
