"""Memory map of a generated PLC program: where it lives on the target CPU, and MAP.json.

Two things live here, one source each:

* :class:`MemoryMap`, the layout of an S7 program: byte offsets of the inputs, the outputs
  (pulse counts ``c1..cn``, the reach flag, the status word) and the first byte of the work
  area. Addresses are written in each dialect's own notation: V memory on the S7-200
  (``VD0``, ``V112.0``), M memory on the S7-300 (``MD0``, ``M112.0``). The byte offsets are
  the same in both dialects, so the S7-200 program translated to AWL (V -> M) uses the same
  map. Inputs default to the paper's Figure 3 (VD0, VD4, VD8 = Px, Py, Pz). The map names a
  target CPU (:data:`CPUS`); every address is checked against that CPU's memory.
* :func:`map_document`, the MAP.json of any dialect (schema :data:`SCHEMA`): every input with
  its unit, every output, every status code the program writes with its meaning, every
  memory range the program uses (work areas included), the start-up behaviour and the
  target CPU with its limits. For the S7 dialects the addresses are the program's
  (:meth:`MemoryMap.document` adds the ranges found in the program text); for ST, SCL and
  PLCopen XML they are the block's interface variables (the emitter passes them).

MAP.json keys (``schema`` ``analysis.plc.map/2``; the first four are the contract of
design.md and unchanged):

``dialect``
    ``s7-200``, ``s7-300``, ``st``, ``scl`` or ``plcopen-xml``.
``inputs``, ``outputs``
    name -> address (S7) or interface variable (ST/SCL).
``units``
    ``{"inputs": "...", "outputs": "..."}``, one line each naming every signal's unit.
``signals``
    name -> ``{"address", "type", "unit", "direction", "meaning"}`` (``joint`` and
    ``pulses_per_rev`` for the counts, ``codes`` for the status word).
``status_codes``
    code (as text) -> ``{"name", "meaning"}``, for every code the program can write.
``memory``
    every range the program reads or writes, in address order: ``{"range", "area",
    "first", "last", "use"}`` (``use`` names the signal, the work variable or what the
    area is for; "program-internal" where nothing more is known).
``work``
    work variable -> address (the IK's REAL temporaries).
``startup``
    what the program does on its first scan, in words, per item.
``target_cpu``
    ``{"name", "limits": {area: "first-last"}, "source"}``; for ST/SCL the runtime.

CPU memory sizes (:data:`CPUS`), with their sources:

* S7-200: V memory VB0-VB2047 on the CPU 221/222, VB0-VB8191 on the CPU 224, VB0-VB10239
  on the CPU 224XP/226; M0.0-M31.7, SM0.0-SM549.7 (CPU 224 and up; SMB0-SMB179 on the 221,
  SMB0-SMB299 on the 222), LB0-LB63 per program level, AC0-AC3, I0.0-I15.7, Q0.0-Q15.7,
  S0.0-S31.7 (S7-200 System Manual, Table 6-1 "Memory ranges", from a secondary summary in
  the team's STL reference notes).
* S7-300: bit memory (M) 128 bytes on the CPU 312, 256 on the CPU 314, 2048 on the CPU
  315-2 DP, 4096 on the CPU 317-2 DP (1024, 2048, 16384 and 32768 "flags"; a distributor's
  summary of the S7-300 CPU data sheets, hopluc.com.vn "SIMATIC S7-300": secondary, check
  the CPU manual, "CPU 31xC and CPU 31x, Technical Data"). awlsim's default M area is 2048
  bytes, the CPU 315-2 DP's, which is therefore the default S7-300 target.
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass, field
from pathlib import Path

__all__ = [
    "CPUS",
    "DEFAULT_CPU",
    "DIALECTS",
    "SCHEMA",
    "Cpu",
    "MemoryMap",
    "default_map",
    "map_document",
    "parse_address",
    "program_addresses",
    "status_meanings",
]

DIALECTS = ("s7-200", "s7-300")
"""Dialects with fixed addresses (:class:`MemoryMap`); ST, SCL and PLCopen XML use the
block interface (:func:`map_document` with interface names)."""
INPUTS = ("px", "py", "pz")
SCHEMA = "analysis.plc.map/2"

_ADDR = re.compile(r"^(?P<area>[VM])(?P<width>[DWB]?)(?P<byte>\d+)(?:\.(?P<bit>[0-7]))?$")


@dataclass(frozen=True)
class Cpu:
    """A target CPU: its dialect and the size of each memory area [bytes]."""

    name: str
    dialect: str
    areas: dict
    source: str

    @property
    def data_area(self) -> str:
        """The area the program's I/O and work variables live in (V or M)."""
        return "V" if self.dialect == "s7-200" else "M"

    @property
    def data_bytes(self) -> int:
        return self.areas[self.data_area]

    def limits(self) -> dict[str, str]:
        """Area -> "first-last" in the dialect's notation (``"V": "VB0-VB8191"``)."""
        out = {}
        for area, n in self.areas.items():
            if area == "AC":
                out[area] = f"AC0-AC{n - 1}"
            elif area in ("T", "C"):
                out[area] = f"{area}0-{area}{n - 1}"
            else:
                out[area] = f"{area}B0-{area}B{n - 1}"
        return out


