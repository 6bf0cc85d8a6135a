"""The package's import graph, function-level imports included: cycles, arrows up the floors,
module and function sizes (issue 28: "an outside look at the import graph").

    .venv/bin/python tools/import_graph.py [--under analysis.kinematics] [--json]

Every ``import`` and ``from ... import`` in every module of ``src/analysis`` is an edge (at
module level or inside a function, under ``TYPE_CHECKING`` excepted); ``from pkg import name``
is an edge to ``pkg.name`` when that is a module, else to ``pkg``. A package's
``__init__`` is the module ``pkg``. Cycles are the strongly connected components of more than
one module (Tarjan). Floors, lowest first: the shared base (``validate``, ``paths``,
``fonts``, ``papers``, ``safe_io``, ``escape``), ``kinematics``, ``audit``/``studies``/``plc``,
``app``; an edge from a lower floor to a higher one is an arrow up, allowed only with a
stated reason in :data:`REASONS`. A *private import* is ``from analysis.x import _name``
(or ``import analysis.x._y``) from outside the module or package that owns the name:
:data:`PRIVATE_OK` lists the packages whose private submodules their own ``__init__`` and
siblings may import.

``--check`` exits 1 when a cycle, an arrow up without a reason or a private import is found
(``tests/test_structure.py`` runs it).
"""

from __future__ import annotations

import argparse
import ast
import json
import sys
from pathlib import Path

SRC = Path(__file__).resolve().parents[1] / "src"
FLOORS = {"validate": 0, "paths": 0, "fonts": 0, "papers": 0, "safe_io": 0, "escape": 0,
          "kinematics": 1, "audit": 2, "studies": 2, "plc": 2, "app": 3, "__main__": 3,
          "": 0}  # fmt: skip
REASONS: dict[tuple[str, str], str] = {}
"""(importer, imported) -> why this arrow up the floors is needed. Empty: there is none."""


def modules() -> dict[str, Path]:
    out = {}
    for path in sorted((SRC / "analysis").rglob("*.py")):
        parts = list(path.relative_to(SRC).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        out[".".join(parts)] = path
    return out


def _type_checking(node: ast.If) -> bool:
    t = node.test
    return (isinstance(t, ast.Name) and t.id == "TYPE_CHECKING") or (
        isinstance(t, ast.Attribute) and t.attr == "TYPE_CHECKING"
    )


def edges(mods: dict[str, Path]) -> dict[str, set[tuple[str, bool]]]:
    """module -> {(imported module, inside a function)}."""
    out: dict[str, set[tuple[str, bool]]] = {}
    for name, path in mods.items():
        tree = ast.parse(path.read_text(encoding="utf-8"))
        pkg = name if path.name == "__init__.py" else name.rpartition(".")[0]
        found: set[tuple[str, bool]] = set()

        def visit(node, in_fn: bool, found=found, pkg=pkg) -> None:
            if isinstance(node, ast.If) and _type_checking(node):
                for n in node.orelse:
                    visit(n, in_fn)
                return
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)):
                in_fn = True
            if isinstance(node, ast.Import):
                for a in node.names:
                    if a.name.startswith("analysis"):
                        found.add((_owner(a.name, mods), in_fn))
            elif isinstance(node, ast.ImportFrom):
                base = node.module or ""
                if node.level:
                    up = pkg.split(".")
                    up = up[: len(up) - node.level + 1]
                    base = ".".join([*up, *([base] if base else [])])
                if base.startswith("analysis"):
                    for a in node.names:
                        sub = f"{base}.{a.name}"
                        found.add((sub if sub in mods else _owner(base, mods), in_fn))
            for child in ast.iter_child_nodes(node):
                visit(child, in_fn)

        visit(tree, False)
        found.discard((name, False))
        found.discard((name, True))
        out[name] = found
    return out


def _owner(name: str, mods) -> str:
    while name and name not in mods:
        name = name.rpartition(".")[0]
    return name


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """Strongly connected components with more than one module (Tarjan, iterative)."""
    index, low, on, stack, out = {}, {}, set(), [], []
    counter = [0]
    for root in graph:
        if root in index:
            continue
        work = [(root, iter(sorted(graph.get(root, ()))))]
        index[root] = low[root] = counter[0]
        counter[0] += 1
        stack.append(root)
        on.add(root)
        while work:
            v, it = work[-1]
            nxt = next(it, None)
            if nxt is not None:
                if nxt not in index:
                    index[nxt] = low[nxt] = counter[0]
                    counter[0] += 1
                    stack.append(nxt)
                    on.add(nxt)
                    work.append((nxt, iter(sorted(graph.get(nxt, ())))))
                elif nxt in on:
                    low[v] = min(low[v], index[nxt])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[v])
            if low[v] == index[v]:
                comp = []
                while True:
                    w = stack.pop()
                    on.discard(w)
                    comp.append(w)
                    if w == v:
                        break
                if len(comp) > 1:
                    out.append(sorted(comp))
    return out


