"""Execute generated AWL on awlsim (PyPI ``awlsim``, GPL-2.0-or-later, used as a tool).

One program load, then one OB1 cycle per target: write Px, Py, Pz into the input
addresses, ``runCycle()``, read c1..c3 and the reach flag back (awlsim's Python API:
``AwlSim``, ``runCycle``).
The M area (2048 bytes by default) is read and written directly, big-endian.

:func:`sweep` is that on a fresh CPU, as one call. Within one test run the notebooks and
the tests execute some of the same programs on the same targets (notebook 07 and
``tests/plc/test_plc_awlsim.py``, for instance); with ``ANALYSIS_AWLSIM_MEMO`` naming a
directory, :func:`sweep` stores each result there under a digest of everything that
determines it (the AWL text, the memory map, the targets' bytes, the sentinel, the REAL
addresses read, awlsim's version and this module's source) and a later identical call
reads it instead of executing again. ``make test`` points it at a directory it empties
first, so every distinct program and target set runs on awlsim once per ``make test``;
unset (the default), every call executes.

awlsim evaluates REAL operations in Python doubles and rounds every accumulator store to
float32, like a CPU's REAL arithmetic. RND rounds ties to even (S7-300), the S7-200 ROUND
halves away from zero: a float32 value of exactly k + 0.5 is the only place they differ.
"""

from __future__ import annotations

import functools
import hashlib
import os
import re
import struct
import tempfile
import zipfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import numpy.typing as npt

from analysis.plc.memmap import MemoryMap

__all__ = ["MEMO_ENV", "AwlRunner", "RunResult", "S7200Runner", "Sweep", "sweep"]

_STOP = re.compile(r"^// analysis\.plc\.translate: .*STOP bit M (\d+)\.(\d)", re.MULTILINE)
_M_OPERAND = re.compile(r"\bM([BWD]?)\s*(\d+)")


def m_bytes_used(source: str) -> int:
    """One past the highest M byte the code of an AWL source addresses: its statements'
    operands, never a comment or a title (text the CPU does not run)."""
    top = 0
    for line in source.splitlines():
        code = line.split("//", 1)[0]
        if not code.strip() or code.lstrip().upper().startswith("TITLE"):
            continue
        for m in _M_OPERAND.finditer(code):
            top = max(top, int(m.group(2)) + {"": 1, "B": 1, "W": 2, "D": 4}[m.group(1)])
    return top


_FORMAT = {"BYTE": "B", "INT": "h", "WORD": "H", "DINT": "i", "DWORD": "I", "REAL": "f"}
_WIDTH_LETTER = {"BYTE": "B", "INT": "W", "WORD": "W", "DINT": "D", "DWORD": "D", "REAL": "D"}

CYCLE_TIME_LIMIT_US = 60_000_000
"""awlsim's cycle watchdog [us] for the runners: a minute, not its default second."""
MAX_M_BYTES = 65_536
"""The largest M area a runner gives awlsim (S7 byte addresses end at 65535; a translated
S7-200 program of the largest CPU keeps about 11 KiB there)."""
MEMO_ENV = "ANALYSIS_AWLSIM_MEMO"
"""Environment variable: a directory where :func:`sweep` keeps its results (unset: none)."""


def _awlsim():
    """Import awlsim lazily (it is a test/verification dependency); clear error if missing."""
    try:
        # awlsim's modules must be imported in this order (common, core, compiler), as
        # its own awlsim-test does; a different order leaves names undefined in core.cpu
        import awlsim_loader.common  # noqa: I001
        import awlsim_loader.core
        import awlsim_loader.awlcompiler  # noqa: F401
        from awlsim.awlcompiler import AwlParser
        from awlsim.common.cpuconfig import S7CPUConfig
        from awlsim.common.sources import AwlSource
        from awlsim.core.main import AwlSim
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise ImportError(
            "awlsim is needed to execute PLC code: pip install awlsim==0.77.1"
        ) from exc
    return AwlParser, S7CPUConfig, AwlSource, AwlSim


@dataclass(frozen=True)
class RunResult:
    """Pulses read back from the PLC for N targets.

    Attributes
    ----------
    pulses : ndarray of int64, shape (N, n)
        c1 .. cn after the cycle (unchanged from before the cycle if not reachable).
    reachable : ndarray of bool, shape (N,)
    reals : ndarray, shape (N, K), optional
        REAL work values read after each cycle (e.g. the unrounded pulse values).
    status : ndarray of int64, shape (N,), optional
        The program's status word (:class:`analysis.kinematics.status.Status` codes).
    """

    pulses: npt.NDArray[np.int64]
    reachable: npt.NDArray[np.bool_]
    reals: npt.NDArray[np.float64] | None = None
    status: npt.NDArray[np.int64] | None = None


