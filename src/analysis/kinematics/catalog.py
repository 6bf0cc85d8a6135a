"""The arms a user can name: every description in ``data/arms/`` (the ``arms`` command, the
explorer's arm menu), each loaded on its own, so one broken file is reported and the others
still listed."""

from __future__ import annotations

from pathlib import Path

from analysis.kinematics.loader import load_arm
from analysis.paths import data_dir

__all__ = ["arm_names", "describe_arm", "list_arms"]


def arm_names() -> tuple[str, ...]:
    """The names of the descriptions in ``data/arms/*.toml``, sorted."""
    return tuple(sorted(p.stem for p in (data_dir() / "arms").glob("*.toml")))


def describe_arm(name: str | Path) -> dict:
    """One arm as plain data: ``name`` (what ``--arm`` takes: the file's stem), ``title,
    paper, joints`` (names), ``joint_units``, ``branches``, ``inputs``, ``parameters`` {name:
    {value, unit, status}}, ``pulses_per_rev`` (per joint, or null where the description
    gives no drive: an engineer's D-H table) (an arm without a closed form: no branches, no
    inputs, and ``no_ik``, the reason); or ``name`` and ``error`` (the reason it does not
    load, one line) if it does not."""
    stem = Path(str(name)).stem
    try:
        arm = load_arm(str(name))
    except (ValueError, OSError) as exc:
        return {"name": stem, "error": " ".join(str(exc).split())}
    d = arm.description
    return {
        "name": stem,
        "title": d.title,
        "paper": d.paper,
        "joints": list(arm.joint_names),
        "joint_units": list(arm.joint_units),
        "branches": list(arm.branches) if arm.closed_form else [],
        "inputs": list(arm.inputs) if arm.closed_form else [],
        "parameters": {
            k: {"value": p.value, "unit": p.unit, "status": p.status}
            for k, p in d.parameters.items()
        },
        "pulses_per_rev": list(arm.params.pulses_per_rev) if arm.has_drive else None,
        **({} if arm.closed_form else {"no_ik": " ".join(arm.no_ik.split())}),
    }


def list_arms() -> list[dict]:
    """:func:`describe_arm` of every description in ``data/arms/``."""
    return [describe_arm(name) for name in arm_names()]
