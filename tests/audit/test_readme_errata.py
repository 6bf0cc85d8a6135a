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


def test_errata_cache_answers_and_names_what_changed(tmp_path, monkeypatch):
    """errata answers from its cache when no input changed (one file per data folder, bounded)
    and otherwise names the inputs it recomputes for."""
    import json

    monkeypatch.setattr(reg, "_cache_dir", lambda: tmp_path)
    assert reg.changed_inputs() == ["(no earlier build from this data folder)"]
    assert reg.cached_answers(["picker"]) is None
    built = reg._answers(["picker"], reg._inputs())
    assert reg.cached_answers(["picker"]) == json.loads(json.dumps(built))
    assert reg.changed_inputs() == []
    inputs = json.loads((tmp_path / "inputs.json").read_text(encoding="utf-8"))
    inputs["data/registers/picker.toml"] = "0" * 64  # as if the register had changed since
    (tmp_path / "inputs.json").write_text(json.dumps(inputs), encoding="utf-8")
    assert reg.changed_inputs() == ["data/registers/picker.toml"]
    for k in range(reg._KEEP + 3):  # bounded: the newest answers only
        (tmp_path / f"{k:064d}-picker.json").write_text("{}", encoding="utf-8")
    reg._answers(["picker"], reg._inputs())
    assert len(list(tmp_path.glob("*-*.json"))) == reg._KEEP
