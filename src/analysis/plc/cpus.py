"""The target CPUs: the size of each memory area, and their addresses.

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

import re
from dataclasses import dataclass

__all__ = ["CPUS", "DEFAULT_CPU", "Cpu", "cpu_name", "parse_address", "target_cpu"]

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
    return target_cpu(match[0] if match else text.strip(), dialect).name


def target_cpu(name: str | None, dialect: str) -> Cpu:
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
    target = target_cpu(cpu, dialect)
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
