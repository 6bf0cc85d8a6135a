"""PLC code for the paper's IK (Figures 3-6, eqs. 6-22): one IR, a printer per dialect, engines.

Modules, low to high: :mod:`.approx` (ATAN2/ACOS for the S7-200 and their measured error),
:mod:`.model` (the program as one function; its float32 prediction), :mod:`.instr` (the
instructions), :mod:`.ir` (the program built from an arm), :mod:`.cpus`, :mod:`.mapdoc` and
:mod:`.memmap` (target CPUs, MAP.json, memory layout), :mod:`.printer` (the printers' base),
:mod:`.s7200` (S7-200 STL), :mod:`.awl` (S7-300 AWL), :mod:`.st` (ST, SCL), :mod:`.plcopen`
(PLCopen XML), :mod:`.emit` (the S7 entry points),
:mod:`.dialects` (the registry), :mod:`.generate` (the ``stl`` command), :mod:`.motion` (PTO
networks), :mod:`.translate` (S7-200 STL -> AWL), :mod:`.runner` (awlsim), :mod:`.engines`
(``stl-run``), :mod:`.targets` and :mod:`.sweep` (test targets), :mod:`.verify` (comparison),
:mod:`.paper_listings` (the paper's own STL executed).
"""
