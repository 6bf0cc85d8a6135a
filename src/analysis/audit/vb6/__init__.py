"""Run the GR-1 thesis's Visual Basic 6 listing as printed, with VB6 semantics.

The thesis (``data/papers/gr1.toml``, appendix "程序清单", pp. 36-46) computes Table 5-4
with the event procedure ``Command1_Click`` and draws the cubic trajectories of section
5.4 with ``Command3_Click``. This module executes that listing, not a cleaned-up copy, so
that every printed number can be traced to the statement that produced it.

Why a small interpreter of our own
----------------------------------
No maintained Python implementation of VB6 exists. The Rust crate ``vb6interpret`` is not
Python; ``vb2py`` (last release 2020) translates VB to Python source but maps every VB
number onto a Python float or int, so it cannot show the effects this audit is about
(``Dim a, b As Single`` declaring only ``b``, float32 rounding of Singles, Integer
division giving Single, Variant String arithmetic). Adding either would also add a
dependency. The listing uses a small subset of the language, so this module implements
exactly that subset (about 40 statements and functions) and refuses anything else with
:class:`VB6SyntaxError`.

Semantics modelled (each has a test in ``tests/audit/test_vb6.py``)
-------------------------------------------------------------------
- ``Dim a, b, c As Single`` declares only ``c`` as Single; ``a`` and ``b`` are Variant
  (Empty until assigned). Undeclared names are implicit local Variants (no
  ``Option Explicit`` in the listing).
- Values carry their VB type: Integer (16 bit), Long (32 bit), Single (IEEE float32),
  Double, String, Boolean, Empty. Assignment to a typed variable converts: Single rounds
  to float32, Integer/Long round half to even and raise error 6 (Overflow) out of range,
  a String that is not numeric raises error 13 (Type mismatch).
- ``+ - *``: the result has the type of the more precise operand (Integer < Long <
  Single < Double), Single with Long gives Double; a Variant result that overflows is
  promoted (Integer -> Long -> Double), a typed one raises error 6. ``/`` gives Double,
  or Single when both operands are Integer/Single, as the VB6 reference's "/ Operator"
  page states (some VBA write-ups report Double for Integer / Integer; in the listing
  only ``Command3_Click``'s ``3 / (c * c)`` and ``2 / (c * c * c)`` are affected, by
  less than 1e-4 deg, and Table 5-4 not at all); ``x/0`` raises error 11, ``0/0``
  error 6. A Variant String in ``-``, ``*``, ``/`` is converted to Double; in ``+`` a
  Variant String and a Variant number are added, two Strings are concatenated.
- ``Sin``, ``Cos``, ``Tan`` take radians, ``Atn`` takes one argument and returns radians
  in (-pi/2, pi/2); ``Sqr`` of a negative number raises error 5; ``Abs``, ``Fix``,
  ``Int`` keep their argument's type; ``Val`` reads the leading number of a string,
  ignoring blanks, and returns Double; ``Format(x, "####.###")`` rounds half away from
  zero after reducing ``x`` to 15 significant digits (VB's Double-to-text conversion) and
  shows nothing for zeros a ``#`` does not need (``0.5`` -> ``".5"``, ``0`` -> ``"."``).
- Controls: ``TextN`` (TextBox, default property ``Text``), ``CommandN`` (CommandButton,
  default property ``Value``, so ``Command3 = False`` sets ``Command3.Value``, not
  ``Enabled``), ``FrameN``, ``PictureN`` (PictureBox; ``Cls``, ``Scale``, ``Line``,
  ``PSet``, ``Print`` and property writes are recorded, nothing is drawn).

``Exit Sub`` is modelled for the audit's corrections (a refusal that leaves the procedure).

Not modelled (the listing does not use them): arrays, user functions, ``Select Case``,
``Do`` loops, ``GoTo``, ``On Error``, Currency, Decimal, Date, Null.

Two switches give counterfactual readings used by the audit (they are not VB6):
``dim_types_all=True`` applies a Dim list's ``As`` type to every name in the list, and
``trig_degrees=True`` makes ``Sin``/``Cos``/``Tan`` read their argument in degrees.

The thesis's listing itself, its one repair and a run of its 计算 button on Table 5-3 are
the GR-1's (:mod:`analysis.audit.papers.gr1.listing`: ``listing``, ``run_command1``).

The interpreter is split by stage: :mod:`~analysis.audit.vb6.values` (types, conversions,
operators), :mod:`~analysis.audit.vb6.functions` (built-ins), :mod:`~analysis.audit.vb6.lexer`,
:mod:`~analysis.audit.vb6.parser` and :mod:`~analysis.audit.vb6.form` (the run-time); their
public names are imported here.
"""

from __future__ import annotations

from typing import Any

# ``X as X``: the interpreter's other public names, importable from here as before
from analysis.audit.vb6.form import Control as Control
from analysis.audit.vb6.form import VB6Form
from analysis.audit.vb6.functions import vb_format, vb_val
from analysis.audit.vb6.lexer import Token as Token
from analysis.audit.vb6.lexer import tokenize as tokenize
from analysis.audit.vb6.parser import Parser as Parser
from analysis.audit.vb6.values import BOOLEAN as BOOLEAN
from analysis.audit.vb6.values import DOUBLE as DOUBLE
from analysis.audit.vb6.values import EMPTY as EMPTY
from analysis.audit.vb6.values import EMPTY_VALUE as EMPTY_VALUE
from analysis.audit.vb6.values import INTEGER as INTEGER
from analysis.audit.vb6.values import LONG as LONG
from analysis.audit.vb6.values import SINGLE as SINGLE
from analysis.audit.vb6.values import STRING as STRING
from analysis.audit.vb6.values import VARIANT as VARIANT
from analysis.audit.vb6.values import Value, VB6Error, VB6SyntaxError
from analysis.audit.vb6.values import binary as binary
from analysis.audit.vb6.values import coerce as coerce
from analysis.audit.vb6.values import to_number as to_number
from analysis.audit.vb6.values import to_string as to_string
from analysis.audit.vb6.values import truthy as truthy
from analysis.audit.vb6.values import unary_minus as unary_minus

__all__ = [
    "VB6Error",
    "VB6Form",
    "VB6SyntaxError",
    "Value",
    "run",
    "vb_format",
    "vb_val",
]

def run(
    source: str,
    sub: str,
    inputs: dict[str, Any] | None = None,
    *,
    form: VB6Form | None = None,
    **options: bool,
) -> dict[str, Any]:
    """Run event procedure ``sub`` of ``source`` after typing ``inputs`` into TextBoxes.

    Returns ``{"locals", "module", "text", "writes", "controls", "form"}``: the
    procedure's local variables and the module variables as ``{name: Value}``, every
    TextBox's Text, the ordered property writes ``(control, property, value)``, each
    control's properties and log, and the :class:`VB6Form` (pass it back as ``form`` to
    run another procedure on the same state, e.g. ``Command3_Click`` after
    ``Command1_Click``). ``options`` are :class:`VB6Form`'s switches.
    """
    form = form or VB6Form(source, **options)
    n_writes = len(form.writes)
    form.set_text(inputs or {})
    locals_ = form.call(sub)
    return {
        "locals": locals_,
        "module": {v[0]: v[2] for v in form.module_vars.values()},
        "text": form.text(),
        "writes": form.writes[n_writes:],
        "controls": {
            c.name: {"props": dict(c.props), "log": c.log} for c in form.controls.values()
        },
        "form": form,
    }