_S7200_SRC = "S7-200 System Manual, Table 6-1 (memory ranges), from a secondary summary"
_S7300_SRC = (
    "S7-300 CPU data sheets (CPU 31xC and CPU 31x, Technical Data), as summarised by "
    "hopluc.com.vn 'SIMATIC S7-300' (secondary: check the CPU manual)"
)


def _s7200(name: str, v: int, sm: int) -> Cpu:
    areas = {"V": v, "M": 32, "SM": sm, "L": 64, "I": 16, "Q": 16, "S": 32, "AC": 4}
    return Cpu(name, "s7-200", {**areas, "T": 256, "C": 256}, _S7200_SRC)


def _s7300(name: str, m: int) -> Cpu:
    return Cpu(name, "s7-300", {"M": m, "I": 128, "Q": 128}, _S7300_SRC)


CPUS: dict[str, Cpu] = {
    c.name: c
    for c in (
        _s7200("CPU 221", 2048, 180),
        _s7200("CPU 222", 2048, 300),
        _s7200("CPU 224", 8192, 550),
        _s7200("CPU 224XP", 10240, 550),
        _s7200("CPU 226", 10240, 550),
        _s7300("CPU 312", 128),
        _s7300("CPU 314", 256),
        _s7300("CPU 315-2 DP", 2048),
        _s7300("CPU 317-2 DP", 4096),
    )
}
"""Target CPUs by name (sources in the module docstring)."""

DEFAULT_CPU = {"s7-200": "CPU 224", "s7-300": "CPU 315-2 DP"}
"""The paper's CPU 224 (Section 2.3), and the S7-300 whose M area awlsim has by default."""


def cpu_name(text: str, dialect: str) -> str:
    """The :data:`CPUS` name a user means by ``text`` for ``dialect`` (``"224"``, ``"cpu
    224xp"``, ``"CPU 315-2DP"``: case, spaces and the ``CPU`` prefix free), else a
    ValueError naming the value and the CPUs known for that dialect.

    >>> cpu_name("224xp", "s7-200"), cpu_name("cpu315-2 dp", "s7-300")
    ('CPU 224XP', 'CPU 315-2 DP')
    """
    if not isinstance(text, str) or not text.strip():
        raise ValueError(f"target CPU {text!r}: expected a CPU name (e.g. CPU 224)")

    def key(s: str) -> str:
        s = re.sub(r"[\s_]", "", s.upper())
        return s[3:] if s.startswith("CPU") else s

    match = [name for name in CPUS if key(name) == key(text)]
    return _cpu(match[0] if match else text.strip(), dialect).name


