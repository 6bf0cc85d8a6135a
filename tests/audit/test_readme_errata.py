"""The README's "What the audit found" block is generated, never typed: it must equal
what ``analysis.audit.register.render_markdown()`` produces from the register."""

from analysis.audit import register as errata
from analysis.kinematics.params import data_dir


def test_readme_block_is_current():
    old, new = errata.readme_text()
    assert old == new, (
        "README errata block is stale: run `python -m analysis.audit.register --write`"
    )


def test_readme_block_carries_the_counts():
    readme = (data_dir().parent / "README.md").read_text(encoding="utf-8")
    block = readme.split(errata.BEGIN, 1)[1].split(errata.END, 1)[0]
    n = len(errata.audit())
    holds = sum(it.verdict == "holds" for it in errata.audit())
    assert f"**{holds} of {n} printed items hold" in block
    for row in errata.load_register():
        assert f"| {row['id']} |" in block
