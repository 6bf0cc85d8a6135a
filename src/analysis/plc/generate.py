"""A PLC program and its memory map, as text files for a dialect (the ``stl`` command).

:func:`generate` builds the program of an arm's closed form (:func:`analysis.plc.ir.
build_program`), allocates its variables (:mod:`.memmap`) and prints it (:mod:`.emit`). For
the paper's arm on the S7-200 it adds the motion networks that turn the counts into stepper
moves on the CPU 224's two PTO channels (:mod:`.motion`, Table 2's I/O). The MAP.json it
returns (:meth:`~.memmap.MemoryMap.document`) names every signal with its unit, every status
code the program writes, every memory range the program text uses and what the first scan
does; every address is checked against the target CPU's memory (ValueError naming the CPU
and the limit).

Start-up. By default the program writes nothing into its inputs: an HMI's target survives a
power cycle (if the CPU retains that memory) and is never replaced by an example. The
paper's Figure 3 writes its example target (100, 100, 600) mm on the first scan; pass
``startup_target="paper"`` (the closed form's ``STARTUP_TARGET``, Figure 3 for the grabber)
or three numbers to generate that network, and MAP.json says so.
"""

from __future__ import annotations

import json

from analysis.plc.emit import allocate, emit_s7200, emit_s7300
from analysis.plc.ir import Program, build_program
from analysis.plc.memmap import DIALECTS, MemoryMap, default_map
from analysis.plc.motion import MOTION_STARTUP, motion_networks, motion_uses

__all__ = ["generate", "input_units", "status_codes"]



def input_units(arm) -> dict[str, str]:
    """Input name -> unit (:attr:`analysis.kinematics.arm.Arm.input_units`)."""
    return dict(zip(arm.inputs, arm.input_units, strict=True))


def status_codes(program: Program) -> list[int]:
    """The status codes ``program`` writes: 0, and every refusal's (``accept``'s list in the
    structured IR, ``seti status k`` once flattened)."""
    codes = {0}
    for i in program.body:
        if i.op == "accept":
            codes |= {int(k) for k in i.args[0]}
        elif i.op in ("refuse", "notfinite"):
            codes.add(int(i.args[1]))
        elif i.op == "seti" and i.dst == "status":
            codes.add(int(i.args[0]))
    return sorted(codes)


def _startup_values(arm, startup_target):
    if startup_target is None:
        return None
    if isinstance(startup_target, str):
        if startup_target != "paper":
            raise ValueError(f"startup_target {startup_target!r}: expected 'paper' or numbers")
        start = arm.startup_target
        if start is None:
            raise ValueError(f"arm {arm.name} names no example target (STARTUP_TARGET)")
        return start
    return tuple(float(v) for v in startup_target)


def _startup_doc(dialect, prog, start, units, with_motion) -> dict[str, str]:
    doc = {}
    if start is None:
        doc["inputs"] = (
            "not written: the program computes from whatever the inputs hold (an HMI's value "
            "survives a restart only where the CPU retains that memory)"
        )
    else:
        where = "the first scan (SM0.1)" if dialect == "s7-200" else "OB100 (start-up)"
        vals = ", ".join(f"{k} = {v:g} {units[k]}" for k, v in zip(prog.inputs, start, strict=True))
        doc["inputs"] = (
            f"written on {where} with the example target {vals} (the paper's Figure 3): a "
            "value the HMI wrote before the restart is overwritten"
        )
    doc["outputs"] = (
        "c1..cn keep their value until the first scan that solves a target; status and the "
        "reach flag are written on every scan"
    )
    if with_motion:
        doc["motion"] = MOTION_STARTUP
    return doc


def generate(
    dialect: str = "s7-300",
    branch: str | None = None,
    trig: str | None = None,
    mmap: MemoryMap | None = None,
    arm=None,
    motion: bool = True,
    theta1_on_axis: float | None = None,
    optimize: bool = True,
    startup_target=None,
    cpu: str | None = None,
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
    arm : Arm, optional
        The arm (:class:`analysis.kinematics.arm.Arm`; default: the paper's, Table 3).
    motion : bool
        S7-200 and the paper's arm only: append the PTO motion networks.
    theta1_on_axis : float, optional
        Waist angle [rad] on the base axis (default: refuse such targets, status 3).
    optimize : bool
        S7-300: the AWL after :func:`~.peephole.optimize_awl` (fewer loads and stores, the
        same results). The S7-200 text is never rewritten.
    startup_target : None, "paper" or numbers
        What the first scan writes into the inputs: nothing (default), the closed form's
        example (``"paper"``: Figure 3's (100, 100, 600) mm for the grabber), or these
        values (in the inputs' units).
    cpu : str, optional
        Target CPU (:data:`~.memmap.CPUS`; default the map's, else CPU 224 / CPU 315-2 DP).
    """
    from analysis.plc.st_generate import ST_FAMILY, generate_st

    if dialect in ST_FAMILY:  # IEC 61131-3 ST, SCL, PLCopen XML: no addresses, no motion
        if mmap is not None:
            raise ValueError(f"a memory layout names addresses; {dialect} has none")
        return generate_st(dialect, branch, trig, arm, theta1_on_axis)
    if dialect not in DIALECTS:
        raise ValueError(f"dialect {dialect!r} is not one of {', '.join((*DIALECTS, *ST_FAMILY))}")
    if arm is None:
        from analysis.kinematics.arm import paper_arm

        arm = paper_arm()
    trig = trig or ("native" if dialect == "s7-300" else "subroutine")
    if dialect == "s7-200" and trig == "native":
        raise ValueError("--trig native is not possible on the S7-200 (no ATAN/ACOS instruction)")
    prog = build_program(arm, branch, trig, theta1_on_axis=theta1_on_axis)
    mmap = (mmap or default_map(dialect, prog.inputs, len(prog.outputs))).with_dialect(dialect)
    if cpu is not None:
        mmap = mmap.with_cpu(cpu)
    start = _startup_values(arm, startup_target)
    units = input_units(arm)
    if start is not None and len(start) != len(prog.inputs):
        raise ValueError(
            f"startup_target has {len(start)} values; the program has {len(prog.inputs)} "
            f"inputs ({', '.join(prog.inputs)})"
        )
    work = allocate(prog, mmap)
    mmap.check_end(max(work.values(), default=mmap.work_base) + 3, "the work area")
    with_motion = dialect == "s7-200" and motion and arm.name == "grabber"
    if dialect == "s7-300":
        text = emit_s7300(prog, mmap, startup_target=start, optimize=optimize)
    else:
        text = emit_s7200(
            prog, mmap, startup_target=start, motion=motion_networks(mmap) if with_motion else None
        )
    uses = {"AC0": "finiteness test of the inputs (exponent bits, no REAL compare)"}
    if with_motion:
        uses.update(motion_uses())
    joints = arm.description.joints
    outputs = {
        f"c{j + 1}": {"joint": joints[j].name, "pulses_per_rev": arm.params.pulses_per_rev[j]}
        for j in range(len(prog.outputs))
    }
    doc = mmap.document(
        text,
        units=units,
        outputs=outputs,
        status_codes=status_codes(prog),
        work=work,
        uses=uses,
        startup=_startup_doc(dialect, prog, start, units, with_motion),
        arm=arm.name,
        branch=prog.branch,
    )
    return text, json.dumps(doc, indent=2, ensure_ascii=False) + "\n"
