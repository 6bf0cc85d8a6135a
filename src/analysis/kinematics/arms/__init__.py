"""One closed form per arm, each written once against a math namespace, and the typed
contract every closed form is held to when it loads (:class:`ClosedForm`).

A closed-form module (``analysis.kinematics.arms.<name>``) provides:

==================  =====================================================================
``BRANCHES``        branch names, the default (the paper's) first
``INPUTS``          names of the target's values, 1 to 6 (``px, py, pz``: a point)
``INPUT_UNITS``     their units, ``"mm"`` (a coordinate) or ``"rad"`` (an angle)
``STATUSES``        the refusals it can give (:class:`~analysis.kinematics.status.Status`;
                    their words are ``STATUS_TEXT``); joint limits and non-finite inputs
                    are the shared solver's and the PLC's, not the closed form's
``STARTUP_TARGET``  the target a generated PLC program writes on its first scan: a tuple
                    of ``len(INPUTS)`` numbers in ``INPUT_UNITS``, ``None`` (write
                    nothing), or a function of the parameters returning either
``check(P)``        reject unusable parameters (ValueError naming the value)
``geometry(P)``     named points and radii for messages and figures
``ik(m, p, P, *, tol, ...)``  the branches, the refusal conditions in priority order and
                    the signed distance outside the reach (below)
``refusal(status, p, P, *, tol, distance)``  the one-line reason and the limit crossed
==================  =====================================================================

and, optionally:

==================  =====================================================================
``fk(m, q, P)``     forward kinematics of an arm that is not a D-H chain (a closed chain:
                    the picker): ``{"frames": [point, ...], "rotation": 3x3 rows,
                    "valid": condition}`` with the tool point last (points in drawing
                    order), and optionally ``"joints"`` {name: value}: every joint of the
                    chain, the passive ones too (revolute, rad); without ``fk`` the
                    description's D-H rows are the FK
``fk_refusal(q, P)``  the reason one configuration (n,) has no pose, where ``fk``'s
                    ``"valid"`` condition is false (the picker's sliders where link 5
                    cannot close)
``sample_q(rng, n, P, bounds)``  candidate configurations (n, n_joints) for
                    :func:`analysis.kinematics.sampling.sample_q` when uniform draws
                    within the joint limits are not configurations of the arm (the
                    palletizer keeps its gripper level)
==================  =====================================================================

``ik`` returns a dict: ``branches`` {name: n joint values}, ``refusals`` [(Status,
condition), ...] of the target, optionally ``branch_refusals`` {name: [(Status, condition),
...]} for what only some branches cannot do, ``outside`` (signed distance [mm] outside the
reachable set, > 0 unreachable), and anything else it wants to report (the GR-1's
``off_plane``). Its keyword options besides ``tol`` are read from its signature:
``axis_tol`` (distance [mm] to a singular set; default ``tol``), ``margin_rad`` (a band
[rad] taken off the arm's own angular tolerances) and ``theta1_on_axis`` (the waist angle
on the base axis) are passed only to a closed form that declares them, so an arm without
an angular tolerance does not carry an unused ``margin_rad``.
:meth:`ClosedForm.solve` calls it and returns a typed :class:`IKResult`.

Tolerances: a target up to ``tol`` [mm] outside a reach shell is put on it; a target within
``axis_tol`` [mm] of a singular set (the base axis, a wrist on the shoulder) is refused
there or, with ``theta1_on_axis``, taken as on it. The generated PLC programs pass a
negative ``tol``, a larger ``axis_tol`` and a positive ``margin_rad``
(:mod:`analysis.plc.model`): they refuse a band around every boundary, so float32
arithmetic never accepts what Python refuses.

To add an arm: write its description (``data/arms/<name>.toml``, or a file anywhere), and
either name an existing closed form in it (``closed_form = "grabber"`` serves every 3R arm
of that shape, whatever its lengths) or write a module with the names above: here
(``analysis/kinematics/arms/<name>.py``), or next to the description
(``closed_form = "<file>.py"``, a file in the description's folder: such a description
runs code). When the arm loads (:func:`analysis.kinematics.loader.load_arm`, the one place
that picks a closed form), :meth:`ClosedForm.probe` records its
``ik`` once with the parameters: a closed form that the recorder cannot follow (Python's
``if`` on a value, ``math.sqrt``) is refused then, with the reason, instead of breaking the
compiled and PLC backends later.
"""

