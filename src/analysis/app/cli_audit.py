"""``python -m analysis errata`` and ``report``: the registers and the report site
(:mod:`analysis.app.cli` builds the parser)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from analysis.app.cli_common import PROG, HelpFormatter, Progress, to_json

__all__ = ["add_errata", "add_report", "cmd_errata", "cmd_report"]


def cmd_errata(args: argparse.Namespace) -> int:
    from analysis.audit import register as reg

    papers = [args.paper] if args.paper else None
    if args.paper and args.paper not in reg.available():
        reg.register(args.paper)  # raises, naming the papers
    progress = Progress("errata")
    # --check is answered from the cache of the generated files' digests when no input changed
    # (under 1 s); reg.check builds the registers only when it must
    if not (args.check and reg.check_is_cached(papers)):
        for i, paper in enumerate(papers or reg.available(), 1):  # built once, cached
            progress.update(f"building the register of {paper} ({i}/{len(papers or reg.available())})")  # noqa: E501
            if args.write or args.check or not args.json:
                reg.register(paper)
    progress.done()
    if args.write:
        changed = reg.write_all(papers)
        if args.json:
            print(to_json({"changed": changed}))
        else:
            print("\n".join(changed) or "up to date")
        return 0
    if args.check:
        stale = reg.check(papers)
        if args.json:
            print(to_json({"up_to_date": not stale, "stale": stale}))
        elif stale:
            print(f"out of date: {', '.join(stale)} (run: {PROG} errata --write)", file=sys.stderr)
        else:
            print("up to date")
        return 1 if stale else 0
    if args.json:
        every = papers or reg.available()
        print(to_json({p: reg.load(p).to_dict(orient="records") for p in every}))
        return 0
    print(reg.render_markdown(papers), end="")
    return 0


def add_errata(sub) -> None:
    """``errata``: show, check or write the registers."""
    p = sub.add_parser(
        "errata",
        help="the errata registers: show, --check, --write",
        description="The registers of every paper (data/errata/<paper>.csv) and the README "
        "block, generated from data/registers/<paper>.toml.",
        epilog="examples:\n  python -m analysis errata --check\n"
        "  python -m analysis errata --paper grabber",
        formatter_class=HelpFormatter,
    )
    g = p.add_mutually_exclusive_group()
    g.add_argument("--check", action="store_true", help="exit 1 if a generated file is stale")
    g.add_argument("--write", action="store_true", help="rewrite the registers and README")
    p.add_argument(
        "--paper",
        help="only this paper's register (grabber, palletizer, picker, gr1); the README block "
        "lists every paper and is checked and written only without --paper",
    )
    p.add_argument(
        "--json", action="store_true",
        help="machine-readable: the register rows, or {up_to_date, stale} with --check, "
        "{changed} with --write",
    )  # fmt: skip
    p.set_defaults(func=cmd_errata)


def cmd_report(args: argparse.Namespace) -> int:
    from analysis.app.report import build_report

    index = build_report(args.out, notebooks=args.notebooks or None)
    print(index)
    return 0


def add_report(sub) -> None:
    """``report``: the report site."""
    p = sub.add_parser(
        "report",
        help="execute every notebook and build the report site",
        description="Execute every notebook fresh (the stored ones are not modified), collect "
        "the figures and build the report under --out.",
    )
    p.add_argument("--out", type=Path, default=Path("build/report"), help="output folder")
    p.add_argument("--notebooks", nargs="*", type=Path, help="only these notebooks")
    p.set_defaults(func=cmd_report)
