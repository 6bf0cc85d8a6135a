"""The registers of every paper: one schema, a test per cause and per manifestation.

``test_cause[<id>]`` runs the cause's demonstration, which fails if the printed form were
right; ``test_manifestation[<id>]`` asserts that the manifestation's check rejects the
printed text and accepts the corrected one (for an uncertain cause: tells the readings
apart). The files must be what the audits generate; the loader is strict. The numeric
tests at the end hold key errata against NumPy and the D-H chain, independently of SymPy.
"""

import csv

import numpy as np
import pytest

from analysis.audit import grabber_audit as audit
from analysis.audit import register as reg
from analysis.audit import schema
from analysis.kinematics.dh import inverse_transform
from analysis.kinematics.params import paper_params
from analysis.papers import grabber as paper

PAPERS = reg.available()


# The ids are read from the register files (cheap at collection); the registers themselves
# are built only where a test runs (reg.register caches them per process). A file that is not
# what its audit generates fails test_register_file_is_current_and_valid, and an id the audit
# does not produce fails its own test.
def _rows(kind: str):
    for p in PAPERS:
        for row in schema.read_rows(reg.register_path(p)):
            if bool(row["cause"]) == (kind == "manifestation"):
                yield pytest.param(p, row["id"], id=row["id"])


def _causes():
    return list(_rows("cause"))


def _manifestations():
    return list(_rows("manifestation"))


@pytest.mark.parametrize(("paper_name", "cause_id"), _causes())
def test_cause(paper_name, cause_id):
    cause = reg.register(paper_name).cause(cause_id)
    assert cause.demonstrate(), f"{cause_id}: the demonstration does not hold"


@pytest.mark.parametrize(("paper_name", "mid"), _manifestations())
def test_manifestation(paper_name, mid):
    m = reg.register(paper_name).manifestation(mid)
    assert not m.verify(m.printed), f"{mid}: the printed text passes the check"
    assert m.verify(m.corrected), f"{mid}: the correction {m.corrected!r} fails the check"


@pytest.mark.parametrize("paper_name", PAPERS)
def test_register_file_is_current_and_valid(paper_name):
    path = reg.register_path(paper_name)
    assert path.read_text(encoding="utf-8") == reg.register(paper_name).csv_text()
    rows = schema.read_rows(path)
    r = reg.register(paper_name)
    assert len(rows) == len(r.causes) + r.n_manifestations
    assert {row["check"] for row in rows} == {
        *(c.check for c in r.causes),
        *(m.check for c in r.causes for m in c.manifestations),
    }


def test_every_wrong_item_is_one_manifestation_of_seed_000():
    used = [m.source for c in reg.register("grabber").causes for m in c.manifestations]
    wrong = sorted(it.id for it in audit.audit() if it.verdict == "wrong")
    assert sorted(u for u in used if u) == wrong


def test_headline_counts_causes_not_manifestations():
    r = reg.register("grabber")
    c = r.counts()
    assert sum(c.values()) == len(r.causes) < r.n_manifestations
    text = reg.headline(r)
    counted = c["error"] + c["omission"] + c["unsupported"]
    assert f"**{counted} root causes against the paper**" in text


def _write(path, rows, columns=schema.COLUMNS):
    with path.open("w", newline="", encoding="utf-8") as fh:
        w = csv.DictWriter(fh, fieldnames=list(columns))
        w.writeheader()
        w.writerows(rows)


CAUSE = {
    "id": "x-cause",
    "cause": "",
    "status": "error",
    "kind": "sign",
    "location": "eq. 1",
    "printed": "",
    "corrected": "",
    "evidence": "why",
    "check": "tests/audit/test_register.py::test_cause[x-cause]",
}
MANIF = {
    **CAUSE,
    "id": "x-cause/eq1",
    "cause": "x-cause",
    "printed": "a",
    "corrected": "b",
    "check": "tests/audit/test_register.py::test_manifestation[x-cause/eq1]",
}


@pytest.mark.parametrize(
    ("rows", "message"),
    [
        ([{**CAUSE, "kind": "typo"}], "kind"),
        ([{**CAUSE, "status": "wrongish"}], "status"),
        ([{**CAUSE, "check": "test_x"}], "check"),
        ([{**CAUSE, "evidence": ""}], "empty"),
        ([CAUSE, CAUSE], "duplicated"),
        ([MANIF], "not above it"),
        ([CAUSE, {**MANIF, "printed": ""}], "both texts"),
        ([CAUSE, {**MANIF, "status": "holds"}], "consistent"),
        ([{**CAUSE, "id": "Bad Id"}], "malformed"),
    ],
)
def test_loader_rejects_bad_rows(tmp_path, rows, message):
    path = tmp_path / "r.csv"
    _write(path, rows)
    with pytest.raises(ValueError, match=message):
        schema.read_rows(path)


def test_loader_rejects_columns_and_ragged_rows(tmp_path):
    path = tmp_path / "r.csv"
    _write(path, [{k: v for k, v in CAUSE.items() if k != "check"}], schema.COLUMNS[:-1])
    with pytest.raises(ValueError, match="columns"):
        schema.read_rows(path)
    path.write_text(",".join(schema.COLUMNS) + "\n" + "a,b\n", encoding="utf-8")
    with pytest.raises(ValueError, match="line 2"):
        schema.read_rows(path)


