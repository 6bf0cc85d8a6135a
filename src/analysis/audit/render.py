"""The README block and the site's counts, rendered from built registers
(:class:`~analysis.audit.schema.Register`): pure functions, no register is built here."""

from __future__ import annotations

from analysis.audit.schema import COUNTED, STATUSES, Cause, Register

__all__ = ["cell", "headline", "render_paper"]


def cell(s: str, limit: int | None = None) -> str:
    s = " ".join(str(s).split())
    if limit and len(s) > limit:
        s = s[: limit - 1] + "…"
    return s.replace("|", "\\|")


_NAMES = {
    "error": ("error", "errors"), "omission": ("omission", "omissions"),
    "unsupported": ("unsupported claim", "unsupported claims"),
    "uncertain": ("reading the extraction leaves uncertain", "readings the extraction leaves uncertain"),  # noqa: E501
    "notation": ("notation variant", "notation variants"),
    "extraction": ("extraction artefact", "extraction artefacts"),
    "holds": ("audited claim that holds", "audited claims that hold"),
}  # fmt: skip


def _n(n: int, status: str) -> str:
    return f"{n} {_NAMES[status][n != 1]}"


def headline(reg: Register) -> str:
    """The count of causes (by status) and of the places they show."""
    c = reg.counts()
    against = [_n(c[s], s) for s in COUNTED if c[s]]
    apart = [_n(c[s], s) for s in STATUSES if s not in COUNTED and c[s]]
    shown = sum(len(x.manifestations) for x in reg.causes if x.status in COUNTED)
    text = (
        f"**{sum(c[s] for s in COUNTED)} root causes against the paper** "
        f"({', '.join(against)}), shown in {shown} places."
    )
    if apart:
        text += " Listed apart, not counted: " + ", ".join(apart) + "."
    return text


def _cause_row(c: Cause) -> str:
    where = ""
    if c.manifestations and c.status != "holds":
        where = f"{len(c.manifestations)}: " + cell(c.locations, 90)
    return f"| `{c.id}` | {c.status} | {c.severity} | {c.kind} | {cell(c.title, 140)} | {where} |"


def render_paper(reg: Register) -> str:
    lines = [f"### {reg.title}", "", headline(reg)]
    if reg.summary.get("verdict"):
        lines += ["", f"*Verdict.* {cell(reg.summary['verdict'])}"]
    if reg.summary.get("take_away"):
        lines += ["", f"*Take away.* {cell(reg.summary['take_away'])}"]
    lines += [
        "",
        f"Register: `data/registers/{reg.paper}.toml`, generated `data/errata/{reg.paper}.csv` "
        "(one row per cause, its manifestations beneath; every row names its test).",
        "",
        "| cause | status | severity | kind | what | where |",
        "|---|---|---|---|---|---|",
    ]
    order = {s: i for i, s in enumerate(STATUSES)}
    lines += [_cause_row(c) for c in sorted(reg.causes, key=lambda c: order[c.status])]
    return "\n".join(lines) + "\n"
