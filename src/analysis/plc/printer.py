"""The base of every PLC dialect's printer, and what a printer hands back.

A dialect is one class (SymPy's printers: ``C99CodePrinter(C89CodePrinter)``), registered by
name in :data:`analysis.plc.dialects.DIALECTS`. The class carries what the rest of the
project asks of a dialect: its name and help line (the ``stl`` and ``stl-run`` choices), the
trigonometry it can print (:data:`analysis.plc.ir.TRIG`, the first its default), whether it
names fixed addresses (a memory map, ``--layout``, ``--cpu``), the tie rule of its pulse
rounding (the float32 model of :mod:`analysis.plc.model`, the comparisons of
:mod:`analysis.plc.verify`), and the engine that runs its text (``stl-run``). An instance
prints: one method per IR instruction (:class:`analysis.kinematics.printing.Printer`), one
per block, one :meth:`PlcPrinter.compare` and one :meth:`PlcPrinter.comment`.

:meth:`PlcPrinter.generate` turns an arm's :class:`~analysis.plc.instr.Program` into a
:class:`Generated`: the program text, its MAP.json and any further named files (a tag table,
a global variable list) a dialect writes beside the program.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any, ClassVar

import numpy as np

from analysis.kinematics.printing import Printer
from analysis.plc.cpus import cpu_name

__all__ = ["Generated", "Options", "PlcPrinter", "fmt_real"]


def fmt_real(v: float, exp_char: str = "e") -> str:
    """A REAL literal with a decimal point, 9 significant digits of the float32 value."""
    v = float(np.float32(v))
    if v == 0:
        return "0.0"
    s = f"{v:.9g}"
    if "e" in s:
        m, e = s.split("e")
        if "." not in m:
            m += ".0"
        return f"{m}{exp_char}{int(e)}"
    return s if "." in s else s + ".0"


@dataclass(frozen=True)
class Options:
    """What :func:`analysis.plc.generate.generate` passes on to a dialect besides the arm and
    its program (each dialect takes the ones that apply to it; the others are refused before:
    :meth:`PlcPrinter.check_options`)."""

    mmap: Any = None
    """A :class:`~analysis.plc.memmap.MemoryMap` (dialects with addresses)."""
    cpu: str | None = None
    motion: bool = True
    optimize: bool = True
    startup_target: Any = None


@dataclass(frozen=True)
class Generated:
    """A dialect's output for one arm: ``program`` (the text ``stl -o`` writes), ``map``
    (MAP.json text) and ``files``: further named files a dialect writes beside the program
    (name -> text; none today). Unpacks as ``text, mjson = generate(...)``."""

    program: str
    map: str
    files: Mapping[str, str] = field(default_factory=lambda: MappingProxyType({}))

    def __iter__(self):
        return iter((self.program, self.map))


class PlcPrinter(Printer):
    """Base of the PLC dialects' printers (module docstring).

    Class attributes
    ----------------
    name : str
        The dialect's name (``--dialect``; the key in the registry).
    title : str
        One line naming the language and where it runs (``stl --help``).
    trigs : tuple of str
        The trigonometry it prints (:data:`analysis.plc.ir.TRIG`); the first is its default.
    addresses : bool
        The program lives at fixed addresses (a memory map: ``--layout``, ``--cpu``).
    rounding : str
        How its pulse rounding breaks a tie (``"half-away"``: eqs. 20-22; ``"half-even"``).
    engine : str or None
        What runs its text offline (``stl-run``), None if nothing does.
    """

    name: ClassVar[str] = ""
    title: ClassVar[str] = ""
    trigs: ClassVar[tuple[str, ...]] = ()
    addresses: ClassVar[bool] = False
    rounding: ClassVar[str] = "half-away"
    engine: ClassVar[str | None] = None
    readable: ClassVar[bool] = False
    """Its programs name every intermediate for a person to read (``build_program(...,
    readable=True)``), rather than reusing temporaries."""
    max_program_bytes: ClassVar[int] = 1024 * 1024
    """The largest program text its engine is given (``stl-run``, enforced while reading)."""
    trig_reason: ClassVar[str] = ""
    """Why the dialect cannot print other trigonometry (named when ``--trig`` asks for it)."""

    # --- what a dialect accepts -------------------------------------------------------------
    @classmethod
    def check_trig(cls, trig: str | None) -> str:
        """``trig`` or the dialect's default; ValueError naming what the dialect can print."""
        if trig is None:
            return cls.trigs[0]
        if trig not in cls.trigs:
            why = cls.trig_reason or f"it prints {', '.join(cls.trigs)}"
            raise ValueError(f"--trig {trig} is not possible on {cls.target} ({why})")
        return trig

    @classmethod
    def check_options(cls, options: Options) -> None:
        """Refuse options that name addresses for a dialect that has none."""
        if not cls.addresses and options.mmap is not None:
            raise ValueError(f"a memory layout names addresses; {cls.name} has none")

    # --- output -------------------------------------------------------------------------------
    @classmethod
    def generate(cls, arm, program, options: Options) -> Generated:
        """The program text, MAP.json and further files of ``program`` (an IR
        :class:`~analysis.plc.instr.Program` of ``arm``)."""
        raise NotImplementedError(cls.name)

    # --- running --------------------------------------------------------------------------------
    @classmethod
    def session(cls, text: str, *, cpu: str | None = None, source: str = "program"):
        """An engine loaded with ``text`` (:mod:`analysis.plc.engines`), for ``stl-run``."""
        raise ValueError(f"no engine runs {cls.name} programs offline")

    @classmethod
    def session_cpu(cls, text: str) -> str:
        """The target CPU ``--cpu`` names for a session (:func:`~analysis.plc.cpus.cpu_name`);
        ValueError for a dialect whose engine takes none."""
        if not cls.addresses:
            raise ValueError(f"--cpu applies to a dialect with addresses, not {cls.name}")
        return cpu_name(text, cls.name)

    @classmethod
    def awlsim_source(cls, text: str) -> str:
        """The AWL source that runs this dialect's ``text`` on awlsim."""
        raise ValueError(f"{cls.name} programs do not run on awlsim")

    # --- the two things every printer prints its own way --------------------------------------
    def comment(self, text: str) -> str:
        """A comment holding ``text``."""
        raise NotImplementedError

    def compare(self, op: str, a: str, b: str):
        """A compare of printed operands ``a``, ``b`` by the op table's symbol ``op`` (``<``
        ``<=`` ``>`` ``>=`` ``==``, and ``<>``), as the dialect writes it."""
        raise NotImplementedError
