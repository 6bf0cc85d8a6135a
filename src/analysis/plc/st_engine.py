"""Execute generated IEC 61131-3 ST on an independent engine: the ST compiler and virtual
machine of pyplcopen's source distribution.

The engine (``core/st`` of the PyPI sdist ``pyplcopen==0.21.0``, header-only C++17,
Apache-2.0; not part of the pyplcopen wheel, whose Python API exposes no ST execution) is
built once by ``make st-engine`` with Debian's g++ together with the project's small driver
``tools/st-engine/st_run.cpp``: the sdist is downloaded by pip with its hash checked
(``tools/st-engine/requirements.txt``), and the binary lands in the virtual environment as
``bin/analysis-st-run``, keyed by the sdist's hash, the drivers' sources and the patch
(``--key``). The sdist's simulated axis is patched after unpacking
(``tools/st-engine/pyplcopen-0.21.0-motion.patch``: a velocity command reaches its velocity on
a jerk-limited ramp instead of a step, and MC_Halt/MC_Stop brake on a velocity ramp to rest
instead of running past the rest point and coming back; the header says why, with the
figures). Nothing is downloaded or compiled at run time. Why this engine: the only ST executor
installable from the registries here (stl_reference.md: matiec, OpenPLC, Beremiz, RuSTy,
IronPLC cannot be installed; blark only parses); it is an implementation independent of
this project and of awlsim, REAL is binary32 with each operation rounded, REAL_TO_DINT
rounds to nearest (ties to even) and a NaN/inf into an integer faults.

:func:`sweep` runs a program's function block once per target, through a generated
``PROGRAM`` (:func:`harness`) whose variables the driver writes between scans, as an HMI
writes a PLC's variables, and reads back after each scan. A function block's outputs cannot
be written from outside, so "a refused scan leaves c1..cn alone" is observed by comparing
with the previous scan: the result reports ``sentinel`` wherever a refused scan left the
counts as they were, and the counts themselves where it changed them (which
:func:`analysis.plc.verify.compare` then counts as a failure).
"""

from __future__ import annotations

import functools
import hashlib
import os
import re
import subprocess
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import numpy.typing as npt

from analysis.plc.runner import RunResult

__all__ = [
    "ENGINE_ENV",
    "POWER_OK",
    "EngineFault",
    "EngineMissing",
    "MachineRun",
    "SimAxis",
    "StRun",
    "blank_comments",
    "build_key",
    "engine_path",
    "harness",
    "machine_engine_path",
    "program_variables",
    "run_machine",
    "run_program",
    "sweep",
]

ENGINE_ENV = "ANALYSIS_ST_ENGINE"
"""Environment variable: path of the engine binary (default: the virtual environment's
``bin/analysis-st-run``, which ``make st-engine`` builds)."""

_REPO = Path(__file__).resolve().parents[3]
_DRIVER = _REPO / "tools" / "st-engine" / "st_run.cpp"
_PIN = _REPO / "tools" / "st-engine" / "requirements.txt"
_MACHINE = _REPO / "tools" / "st-engine" / "st_machine.cpp"
_PATCH = _REPO / "tools" / "st-engine" / "pyplcopen-0.21.0-motion.patch"


class EngineMissing(RuntimeError):
    """The ST engine is not built (or was built from other sources): ``make st-engine``."""


def build_key() -> str | None:
    """The key the binary must report: sha256 of the pinned requirement line (with the
    sdist's hash), of the drivers' sources and of the patch applied to the sdist (the
    Makefile's ST_SOURCES, in its order); None outside a source checkout."""
    sources = (_PIN, _DRIVER, _MACHINE, _PATCH)
    if not all(p.exists() for p in sources):
        return None
    h = hashlib.sha256()
    for p in sources:
        h.update(p.read_bytes())
    return h.hexdigest()[:16]


def engine_path(check: bool = True) -> Path:
    """The engine binary; ``check``: raise :class:`EngineMissing` unless it exists and was
    built from this checkout's driver and pin."""
    env = os.environ.get(ENGINE_ENV)
    path = Path(env) if env else Path(sys.prefix) / "bin" / "analysis-st-run"
    if not check:
        return path
    if not path.exists():
        raise EngineMissing(f"the ST engine {path} is not built: run `make st-engine`")
    key = build_key()
    if key is not None:
        got = subprocess.run([str(path), "--key"], capture_output=True, text=True).stdout.strip()
        if got != key:
            raise EngineMissing(
                f"the ST engine {path} was built from other sources (key {got!r}, this "
                f"checkout {key!r}): run `make st-engine`"
            )
    return path