def _cpu(name: str | None, dialect: str) -> Cpu:
    name = name or DEFAULT_CPU[dialect]
    cpu = CPUS.get(name)
    if cpu is None:
        known = ", ".join(k for k, c in CPUS.items() if c.dialect == dialect)
        raise ValueError(f"target CPU {name!r} is not known for {dialect} (known: {known})")
    if cpu.dialect != dialect:
        raise ValueError(f"target CPU {name} is an {cpu.dialect} CPU, not an {dialect} one")
    return cpu


def parse_address(addr: str, dialect: str, cpu: str | None = None) -> tuple[str, int, int | None]:
    """Split ``"VD12"``/``"M112.0"`` into (width, byte, bit); raise ValueError if invalid.

    ``width`` is "D" for a 32-bit double word, "X" for a bit. The address must lie in the
    target CPU's data area (default: :data:`DEFAULT_CPU`).
    """
    target = _cpu(cpu, dialect)
    area = target.data_area
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
    if last >= target.data_bytes:
        raise ValueError(
            f"address {addr!r} ends at byte {last}, beyond the {target.name}'s {area} memory "
            f"({area}B0-{area}B{target.data_bytes - 1})"
        )
    if width == "D" and byte % 4:
        raise ValueError(f"address {addr!r}: double words must start on a multiple of 4 bytes")
    return ("D" if width else "X"), byte, (int(bit) if bit is not None else None)


def status_meanings() -> dict[int, tuple[str, str]]:
    """Status code -> (name, one-sentence meaning), for every code a program can write."""
    from analysis.kinematics.status import Status

    meaning = {
        Status.OK: "solved: c1..cn hold the pulse counts, the reach flag is on",
        Status.OUT_OF_REACH: "the target is farther than the arm reaches; outputs unchanged",
        Status.INSIDE_REACH: "the target is nearer than the inner reach radius; outputs unchanged",
        Status.BASE_AXIS: "the target is on the waist axis, where the waist angle is "
        "undefined; outputs unchanged",
        Status.JOINT_LIMITS: "reachable, but the branch's angles are outside the joint "
        "limits; outputs unchanged",
        Status.DEGENERATE: "the closed form's own singular case (e.g. the wrist on the "
        "shoulder); outputs unchanged",
        Status.INVALID: "an input is NaN or infinite (bit test, no REAL compare); outputs "
        "unchanged",
        Status.ORIENTATION: "an orientation this arm cannot take (a 5-DOF arm's missing "
        "freedom); outputs unchanged",
    }
    return {int(s): (s.text, meaning[s]) for s in Status}


# ------------------------------------------------------------------------------------------
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
        if self.dialect not in DIALECTS:
            raise ValueError(f"dialect {self.dialect!r} is not one of {', '.join(DIALECTS)}")
        object.__setattr__(self, "cpu", _cpu(self.cpu, self.dialect).name)
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
            memory=_ranges(found, groups),
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
            if dialect in DIALECTS:
                _cpu(cpu, dialect)
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


