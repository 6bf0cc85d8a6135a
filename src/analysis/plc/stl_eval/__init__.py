"""The S7-200 evaluator: STEP 7-Micro/WIN STL programs run scan by scan, and the paper's
listings read and run as the audit uses them.

* :class:`S7200` (:mod:`.cpu`), :func:`load_program` (:mod:`.loader`): a CPU 224 (or another S7-200
  CPU) running a whole program: blocks, networks, VAR sections, subroutines with
  parameters, the logic stack and power flow, ENO/AENO, SM bits, integer and REAL
  arithmetic with the System Manual's overflow, NaN and division-by-zero rules, PTO. Each
  instruction's semantics source is in :func:`instruction_table` (:mod:`.instructions`); the
  instructions run in families, one module each (:mod:`.operands`, :mod:`.bit_logic`,
  :mod:`.arithmetic`, :mod:`.program_control`, :mod:`.pulse_output`). Errors name the line, the
  block, the network and the statement (:class:`StlError`).
* :func:`parse_stl`, :func:`evaluate`, :func:`overlaps`, :func:`defs_uses`,
  :func:`invalid_operands`, :class:`VMemory` (:mod:`.legacy`): the paper's Figures 3-6 as
  listings, for the audit (``analysis.audit.grabber_stl``); :func:`evaluate` runs them on
  :class:`S7200`.
* ``python -m analysis stl-run PROGRAM --dialect s7-200 --set VD0=100.0 --read VD100:DINT``
  (:mod:`analysis.app.cli_plc`) runs a program file from the command line.
"""

from analysis.plc.stl_eval.cpu import S7200, Fault
from analysis.plc.stl_eval.instructions import INSTRUCTIONS, instruction_table
from analysis.plc.stl_eval.legacy import (
    V_BYTES,
    Instr,
    VMemory,
    arcus_library,
    defs_uses,
    dint,
    evaluate,
    invalid_operands,
    overlaps,
    parse_stl,
    real,
    real_from_bits,
    real_memory,
    span,
)
from analysis.plc.stl_eval.loader import Library, Loaded, load_program
from analysis.plc.stl_eval.operands import TYPES
from analysis.plc.stl_eval.pulse_output import PtoChannel, Train
from analysis.plc.stl_eval.syntax import StlError, parse_program

__all__ = [
    "INSTRUCTIONS",
    "S7200",
    "TYPES",
    "V_BYTES",
    "Fault",
    "Instr",
    "Library",
    "Loaded",
    "PtoChannel",
    "StlError",
    "Train",
    "VMemory",
    "arcus_library",
    "defs_uses",
    "dint",
    "evaluate",
    "instruction_table",
    "invalid_operands",
    "load_program",
    "overlaps",
    "parse_program",
    "parse_stl",
    "real",
    "real_from_bits",
    "real_memory",
    "span",
]