from __future__ import annotations

import importlib
import inspect
import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from functools import cache
from types import ModuleType
from typing import Any, NamedTuple

from analysis.kinematics.status import STATUS_TEXT, Status
from analysis.kinematics.trace import Graph, TraceOps

__all__ = [
    "INPUT_UNIT_NAMES",
    "MAX_INPUTS",
    "OPTIONS",
    "ClosedForm",
    "IKResult",
    "check_module",
    "from_file",
    "from_module",
    "known",
]

MAX_INPUTS = 6
"""Most values a target may have: a pose (a point and three angles)."""
INPUT_UNIT_NAMES = ("mm", "rad")
OPTIONS = ("axis_tol", "margin_rad", "theta1_on_axis", "precise")
"""The shared keyword options of ``ik`` (module docstring); a closed form may add its own
(the GR-1's ``orientation_tol``). ``precise=True`` asks for the float64 backends' formulas
where a closed form has a better conditioned one than its PLC program's (the GR-1's and the
derived arms' elbow from 1 -/+ cos in factored form): the solver body
(:func:`analysis.kinematics.solution.solve_body`) passes it; the PLC programs and their
float32 model keep the form that is bit-exact on awlsim."""
_SHARED_STATUSES = (Status.OK, Status.JOINT_LIMITS, Status.INVALID)

_REQUIRED = {
    "BRANCHES": "branch names, the default first",
    "INPUTS": "names of the target's values",
    "INPUT_UNITS": "units of INPUTS, 'mm' or 'rad' each",
    "STATUSES": "the refusal statuses ik can give",
    "STARTUP_TARGET": "the PLC's first-scan target (a tuple, None, or a function of P)",
    "check": "check(P): reject unusable parameters",
    "geometry": "geometry(P): named points and radii",
    "ik": "ik(m, p, P, *, tol, ...): the branches and refusals",
    "refusal": "refusal(status, p, P, *, tol, distance): the reason and the limit",
}
_OPTIONAL = ("fk", "fk_refusal", "sample_q")


class IKResult(NamedTuple):
    """What a closed form's ``ik`` returned, checked and completed.

    Attributes
    ----------
    branches : dict of str to tuple
        Joint values per branch, in the order of ``BRANCHES`` [rad | mm].
    refusals : tuple of (Status, condition)
        The target's refusals in priority order (the first that holds is its status).
    branch_refusals : dict of str to tuple of (Status, condition)
        Every branch, with what only that branch cannot do (empty for most arms).
    outside : value
        Signed distance outside the reachable set [mm] (> 0 unreachable).
    extra : dict
        Anything else the closed form reported (the GR-1's ``off_plane``, ``wrist``).
    """

    branches: dict
    refusals: tuple
    branch_refusals: dict
    outside: Any
    extra: dict