class AwlRunner:
    """A loaded awlsim CPU running one AWL program.

    Parameters
    ----------
    source : str
        Complete AWL source (OBs, FCs).
    mmap : MemoryMap
        Where the inputs/outputs are (byte offsets; V or M notation both map to M).
    first_scan : bool
        Run one OB1 cycle right after loading (the first scan), so that the first
        :meth:`solve` target is not overwritten by first-scan initialisation.
    m_bytes : int, optional
        The M area [bytes], the target CPU's (``cpu_name`` names it in the refusal of a
        program that addresses more); default: what the program's code addresses (at least
        awlsim's 2048 bytes, at most :data:`MAX_M_BYTES`). Comments never size it.
    cycle_limit_us : int
        awlsim's scan watchdog [us] (:data:`CYCLE_TIME_LIMIT_US`).
    """

    def __init__(
        self,
        source: str,
        mmap: MemoryMap,
        name: str = "program",
        *,
        first_scan: bool = True,
        m_bytes: int | None = None,
        cpu_name: str = "the runner",
        cycle_limit_us: int = CYCLE_TIME_LIMIT_US,
    ) -> None:
        # M area: awlsim's 2048 bytes, or what the program's code addresses (a translated
        # S7-200 program keeps all of its V memory in M, its other areas above), at most
        # MAX_M_BYTES; or the target CPU's (m_bytes), which no operand may pass
        need = m_bytes_used(source)
        size = m_bytes if m_bytes is not None else max(2048, need)
        if need > min(size, MAX_M_BYTES):
            size = min(size, MAX_M_BYTES)
            raise ValueError(
                f"the program addresses M byte {need - 1:,}, beyond {cpu_name}'s M memory "
                f"(MB0-MB{size - 1})"
            )
        AwlParser, S7CPUConfig, AwlSource, AwlSim = _awlsim()
        self.mmap = mmap
        self.sim = AwlSim()
        cpu = self.sim.getCPU()
        cpu.getConf().setConfiguredMnemonics(S7CPUConfig.MNEMONICS_EN)
        # awlsim's watchdog (1 s per cycle) measures Python's wall time: on a loaded test
        # machine a cycle of the GR-1 program can take longer, which says nothing about the
        # program (scan times are measured in benchmarks/plc_scan.py)
        cpu.getConf().setCycleTimeLimitUs(cycle_limit_us)
        cpu.getSpecs().setNrFlags(size)
        m = _STOP.search(source)
        self._stop = (int(m.group(1)), int(m.group(2))) if m else None
        parser = AwlParser()
        parser.parseSource(AwlSource.fromBytes(name, source.encode("utf-8")))
        self.sim.reset()
        self.sim.load(parser.getParseTree())
        self.sim.build()
        self.sim.startup()
        self.mem = cpu.flags.getDataBytes()
        if first_scan:
            self.cycle()  # the first scan (SM0.1 / OB100 networks) runs before any test input

    # --- memory access ------------------------------------------------------------------
    def write_real(self, byte: int, value: float) -> None:
        self.mem[byte : byte + 4] = struct.pack(">f", value)

    def read_real(self, byte: int) -> float:
        return struct.unpack(">f", bytes(self.mem[byte : byte + 4]))[0]

    def write_dint(self, byte: int, value: int) -> None:
        self.mem[byte : byte + 4] = struct.pack(">i", value)

    def read_dint(self, byte: int) -> int:
        return struct.unpack(">i", bytes(self.mem[byte : byte + 4]))[0]

    def read_bit(self, byte: int, bit: int) -> bool:
        return bool(self.mem[byte] >> bit & 1)

    def write_bit(self, byte: int, bit: int, value: bool) -> None:
        if value:
            self.mem[byte] |= 1 << bit
        else:
            self.mem[byte] &= ~(1 << bit) & 0xFF

    def cycle(self) -> None:
        self.sim.runCycle()

    # --- typed access by address (the stl-run command) -----------------------------------
    def _area(self, addr: str, typ: str):
        m = re.fullmatch(r"(M|I|Q)([BWD]?)(\d+)(?:\.([0-7]))?", addr.strip().upper())
        if (
            not m
            or (typ == "BOOL") != (m.group(4) is not None)
            or (typ != "BOOL" and m.group(2) != _WIDTH_LETTER[typ])
        ):
            raise ValueError(f"{addr!r} is not an S7-300 {typ} address (M, I or Q)")
        cpu = self.sim.getCPU()
        mem = {"M": self.mem, "I": cpu.inputs.getDataBytes(), "Q": cpu.outputs.getDataBytes()}
        buf = mem[m.group(1)]
        off = int(m.group(3))
        size = 1 if typ in ("BOOL", "BYTE") else 2 if typ in ("INT", "WORD") else 4
        if off + size > len(buf):
            raise ValueError(f"{addr} is beyond the {m.group(1)} area ({len(buf)} bytes)")
        return buf, off, int(m.group(4)) if m.group(4) is not None else None

    def read(self, typ: str, addr: str):
        """The value at an M, I or Q address as BOOL, BYTE, INT, WORD, DINT, DWORD or REAL."""
        buf, off, bit = self._area(addr, typ)
        if typ == "BOOL":
            return bool(buf[off] >> bit & 1)
        return struct.unpack_from(">" + _FORMAT[typ], bytes(buf[off : off + 4]), 0)[0]

    def write(self, typ: str, addr: str, value) -> None:
        buf, off, bit = self._area(addr, typ)
        if typ == "BOOL":
            buf[off] = buf[off] | (1 << bit) if value else buf[off] & ~(1 << bit) & 0xFF
            return
        data = struct.pack(">" + _FORMAT[typ], value)
        buf[off : off + len(data)] = data

    @property
    def stopped(self) -> bool:
        """True once translated S7-200 code hit a NaN in a REAL compare (CPU STOP)."""
        return self._stop is not None and self.read_bit(*self._stop)

    # --- one target per cycle -------------------------------------------------------------
    def solve(
        self, targets: npt.ArrayLike, sentinel: int | None = None, reals: tuple[int, ...] = ()
    ) -> RunResult:
        """Run one OB1 cycle per target and read the pulses back.

        Parameters
        ----------
        targets : array_like, shape (N, k)
            The program's inputs (Px, Py, Pz [mm]), in the map's order; written as float32
            REALs (NaN/inf allowed: the program must reject them).
        sentinel : int, optional
            Written to c1..c3 before each cycle, so that "unchanged" is observable.
        reals : tuple of int
            Byte offsets of REAL double words to read after each cycle.
        """
        ins = list(self.mmap.inputs.values())
        t = np.asarray(targets, dtype=float).reshape(-1, len(ins))
        names = sorted((k for k in self.mmap.outputs if k[0] == "c"), key=lambda k: int(k[1:]))
        outs = [self.mmap.outputs[k] for k in names]
        rbyte, rbit = self.mmap.outputs["reachable"]
        sbyte = self.mmap.outputs.get("status")
        pulses = np.zeros((len(t), len(outs)), dtype=np.int64)
        ok = np.zeros(len(t), dtype=bool)
        status = np.full(len(t), -1, dtype=np.int64)
        extra = np.full((len(t), len(reals)), np.nan)
        for n, p in enumerate(t):  # one PLC scan per target: this loop IS the test harness
            for b, v in zip(ins, p, strict=True):
                self.write_real(b, float(v))
            if sentinel is not None:
                for b in outs:
                    self.write_dint(b, sentinel)
            self.cycle()
            pulses[n] = [self.read_dint(b) for b in outs]
            ok[n] = self.read_bit(rbyte, rbit)
            if sbyte is not None:
                status[n] = self.read_dint(sbyte)
            extra[n] = [self.read_real(b) for b in reals]
        return RunResult(pulses, ok, extra if reals else None, status)


