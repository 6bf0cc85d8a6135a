"""A PLC program and its memory map, as text files for a dialect (the ``stl`` command).

:func:`generate` builds the program of an arm's closed form (:func:`analysis.plc.ir.
build_program`), allocates its variables (:mod:`.memmap`) and prints it (:mod:`.emit`). For
the paper's arm on the S7-200 it adds the motion networks that turn the counts into stepper
moves on the CPU 224's two PTO channels (:mod:`.motion`, Table 2's I/O).
"""

from __future__ import annotations

from analysis.kinematics.arm import Params
from analysis.kinematics.arms import closed_form
from analysis.plc.emit import allocate, emit_s7200, emit_s7300
from analysis.plc.ir import build_program
from analysis.plc.memmap import DIALECTS, MemoryMap, default_map
from analysis.plc.motion import motion_networks

__all__ = ["generate"]


def generate(
    dialect: str = "s7-300",
    branch: str | None = None,
    trig: str | None = None,
    mmap: MemoryMap | None = None,
    params: Params | None = None,
    motion: bool = True,
    theta1_on_axis: float | None = None,
    optimize: bool = True,
) -> tuple[str, str]:
    """Program text and MAP.json text for one dialect.

    Parameters
    ----------
    dialect : {"s7-200", "s7-300", "st", "scl", "plcopen-xml"}
        The last three: :func:`analysis.plc.st_generate.generate_st`.
    branch : str, optional
        Default: the arm's first (the paper's) branch.
    trig : {"native", "subroutine"}, optional
        Default: native on the S7-300, subroutine on the S7-200 (its only choice).
    mmap : MemoryMap, optional
        Addresses (default: :func:`~.memmap.default_map` for the program's I/O).
    params : Params, optional
        The arm and its numbers (default: the paper's arm, Table 3).
    motion : bool
        S7-200 and the paper's arm only: append the PTO motion networks.
    theta1_on_axis : float, optional
        Waist angle [rad] on the base axis (default: refuse such targets, status 3).
    optimize : bool
        S7-300: the AWL after :func:`~.peephole.optimize_awl` (fewer loads and stores, the
        same results). The S7-200 text is never rewritten.
    """
    from analysis.plc.st_generate import ST_FAMILY, generate_st

    if dialect in ST_FAMILY:  # IEC 61131-3 ST, SCL, PLCopen XML: no addresses, no motion
        if mmap is not None:
            raise ValueError(f"a memory layout names addresses; {dialect} has none")
        return generate_st(dialect, branch, trig, params, theta1_on_axis)
    if dialect not in DIALECTS:
        raise ValueError(
            f"dialect {dialect!r} is not one of {', '.join((*DIALECTS, *ST_FAMILY))}"
        )
    if params is None:
        from analysis.kinematics.params import paper_params

        params = paper_params()
    trig = trig or ("native" if dialect == "s7-300" else "subroutine")
    if dialect == "s7-200" and trig == "native":
        raise ValueError("--trig native is not possible on the S7-200 (no ATAN/ACOS instruction)")
    prog = build_program(params, branch, trig, theta1_on_axis=theta1_on_axis)
    mmap = (mmap or default_map(dialect, prog.inputs, len(prog.outputs))).with_dialect(dialect)
    # the first-scan example target: the closed form's STARTUP_TARGET (the paper's Figure 3
    # (100, 100, 600) mm for the grabber; None: write nothing)
    start = closed_form(params.description.closed_form).startup_target(params)
    if dialect == "s7-300":
        text = emit_s7300(prog, mmap, startup_target=start, optimize=optimize)
    else:
        with_motion = motion and params.arm == "grabber"
        text = emit_s7200(
            prog, mmap, startup_target=start, motion=motion_networks(mmap) if with_motion else None
        )
    return text, mmap.to_json(allocate(prog, mmap))
