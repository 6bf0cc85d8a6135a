"""tests/conftest.py: the order of the collection and the loadscope units of `make test`."""

from __future__ import annotations

import conftest


def test_the_register_builders_share_one_unit_and_nothing_else_does():
    shared = {
        "tests/audit/test_register.py::test_cause[gr1-gui-check]",
        "tests/audit/test_readme_errata.py::test_readme_block_is_current",
        "tests/app/test_report.py::test_build_report_writes_the_site",
    }
    alone = {
        "tests/app/test_cli.py::test_every_command_has_help[fk]",
        "tests/app/test_report_site.py::test_x",
        "notebooks/02_inverse_kinematics.ipynb::Cell 0",
    }
    assert {conftest.shared_scope(n) for n in shared} == {"the papers' registers"}
    assert {conftest.shared_scope(n) for n in alone} == {None}