class S7200Runner:
    """The S7-200 program text on the project's S7-200 evaluator
    (:class:`analysis.plc.stl_eval.S7200`), with :meth:`solve` as :class:`AwlRunner`'s: one
    scan per target, the same :class:`RunResult`. No translation and no awlsim: the
    independent second execution of the generated S7-200 text."""

    def __init__(self, text: str, mmap: MemoryMap, *, first_scan: bool = True) -> None:
        from analysis.plc.stl_eval import S7200, load_program

        if mmap.dialect != "s7-200":
            raise ValueError(f"S7200Runner runs S7-200 programs, not {mmap.dialect}")
        self.mmap = mmap
        self.cpu = S7200(load_program(text, cpu=mmap.cpu))
        if first_scan:
            self.cpu.scan()

    @property
    def stopped(self) -> bool:
        return self.cpu.stopped

    def solve(
        self, targets: npt.ArrayLike, sentinel: int | None = None, reals: tuple[int, ...] = ()
    ) -> RunResult:
        """One scan per target (see :meth:`AwlRunner.solve`)."""
        v = self.cpu.mem["V"]
        ins = list(self.mmap.inputs.values())
        t = np.asarray(targets, dtype=float).reshape(-1, len(ins))
        names = sorted((k for k in self.mmap.outputs if k[0] == "c"), key=lambda k: int(k[1:]))
        outs = [self.mmap.outputs[k] for k in names]
        rbyte, rbit = self.mmap.outputs["reachable"]
        sbyte = self.mmap.outputs.get("status")
        pulses = np.zeros((len(t), len(outs)), dtype=np.int64)
        ok = np.zeros(len(t), dtype=bool)
        status = np.full(len(t), -1, dtype=np.int64)
        extra = np.full((len(t), len(reals)), np.nan)
        f32, i32 = struct.Struct(">f"), struct.Struct(">i")
        for n, p in enumerate(t):
            for b, x in zip(ins, p, strict=True):
                f32.pack_into(v, b, float(x))
            if sentinel is not None:
                for b in outs:
                    i32.pack_into(v, b, sentinel)
            self.cpu.scan()
            pulses[n] = [i32.unpack_from(v, b)[0] for b in outs]
            ok[n] = bool(v[rbyte] >> rbit & 1)
            if sbyte is not None:
                status[n] = i32.unpack_from(v, sbyte)[0]
            extra[n] = [f32.unpack_from(v, b)[0] for b in reals]
        return RunResult(pulses, ok, extra if reals else None, status)


