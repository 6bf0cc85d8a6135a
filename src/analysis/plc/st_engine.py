"""Execute generated IEC 61131-3 ST on an independent engine: the ST compiler and virtual
machine of pyplcopen's source distribution.

The engine (``core/st`` of the PyPI sdist ``pyplcopen==0.21.0``, header-only C++17,
Apache-2.0; not part of the pyplcopen wheel, whose Python API exposes no ST execution) is
built once by ``make st-engine`` with Debian's g++ together with the project's small driver
``tools/st-engine/st_run.cpp``: the sdist is downloaded by pip with its hash checked
(``tools/st-engine/requirements.txt``), and the binary lands in the virtual environment as
``bin/analysis-st-run``, keyed by the sdist's hash and the driver's source (``--key``).
Nothing is downloaded or compiled at run time. Why this engine: the only ST executor
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
    "EngineMissing",
    "StRun",
    "blank_comments",
    "build_key",
    "engine_path",
    "harness",
    "run_program",
    "sweep",
]

ENGINE_ENV = "ANALYSIS_ST_ENGINE"
"""Environment variable: path of the engine binary (default: the virtual environment's
``bin/analysis-st-run``, which ``make st-engine`` builds)."""

_REPO = Path(__file__).resolve().parents[3]
_DRIVER = _REPO / "tools" / "st-engine" / "st_run.cpp"
_PIN = _REPO / "tools" / "st-engine" / "requirements.txt"


class EngineMissing(RuntimeError):
    """The ST engine is not built (or was built from other sources): ``make st-engine``."""


def build_key() -> str | None:
    """The key the binary must report: sha256 of the pinned requirement line (with the
    sdist's hash) and of the driver source; None outside a source checkout."""
    if not (_DRIVER.exists() and _PIN.exists()):
        return None
    h = hashlib.sha256()
    for p in (_PIN, _DRIVER):
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
    outputs (``c1..cn`` DINT, ``reachable`` BOOL, ``status`` DINT) to its own variables."""
    decl = [f"    {n} : REAL;" for n in inputs]
    decl += [f"    {n} : DINT;" for n in outputs]
    decl += ["    reachable : BOOL;", "    status : DINT;", f"    ik : {fb};"]
    call = ", ".join(f"{n} := {n}" for n in inputs)
    copy = [f"{n} := ik.{n};" for n in (*outputs, "reachable", "status")]
    return "\n".join(
        [f"PROGRAM {name}", "VAR", *decl, "END_VAR", f"ik({call});", *copy, "END_PROGRAM", ""]
    )


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
