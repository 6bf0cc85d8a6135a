"""The S7 dialects' entry points: ``emit_s7200``, ``emit_s7300`` (as SymPy's ``ccode``).

Each builds its dialect's printer (:class:`~analysis.plc.s7200.S7200Printer`, S7-200 STL;
:class:`~analysis.plc.awl.AwlPrinter`, S7-300 AWL) on a memory map (the default one for the
program's I/O unless given), allocates the work area and prints a
:class:`~analysis.plc.instr.Program`. :func:`analysis.plc.generate.generate` does the same
for any dialect of :data:`analysis.plc.dialects.DIALECTS`, with the MAP.json.
"""

from __future__ import annotations

from analysis.plc.awl import AwlPrinter
from analysis.plc.instr import Program, Subroutine
from analysis.plc.memmap import MemoryMap, default_map
from analysis.plc.printer import fmt_real
from analysis.plc.s7200 import S7200Printer, allocate

__all__ = [
    "AwlPrinter",
    "S7200Printer",
    "allocate",
    "emit_s7200",
    "emit_s7200_subroutines",
    "emit_s7300",
    "fmt_real",
]


def emit_s7200(
    program: Program,
    mmap: MemoryMap | None = None,
    *,
    startup_target=(100.0, 100.0, 600.0),
    motion: list[str] | None = None,
) -> str:
    """S7-200 STL (STEP 7-Micro/WIN text form) of ``program`` (:class:`S7200Printer`).

    OB1 networks: the Figure 3 data acquisition on the first scan (``SM0.1``, REAL moves,
    unlike the paper's ``MOVD 100, VD0``), then the IK networks (Figures 4-6 corrected),
    then ``motion`` networks if given (see :mod:`.motion`). Subroutines follow OB1.
    """
    mmap = mmap or default_map("s7-200", program.inputs, len(program.outputs))
    printer = S7200Printer(mmap, startup_target=startup_target, motion=motion)
    printer.check_program(program)
    printer.work = allocate(program, mmap)
    return printer.doprint_program(program)


def emit_s7200_subroutines(subs: list[Subroutine], mmap: MemoryMap | None = None) -> str:
    """S7-200 text of subroutine blocks only (e.g. to go with the paper's own OB1)."""
    return S7200Printer(mmap or default_map("s7-200")).doprint_subroutines(subs)


def emit_s7300(
    program: Program,
    mmap: MemoryMap | None = None,
    *,
    startup_target=(100.0, 100.0, 600.0),
    extra_ob1: list[str] | None = None,
    optimize: bool = True,
) -> str:
    """S7-300/400 AWL source of ``program`` (FCs, OB100 with the Figure 3 target, OB1;
    :class:`AwlPrinter`).

    Parameters
    ----------
    program : Program
    mmap : MemoryMap, optional
        Dialect must be "s7-300" (default map if omitted).
    startup_target : 3 floats or None
        Written to the inputs in OB100 (startup), like the paper's Figure 3 example
        (100, 100, 600) mm; None leaves the inputs alone.
    extra_ob1 : list of str, optional
        AWL lines appended to OB1.
    optimize : bool
        Remove reloads of a value just stored and stores overwritten before they are read
        (:func:`~.peephole.optimize_awl`): the same results in fewer instructions.
    """
    mmap = mmap or default_map("s7-300", program.inputs, len(program.outputs))
    printer = AwlPrinter(mmap, startup_target=startup_target, extra_ob1=extra_ob1,
                         optimize=optimize)  # fmt: skip
    printer.check_program(program)
    printer.work = allocate(program, mmap)
    return printer.doprint_program(program)
