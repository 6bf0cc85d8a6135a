"""PLC code for the paper's IK (Figures 3-6, eqs. 6-22): one IR, two emitters, awlsim runs.

Modules: :mod:`.ir` (program representation, generated from ``ArmParams``), :mod:`.approx`
(ATAN2/ACOS for the S7-200 and their measured error), :mod:`.emit` (S7-200 STL, S7-300
AWL), :mod:`.memmap` (MAP.json), :mod:`.motion` (PTO networks), :mod:`.translate`
(S7-200 STL -> AWL), :mod:`.runner` (awlsim), :mod:`.verify` (targets, comparison),
:mod:`.paper_listings` (the paper's own STL executed), :mod:`.cli` (``stl`` command).
"""

from analysis.plc.emit import emit_s7200, emit_s7300
from analysis.plc.ir import Program, build_program
from analysis.plc.memmap import MemoryMap, default_map

__all__ = ["MemoryMap", "Program", "build_program", "default_map", "emit_s7200", "emit_s7300"]
