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

    if args.paper_file:  # a paper outside data/ (being added): its records' audit
        found = reg.audit_file(args.paper_file, args.register).findings
        print(to_json({"findings": list(found)}) if args.json else "\n".join(found) or "explained")
        return 1 if found else 0
    papers = [args.paper] if args.paper else None
    if args.paper and args.paper not in reg.available():
        reg.register(args.paper)  # raises, naming the papers
    # answered from the cache of what the registers give when no input changed (under 1 s);
    # otherwise say what changed and rebuild the registers (seconds)
    if not args.json or args.check or args.write:
        if args.write or reg.cached_answers(papers) is None:
            changed = reg.changed_inputs()
            print(f"errata: recomputing the registers ({len(changed)} input(s) changed since the "
                  f"last build: {', '.join(changed[:6])}{' ...' if len(changed) > 6 else ''})",
                  file=sys.stderr)  # fmt: skip
            progress = Progress("errata")
            for i, paper in enumerate(papers or reg.available(), 1):  # built once, cached
                progress.update(f"building the register of {paper} ({i}/{len(papers or reg.available())})")  # noqa: E501
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
        stale, found = reg.check(papers), reg.findings(papers)
        if args.json:
            ok = not stale and not found
            print(to_json({"up_to_date": ok, "stale": stale, "findings": found}))
        else:
            if stale:
                print(f"out of date: {', '.join(stale)} (run: {PROG} errata --write)", file=sys.stderr)  # noqa: E501
            for f in found:
                print(f, file=sys.stderr)
            if not stale and not found:
                print("up to date")
        return 1 if stale or found else 0
    if args.json:
        from analysis.audit.schema import read_rows

        print(to_json({p: read_rows(reg.register_path(p)) for p in papers or reg.available()}))
        return 0
    print(reg.markdown(papers), end="")
    return 0


def add_errata(sub) -> None:
    """``errata``: show, check or write the registers."""
    p = sub.add_parser(
        "errata",
        help="the errata registers: show, --check, --write",
        description="The registers of every paper (data/errata/<paper>.csv) and the README "
        "block, generated from data/registers/<paper>.toml; --check also lists every printed "
        "record whose check fails and that no cause explains.",
        epilog="examples:\n  python -m analysis errata --check\n"
        "  python -m analysis errata --paper grabber\n"
        "  python -m analysis errata --paper-file example/paper.toml --register "
        "example/register.toml",
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
        help="machine-readable: the register rows, or {up_to_date, stale, findings} with "
        "--check, {changed} with --write",
    )  # fmt: skip
    p.add_argument(
        "--paper-file", metavar="PAPER.toml",
        help="audit a paper's data file outside data/ (one being added): every printed record "
        "checked, each failure no cause explains listed; exit 1 if any",
    )  # fmt: skip
    p.add_argument("--register", metavar="REGISTER.toml", help="with --paper-file: its register")
    p.set_defaults(func=cmd_errata)


def cmd_report(args: argparse.Namespace) -> int:
    from analysis.app.report import build_report

    if str(args.out) == "-":
        raise ValueError("--out -: the report is a folder of pages, not one stream; give a "
                         "folder (default build/report)")  # fmt: skip
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