@dataclass(frozen=True, eq=False)
class ClosedForm:
    """A closed-form module checked against the contract (see the module docstring).

    Build it with :func:`check_module`; an error names the missing or malformed piece.
    Attributes the contract does not name (``ORIENTATION_TOL_RAD``, ``PROJECTION_HINT``)
    are read from the module; ``BRANCHES`` and ``INPUTS`` too, as the module spells them.
    """

    name: str
    module: ModuleType = field(repr=False)
    branches: tuple[str, ...]
    inputs: tuple[str, ...]
    input_units: tuple[str, ...]
    statuses: tuple[Status, ...]
    options: frozenset[str]
    """Keyword options ``ik`` takes besides ``tol``."""
    _startup: Any = field(repr=False)
    check: Callable = field(repr=False)
    geometry: Callable = field(repr=False)
    refusal: Callable = field(repr=False)
    fk: Callable | None = field(repr=False, default=None)
    propose: Callable | None = field(repr=False, default=None)
    """The module's ``sample_q`` hook (candidate configurations), or None."""

    def __getattr__(self, name: str):
        if name.startswith("__") and name != "__name__":
            raise AttributeError(name)
        return getattr(self.module, name)

    # --- the contract's derived facts --------------------------------------------------------
    @property
    def status_words(self) -> dict[str, str]:
        """``{word: meaning}`` of the refusals this closed form gives (``STATUS_TEXT``)."""
        return {STATUS_TEXT[s]: s.name.lower().replace("_", " ") for s in self.statuses}

    @property
    def chain(self) -> str:
        """``"closed"`` if the closed form gives the FK itself (a closed chain), else ``"dh"``
        (the description's D-H rows)."""
        return "closed" if self.fk is not None else "dh"

    def startup_target(self, P) -> tuple[float, ...] | None:
        """The first-scan target for parameters ``P`` (in ``INPUT_UNITS``), or None."""
        value = self._startup(P) if callable(self._startup) else self._startup
        return _check_startup(self.name, value, len(self.inputs))

    # --- solving -------------------------------------------------------------------------------
    def solve(
        self,
        m,
        p,
        P,
        *,
        tol,
        axis_tol=None,
        margin_rad: float = 0.0,
        theta1_on_axis=None,
        precise: bool = False,
        **extra,
    ) -> IKResult:
        """Run ``ik`` in namespace ``m`` with the options it declares; return an
        :class:`IKResult` with every branch's refusals (empty where it has none).

        ``axis_tol``, ``margin_rad`` and ``precise`` are dropped for a closed form that has
        no singular set, angular tolerance or better conditioned form to apply them to;
        ``theta1_on_axis`` for one without a base-axis singularity is an error (it would be
        silently ignored otherwise).
        """
        opts = dict(extra)
        unknown = set(opts) - self.options
        if unknown:
            raise ValueError(f"closed form {self.name!r} takes no option {sorted(unknown)}")
        if theta1_on_axis is not None:
            if "theta1_on_axis" not in self.options:
                raise ValueError(
                    f"arm closed form {self.name!r} has no base-axis singularity: "
                    "theta1_on_axis does not apply"
                )
            opts["theta1_on_axis"] = theta1_on_axis
        if axis_tol is not None and "axis_tol" in self.options:
            opts["axis_tol"] = axis_tol
        if margin_rad and "margin_rad" in self.options:
            opts["margin_rad"] = margin_rad
        if precise and "precise" in self.options:
            opts["precise"] = True
        raw = self.module.ik(m, p, P, tol=tol, **opts)
        return self._result(raw)

    def _result(self, raw) -> IKResult:
        where = f"closed form {self.name!r}: ik"
        if not isinstance(raw, Mapping):
            raise TypeError(f"{where} returned {type(raw).__name__}, not a dict")
        for key in ("branches", "refusals", "outside"):
            if key not in raw:
                raise ValueError(f"{where} returned no {key!r}")
        branches = raw["branches"]
        if tuple(branches) != self.branches:
            raise ValueError(
                f"{where} returned branches {tuple(branches)}, BRANCHES says {self.branches}"
            )
        sizes = {len(v) for v in branches.values()}
        if len(sizes) != 1:
            raise ValueError(f"{where}: branches have different joint counts {sorted(sizes)}")
        per_branch = dict(raw.get("branch_refusals", {}))
        stray = set(per_branch) - set(self.branches)
        if stray:
            raise ValueError(f"{where}: branch_refusals for unknown branches {sorted(stray)}")
        refusals = tuple(raw["refusals"])
        per = {b: tuple(per_branch.get(b, ())) for b in self.branches}
        for code, _ in (*refusals, *(r for v in per.values() for r in v)):
            if code not in self.statuses:
                raise ValueError(
                    f"{where} refuses with {Status(code).name}, which STATUSES does not list"
                )
        extra = {k: v for k, v in raw.items() if k not in _RESULT_KEYS}
        return IKResult(dict(branches), refusals, per, raw["outside"], extra)

    def probe(self, params, n_joints: int | None = None) -> int:
        """Record ``ik`` once with the recorder of the compiled and PLC backends; return the
        number of joint values per branch.

        ``params`` is the parameters' names (recorded as inputs, as the compiled kernel
        does) or a mapping of their values (constants, as in the PLC program). Raises
        ValueError naming the closed form and what went wrong: a construct the recorder
        cannot follow (Python's ``if``/``and``/``or`` on a value, ``math`` functions instead
        of ``m``'s), or a joint count other than ``n_joints``.
        """
        g = Graph()
        m = TraceOps(g)
        p = tuple(g.input(k) for k in self.inputs)
        if isinstance(params, Mapping):
            P = dict(params)
        else:
            clash = set(params) & {*self.inputs, "tol"}
            if clash:
                raise ValueError(
                    f"closed form {self.name!r}: parameter name(s) {sorted(clash)} are also "
                    "input names; rename them"
                )
            P = {k: g.input(k) for k in params}
        try:
            res = self.solve(m, p, P, tol=g.input("tol"))
        except (TypeError, AttributeError) as exc:
            raise ValueError(
                f"closed form {self.name!r} cannot be recorded for the compiled and PLC "
                f"backends ({type(exc).__name__}: {exc}); write every operation on the "
                "target and the parameters through the namespace m (m.sqrt, m.atan2, "
                "m.select, ...)"
            ) from None
        n = len(next(iter(res.branches.values())))
        if n_joints is not None and n != n_joints:
            raise ValueError(
                f"closed form {self.name!r} gives {n} joint values per branch; the "
                f"description has {n_joints} joints"
            )
        return n