def private_imports(mods: dict[str, Path]) -> list[tuple[str, str]]:
    """(importer, "module.name") for every private name imported from another module: a
    name or a module path part that starts with one underscore, imported from outside the
    package that holds it (``analysis.safe_io`` may import ``analysis.safe_io._read``)."""
    out = []
    for name, path in mods.items():
        pkg = name if path.name == "__init__.py" else name.rpartition(".")[0]
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom):
                base = node.module or ""
                if node.level:
                    up = pkg.split(".")
                    up = up[: len(up) - node.level + 1]
                    base = ".".join([*up, *([base] if base else [])])
                targets = [f"{base}.{a.name}" for a in node.names]
            elif isinstance(node, ast.Import):
                targets = [a.name for a in node.names]
            else:
                continue
            for target in targets:
                if not target.startswith("analysis."):
                    continue
                parts = target.split(".")
                first = next((i for i, s in enumerate(parts) if _private(s)), None)
                if first is None:
                    continue
                owner = ".".join(parts[:first])  # the package or module that holds the name
                if name != owner and not name.startswith(owner + "."):
                    out.append((name, target))
    return sorted(out)


def _private(part: str) -> bool:
    return part.startswith("_") and not part.startswith("__")


def floor(mod: str) -> int:
    parts = mod.split(".")
    return FLOORS.get(parts[1] if len(parts) > 1 else "", 0)


def sizes(mods: dict[str, Path]) -> tuple[list, list]:
    big_mods, big_fns = [], []
    for name, path in mods.items():
        text = path.read_text(encoding="utf-8")
        n = text.count("\n")
        if n > 600:
            big_mods.append((name, n))
        for node in ast.walk(ast.parse(text)):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                length = node.end_lineno - node.lineno + 1
                if length > 100:
                    big_fns.append((f"{name}.{node.name}", length))
    return sorted(big_mods, key=lambda t: -t[1]), sorted(big_fns, key=lambda t: -t[1])


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--under", default="analysis", help="report cycles among these modules")
    ap.add_argument("--json", action="store_true")
    ap.add_argument("--check", action="store_true",
                    help="exit 1 on a cycle, an arrow up without a reason or a private import")
    args = ap.parse_args(argv)
    mods = modules()
    e = edges(mods)
    graph = {m: {t for t, _ in v} for m, v in e.items()}
    cyc = [c for c in cycles(graph) if any(m.startswith(args.under) for m in c)]
    up = sorted(
        (m, t) for m, v in e.items() for t, _ in v
        if t and floor(t) > floor(m) and m.startswith(args.under)
    )  # fmt: skip
    unreasoned = [a for a in up if a not in REASONS]
    private = [p for p in private_imports(mods) if p[0].startswith(args.under)]
    n_edges = sum(len(v) for v in e.values())
    n_fn = sum(1 for v in e.values() for _, f in v if f)
    big_mods, big_fns = sizes({k: p for k, p in mods.items() if k.startswith(args.under)})
    doc = {"modules": len(mods), "edges": n_edges, "function_level": n_fn, "cycles": cyc,
           "arrows_up": [[m, t, REASONS.get((m, t))] for m, t in up],
           "private_imports": private, "modules_over_600": big_mods,
           "functions_over_100": big_fns}  # fmt: skip
    if args.json:
        print(json.dumps(doc, indent=1))
    else:
        print(f"{len(mods)} modules, {n_edges} internal imports ({n_fn} inside functions)")
        print(f"cycles among {args.under}: {len(cyc)}")
        for c in cyc:
            print("  " + " <-> ".join(c))
        print(f"arrows up the floors from {args.under}: {len(up)}")
        for m, t in up:
            print(f"  {m} -> {t}: {REASONS.get((m, t), 'NO REASON GIVEN')}")
        print(f"private names imported across modules: {len(private)}")
        for m, t in private:
            print(f"  {m} imports {t}")
        print(f"modules over 600 lines: {big_mods}")
        print(f"functions over 100 lines: {big_fns}")
    return 1 if args.check and (cyc or unreasoned or private) else 0


if __name__ == "__main__":
    sys.exit(main())
