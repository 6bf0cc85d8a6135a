"""Memory map of a generated PLC program: where it lives on the target CPU, and MAP.json.

:class:`MemoryMap`, the layout of an S7 program: byte offsets of the inputs, the outputs
(pulse counts ``c1..cn``, the reach flag, the status word) and the first byte of the work
area. Addresses are written in each dialect's own notation: V memory on the S7-200 (``VD0``,
``V112.0``), M memory on the S7-300 (``MD0``, ``M112.0``). The byte offsets are the same in
both dialects, so the S7-200 program translated to AWL (V -> M) uses the same map. Inputs
default to the paper's Figure 3 (VD0, VD4, VD8 = Px, Py, Pz). The map names a target CPU
(:data:`CPUS`); every address is checked against that CPU's memory.
:meth:`MemoryMap.document` writes the program's MAP.json (:func:`~.mapdoc.map_document`,
with the ranges found in the program text).

The map's dialects are those of the target CPUs (:data:`~analysis.plc.cpus.DEFAULT_CPU`);
the CPUs and their addresses are :mod:`analysis.plc.cpus`, the MAP.json document
:mod:`analysis.plc.mapdoc`.
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass, field
from pathlib import Path

from analysis.plc.cpus import CPUS, DEFAULT_CPU, Cpu, cpu_name, parse_address, target_cpu
from analysis.plc.mapdoc import SCHEMA, SM_USES, map_document, program_addresses, ranges

__all__ = [
    "CPUS",
    "DEFAULT_CPU",
    "SCHEMA",
    "Cpu",
    "MemoryMap",
    "cpu_name",
    "default_map",
    "map_document",
    "parse_address",
    "program_addresses",
]

INPUTS = ("px", "py", "pz")


@dataclass(frozen=True)
class MemoryMap:
    """Where the program's inputs, outputs and work variables live.

    Attributes
    ----------
    dialect : {"s7-200", "s7-300"}
    inputs : dict
        Input name (``px, py, pz`` or the arm's) -> byte of a REAL double word.
    outputs : dict
        ``c1 .. cn`` and ``status`` -> byte of a DINT double word (pulses; status code);
        ``reachable`` -> (byte, bit).
    work_base : int
        First byte of the work area (REAL temporaries, allocated upward, 4 bytes each).
    cpu : str, optional
        The target CPU (:data:`CPUS`; default :data:`DEFAULT_CPU` of the dialect). Every
        address must lie in its data area (V on the S7-200, M on the S7-300).
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
    cpu: str | None = None

    def __post_init__(self) -> None:
        if self.dialect not in DEFAULT_CPU:
            raise ValueError(f"dialect {self.dialect!r} is not one of {', '.join(DEFAULT_CPU)}")
        object.__setattr__(self, "cpu", target_cpu(self.cpu, self.dialect).name)
        top = self.target.data_bytes - 1
        if "reachable" not in self.outputs:
            raise ValueError("outputs must name the reach flag 'reachable' (a bit)")
        for k in self.outputs:
            if k != "reachable" and k != "status" and not re.fullmatch(r"c[1-9]\d*", k):
                raise ValueError(f"output {k!r} is not c1..cn, status or reachable")
        dwords = [*self.inputs.values(), *(v for k, v in self.outputs.items() if k != "reachable")]
        used: set[int] = set()
        for b in dwords:
            if not isinstance(b, int) or b < 0 or b % 4 or b + 3 > top:
                raise ValueError(
                    f"double-word offset {b!r} must be a multiple of 4 in 0..{top - 3} "
                    f"(the {self.cpu}'s {self.area} memory is {self.area}B0-{self.area}B{top})"
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
        if not 0 <= byte <= top:
            raise ValueError(f"reachable bit byte {byte} is beyond {self.area}B{top} ({self.cpu})")
        if self.work_base % 4 or self.work_base <= max(used | {byte}):
            raise ValueError(
                f"work_base {self.work_base} must be a multiple of 4 above the I/O area"
            )
        if self.work_base > top:
            raise ValueError(
                f"work_base {self.work_base} is beyond the {self.cpu}'s {self.area} memory "
                f"({self.area}B0-{self.area}B{top})"
            )

    @property
    def target(self) -> Cpu:
        return CPUS[self.cpu]

    def check_program(self, inputs, outputs) -> None:
        """Raise ValueError unless this map names exactly the program's I/O."""
        need_out = {*outputs, "reachable", "status"}
        if set(self.inputs) != set(inputs) or set(self.outputs) != need_out:
            raise ValueError(
                f"the map names inputs {sorted(self.inputs)} and outputs {sorted(self.outputs)};"
                f" the program needs inputs {sorted(inputs)} and outputs {sorted(need_out)}"
            )

    def check_end(self, last_byte: int, what: str) -> None:
        """Refuse a program that needs data bytes up to ``last_byte`` beyond the CPU's area
        (the error names the CPU and its limit)."""
        top = self.target.data_bytes - 1
        if last_byte > top:
            raise ValueError(
                f"{what} ends at {self.area}B{last_byte}, beyond the {self.cpu}'s {self.area} "
                f"memory ({self.area}B0-{self.area}B{top}); choose a CPU with more "
                f"{self.area} memory or a map with a lower work_base"
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
        """The same byte layout in another dialect (its default CPU unless the same)."""
        cpu = self.cpu if dialect == self.dialect else None
        return MemoryMap(dialect, dict(self.inputs), dict(self.outputs), self.work_base, cpu)

    def with_cpu(self, cpu: str) -> MemoryMap:
        return MemoryMap(self.dialect, dict(self.inputs), dict(self.outputs), self.work_base, cpu)

    def to_dict(self, work: dict[str, int] | None = None) -> dict:
        """The layout as MAP.json keys (no program: see :meth:`document` for the full map)."""
        d = {
            "dialect": self.dialect,
            "inputs": {k: self.address(k) for k in self.inputs},
            "outputs": {k: self.address(k) for k in self.outputs},
            "target_cpu": self._cpu_doc(),
        }
        if work:
            d["work"] = {k: self.dword(v) for k, v in sorted(work.items(), key=lambda kv: kv[1])}
        return d

    def _cpu_doc(self) -> dict:
        t = self.target
        return {"name": t.name, "limits": t.limits(), "source": t.source}

    def to_json(self, work: dict[str, int] | None = None) -> str:
        return json.dumps(self.to_dict(work), indent=2) + "\n"

    def document(
        self,
        program_text: str,
        *,
        units: dict[str, str],
        outputs: dict[str, dict] | None = None,
        status_codes=(),
        work: dict[str, int] | None = None,
        uses: dict[str, str] | None = None,
        startup: dict[str, str] | None = None,
        arm: str | None = None,
        branch: str | None = None,
    ) -> dict:
        """The complete MAP.json of ``program_text`` laid out by this map.

        Parameters
        ----------
        program_text : str
            The program as written (S7-200 STL or S7-300 AWL): every address it uses is
            listed under ``memory``, and checked against the target CPU (ValueError naming
            the CPU and the limit).
        units : dict
            Input name -> unit ("mm", "deg" or "rad").
        outputs : dict, optional
            Count name -> extra facts (``joint``, ``pulses_per_rev``).
        status_codes : iterable of int
            The codes the program writes.
        work : dict, optional
            Work variable -> byte.
        uses : dict, optional
            Address (as in the program, e.g. ``"VB120"``, ``"I0.0"``, ``"SMB67"``) -> what
            it is for; the rest are named from the I/O and ``work``.
        startup : dict, optional
            Item -> what the first scan does to it (``"inputs"`` is always stated).
        """
        addresses = {k: self.address(k) for k in (*self.inputs, *self.outputs)}
        work = work or {}
        groups: dict[str, tuple[str, str]] = {}
        for k, b in work.items():
            groups[self.dword(b)] = ("work", k)
        for k, a in addresses.items():
            groups[a] = ("inputs" if k in self.inputs else "outputs", k)
        for a, what in {**SM_USES, **(uses or {})}.items():
            groups[a] = (a, f"{a} {what}")
        groups["#locals"] = ("#locals", "subroutine parameters and locals (each call level)")
        found = program_addresses(program_text, self.dialect)
        for area, _, last, opnd in found:
            if area == self.area:
                self.check_end(last, f"the program's {opnd}")
            elif area not in ("AC", "T", "C") and (limit := self.target.areas.get(area)):
                if last >= limit:
                    raise ValueError(
                        f"the program's {opnd} is beyond the {self.cpu}'s {area} memory "
                        f"({area}B0-{area}B{limit - 1})"
                    )
        doc = map_document(
            self.dialect,
            inputs={k: addresses[k] for k in self.inputs},
            outputs={k: addresses[k] for k in self.outputs},
            units=units,
            output_facts=outputs,
            status_codes=status_codes,
            memory=ranges(found, groups),
            work={k: self.dword(v) for k, v in sorted(work.items(), key=lambda kv: kv[1])},
            startup=startup,
            target_cpu=self._cpu_doc(),
            arm=arm,
            branch=branch,
        )
        return doc

    @classmethod
    def from_dict(cls, d: dict) -> MemoryMap:
        """Read a MAP.json (as written by :meth:`document` or :meth:`to_dict`, schema 1 or
        2); ``work``, ``memory`` and the descriptive keys are ignored."""
        try:
            dialect = d["dialect"]
            cpu = d.get("target_cpu")
            cpu = cpu.get("name") if isinstance(cpu, dict) else cpu
            if dialect in DEFAULT_CPU:
                target_cpu(cpu, dialect)
            ins = {k: parse_address(v, dialect, cpu) for k, v in d["inputs"].items()}
            outs = {k: parse_address(v, dialect, cpu) for k, v in d["outputs"].items()}
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
        # work area: where the map's "work" variables begin (if above the I/O area: a map
        # whose I/O was edited gets a new one), else from byte 200 or above the I/O area
        work_base = max(200, (top // 4 + 1) * 4)
        work = d.get("work")
        if isinstance(work, dict) and work:
            try:
                first = min(parse_address(a, dialect, cpu)[1] for a in work.values())
            except (ValueError, TypeError, AttributeError):
                first = None
            if first is not None and first > top + 3:
                work_base = first
        work_base = d.get("work_base", work_base)
        if isinstance(work_base, bool) or not isinstance(work_base, int):
            raise ValueError(f"work_base {work_base!r} must be a whole number of bytes")
        return cls(dialect, {k: b for k, (_, b, _) in ins.items()}, outputs, work_base, cpu)

    @classmethod
    def from_json(cls, path: str | Path) -> MemoryMap:
        try:
            d = json.loads(Path(path).read_text())
        except json.JSONDecodeError as exc:
            raise ValueError(f"{path}: not valid JSON ({exc})") from None
        except OSError as exc:
            raise ValueError(f"cannot read {path}: {exc.strerror}") from None
        if not isinstance(d, dict):
            raise ValueError(f"{path}: a map is a JSON object")
        return cls.from_dict(d)


def default_map(
    dialect: str = "s7-300", inputs=INPUTS, n_outputs: int = 3, cpu: str | None = None
) -> MemoryMap:
    """The default map: inputs from byte 0 (Figure 3: VD0, VD4, VD8), pulses c1..cn from
    byte 100, then the reach flag (its own byte) and the status double word."""
    ins = {k: 4 * i for i, k in enumerate(inputs)}
    outs: dict = {f"c{j + 1}": 100 + 4 * j for j in range(n_outputs)}
    flag = 100 + 4 * n_outputs
    outs["reachable"] = (flag, 0)
    outs["status"] = flag + 4
    return MemoryMap(dialect, ins, outs, max(200, flag + 8), cpu)