_RESULT_KEYS = ("branches", "refusals", "branch_refusals", "outside")


def _check_startup(name: str, value, n: int) -> tuple[float, ...] | None:
    if value is None:
        return None
    try:
        values = tuple(float(v) for v in value)
    except (TypeError, ValueError):
        values = ()
    if len(values) != n or not all(math.isfinite(v) for v in values):
        raise ValueError(
            f"closed form {name!r}: STARTUP_TARGET = {value!r} must be None or {n} finite "
            f"numbers (one per input)"
        )
    return values


def _ik_options(name: str, ik) -> frozenset[str]:
    try:
        sig = inspect.signature(ik)
    except (TypeError, ValueError):
        raise ValueError(f"closed form {name!r}: ik is not a function") from None
    params = list(sig.parameters.values())
    positional = [p for p in params if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)]
    if len(positional) < 3:
        raise ValueError(f"closed form {name!r}: ik must take (m, p, P, *, tol, ...)")
    keywords = {p.name for p in params if p.kind == p.KEYWORD_ONLY}
    if "tol" not in keywords:
        raise ValueError(f"closed form {name!r}: ik must take the keyword argument tol")
    return frozenset(keywords - {"tol"})


def _names(value, what: str, name: str) -> tuple[str, ...]:
    if isinstance(value, str) or not all(isinstance(v, str) for v in value):
        raise ValueError(f"closed form {name!r}: {what} must be a tuple of names, got {value!r}")
    out = tuple(value)
    if len(set(out)) != len(out):
        raise ValueError(f"closed form {name!r}: {what} {out} repeats a name")
    return out


