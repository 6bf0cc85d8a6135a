"""The one loader: an arm description in, an :class:`~analysis.kinematics.model.Arm` out.

:func:`load_arm` is the single place that turns a description into an arm, once per version
of the description:

1. it reads the description (:func:`analysis.kinematics.description.load_description`: pure
   data, checked against the schema; nothing run, nothing looked up);
2. it picks the closed form the description names (:func:`closed_form_of`): a module of
   :mod:`analysis.kinematics.arms` (``closed_form = "grabber"``), a Python file in the
   description's own folder (``closed_form = "my_arm.py"``: such a description runs code),
   or one derived from the D-H rows (no ``closed_form``: :func:`analysis.kinematics.derive.
   derive`); a chain outside the derived families gets none, and the reason;
3. it checks it: the contract (:func:`analysis.kinematics.arms.check_module`), the
   parameters (the closed form's ``check``), one recording for the compiled and PLC
   backends (:meth:`~analysis.kinematics.arms.ClosedForm.probe`, once per closed form and
   parameter set), and the closed form against the description's own chain on sampled
   configurations (:func:`analysis.kinematics.consistency.check`);
4. it returns the arm holding the description, the closed-form object and the parameters as
   plain numbers (:class:`~analysis.kinematics.params.Params`).

Nothing downstream looks a closed form up by name again: the compiled kernels, the PLC
programs, the URDF and the explorer take it from the arm.
"""

from __future__ import annotations

import contextlib
from functools import lru_cache
from pathlib import Path

from analysis.kinematics import consistency
from analysis.kinematics.arms import ClosedForm, check_module, from_file, from_module
from analysis.kinematics.derive import NotDerivable, derive
from analysis.kinematics.description import DERIVED, ArmDescription, load_description
from analysis.kinematics.model import Arm
from analysis.kinematics.params import Params
from analysis.kinematics.schema import DescriptionError, NoDrive

__all__ = ["arm_of", "closed_form_file", "closed_form_of", "derived_arm", "load_arm",
           "paper_arm"]  # fmt: skip


def load_arm(name: str | Path = "grabber", tables: dict | None = None) -> Arm:
    """The arm described by ``data/arms/<name>.toml``, or by the description file at path
    ``name`` (anywhere on disk; see :func:`~analysis.kinematics.description.
    load_description`, which also explains ``tables``)."""
    return arm_of(load_description(name, tables))


def paper_arm() -> Arm:
    """The arm of the paper (seed 000), parameters from ``data/table3.csv``."""
    return load_arm("grabber")


def derived_arm(desc: ArmDescription | str | Path) -> Arm:
    """The arm of description ``desc`` (or a name or path) on the closed form derived from
    its D-H rows, whatever its ``closed_form`` names (the seed arms' oracle)."""
    if not isinstance(desc, ArmDescription):
        desc = load_description(desc)
    return arm_of(desc, derived=True)


@lru_cache(maxsize=256)
def arm_of(desc: ArmDescription, *, derived: bool = False) -> Arm:
    """The arm of a loaded description (steps 2-4 of the module docstring), once per
    description object (:func:`load_description` returns one per file version).

    Every refusal is one line naming the description's file and the key it is about
    (:class:`~analysis.kinematics.schema.DescriptionError`): ``closed_form`` for the closed
    form's own errors (a user's code failing included), ``parameters`` for the values its
    ``check`` refuses, the rows for a closed form that does not solve them."""
    file = desc.path.name if desc.path else desc.name
    with _stage(file, "closed_form"):
        cf, reason = closed_form_of(desc, derived=derived)
    if not desc.has_rows and (cf is None or cf.fk is None):
        raise DescriptionError(file, "closed_form", "the description has no [[rows]] and "
                               f"{desc.closed_form!r} gives no fk: no forward kinematics")
    if desc.has_rows and cf is not None and cf.fk is not None:
        raise DescriptionError(file, "closed_form", f"both D-H [[rows]] and {cf.name!r} with "
                               "its own fk describe the chain; keep one")  # fmt: skip
    params = _params(desc)
    if cf is not None:
        with _stage(file, "parameters"):
            cf.check(params)
        with _stage(file, "closed_form"):
            _probe(cf, tuple(params), len(desc.joints))
        if desc.has_rows:
            with _stage(file, "[[rows]]"):
                consistency.check(desc, cf, params)
    return Arm(desc, cf, params, reason)


