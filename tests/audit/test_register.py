"""The errata register: every row proven, the files current, the loader strict.

``test_erratum[<id>]`` is the check named in each ``paper-*`` register row: it fails if
the printed text passed the machine check or the corrected text did not.
``test_item_verdict[<id>]`` re-derives every audited item (including those that hold).
The numeric tests at the end hold key errata against NumPy/Pinocchio, independently of
the SymPy derivation.
"""

import csv
import shutil

import numpy as np
import pytest

from analysis.audit import register as errata
from analysis.kinematics.dh import inverse_transform
from analysis.kinematics.params import data_dir, paper_params
from analysis.papers import grabber as paper


def _csv(name):
    with (data_dir() / name).open(newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


OWN_ROWS = [r for r in _csv("errata.csv") if r["id"].startswith(errata.OWN_PREFIX)]
AUDIT_ROWS = _csv("paper_audit.csv")


@pytest.mark.parametrize("row", [pytest.param(r, id=r["id"]) for r in OWN_ROWS])
def test_erratum(row, request):
    item = errata.item(row["id"])
    assert item.verdict == "wrong"
    assert row["check"] == f"tests/audit/test_register.py::{request.node.name}"
    assert row["kind"] in errata.KINDS
    assert not item.verify(row["printed"]), f"{row['id']}: the printed text passes the check"
    assert item.verify(row["corrected"]), (
        f"{row['id']}: the correction {row['corrected']!r} fails the check"
    )


@pytest.mark.parametrize("row", [pytest.param(r, id=r["id"]) for r in AUDIT_ROWS])
def test_item_verdict(row):
    item = errata.item(row["id"])
    assert item.verdict == row["verdict"]
    assert item.verify(item.printed) == (item.verdict == "holds")


def test_register_and_audit_files_are_current():
    assert (data_dir() / "errata.csv").read_text(encoding="utf-8") == errata.register_text()
    audit_rows = [{k: v for k, v in r.items()} for r in AUDIT_ROWS]
    assert audit_rows == errata.audit_table()


def test_register_validates():
    rows = errata.load_register()
    assert {r["id"] for r in rows} >= {r["id"] for r in errata.register_rows()}


def test_coverage_counts():
    items = errata.audit()
    wrong = [it for it in items if it.verdict == "wrong"]
    assert len(items) == len(AUDIT_ROWS) and len(wrong) == len(OWN_ROWS)
    assert all(it.verdict in ("holds", "wrong", "undecidable") for it in items)
    assert all(it.check.startswith("tests/audit/test_register.py::") for it in items)


def _write(path, rows, columns=errata.COLUMNS):
    with path.open("w", newline="", encoding="utf-8") as fh:
        w = csv.DictWriter(fh, fieldnames=list(columns))
        w.writeheader()
        w.writerows(rows)


PLC_ROW = {
    "id": "plc-fig4-run",
    "location": "Figure 4",
    "printed": "c1 = 9",
    "corrected": "c1 = 500",
    "kind": "unit",
    "check": "tests/plc/test_plc_awlsim.py::test_paper_figure4",
}


def test_foreign_rows_are_kept_and_own_rows_regenerated(tmp_path):
    path = tmp_path / "errata.csv"
    shutil.copy(data_dir() / "errata.csv", path)
    rows = errata.load_register(path)
    rows[0]["corrected"] = "tampered"
    _write(path, [*rows, PLC_ROW])
    text = errata.register_text(path)
    _write(tmp_path / "new.csv", [])
    (tmp_path / "new.csv").write_text(text, encoding="utf-8")
    new = errata.load_register(tmp_path / "new.csv")
    assert new[-1] == PLC_ROW
    # the live register may already hold foreign (plc-*) rows: compare the own ones
    assert [r for r in new if r["id"].startswith(errata.OWN_PREFIX)] == errata.register_rows()


@pytest.mark.parametrize(
    ("change", "message"),
    [({"kind": "typo"}, "kind"), ({"check": "test_x"}, "check"), ({"printed": ""}, "empty")],
)
def test_loader_rejects_bad_rows(tmp_path, change, message):
    path = tmp_path / "errata.csv"
    _write(path, [{**PLC_ROW, **change}])
    with pytest.raises(ValueError, match=message):
        errata.load_register(path)


def test_loader_rejects_duplicates_and_columns(tmp_path):
    path = tmp_path / "errata.csv"
    _write(path, [PLC_ROW, PLC_ROW])
    with pytest.raises(ValueError, match="duplicated"):
        errata.load_register(path)
    _write(path, [{k: v for k, v in PLC_ROW.items() if k != "check"}], errata.COLUMNS[:-1])
    with pytest.raises(ValueError, match="columns"):
        errata.load_register(path)


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
    corrected = {r["id"].removeprefix("paper-"): r["corrected"] for r in OWN_ROWS}
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
    """The register's corrected eqs. 6, 10, 19, composed, equal Arm.solve's front-up branch."""
    rng = np.random.default_rng(20161)
    q = np.column_stack(
        [
            rng.uniform(-np.pi, np.pi, 500),
            rng.uniform(-np.pi, np.pi, 500),
            rng.uniform(-np.pi + 1e-3, -1e-3, 500),
        ]
    )
    p = arm.fk(q)
    a = errata.closed_form_ik(p)
    b = arm.solve(p, ("front-up",)).branch("front-up")
    d = np.abs(np.mod(a - b + np.pi, 2 * np.pi) - np.pi)
    assert d.max() < 1e-9  # rad; float64 acos/atan2 near the shell boundary, observed ~1e-12


def test_load_dataframe_for_reports():
    df = errata.load()
    assert list(df.columns) == list(errata.COLUMNS)
    assert set(df["id"]) == {r["id"] for r in errata.load_register()}


def test_repaired_figure5_computes_eq18_with_its_single_argument_arctan(arm):
    """With only the VD68 order and the degree factor repaired, the reconstructed Figure 5
    gives the correct c2 where eq. 18's denominator is positive (rows 3, 5-7, 9, 10) and
    c2 + 2000 pulses (+180 deg) where it is negative (rows 1, 2, 4): Table 4's error.
    This supports the reconstruction of Figure 5 (apart from the VD68 order)."""
    from analysis.audit.grabber_stl import figure5_c2, figure5_repaired
    from analysis.audit.table4 import load_printed
    from analysis.kinematics.pulses import angles_to_pulses

    t4 = load_printed()[["x_mm", "y_mm", "z_mm"]].astype(float).to_numpy()
    listing = figure5_repaired()
    for row, p in enumerate(t4, start=1):
        if row == 8:
            continue
        q = arm.ik(p)
        c2 = angles_to_pulses(q)[1]
        shift = 2000 if row in (1, 2, 4) else 0  # 4000 pulses/rev: 180 deg = 2000 pulses
        assert figure5_c2(listing, p, q) == c2 + shift, row
        assert figure5_c2(paper.FIGURE_STL[5], p, q) != c2 + shift, row