def check_module(name: str, mod) -> ClosedForm:
    """Check a closed-form module (or any object with the contract's names) and wrap it.

    Raises ValueError naming the first missing or malformed piece and what it is for.
    """
    missing = [k for k in _REQUIRED if not hasattr(mod, k)]
    if missing:
        what = "; ".join(f"{k} ({_REQUIRED[k]})" for k in missing)
        raise ValueError(f"closed form {name!r} lacks {what}")
    branches = _names(mod.BRANCHES, "BRANCHES", name)
    inputs = _names(mod.INPUTS, "INPUTS", name)
    if not branches:
        raise ValueError(f"closed form {name!r}: BRANCHES is empty")
    if not 1 <= len(inputs) <= MAX_INPUTS:
        raise ValueError(
            f"closed form {name!r}: {len(inputs)} INPUTS; a target has 1 to {MAX_INPUTS} values"
        )
    units = tuple(mod.INPUT_UNITS)
    if len(units) != len(inputs) or not set(units) <= set(INPUT_UNIT_NAMES):
        raise ValueError(
            f"closed form {name!r}: INPUT_UNITS = {units!r} must give one of "
            f"{INPUT_UNIT_NAMES} per input {inputs}"
        )
    try:
        statuses = tuple(Status(s) for s in mod.STATUSES)
    except (TypeError, ValueError):
        raise ValueError(
            f"closed form {name!r}: STATUSES = {mod.STATUSES!r} must be Status codes"
        ) from None
    shared = [s.name for s in statuses if s in _SHARED_STATUSES]
    if shared:
        raise ValueError(
            f"closed form {name!r}: STATUSES lists {shared}, which the shared solver and "
            "the PLC give, not a closed form"
        )
    for k in ("check", "geometry", "ik", "refusal", *(o for o in _OPTIONAL if hasattr(mod, o))):
        if not callable(getattr(mod, k)):
            raise ValueError(f"closed form {name!r}: {k} is not a function")
    options = _ik_options(name, mod.ik)
    startup = mod.STARTUP_TARGET
    if not callable(startup):
        _check_startup(name, startup, len(inputs))
    return ClosedForm(
        name,
        mod,
        branches,
        inputs,
        units,
        statuses,
        options,
        startup,
        mod.check,
        mod.geometry,
        mod.refusal,
        getattr(mod, "fk", None),
        getattr(mod, "sample_q", None),
    )


@cache
def from_module(name: str) -> ClosedForm:
    """The closed form ``analysis.kinematics.arms.<name>``, checked against the contract
    (module docstring); ValueError naming the modules there if there is none.

    Only the loader (:func:`analysis.kinematics.loader.load_arm`) calls this: an arm holds
    its closed form, and nothing downstream looks one up by name."""
    if not isinstance(name, str) or not name.isidentifier() or name.startswith("_"):
        raise ValueError(
            f"closed form {name!r} is not a module name ({', '.join(known())}) or a .py file "
            "next to the description"
        )
    try:
        mod = importlib.import_module(f"analysis.kinematics.arms.{name}")
    except ModuleNotFoundError as exc:
        if exc.name != f"analysis.kinematics.arms.{name}":
            raise
        raise ValueError(
            f"no closed form {name!r} in analysis.kinematics.arms (known: {', '.join(known())})"
        ) from None
    return check_module(name, mod)


def known() -> list[str]:
    """The closed-form modules of this package."""
    import pkgutil

    return sorted(m.name for m in pkgutil.iter_modules(__path__) if not m.name.startswith("_"))


CLOSED_FORM_BYTES = 1 << 20
"""The most of a closed-form file read (1 MiB, as for a description): the file is read
bounded and only if regular (:func:`analysis.safe_io.read_text`) before any of it runs."""


@cache
def from_file(path: str, stamp: tuple) -> ClosedForm:
    """The closed form in the Python file ``path`` (a user's own, ``closed_form =
    "my_arm.py"`` next to the description), run once per version ``stamp`` of the file as
    a module of its own. The loader decides which files may be run
    (:func:`analysis.kinematics.loader.closed_form_file`). The source is read bounded
    (:data:`CLOSED_FORM_BYTES`) and compiled here rather than imported, so that nothing is
    written beside it (an import writes ``__pycache__`` into the user's folder)."""
    import hashlib
    import sys
    import types

    from analysis.safe_io import read_text

    source = read_text(path, CLOSED_FORM_BYTES, "closed form")
    digest = hashlib.sha256(f"{path}{stamp}".encode()).hexdigest()[:16]
    mod = types.ModuleType(f"analysis_user_closed_form_{digest}")
    mod.__file__ = path
    sys.modules[mod.__name__] = mod
    try:
        exec(compile(source, path, "exec", dont_inherit=True), mod.__dict__)  # asked for: README
    except Exception as exc:  # the user's code: report it as a load error, with its reason
        del sys.modules[mod.__name__]
        raise ValueError(
            f"closed form {path} does not import: {type(exc).__name__}: {exc}"
        ) from None
    return check_module(path, mod)