def _params(desc: ArmDescription) -> Params:
    """The description's numbers; the drive only where every joint gives one (else what a
    pulse count raises: :class:`~analysis.kinematics.schema.NoDrive`, naming the first joint
    without one and its missing key)."""
    without = next((j for j in desc.joints if not j.has_drive), None)
    if without is None:
        return Params(desc.values, tuple(j.pulses_per_rev for j in desc.joints))
    return Params(desc.values, None, no_drive=NoDrive(without.file, without.name,
                                                      without.missing_drive))  # fmt: skip


@contextlib.contextmanager
def _stage(file: str, key: str):
    """Report what a stage of loading raises as one line naming ``file`` and ``key``; an
    exception other than ValueError (a user's closed form failing) with its type."""
    try:
        yield
    except DescriptionError:
        raise
    except ValueError as exc:
        text = str(exc)
        rule = text[len(file) + 2 :] if text.startswith(f"{file}: ") else text
        raise DescriptionError(file, key, rule) from None
    except Exception as exc:  # the user's code (a .py closed form): reported, not a traceback
        raise DescriptionError(file, key, f"the closed form raised {type(exc).__name__}: "
                               f"{exc}") from None  # fmt: skip


@lru_cache(maxsize=256)
def _probe(cf: ClosedForm, names: tuple[str, ...], n_joints: int) -> None:
    """Record the closed form once per parameter set (names only: values are recorded as
    inputs, as in the compiled kernel) and check its joint count."""
    cf.probe(names, n_joints)


def closed_form_of(desc: ArmDescription, *, derived: bool = False) -> tuple[ClosedForm | None, str]:
    """The closed form description ``desc`` names, checked against the contract, and ""; or
    None and the reason where a derived one is asked for and the chain is outside the
    families. ``derived``: the derived one whatever the description names."""
    name = desc.closed_form
    if derived or name == DERIVED:
        try:
            made = derive(desc)
        except NotDerivable as exc:
            how = "names no closed_form and" if name == DERIVED else "has rows from which"
            return None, (
                f"arm {desc.name} {how} none can be derived from its D-H table: {exc}. Write "
                'one (analysis.kinematics.arms) and name it with closed_form = "<module>"'
            )
        return check_module(made.__name__, made), ""
    if name.endswith(".py"):
        path = closed_form_file(desc)
        st = path.stat()
        return from_file(str(path), (st.st_mtime_ns, st.st_size, st.st_ino)), ""
    return from_module(name), ""


def closed_form_file(desc: ArmDescription) -> Path:
    """The Python file a description names as its closed form (``closed_form = "x.py"``):
    only a file next to the description, in its own folder (issue 27: "only next to the
    description"), named by a plain file name: no absolute path, no ``..``, and no subfolder
    either, the tables' rule (:func:`analysis.kinematics.tables.table_path`): what a
    description may run is what a listing of its folder shows, never a file somewhere
    below it (a description in a home folder could otherwise run any ``.py`` under it). A
    symbolic link is resolved and must stay in the folder; a regular file.

    Raises ValueError naming the rule broken (the file is never read when refused)."""
    name = desc.closed_form
    where = f"{desc.path.name if desc.path else desc.name}: closed_form = {name!r}"
    rel = Path(name)
    if rel.is_absolute() or name.startswith(("~", "/", "\\")) or ":" in name:
        raise ValueError(f"{where}: a closed-form file must be named relative to the "
                         "description's folder, not by an absolute path")  # fmt: skip
    if ".." in rel.parts or "\\" in name:
        raise ValueError(f"{where}: a closed-form file must lie in the description's folder "
                         "(no '..', no backslash)")  # fmt: skip
    if len(rel.parts) != 1:
        raise ValueError(f"{where}: a closed-form file must lie next to the description, in "
                         "its own folder: a plain file name (no subfolder)")  # fmt: skip
    if desc.path is None:
        raise ValueError(f"{where}: a description without a file has no folder to look in")
    folder = desc.path.resolve().parent
    path = (folder / rel).resolve()
    if path.parent != folder:
        raise ValueError(f"{where}: the file resolves (through a symbolic link) outside the "
                         f"description's folder {folder}")  # fmt: skip
    if not path.exists():
        raise ValueError(f"{where}: no such file in the description's folder")
    if not path.is_file():
        raise ValueError(f"{where}: not a regular file")
    return path
