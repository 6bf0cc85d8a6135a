"""A PLC program and its memory map, as text files for a dialect (the ``stl`` command).

:func:`generate` builds the program of an arm's closed form (:func:`analysis.plc.ir.
build_program`) and hands it to the dialect's printer class (:data:`analysis.plc.dialects.
DIALECTS`), which prints it and writes its MAP.json: for the S7 dialects the variables are
allocated once in the target CPU's memory (:mod:`.memmap`; every address checked against the
CPU, a ValueError naming the CPU and the limit), and for the paper's arm on the S7-200 the
motion networks turn the counts into stepper moves on the CPU 224's two PTO channels
(:mod:`.motion`, Table 2's I/O); for ST, SCL and PLCopen XML the map names the block's
interface. MAP.json names every signal with its unit, every status code the program writes,
every memory range the program text uses and what the first scan does.

Start-up. By default the program writes nothing into its inputs: an HMI's target survives a
power cycle (if the CPU retains that memory) and is never replaced by an example. The
paper's Figure 3 writes its example target (100, 100, 600) mm on the first scan; pass
``startup_target="paper"`` (the closed form's ``STARTUP_TARGET``, Figure 3 for the grabber)
or three numbers to generate that network, and MAP.json says so.
"""

from __future__ import annotations

from analysis.plc.dialects import printer_class
from analysis.plc.ir import build_program
from analysis.plc.printer import Generated, Options

__all__ = ["MACHINE_DIALECTS", "Generated", "generate"]

MACHINE_DIALECTS = ("st", "scl", "plcopen-xml")
"""The dialects whose output carries the machine program (issue 29) unless ``motion=False``."""


def generate(
    arm,
    dialect: str,
    branch: str | None = None,
    trig: str | None = None,
    mmap=None,
    *,
    motion: bool = True,
    theta1_on_axis: float | None = None,
    optimize: bool = True,
    startup_target=None,
    cpu: str | None = None,
) -> Generated:
    """Program text, MAP.json text (and any further files) of ``arm`` for one dialect.

    Parameters
    ----------
    arm : Arm
        The arm (:class:`analysis.kinematics.arm.Arm`: its closed form and numbers).
    dialect : str
        A key of :data:`analysis.plc.dialects.DIALECTS` ("s7-200", "s7-300", "st", "scl",
        "plcopen-xml").
    branch : str, optional
        Default: the arm's first (the paper's) branch.
    trig : {"native", "subroutine", "function"}, optional
        Default: the dialect's (subroutine on the S7-200, its only choice; native on the
        S7-300; function in the ST family).
    mmap : MemoryMap, optional
        Addresses (default: :func:`~.memmap.default_map` for the program's I/O; only for a
        dialect with addresses).
    motion : bool
        S7-200 and the paper's arm: append the PTO motion networks; st, scl, plcopen-xml:
        the machine program beside the IK block (:func:`analysis.plc.machine.generate.
        with_machine`; False: the IK block on its own).
    theta1_on_axis : float, optional
        Waist angle [rad] on the base axis (default: refuse such targets, status 3).
    optimize : bool
        S7-300: the AWL after :func:`~.peephole.optimize_awl` (fewer loads and stores, the
        same results). The S7-200 text is never rewritten.
    startup_target : None, "paper" or numbers
        S7 dialects: what the first scan writes into the inputs: nothing (default), the
        closed form's example (``"paper"``: Figure 3's (100, 100, 600) mm for the grabber),
        or these values (in the inputs' units).
    cpu : str, optional
        Target CPU (:data:`~.cpus.CPUS`; default the map's, else CPU 224 / CPU 315-2 DP).

    Returns
    -------
    Generated
        ``.program``, ``.map`` and ``.files``; unpacks as ``text, mjson``.
    """
    cls = printer_class(dialect)
    options = Options(mmap, cpu, motion, optimize, startup_target)
    cls.check_options(options)
    trig = cls.check_trig(trig)
    program = build_program(arm, branch, trig, theta1_on_axis=theta1_on_axis,
                            readable=cls.readable)  # fmt: skip
    out = cls.generate(arm, program, options)
    if motion and dialect in MACHINE_DIALECTS:  # the machine program beside the IK block
        from analysis.plc.machine.generate import with_machine
        from analysis.plc.st import block_name

        return with_machine(arm, dialect, out, block_name(program, arm.branches[0]))
    return out