def harness(fb: str, inputs, outputs, name: str = "ST_HARNESS") -> str:
    """A PROGRAM calling function block ``fb`` with its inputs (REAL) and copying its
    outputs (``c1..cn`` DINT, ``reachable`` BOOL, ``status`` DINT) to its own variables: every
    scan a rising edge of the block's Execute (called with Execute FALSE, then TRUE)."""
    decl = [f"    {n} : REAL;" for n in inputs]
    decl += [f"    {n} : DINT;" for n in outputs]
    decl += ["    reachable : BOOL;", "    status : DINT;", f"    ik : {fb};"]
    call = ", ".join(f"{n} := {n}" for n in inputs)
    copy = [f"{n} := ik.{n};" for n in (*outputs, "reachable", "status")]
    body = [f"ik(Execute := FALSE, {call});", f"ik(Execute := TRUE, {call});", *copy]
    return "\n".join([f"PROGRAM {name}", "VAR", *decl, "END_VAR", *body, "END_PROGRAM", ""])


@dataclass(frozen=True)
class StRun:
    """What :func:`run_program` returns: ``values`` (N, len(outputs)) as float64, ``faults``
    (N,) the engine's scan error codes (0 ok), ``scan_ns`` the time spent in scans."""

    values: npt.NDArray[np.float64]
    faults: npt.NDArray[np.int64]
    scan_ns: int


def blank_comments(source: str) -> str:
    """``source`` with every ``(* ... *)`` and ``// ...`` comment replaced by spaces
    (newlines kept); string literals are not looked into (the generated ST has none)."""
    return re.sub(
        r"\(\*.*?\*\)|//[^\n]*", lambda m: re.sub(r"[^\n]", " ", m.group(0)), source, flags=re.S
    )


def run_program(
    source: str, program: str, inputs, outputs, rows: npt.ArrayLike, engine: Path | None = None
) -> StRun:
    """Compile ``source`` and run PROGRAM ``program`` once per row of REAL inputs.

    The comments are blanked (each character but newlines replaced by a space, so lines and
    columns stay) before the engine sees the text: pyplcopen 0.21.0's compiler fails with
    ``sema_unknown_identifier`` at line 0 on some comments inside a function block (in its
    VAR sections, or between its statements), which carry no meaning. Raises ValueError
    with the engine's diagnostics if the source does not compile."""
    engine = engine or engine_path()
    source = blank_comments(source)
    data = np.ascontiguousarray(np.asarray(rows, dtype="<f4").reshape(-1, len(inputs)))
    with tempfile.NamedTemporaryFile("w", suffix=".st", delete=False, encoding="utf-8") as f:
        f.write(source)
        path = f.name
    try:
        r = subprocess.run(
            [str(engine), path, program, ",".join(inputs), ",".join(outputs)],
            input=data.tobytes(),
            capture_output=True,
        )
    finally:
        os.unlink(path)
    err = r.stderr.decode("utf-8", "replace")
    if r.returncode != 0:
        raise ValueError(f"the ST engine refused the program:\n{err.strip()}")
    out = np.frombuffer(r.stdout, dtype="<f8").reshape(len(data), len(outputs) + 1)
    ns = next(
        (int(w[1]) for w in (ln.split() for ln in err.splitlines()) if w[:1] == ["scan_ns"]), 0
    )
    return StRun(out[:, :-1].copy(), out[:, -1].astype(np.int64), ns)


def sweep(
    source: str,
    fb: str,
    inputs,
    n_outputs: int,
    targets: npt.ArrayLike,
    sentinel: int | None = None,
    engine: Path | None = None,
) -> tuple[RunResult, StRun]:
    """One scan per target of function block ``fb`` in ``source`` (module docstring).

    Returns the :class:`~analysis.plc.runner.RunResult` (pulses, reachable, status) and the
    raw :class:`StRun`; a scan that faulted has status -1."""
    outs = [f"c{j + 1}" for j in range(n_outputs)]
    text = source + "\n" + harness(fb, inputs, outs)
    t = np.asarray(targets, dtype=float).reshape(-1, len(inputs))
    run = run_program(text, "ST_HARNESS", inputs, [*outs, "reachable", "status"], t, engine)
    pulses = run.values[:, :n_outputs].astype(np.int64)
    reachable = run.values[:, n_outputs] != 0
    status = np.where(run.faults == 0, run.values[:, n_outputs + 1], -1).astype(np.int64)
    if sentinel is not None:
        before = np.vstack([np.zeros((1, n_outputs), np.int64), pulses[:-1]])
        kept = ~reachable[:, None] & (pulses == before)
        pulses = np.where(kept, sentinel, pulses)
    return RunResult(pulses, reachable, None, status), run


# --- a machine, cycle by cycle ------------------------------------------------------------------

