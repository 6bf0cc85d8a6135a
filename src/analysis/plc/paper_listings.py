"""Run the paper's own STL (Figures 3-6, as transcribed in
:data:`analysis.papers.grabber.FIGURE_STL`).

The printed listings are wrapped in one OB1 (Figure 3, 4, 6, 5: Figure 5 reads theta3
from VD48, which Figure 6 writes), given the ARCTAN/ARCCOS subroutines they call (the
generated ones: the paper never lists its own), translated to AWL with
:func:`~.translate.translate_s7200` and executed on awlsim, one fresh CPU per target.
Figure 3 hard-codes the target (``MOVD 100, VD0``): for each Table 4 row the three
constants are replaced by that row's coordinates, printed form kept (``MOVD`` of an
integer). Figure 6 prints the operand ``VDD0``, which is not an S7-200 address; to run it
at all it must be read as something: COS/SIN of ``VDD0`` as theta1 (VD12) and the
products as Px (VD0), the transcriber's reading, recorded in the result.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np
import pandas as pd

from analysis.plc.emit import emit_s7200_subroutines
from analysis.plc.ir import Instr, Subroutine, acos_subroutine, atan2_subroutine
from analysis.plc.memmap import default_map
from analysis.plc.runner import AwlRunner
from analysis.plc.translate import translate_s7200

__all__ = ["PaperRun", "figure_text", "paper_program", "run_paper_listings"]


def _arctan_subroutine(number: int = 3) -> Subroutine:
    body = (
        Instr("network", None, ("ARCTAN(X) = ATAN2(X, 1.0) [rad]",)),
        Instr("mov", "ONE", (1.0,)),
        Instr("call", None, ("ATAN2", ("X", "ONE"), ("R",))),
    )
    return Subroutine(
        "ARCTAN", number, ("X",), ("R",), ("ONE",), body, "ARCTAN(X) [rad] (generated)"
    )


def _arccos_subroutine(number: int = 4) -> Subroutine:
    s = acos_subroutine(number)
    return Subroutine(
        "ARCCOS", number, s.inputs, s.outputs, s.temps, s.body, "ARCCOS(C) [rad] (generated)"
    )


def _figure(n: int) -> str:
    from analysis.papers import grabber as paper

    return paper.FIGURE_STL[n]


def figure_text(
    figure: int,
    target=(100, 100, 600),
    real_inputs: bool = False,
    vdd0: dict[str, str] | None = None,
    degrees: bool = False,
) -> str:
    """One figure's transcribed STL with the target and the VDD0 reading substituted.

    See :func:`paper_program` for the parameters. Figure 3's three ``MOVD n, VDx`` get
    the target's coordinates (as printed: integers; or ``MOVR x`` with ``real_inputs``).
    ``degrees`` repairs Figure 4's unit only (the register's grabber-stl-degrees and
    grabber-stl-vd12): its ``/R 360.0, VD12`` dropped, ``VD16`` scaled by 57.29578 deg/rad
    before ``/R 360.0, VD16``, so that c1 is theta1 / 360 x 4000 and the figure's other
    defects stand apart.
    """
    text = _figure(figure)
    if degrees and figure == 4:
        lines = [ln for ln in text.splitlines() if not re.match(r"/R\s+360\.0,\s*VD12", ln)]
        i = next(k for k, ln in enumerate(lines) if re.match(r"MOVR\s+VD12,\s*VD16", ln))
        text = "\n".join([*lines[: i + 1], "*R     57.29578, VD16", "/R     360.0, VD16",
                          *lines[i + 1 :]])  # fmt: skip
    if figure == 3:
        vals = iter(target)

        def sub(m):
            v = next(vals)
            if real_inputs:
                return f"MOVR   {float(v)!r}, {m.group(2)}"
            return f"MOVD   {int(v)}, {m.group(2)}"

        text = re.sub(r"MOVD\s+(-?\d+),\s*(VD\d+)", sub, text)
    if vdd0:
        out = []
        for ln in text.splitlines():
            op = ln.split()[0] if ln.split() else ""
            if "VDD0" in ln and op in vdd0:
                ln = ln.replace("VDD0", vdd0[op])
            out.append(ln)
        text = "\n".join(out)
    return text


def paper_program(
    target=(100, 100, 600),
    figures=(3, 4),
    real_inputs: bool = False,
    vdd0: dict[str, str] | None = None,
    degrees: bool = False,
) -> str:
    """S7-200 text of the paper's figures in one OB1 plus the generated subroutines.

    Parameters
    ----------
    target : 3 numbers
        Replaces the Figure 3 constants (100, 100, 600).
    figures : sequence of int
        Which figures, in execution order (e.g. (3, 4, 6, 5)).
    real_inputs : bool
        Write the target with ``MOVR x.0`` instead of the printed ``MOVD x`` (integer bits).
    vdd0 : dict, optional
        How to read Figure 6's ``VDD0``, by instruction, e.g.
        ``{"COS": "VD12", "SIN": "VD12", "*R": "VD0", "MOVR": "VD0"}``.
    degrees : bool
        Repair Figure 4's unit only (:func:`figure_text`).
    """
    lines = [
        "ORGANIZATION_BLOCK MAIN:OB1",
        "TITLE=paper Figures " + ", ".join(map(str, figures)),
        "BEGIN",
    ]
    for k, f in enumerate(figures, 1):
        lines.append(f"Network {k} // Figure {f}")
        lines += figure_text(f, target, real_inputs, vdd0, degrees).splitlines()
    lines.append("END_ORGANIZATION_BLOCK")
    subs = [atan2_subroutine(1), _arctan_subroutine(3), acos_subroutine(2), _arccos_subroutine(4)]
    return "\r\n".join(lines) + "\r\n" + emit_s7200_subroutines(subs)


@dataclass(frozen=True)
class PaperRun:
    """What the printed program leaves in its result addresses, per Table 4 target."""

    table: pd.DataFrame
    assumptions: tuple[str, ...]


def run_paper_listings(
    targets,
    figures=(3, 4),
    real_inputs: bool = False,
    vdd0=None,
    outputs=(("c1", 16),),
    reals=(("VD12", 12),),
) -> PaperRun:
    """Execute the paper's figures on awlsim for each target (a fresh CPU each).

    Returns
    -------
    PaperRun
        ``table`` with the target, the DINT outputs (e.g. c1 = VD16) and REAL values
        (e.g. VD12), and whether the CPU stopped (NaN in a REAL compare).
    """
    rows = []
    mmap = default_map("s7-200")
    for t in np.asarray(targets, dtype=float):
        tr = translate_s7200(paper_program(t, figures, real_inputs, vdd0))
        r = AwlRunner(tr.awl, mmap, first_scan=False)
        r.cycle()
        row = {"x_mm": t[0], "y_mm": t[1], "z_mm": t[2]}
        for name, byte in outputs:
            row[name] = r.read_dint(byte)
        for name, byte in reals:
            row[name] = r.read_real(byte)
        row["stopped"] = r.stopped
        rows.append(row)
    notes = [
        "上电置1 read as SM0.0 (always on)",
        "ARCTAN/ARCCOS: the generated subroutines (radians)",
        "ROUND: S7-200 rule (halves away from zero)",
    ]
    notes.append(
        "inputs written with MOVR (REAL)"
        if real_inputs
        else "inputs written as printed: MOVD of integers (REAL bit patterns 1e-43: denormals)"
    )
    if vdd0:
        notes.append("VDD0 read as " + ", ".join(f"{k} -> {v}" for k, v in vdd0.items()))
    return PaperRun(pd.DataFrame(rows), tuple(notes))
