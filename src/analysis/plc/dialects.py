"""The PLC dialects, one registry: name -> printer class (as SymPy's ``c_code_printers``).

Every choice and dispatch reads this mapping: the ``stl --dialect`` choices and their help
(:mod:`analysis.app.cli`), the ``stl-run --dialect`` choices (the dialects with an engine,
:mod:`analysis.app.cli_plc`), :func:`analysis.plc.generate.generate`, the float32 model of a
dialect's arithmetic (:class:`analysis.plc.approx.PlcFloat32Ops`: its tie rule and
trigonometry) and the comparison with Python (:func:`analysis.plc.verify.compare`). A dialect
that extends another subclasses it (AWL has the S7-200 printer's shape, SCL and the PLCopen
XML extend ST). A new dialect is one :class:`~analysis.plc.printer.PlcPrinter` subclass and
one entry here.
"""

from __future__ import annotations

from analysis.plc.awl import AwlPrinter
from analysis.plc.plcopen import PlcopenXmlPrinter
from analysis.plc.printer import PlcPrinter
from analysis.plc.s7200 import S7200Printer
from analysis.plc.st import SclPrinter, StPrinter

__all__ = ["DIALECTS", "printer_class"]

DIALECTS: dict[str, type[PlcPrinter]] = {
    "s7-200": S7200Printer,
    "s7-300": AwlPrinter,
    "st": StPrinter,
    "scl": SclPrinter,
    "plcopen-xml": PlcopenXmlPrinter,
}
"""Dialect name -> its printer class (the class's ``name`` is the key)."""


def printer_class(dialect: str) -> type[PlcPrinter]:
    """The printer class of ``dialect``; ValueError naming the value and the dialects."""
    cls = DIALECTS.get(dialect) if isinstance(dialect, str) else None
    if cls is None:
        raise ValueError(f"dialect {dialect!r} is not one of {', '.join(DIALECTS)}")
    return cls