MACHINE_ENGINE_ENV = "ANALYSIS_ST_MACHINE"
"""Environment variable: path of the machine driver (default: the virtual environment's
``bin/analysis-st-machine``, built by ``make st-engine`` beside ``analysis-st-run``)."""

TIME_UNIT_VARIABLE = "MotionTimeUnit"
CYCLE_VARIABLE = "TaskCycle"
"""The task's cycle time [s] in a machine program: :func:`run_machine` writes the cycle there
before the first scan too (the program plans its profiles in whole cycles of it)."""
"""Seconds per time unit of a motion block's Velocity/Acceleration/Jerk in a machine program
(:mod:`analysis.plc.machine.program`). pyplcopen 0.21.0's ``axis::AxisModel`` plans a motion
block's Velocity, Acceleration, Deceleration and Jerk as they are, per cycle (``FbMoveAbsolute``
copies them into the ``AxisCommand``; ``AxisModel::start`` plans with them unconverted; only
the axis' own limits are set in SI, ``configure_si``); CODESYS SoftMotion, TwinCAT NC and TIA
technology objects take them per second. :func:`run_machine` writes the cycle time [s] here
before the first scan, which turns every ``value * MotionTimeUnit**k`` into per-cycle units:
the one place the unit is converted."""


@dataclass(frozen=True)
class SimAxis:
    """A simulated axis bound to AXIS_REF variable ``name``: limits per second in joint units
    (deg or mm), software limits (None: none), where it physically stands at power-up
    (``start``), what its encoder reads then (``coord``, None: ``start``) and the physical
    position of its reference switch (``switch``, None: none; the axis' digital input 0, TRUE
    at or beyond it: ``tools/st-engine/st_machine.cpp``)."""

    name: str
    max_velocity: float
    max_acceleration: float
    max_jerk: float
    lower: float | None = None
    upper: float | None = None
    start: float = 0.0
    coord: float | None = None
    switch: float | None = None

    def spec(self) -> str:
        def f(x):
            return "nan" if x is None else repr(float(x))

        coord = self.start if self.coord is None else self.coord
        values = (self.max_velocity, self.max_acceleration, self.max_jerk, self.lower,
                  self.upper, self.start, coord, self.switch)  # fmt: skip
        return ",".join([self.name, *(f(x) for x in values)])


POWER_OK = "PowerOK"
"""``<axis>.PowerOK`` in a machine run's writes: the axis' drive power-stage feedback
(``AxisModel::set_power_feedback``): FALSE while powered is an axis error (a drive fault),
TRUE restores it. Not a program variable: the simulated drive's own signal."""


class EngineFault(ValueError):
    """A scan faulted (which fault, at which cycle); the trace up to it is kept."""

    def __init__(self, message: str, run) -> None:
        super().__init__(message)
        self.run = run


@dataclass(frozen=True)
class MachineRun:
    """One row per cycle: ``t`` (s), ``q`` and ``v`` (cycles, axes) in joint units and per
    second (the physical position), ``values`` (cycles, outputs), ``faults`` (cycles,), the
    time spent in scans, ``pos`` (cycles, axes) the encoders' positions (what the PLC reads:
    ``q`` until an axis is re-referenced by homing)."""

    t: npt.NDArray[np.float64]
    q: npt.NDArray[np.float64]
    v: npt.NDArray[np.float64]
    names: tuple[str, ...]
    values: npt.NDArray[np.float64]
    faults: npt.NDArray[np.int64]
    scan_ns: int
    cycle_s: float
    pos: npt.NDArray[np.float64] | None = None

    def __getitem__(self, name: str) -> npt.NDArray[np.float64]:
        return self.values[:, self.names.index(name)]


def machine_engine_path(check: bool = True) -> Path:
    """The machine driver (as :func:`engine_path`; its key checked once per process)."""
    env = os.environ.get(MACHINE_ENGINE_ENV)
    path = Path(env) if env else Path(sys.prefix) / "bin" / "analysis-st-machine"
    if check:
        if not path.exists():
            raise EngineMissing(f"the ST machine driver {path} is not built: run `make st-engine`")
        _check_key(str(path), path.stat().st_mtime_ns)
    return path


@functools.cache
def _check_key(path: str, mtime_ns: int) -> None:
    key = build_key()
    if key is not None:
        got = subprocess.run([path, "--key"], capture_output=True, text=True)
        if got.stdout.strip() != key:
            raise EngineMissing(f"the ST machine driver {path} was built from other sources: "
                                "run `make st-engine`")  # fmt: skip