# ------------------------------------------------------------------------------------------
def map_document(
    dialect: str,
    *,
    inputs: dict[str, str],
    outputs: dict[str, str],
    units: dict[str, str],
    output_facts: dict[str, dict] | None = None,
    status_codes=(),
    memory: list[dict] | None = None,
    work: dict[str, str] | None = None,
    startup: dict[str, str] | None = None,
    target_cpu: dict | None = None,
    arm: str | None = None,
    branch: str | None = None,
) -> dict:
    """MAP.json content for any dialect (the keys in the module docstring).

    ``inputs``/``outputs`` map each name to its address (S7) or interface variable (ST,
    SCL, PLCopen XML); ``units`` gives every input's unit ("mm", "deg" or "rad");
    ``status_codes`` the codes the program writes. Raises ValueError for an input without a
    unit, a unit outside mm/deg/rad, or an unknown status code.
    """
    meanings = status_meanings()
    for k in inputs:
        if units.get(k) not in ("mm", "deg", "rad"):
            raise ValueError(f"input {k}: unit {units.get(k)!r} is not mm, deg or rad")
    codes = sorted({int(c) for c in status_codes})
    for c in codes:
        if c not in meanings:
            raise ValueError(f"status code {c} has no meaning in analysis.kinematics.status")
    facts = output_facts or {}
    signals: dict = {}
    for k, a in inputs.items():
        signals[k] = {
            "address": a,
            "type": "REAL",
            "unit": units[k],
            "direction": "input",
            "meaning": f"target {k} [{units[k]}], written by the HMI",
        }
    counts = [k for k in outputs if re.fullmatch(r"c\d+", k)]
    for k in counts:
        signals[k] = {
            "address": outputs[k],
            "type": "DINT",
            "unit": "pulses",
            "direction": "output",
            "meaning": "pulse count of joint "
            + str(facts.get(k, {}).get("joint", k[1:]))
            + " (eqs. 20-22); unchanged when the target is refused",
            **facts.get(k, {}),
        }
    if "reachable" in outputs:
        signals["reachable"] = {
            "address": outputs["reachable"],
            "type": "BOOL",
            "unit": "",
            "direction": "output",
            "meaning": "on when status = 0 (c1..cn valid); motion starts only with it on",
        }
    if "status" in outputs:
        signals["status"] = {
            "address": outputs["status"],
            "type": "DINT",
            "unit": "code",
            "direction": "output",
            "meaning": "why the target was solved or refused (status_codes)",
            "codes": [str(c) for c in codes],
        }
    by_unit: dict[str, list[str]] = {}
    for k in inputs:
        by_unit.setdefault(units[k], []).append(k)
    doc = {
        "schema": SCHEMA,
        "dialect": dialect,
        **({"arm": arm} if arm else {}),
        **({"branch": branch} if branch else {}),
        "inputs": dict(inputs),
        "outputs": dict(outputs),
        "units": {
            "inputs": "; ".join(f"{', '.join(v)}: {u} (REAL)" for u, v in by_unit.items()),
            "outputs": f"{', '.join(counts)}: pulses (DINT); reachable: BOOL; status: DINT "
            "code (status_codes)",
        },
        "signals": signals,
        "status_codes": {
            str(c): {"name": meanings[c][0], "meaning": meanings[c][1]} for c in codes
        },
    }
    if memory is not None:
        doc["memory"] = memory
    if work:
        doc["work"] = dict(work)
    doc["startup"] = dict(startup or {})
    doc["startup"].setdefault(
        "inputs", "not written by the program: it computes from what the inputs hold"
    )
    if target_cpu is not None:
        doc["target_cpu"] = target_cpu
    return doc


# ------------------------------------------------------------------------------------------
# the memory a program text uses
_S7200_OPND = re.compile(
    r"(?<![#\w&*])(?P<area>SM|AC|V|M|I|Q|S|L)(?P<w>[BWD]?)(?P<n>\d+)(?:\.(?P<bit>[0-7]))?(?![\w.])"
)
_S7300_OPND = re.compile(
    r"(?<![#\w])(?P<area>M|I|Q)(?P<w>[BWD]?)\s*(?P<n>\d+)(?:\.(?P<bit>[0-7]))?(?![\w.])"
)
_WIDTH = {"": 1, "B": 1, "W": 2, "D": 4}


