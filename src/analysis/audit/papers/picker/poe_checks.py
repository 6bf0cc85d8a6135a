"""Seed 002's method, the product of exponentials, checked on every arm of the project.

The picker paper (seed 002) builds its forward kinematics as a product of exponentials
(secs. 1.1-1.2, eqs. 3-9: bodies lost, the text describes them) of revolute and prismatic
twists. :mod:`analysis.kinematics.poe` is that formula, written once. Here it is held,
arm by arm, against routes that share no code with it:

* every seed arm that is a D-H chain (:func:`dh_arm_names`):
  screws read off the D-H frames at q = 0 only (:func:`~analysis.kinematics.poe.
  screws_from_dh`), then the pose at seeded q by POE, by the D-H product
  (:meth:`~analysis.kinematics.dh.DHTable.fk`), by Pinocchio built from the D-H rows
  (:class:`~analysis.kinematics.pinocchio_model.PinocchioArm`) and by Pinocchio built from
  the screws (:class:`~analysis.kinematics.pinocchio_model.PinocchioPOE`);
* the picker (``data/arms/picker.toml``, no D-H description: its sliders are prismatic, which
  the project's D-H module does not model, and the paper's point is to avoid D-H): both
  chains (main: waist, vertical slider, three passive and three wrist revolutes; secondary:
  waist, horizontal slider, four passive revolutes) by POE and by Pinocchio built from the
  screws, and the secondary chain closing onto the main one (the structure equation's role).

Tolerances: 1e-9 mm and 1e-12 (rotation entries). Lengths up to ~2e3 mm composed over at
most 8 rigid motions give float64 round-off ~1e-12 mm; a wrong axis or sign is off by
millimetres (tests/kinematics/test_poe.py mutates them).
"""

from __future__ import annotations

import numpy as np

from analysis.kinematics import poe
from analysis.kinematics.arm import load_arm
from analysis.kinematics.description import load_description

__all__ = ["ATOL_MM", "ATOL_ROT", "cross_check", "dh_arm_names"]

ATOL_MM = 1e-9
ATOL_ROT = 1e-12


SEED_DH_ARMS = ("gr1", "grabber", "palletizer")
"""The seed papers' arms that are D-H chains (sorted): the register checks these, not
whatever other description a user adds to ``data/arms`` (the picker is a closed chain)."""


def dh_arm_names() -> tuple[str, ...]:
    """Names of the seed arms described by D-H rows (:data:`SEED_DH_ARMS`)."""
    return tuple(n for n in SEED_DH_ARMS if load_description(n).has_rows)


def _errors(T, ref) -> tuple[float, float]:
    return (
        float(np.abs(T[..., :3, 3] - ref[..., :3, 3]).max()),
        float(np.abs(T[..., :3, :3] - ref[..., :3, :3]).max()),
    )


def cross_check(n: int = 1000, seed: int = 2016) -> list[dict]:
    """One row per chain: ``arm``, ``chain``, ``joints`` (R/P string), ``n`` configurations,
    and the largest position [mm] / rotation-entry differences of POE against each other
    route (NaN where the route does not exist), plus ``ok`` (all within tolerance).
    """
    from analysis.kinematics import picker as pk
    from analysis.kinematics.pinocchio_model import PinocchioArm, PinocchioPOE

    rows = []
    for name in dh_arm_names():
        # one generator per arm, so that adding an arm leaves the others' samples alone
        rng = np.random.default_rng([seed, *name.encode()])
        table = load_arm(name).table
        S, M = poe.screws_from_dh(table)
        q = rng.uniform(-np.pi, np.pi, (n, table.n_joints))
        T = poe.fk(S, M, q)
        pin_dh = PinocchioArm(table)
        T_pin_dh = np.stack([pin_dh.placement(qk) for qk in q])
        row = {
            "arm": name,
            "chain": f"D-H ({table.convention})",
            "joints": "".join("R" if k == "revolute" else "P" for k in poe.joint_kinds(S)),
            "n": n,
        }
        for key, ref in (
            ("D-H product", table.fk(q)),
            ("Pinocchio (D-H rows)", T_pin_dh),
            ("Pinocchio (screws)", PinocchioPOE(S, M).placements(q)),
        ):
            row[f"{key} [mm]"], row[f"{key} [rot]"] = _errors(T, ref)
        rows.append(row)
    picker = pk.load_picker()
    active = picker.random_active(np.random.default_rng([seed, *b"picker"]), n)
    q_all = picker.joints(active)
    for chain, (S, M), q in (
        ("main (open)", picker.open_chain(), q_all[:, :8]),
        ("secondary", picker.secondary_chain(), q_all[:, [0, 8, 9, 10, 11, 12]]),
    ):
        T = poe.fk(S, M, q)
        row = {
            "arm": "picker",
            "chain": chain,
            "joints": "".join("R" if k == "revolute" else "P" for k in poe.joint_kinds(S)),
            "n": n,
            "D-H product [mm]": float("nan"),
            "D-H product [rot]": float("nan"),
            "Pinocchio (D-H rows) [mm]": float("nan"),
            "Pinocchio (D-H rows) [rot]": float("nan"),
        }
        row["Pinocchio (screws) [mm]"], row["Pinocchio (screws) [rot]"] = _errors(
            T, PinocchioPOE(S, M).placements(q)
        )
        rows.append(row)
    loops = picker.loop_residuals(active)
    rows[-1]["loop closure [mm]"] = float(loops["secondary_position"].max())
    for r in rows:
        mm = [v for k, v in r.items() if k.endswith("[mm]") and np.isfinite(v)]
        rot = [v for k, v in r.items() if k.endswith("[rot]") and np.isfinite(v)]
        r["ok"] = bool(max(mm) < ATOL_MM and max(rot) < ATOL_ROT)
    return rows