def test_cause_and_manifestation_ids_are_checked():
    with pytest.raises(ValueError, match="status"):
        schema.Cause("x", "t", "bad", "sign", "e")
    with pytest.raises(ValueError, match="must be named"):
        m = schema.Manifestation("y/z", "l", "p", "c", "e")
        schema.Cause("x", "t", "error", "sign", "e", (m,))


# ---- independent numeric cross-checks (NumPy D-H chain, no SymPy) -----------------------------
@pytest.fixture(scope="module")
def configs():
    rng = np.random.default_rng(20161)
    return rng.uniform(-np.pi, np.pi, size=(50, 3))


def _num(text, q, P=(0.0, 0.0, 0.0)):
    prm = paper_params()
    f = paper.parse(text)
    vals = {
        paper.SYMBOLS["theta1"]: q[0],
        paper.SYMBOLS["theta2"]: q[1],
        paper.SYMBOLS["theta3"]: q[2],
        paper.SYMBOLS["L1"]: prm.L1,
        paper.SYMBOLS["L2"]: prm.L2,
        paper.SYMBOLS["L3"]: prm.L3,
        paper.SYMBOLS["Px"]: P[0],
        paper.SYMBOLS["Py"]: P[1],
        paper.SYMBOLS["Pz"]: P[2],
    }
    return float(f.subs(vals).evalf())


def test_eq12_matrix_against_numeric_inverse(configs):
    """Printed eq. 12 vs inv(A1 A2 A3) from NumPy: wrong exactly at (2,2) and (3,3) (1-based)."""
    table = paper_params().dh_table()
    wrong = set()
    for q in configs[:10]:
        Tinv = inverse_transform(table.fk(q))
        for i in range(4):
            for j in range(4):
                if abs(_num(paper.MATRICES["eq12"]["rows"][i][j], q) - Tinv[i, j]) > 1e-9:
                    wrong.add((i + 1, j + 1))
    assert wrong == {(2, 2), (3, 3)}


def test_eq5_eq13_eq14_against_numeric_fk(configs, arm):
    """At P = fk(q) the printed eqs. 5, 13, 14 leave a residual, the corrected ones do not."""
    bad = {"eq5": 0, "eq13": 0, "eq14": 0}
    corrected = {k: audit.item(f"paper-{k}").corrected for k in bad}
    for q in configs:
        P = arm.fk(q)
        for key in bad:
            spec = paper.EQUATIONS[key]
            lhs, rhs = corrected[key].split("=")
            bad[key] += abs(_num(spec["lhs"], q, P) - _num(spec["rhs"], q, P)) > 1e-6
            assert abs(_num(lhs, q, P) - _num(rhs, q, P)) < 1e-6  # 1e-6 mm: float64 at |P| ~ 1e3 mm
    assert all(v > 40 for v in bad.values()), bad


def test_t3_a_x_against_numeric_fk(configs):
    table = paper_params().dh_table()
    T = table.fk(configs)
    assert np.allclose(
        T[:, 0, 2], np.sin(configs[:, 0]), atol=1e-12
    )  # a_x = sin(theta1), printed 0


def test_corrected_closed_form_is_arm_ik(arm):
    """The closed form's SymPy expressions (what the register's corrections are held
    against), lambdified, equal Arm.solve's front-up branch (numpy namespace)."""
    rng = np.random.default_rng(20161)
    q = np.column_stack(
        [
            rng.uniform(-np.pi, np.pi, 500),
            rng.uniform(-np.pi, np.pi, 500),
            rng.uniform(-np.pi + 1e-3, -1e-3, 500),
        ]
    )
    p = arm.fk(q)
    a = audit.closed_form_ik(p)
    b = arm.solve(p, ("front-up",)).branch("front-up")
    d = np.abs(np.mod(a - b + np.pi, 2 * np.pi) - np.pi)
    assert d.max() < 1e-9  # rad; float64 acos/atan2 near the shell boundary, observed ~1e-12


def test_repaired_figure5_computes_eq18_with_its_single_argument_arctan(arm):
    """With only the VD68 order and the degree factor repaired, the reconstructed Figure 5
    gives the correct c2 where eq. 18's denominator is positive (rows 3, 5-7, 9, 10) and
    c2 + 2000 pulses (+180 deg) where it is negative (rows 1, 2, 4): Table 4's error.
    This supports the reconstruction of Figure 5 (apart from the VD68 order)."""
    from analysis.audit.grabber_stl import figure5_c2, figure5_repaired
    from analysis.audit.table4 import load_printed
    from analysis.kinematics.pulses import angles_to_pulses

    t4 = load_printed()[["x_mm", "y_mm", "z_mm"]].astype(float).to_numpy()
    # VD106 moved off VD104's bytes (grabber-overlap): the overlap itself changes row 1
    listing = figure5_repaired().replace("VD106", "VD300")
    for row, p in enumerate(t4, start=1):
        if row == 8:
            continue
        q = arm.ik(p)
        c2 = angles_to_pulses(q)[1]
        shift = 2000 if row in (1, 2, 4) else 0  # 4000 pulses/rev: 180 deg = 2000 pulses
        assert figure5_c2(listing, p, q) == c2 + shift, row
        assert figure5_c2(paper.FIGURE_STL[5], p, q) != c2 + shift, row
    # with the overlap (as printed), row 1 is one pulse off: measured 2114 vs 2113
    p1 = t4[0]
    assert figure5_c2(figure5_repaired(), p1, arm.ik(p1)) == 2114