def program_addresses(text: str, dialect: str) -> list[tuple[str, int, int, str]]:
    """Every memory operand ``text`` names: ``(area, first byte, last byte, operand)``, one
    per distinct operand (``AC`` by register number).

    Comments (``//``) are ignored; S7-200 subroutine locals (``#name``) are reported as one
    L range, LB0 up to the largest local frame of any subroutine (each call level has its
    own 64 bytes).
    """
    pat = _S7200_OPND if dialect == "s7-200" else _S7300_OPND
    found: dict[str, tuple[str, int, int, str]] = {}
    sizes = {"BOOL": 0, "BYTE": 1, "WORD": 2, "INT": 2, "DWORD": 4, "DINT": 4, "REAL": 4}
    local_bytes = frame = bits = 0
    for raw in text.splitlines():
        line = raw.split("//", 1)[0].strip()
        if not line:
            continue
        if dialect == "s7-200":
            if line.startswith(("SUBROUTINE_BLOCK", "ORGANIZATION_BLOCK", "INTERRUPT_BLOCK")):
                frame = bits = 0
            m = re.fullmatch(r"(\w+)\s*:\s*(\w+)\s*;?", line)
            if m and m.group(2).upper() in sizes:  # a VAR declaration: its L bytes
                size = sizes[m.group(2).upper()]
                if size == 0:
                    bits += 1
                    frame += bits % 8 == 1
                else:
                    frame += size
                local_bytes = max(local_bytes, frame)
                continue
        if line.startswith(("TITLE", "Network", "NETWORK", "FUNCTION", "ORGANIZATION", "VAR")):
            continue
        parts = line.split(None, 1)
        if len(parts) < 2 or parts[0].startswith(("END_", "DATA_BLOCK")):
            continue
        for m in pat.finditer(parts[1]):
            area, n = m.group("area"), int(m.group("n"))
            text_ = m.group(0).replace(" ", "")
            if area == "AC":
                found[text_] = ("AC", n, n, text_)
                continue
            if m.group("bit") is None and not m.group("w"):
                continue  # "M 12" without width or bit is not a memory operand
            width = 1 if m.group("bit") is not None else _WIDTH[m.group("w")]
            found[text_] = (area, n, n + width - 1, text_)
    if local_bytes:
        found["#locals"] = ("L", 0, local_bytes - 1, "#locals")
    return sorted(found.values(), key=lambda t: (_AREA_ORDER.get(t[0], 99), t[1], t[2], t[3]))


SM_USES = {
    "SM0.0": "always on",
    "SM0.1": "first scan only",
    "SM0.3": "first scan after power-up",
    "SM0.5": "1 s clock (0.5 s on, 0.5 s off)",
    "SM1.0": "result zero",
    "SM1.1": "overflow or illegal value",
    "SM1.2": "result negative",
    "SM1.3": "division by zero",
}
"""What the S7-200's common SM bits are (S7-200 System Manual, Appendix D, SMB0/SMB1)."""

_AREA_ORDER = {a: k for k, a in enumerate(("V", "M", "I", "Q", "SM", "S", "L", "AC"))}


def _ranges(addresses, groups: dict[str, tuple[str, str]]) -> list[dict]:
    """Merge operands into ranges: overlapping or adjacent bytes of the same group
    (``groups``: operand -> (group key, label)) become one range, labelled with its members."""
    out: list[dict] = []
    for area, first, last, opnd in addresses:
        key, label = groups.get(opnd, ("internal", "program-internal"))
        prev = out[-1] if out else None
        if (
            prev is not None
            and prev["area"] == area
            and prev["_key"] == key
            and first <= prev["last"] + 1
        ):
            prev["last"] = max(prev["last"], last)
            prev["_members"].append(opnd)
            if label not in prev["_labels"]:
                prev["_labels"].append(label)
            continue
        out.append(
            {
                "area": area,
                "first": first,
                "last": last,
                "_key": key,
                "_labels": [label],
                "_members": [opnd],
            }
        )
    for r in out:
        a, f, l_ = r["area"], r["first"], r["last"]
        members = r.pop("_members")
        if len(members) == 1 and not members[0].startswith("#"):
            r["range"] = members[0]
        elif a == "AC":
            r["range"] = f"AC{f}" if f == l_ else f"AC{f}-AC{l_}"
        else:
            r["range"] = f"{a}B{f}" if f == l_ else f"{a}B{f}-{a}B{l_}"
        labels = r.pop("_labels")
        key = r.pop("_key")
        r["use"] = (
            f"{key}: " + ", ".join(labels)
            if key in ("inputs", "outputs", "work")
            else "; ".join(labels)
        )
    return [{k: r[k] for k in ("range", "area", "first", "last", "use")} for r in out]
