"""A paper's own printed D-H table as the model its records are checked against.

A paper that prints its arm as a D-H table says so in its data (``[paper.model] dh = "<table
record>"``, the table's columns ``theta``, ``d``, ``a``, ``alpha_deg`` in the paper's symbols,
``convention`` standard or modified, ``lengths``: a value for each length symbol) and then needs
no Python of its own: :func:`bespoke` defines what its records' checks compute against,

- matrices ``A1`` .. ``An`` (the link transforms of the table's rows, SymPy) and their inverses
  ``A1inv`` ..., for ``matrix`` checks (``product = ["A1", "A2"]``);
- the value ``dh_trig``: cos and sin of a row's ``alpha_deg`` (a ``cos_alpha`` or
  ``sin_alpha`` column, as seed 000's Table 1 prints them), and the value ``fk``: a table row's
  ``x_mm``, ``y_mm``, ``z_mm`` from its ``theta<k>_deg`` columns by the table's forward
  kinematics;
- the domain ``configurations``: 200 seeded joint vectors in (-pi, pi] with their positions
  ``px``, ``py``, ``pz`` [mm] and the lengths, for ``claim`` and ``sampled`` checks.

The link transform is :func:`analysis.kinematics.dh.link_transform_sym`, the project's one.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from analysis.audit.bespoke import Bespoke

__all__ = ["bespoke"]


def _rows(paper):
    spec = paper.meta["model"]
    rec = paper.record(spec["dh"])
    return spec, list(paper.table_rows(rec.id).values())


def _links(paper) -> list[sp.Matrix]:
    from analysis.kinematics.dh import link_transform_sym

    spec, rows = _rows(paper)
    out = []
    for r in rows:
        theta, d, a = (paper.parse(str(r[k])) for k in ("theta", "d", "a"))
        alpha = sp.pi * sp.nsimplify(str(r["alpha_deg"])) / 180
        out.append(link_transform_sym(theta, d, a, alpha, spec.get("convention", "standard")))
    return out


def _inverse(A: sp.Matrix) -> sp.Matrix:
    R, p = A[:3, :3], A[:3, 3]
    return R.T.row_join(-R.T * p).col_join(sp.Matrix([[0, 0, 0, 1]]))


def bespoke(paper) -> Bespoke:
    """What the records of ``paper`` (with ``[paper.model] dh``) compute against."""
    B = Bespoke(paper.id)
    spec, rows = _rows(paper)
    lengths = {paper.symbols()[k]: float(v) for k, v in spec.get("lengths", {}).items()}
    joints = [paper.parse(str(r["theta"])) for r in rows]
    for i in range(len(rows)):
        B.matrix(f"A{i + 1}")(lambda i=i: _links(paper)[i])
        B.matrix(f"A{i + 1}inv")(lambda i=i: _inverse(_links(paper)[i]))

    def tip():
        T = sp.eye(4)
        for A in _links(paper):
            T = T * A
        f = sp.lambdify(joints, list(T[:3, 3].subs(lengths)), "numpy")

        def at(*q):  # (x, y, z), each broadcast to the joints' shape (z may be a constant)
            shape = np.broadcast(*q).shape
            return [np.broadcast_to(np.asarray(v, dtype=float), shape) for v in f(*q)]

        return at

    @B.value("dh_trig")
    def _trig(row, column):
        alpha = np.radians(float(paper.table_rows(spec["dh"])[row]["alpha_deg"]))
        return float(np.cos(alpha) if column.startswith("cos") else np.sin(alpha))

    @B.value("fk")
    def _fk(row, column):
        tables = [r.id for r in paper.records.values() if r.type == "table"
                  and "theta1_deg" in (r.get("columns") or ())]  # fmt: skip
        if len(tables) != 1:
            raise ValueError(f"{paper.id}: 'fk' needs one table of theta<k>_deg, not {tables}")
        cells = paper.table_rows(tables[0])[row]
        q = [np.radians(float(cells[f"theta{k + 1}_deg"])) for k in range(len(joints))]
        return float(tip()(*q)["xyz".index(column[0])])

    @B.domain("configurations")
    def _configurations():
        q = np.random.default_rng(2024).uniform(-np.pi, np.pi, (200, len(joints)))
        x, y, z = tip()(*q.T)
        out = {"px": x, "py": y, "pz": z}
        out.update({str(s): q[:, k] for k, s in enumerate(joints)})
        out.update({str(k): v for k, v in lengths.items()})
        return out

    return B