def _diagnostic(err: str) -> str:
    lines = [ln for ln in err.splitlines() if ln and not ln.startswith("scan_ns")]
    first = lines[0] if lines else "no diagnostic"
    more = f" (and {len(lines) - 1} more)" if len(lines) > 1 else ""
    return first + more


def _with_source(source: str, fn):
    with tempfile.NamedTemporaryFile("w", suffix=".st", delete=False, encoding="utf-8") as f:
        f.write(blank_comments(source))
        path = f.name
    try:
        return fn(path)
    finally:
        os.unlink(path)


def program_variables(source: str, program: str, engine: Path | None = None) -> dict[str, str]:
    """The variables of PROGRAM ``program`` in ``source`` and their types (as the engine
    compiled them: BOOL, INT, DINT, REAL, LREAL, TIME, AXIS_REF, ...). ValueError with the
    first diagnostic (line and column) if it does not compile."""
    return dict(_program_variables(source, program, str(engine or machine_engine_path())))


@functools.lru_cache(maxsize=64)
def _program_variables(source: str, program: str, engine: str) -> tuple[tuple[str, str], ...]:
    r = _with_source(source, lambda p: subprocess.run(
        [engine, "--vars", p, program], capture_output=True, timeout=60))  # fmt: skip
    if r.returncode != 0:
        raise ValueError(f"the program does not compile: {_diagnostic(r.stderr.decode())}")
    return tuple(tuple(ln.partition("\t")[::2]) for ln in r.stdout.decode().splitlines())


def run_machine(
    source: str,
    program: str,
    axes,
    writes,
    outputs,
    *,
    cycle_s: float = 0.004,
    n_cycles: int,
    engine: Path | None = None,
) -> MachineRun:
    """Run PROGRAM ``program`` for ``n_cycles`` cycles of ``cycle_s`` with one simulated
    axis per :class:`SimAxis` in ``axes``; ``writes`` are ``(cycle, name, value)`` stored
    before that cycle's scan (an HMI writing between scans; ``<axis>.PowerOK``: the drive's
    power feedback, :data:`POWER_OK`); ``outputs`` the variables traced.
    If the program declares :data:`TIME_UNIT_VARIABLE` or :data:`CYCLE_VARIABLE`, the cycle
    time [s] is written there before the first scan. Raises :class:`EngineFault` (with the
    trace so far) when a scan faults, ValueError when the program does not compile or a name
    is not its variable."""
    engine = engine or machine_engine_path()
    cycle_ns = round(cycle_s * 1e9)
    axes = list(axes)
    drive = {f"{a.name}.{POWER_OK}".lower(): f"@{k}" for k, a in enumerate(axes)}
    writes = [(c, drive.get(n.lower(), n), v) for c, n, v in writes]
    names = sorted({n for _, n, _ in writes})
    rows = [(c, names.index(n), float(v)) for c, n, v in writes]
    variables = program_variables(source, program, engine)
    lower = {k.lower(): k for k in variables}
    for var in (TIME_UNIT_VARIABLE, CYCLE_VARIABLE):
        if var.lower() in lower:
            tu = lower[var.lower()]
            if tu not in names:
                names.append(tu)
            rows.insert(0, (0, names.index(tu), cycle_ns * 1e-9))
    rows.sort(key=lambda r: r[0])
    data = np.array(rows, dtype=[("c", "<i8"), ("i", "<i8"), ("v", "<f8")]).tobytes()
    cmd = [str(engine), "", program, str(cycle_ns), str(int(n_cycles)),
           ";".join(a.spec() for a in axes), ",".join(names), ",".join(outputs)]  # fmt: skip

    def go(path):
        cmd[1] = path
        return subprocess.run(cmd, input=data, capture_output=True, timeout=600)

    r = _with_source(source, go)
    err = r.stderr.decode("utf-8", "replace")
    if r.returncode not in (0, 4):
        raise ValueError(_diagnostic(err))
    n, k = len(axes), len(outputs)
    out = np.frombuffer(r.stdout, dtype="<f8").reshape(-1, 3 * n + k + 1)
    ns = next((int(w[1]) for w in (ln.split() for ln in err.splitlines())
               if w[:1] == ["scan_ns"]), 0)  # fmt: skip
    run = MachineRun(
        t=np.arange(len(out)) * (cycle_ns * 1e-9),
        q=out[:, :n].copy(),
        v=out[:, n : 2 * n].copy(),
        names=tuple(outputs),
        values=out[:, 3 * n : 3 * n + k].copy(),
        faults=out[:, -1].astype(np.int64),
        scan_ns=ns,
        cycle_s=cycle_ns * 1e-9,
        pos=out[:, 2 * n : 3 * n].copy(),
    )
    if r.returncode == 4:
        raise EngineFault(f"engine {_diagnostic(err)}", run)
    return run
