"""The README's "What the audit found" block is generated, never typed: it must equal what
``analysis.audit.register.render_markdown()`` produces from the registers."""

from analysis.audit import register as reg
from analysis.paths import PROJECT


def test_readme_block_is_current():
    readme = PROJECT / "README.md"
    assert readme.read_text(encoding="utf-8") == reg.readme_text(readme), (
        "README errata block is stale: run `python -m analysis errata --write`"
    )


def test_readme_block_carries_every_cause_and_headline():
    readme = (PROJECT / "README.md").read_text(encoding="utf-8")
    block = readme.split(reg.BEGIN, 1)[1].split(reg.END, 1)[0]
    for paper in reg.available():
        r = reg.register(paper)
        assert reg.headline(r) in block
        for c in r.causes:
            assert f"| `{c.id}` |" in block
