"""Printers as classes: one per target, one method per operation (SymPy's printing design).

Every generated backend prints the operations of the one table
:data:`analysis.kinematics.ops.OPS`: the compiled kernel
(:class:`analysis.kinematics.compiled.KernelPrinter`), the S7-200 and S7-300 listings
(:mod:`analysis.plc.s7200`, :mod:`analysis.plc.awl`), IEC 61131-3 ST and Siemens SCL
(:mod:`analysis.plc.st`), PLCopen XML (:mod:`analysis.plc.plcopen`).
:meth:`Printer.doprint` dispatches an operation to the printer's ``_print_<op>`` method;
without one, an operation the class names in ``known_functions`` goes to
``_print_function``, and an infix operation of the table (``arith`` and ``compare`` rows)
with an entry in ``infix`` to ``_print_infix``; anything else reaches :meth:`emptyPrinter`,
which refuses it naming the target and the operation. Adding a target is one subclass;
adding an operation is one row in the table and a method (or a ``known_functions`` entry)
in each printer that can express it.

Why not SymPy's own ``CodePrinter``: the programs are printed from a recording of the closed
form (:mod:`analysis.kinematics.trace`), not from SymPy expressions, which SymPy would
reorder (see that module); only the dispatch design is taken.
"""

from __future__ import annotations

from typing import ClassVar

from analysis.kinematics.ops import OPS

__all__ = ["INFIX", "ExpressionPrinter", "Printer"]

INFIX = {op: OPS[op].symbol for op in ("add", "sub", "mul", "div", "lt", "le", "gt", "ge")}
"""The op table's arithmetic and compares with the symbols every expression language shares."""


class Printer:
    """Base of every printer (module docstring).

    Attributes
    ----------
    target : str
        Named in refusals ("the S7-200", "IEC 61131-3 ST").
    known_functions : dict of str to str
        Operation -> the target's function or instruction name.
    infix : dict of str to str
        Operation -> the target's infix symbol (default: the table's ``symbol``).
    """

    target = "this printer"
    known_functions: ClassVar[dict[str, str]] = {}
    infix: ClassVar[dict[str, str]] = {}

    def doprint(self, op: str, *args, **kwargs):
        """Print operation ``op`` on ``args`` (printed operands, or an instruction)."""
        method = getattr(self, f"_print_{op}", None)
        if method is not None:
            return method(*args, **kwargs)
        if op in self.known_functions:
            return self._print_function(op, *args, **kwargs)
        if op in self.infix:
            return self._print_infix(op, *args, **kwargs)
        return self.emptyPrinter(op, *args, **kwargs)

    def symbol(self, op: str) -> str:
        """The infix symbol of ``op`` in this target."""
        return self.infix.get(op) or OPS[op].symbol

    def _print_function(self, op: str, *args, **kwargs):
        raise NotImplementedError(f"{type(self).__name__} prints no functions")

    def _print_infix(self, op: str, *args, **kwargs):
        raise NotImplementedError(f"{type(self).__name__} prints no infix operations")

    def emptyPrinter(self, op: str, *args, **kwargs):
        """The fallback: refuse ``op`` (ValueError naming the target and the operation)."""
        known = op in OPS or op in getattr(self, "control", ())
        what = "has no instruction for" if known else "does not know the operation"
        raise ValueError(f"{self.target} {what} {op!r}")


class ExpressionPrinter(Printer):
    """A printer of one expression per operation of a recording (the compiled kernel's
    Python, :class:`analysis.kinematics.compiled.KernelPrinter`; JavaScript,
    :class:`analysis.app.explore_js.JsPrinter`): calls, parenthesised infix operations and
    negation alike; a subclass names its functions, its ``infix`` symbols (the table's
    arithmetic and compares, :data:`INFIX`, plus its own ``eq``, ``and``, ``or``), ``not``
    and ``select``."""

    def _print_function(self, op, *args):
        return f"{self.known_functions[op]}({', '.join(args)})"

    def _print_infix(self, op, a, b):
        return f"({a} {self.symbol(op)} {b})"

    def _print_neg(self, a):
        return f"(-{a})"