@dataclass(frozen=True)
class Sweep:
    """What :func:`sweep` returns.

    Attributes
    ----------
    result : RunResult
    stopped : bool
        The CPU was stopped (a NaN reached a REAL compare in translated S7-200 code).
    source : {"awlsim", "memo"}
        Executed by this call, or read from ``ANALYSIS_AWLSIM_MEMO`` (executed earlier in
        the run by an identical call).
    """

    result: RunResult
    stopped: bool
    source: str


@functools.cache
def _harness() -> str:
    """What else the results depend on: awlsim's version and this module's source."""
    from awlsim.common.version import VERSION_STRING

    return VERSION_STRING + "\0" + Path(__file__).read_text(encoding="utf-8")


def _digest(source: str, mmap: MemoryMap, t: np.ndarray, sentinel, reals) -> str:
    h = hashlib.sha256()
    for part in (
        _harness(),
        source,
        mmap.to_json(),
        repr((t.shape, sentinel, tuple(reals))),
    ):
        h.update(part.encode("utf-8"))
        h.update(b"\0")
    h.update(np.ascontiguousarray(t, dtype="<f8").tobytes())
    return h.hexdigest()


def _read_memo(path: Path) -> Sweep | None:
    try:
        with np.load(path) as z:
            reals = z["reals"] if bool(z["has_reals"]) else None
            res = RunResult(z["pulses"], z["reachable"], reals, z["status"])
            return Sweep(res, bool(z["stopped"]), "memo")
    except (OSError, ValueError, KeyError, EOFError, zipfile.BadZipFile):
        return None  # absent or unreadable: execute instead


def _write_memo(path: Path, out: Sweep) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    r = out.result
    reals = r.reals if r.reals is not None else np.empty((len(r.pulses), 0))
    fd, tmp = tempfile.mkstemp(dir=path.parent, suffix=".tmp")
    try:
        with os.fdopen(fd, "wb") as fh:
            np.savez(
                fh,
                pulses=r.pulses,
                reachable=r.reachable,
                reals=reals,
                has_reals=r.reals is not None,
                status=r.status,
                stopped=out.stopped,
            )
        os.replace(tmp, path)  # whole or not at all: a reader never sees half a file
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def sweep(
    source: str,
    mmap: MemoryMap,
    targets: npt.ArrayLike,
    sentinel: int | None = None,
    reals: tuple[int, ...] = (),
) -> Sweep:
    """Load ``source`` on a fresh CPU (with its first scan) and run one cycle per target
    (:meth:`AwlRunner.solve`, the same parameters). With ``ANALYSIS_AWLSIM_MEMO`` set, an
    identical earlier call's result is read instead (module docstring)."""
    t = np.asarray(targets, dtype=float).reshape(-1, len(mmap.inputs))
    memo = os.environ.get(MEMO_ENV)
    path = Path(memo) / f"{_digest(source, mmap, t, sentinel, reals)}.npz" if memo else None
    if path is not None and (hit := _read_memo(path)) is not None:
        return hit
    runner = AwlRunner(source, mmap)
    out = Sweep(runner.solve(t, sentinel=sentinel, reals=reals), runner.stopped, "awlsim")
    if path is not None:
        _write_memo(path, out)
    return out
