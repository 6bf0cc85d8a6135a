"""Hostile arm descriptions and hostile files as inputs (issue 27 items 1, 2, 3, 6): one
property per class, each over generated members of the class (Hypothesis, a few examples
each; ``HYPOTHESIS_PROFILE=thorough`` draws more), through the command line in-process.

1. **text and structure**: a field of a seed description (a name, a parameter or joint name,
   a link, a title, a source, a unit, a status, a kind, a table name, a closed form) replaced
   by a hostile string (line breaks, comment and script terminators, control and separator
   characters, non-ASCII letters, doubled or trailing underscores, 5,000 characters) or a
   hostile structure (a list, a table, a boolean, a number, 2,000 nested arrays), or a key
   misspelt or added: the command answers (0) with every name an identifier and every text
   one printable line, or refuses in one line naming the file and the key (2); never a
   traceback;
2. **consistency**: a seed arm's rows changed (a twist, a theta offset, a ``d``, a ``a``, a
   tool row, two lengths swapped, the convention) while it keeps naming its closed form: the
   arm is refused, naming the largest miss; the rows as they are load;
3. **files**: the description, a table it reads, ``--params`` or the CSV input is a FIFO
   without a writer, a device, a directory, a /proc file, a file larger than the limit, one
   endless line, or lies outside the folders a description may read (a table or a ``.py``
   closed form by an absolute path, ``..``, a symbolic link out): refused in one line within
   seconds (:func:`deadline`), nothing of a foreign file quoted, no foreign code run;
4. **inputs protected**: an output option (``stl -o``/``--map``, ``urdf -o``, ``ik
   --output``) names an input (the description, its table, ``--params``, the CSV), directly,
   through a symbolic link or a hard link: refused, the input unchanged; a closed standard
   output: a non-zero exit.
"""

from __future__ import annotations

import contextlib
import os
import re
import tempfile
import threading
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from analysis.escape import toml_string
from analysis.paths import data_dir

from .registry import cli
from .strategies import deadline, examples

SEEDS = ("grabber", "palletizer", "gr1")


def one_line_error(out, file: str) -> str:
    """The refusal's line (exit 2, one line, no traceback), which names ``file``."""
    err = out.stderr.strip()
    assert out.code == 2, (out.code, out.stdout, out.stderr)
    assert err.count("\n") == 0 and "Traceback" not in err and err, err
    assert file in err, (file, err)
    return err


def seed_folder(name: str) -> Path:
    folder = Path(tempfile.mkdtemp(prefix="hostile-desc-"))
    (folder / "arm.toml").write_text((data_dir() / "arms" / f"{name}.toml").read_text("utf-8"))
    if name == "grabber":
        (folder / "table3.csv").write_bytes((data_dir() / "table3.csv").read_bytes())
    return folder


# --------------------------------------------------------------------------------------------
# 1. text and structure
# --------------------------------------------------------------------------------------------
HOSTILE_TEXT = [
    "a\nb", "x\r\nOB100", "*)", "(* x", "--> <!--", "</script><script>alert(1)</script>",
    "\x1b[31mred", "a\u2028b", "a\u2029b", "tab\there", "\x00", "thetä", "θ1", "a__b", "a_",
    "_a", "1a", "a b", "a-b", "", " ", "x" * 5000, '"; DROP', "{}", "$(rm -rf /)",
]  # fmt: skip
HOSTILE_STRUCTURE = ["[1, 2]", "{ a = 1 }", "true", "42", "1e400", "[" * 2000 + "]" * 2000]


FIELDS = {
    # (pattern of the seed's line, replacement template with {v}); v is a TOML value
    "name": (r'(?m)^name = ".*"$', "name = {v}"),
    "title": (r'(?m)^title = ".*"$', "title = {v}"),
    "paper": (r'(?m)^paper = ".*"$', "paper = {v}"),
    "closed_form": (r'(?m)^closed_form = ".*"$', "closed_form = {v}"),
    "convention": (r'(?m)^convention = "\w+"', "convention = {v}"),
    "joint name": (r'(?m)^name = "theta2"$', "name = {v}"),
    "row link or joint": (r'(?m)^joint = "theta3"$', "joint = {v}"),
    "parameter key": (r"(?m)^(L2|a3) = ", "{k} = "),
    "unit": (r'unit = "mm"', "unit = {v}"),
    "status": (r'status = "(printed|assumed)"', "status = {v}"),
    "limits_status": (r'(?m)^limits_status = ".*"$', "limits_status = {v}"),
    "kind": (r'(?m)^joint = "theta1"$', 'joint = "theta1"\nkind = {v}'),
    "unknown key": (r'(?m)^title = ', "{k} = 1\ntitle = "),
}


@st.composite
def hostile_field(draw):
    field = draw(st.sampled_from(sorted(FIELDS)))
    text = draw(st.sampled_from(HOSTILE_TEXT))
    structured = draw(st.booleans()) and field not in ("parameter key", "unknown key")
    value = draw(st.sampled_from(HOSTILE_STRUCTURE)) if structured else toml_string(text)
    return draw(st.sampled_from(SEEDS)), field, text, value


def _bare_key(text: str) -> str:
    return toml_string(text) if not re.fullmatch(r"[A-Za-z0-9_-]+", text) else text


@given(case=hostile_field())
@examples(40)
def test_hostile_text_and_structure_loads_clean_or_is_refused_in_one_line(case):
    arm, field, text, value = case
    folder = seed_folder(arm)
    path = folder / "arm.toml"
    seed = path.read_text("utf-8")
    pattern, template = FIELDS[field]
    repl = template.format(v=value, k=_bare_key(text or "x"))
    changed = re.sub(pattern, lambda m: repl, seed, count=1)
    if changed == seed:
        return  # this seed has no such field (the GR-1 names no table)
    path.write_text(changed, "utf-8")
    with deadline(30, f"{arm} {field}"):
        out = cli("arms", "--arm", str(path), "--json")
        ik = cli("urdf", "--arm", str(path))
    for o in (out, ik):
        assert "Traceback" not in o.stderr, o.stderr
    if ik.code != 0:
        err = one_line_error(ik, "arm.toml")
        assert re.search(r"arm\.toml: [^:]+:", err), err  # the file, then the key (or line)
        return
    from analysis.kinematics.description import load_description
    from analysis.kinematics.schema import identifier_problem

    desc = load_description(path)
    names = [desc.name, *desc.parameters, *(j.name for j in desc.joints)]
    names += [r["joint"] for r in desc.rows if "joint" in r]
    assert all(identifier_problem(n) is None for n in names), names
    for t in (desc.title, desc.paper, *(p.source for p in desc.parameters.values()),
              *(j.limits_status for j in desc.joints)):  # fmt: skip
        assert "\n" not in t and not any(ord(c) < 0x20 or c in "\u2028\u2029\x7f" for c in t), t
    assert desc.convention in ("standard", "modified")


# --------------------------------------------------------------------------------------------
# 2. consistency at load
# --------------------------------------------------------------------------------------------
ROW_CHANGES = {
    "twist": lambda v: (r"(?m)^alpha_deg = (-?\d+)$", lambda m: f"alpha_deg = {int(m[1]) + v}"),
    "theta offset": lambda v: (r"(?m)^(alpha_deg = -?\d+)$",
                               lambda m: f"{m[1]}\ntheta_offset_deg = {v}"),
    "d": lambda v: (r"(?m)^d = 0$", lambda m: f"d = {v}"),
    "a": lambda v: (r"(?m)^a = 0$", lambda m: f"a = {v}"),
}  # fmt: skip


@st.composite
def changed_rows(draw):
    arm = draw(st.sampled_from(SEEDS))
    kind = draw(st.sampled_from([*ROW_CHANGES, "tool row", "swapped", "modified"]))
    value = draw(st.integers(20, 160)) * draw(st.sampled_from([-1, 1]))
    row = draw(st.integers(0, 4))
    return arm, kind, value, row


def _change(text: str, kind: str, value: int, row: int) -> str:
    if kind == "modified":
        return re.sub(r'convention = "(standard|modified)"', lambda m: 'convention = "' + (
            "standard" if m[1] == "modified" else "modified") + '"', text, count=1)  # fmt: skip
    if kind == "tool row":
        tool = f"\n[[rows]]\nlink = \"tool\"\nkind = \"fixed\"\nalpha_deg = 0\na = {abs(value)}\n"
        return text.replace("\n[[joints]]", tool + "\n[[joints]]", 1)
    if kind == "swapped":
        names = re.findall(r'(?m)^a = "(\w+)"$', text)
        if len(names) < 2 or names[0] == names[1]:
            return text
        a, b = names[:2]
        return (text.replace(f'a = "{a}"', "a = \"@\"").replace(f'a = "{b}"', f'a = "{a}"')
                .replace("a = \"@\"", f'a = "{b}"'))  # fmt: skip
    pattern, repl = ROW_CHANGES[kind](value)
    hits = list(re.finditer(pattern, text.split("[[joints]]")[0]))
    if not hits:
        return text
    m = hits[row % len(hits)]
    return text[: m.start()] + repl(m) + text[m.end() :]


@given(case=changed_rows())
@examples(30)
def test_a_closed_form_that_does_not_solve_the_rows_is_refused(case):
    arm, kind, value, row = case
    if kind == "swapped" and arm != "grabber":
        return  # the palletizer's L1 = L2 and the GR-1's a2 = a3: swapped, the same arm
    folder = seed_folder(arm)
    path = folder / "arm.toml"
    seed = path.read_text("utf-8")
    changed = _change(seed, kind, value, row)
    if changed == seed:
        return
    path.write_text(changed, "utf-8")
    with deadline(60, f"{arm} {kind}"):
        out = cli("stl", "--dialect", "s7-300", "--arm", str(path), "-o", str(folder / "x.awl"))
    if not _moves_the_tool(arm, path):
        # the change leaves what the closed form solves as it was (a turn about the tool's own
        # axis of a point arm): the same arm, and it loads
        assert out.code == 0, out.stderr
        return
    err = one_line_error(out, "arm.toml")
    # the closed form's own refusal (another arm's rows) or its contract's (a joint count)
    assert (("does not solve this description's D-H rows" in err and " mm off" in err)
            or "returns the configuration itself" in err or "joint values per branch" in err
            or "D-H row is" in err or "joints for" in err), err  # fmt: skip
    assert not (folder / "x.awl").exists()


def _moves_the_tool(arm: str, path: Path) -> bool:
    """Whether the changed rows put the tool elsewhere than the seed's rows (its point; its
    orientation too where the arm's inputs are a pose), at 50 seeded configurations: the
    oracle, computed from the two D-H tables apart from any closed form."""
    import numpy as np

    from analysis.kinematics.arm import load_arm
    from analysis.kinematics.description import load_description

    seed = load_arm(arm)
    try:
        other = load_description(path).dh_table()
    except ValueError:
        return True
    if other.n_joints != seed.n_joints:
        return True
    q = np.random.default_rng(3).uniform(-np.pi, np.pi, (50, seed.n_joints))
    a, b = seed.table.fk(q), other.fk(q)
    pose = "alpha" in seed.inputs
    return bool(np.abs((a - b)[:, :3, :] if pose else (a - b)[:, :3, 3]).max() > 1e-6)


@pytest.mark.parametrize("arm", SEEDS)
def test_the_seed_rows_load_with_their_closed_forms(arm):
    folder = seed_folder(arm)
    out = cli("ik", "--arm", str(folder / "arm.toml"), *map(str, _default(arm)))
    assert out.code == 0, out.stderr


def _default(arm: str) -> list[str]:
    """A target of ``arm`` in user units (degrees for angles), from a sampled configuration."""
    import numpy as np

    from analysis.kinematics.arm import load_arm

    a = load_arm(arm)
    t = a.target(a.sample_q(np.random.default_rng(1), 1))[0]
    return [repr(float(np.degrees(v) if u == "rad" else v)) for v, u in zip(t, a.input_units,
                                                                             strict=True)]


# --------------------------------------------------------------------------------------------
# 3. files as inputs
# --------------------------------------------------------------------------------------------
FOREIGN = "root:x:0:0:SECRET-CONTENT-MARKER"
MARKER = "ran-foreign-code"


def _file_case(kind: str, folder: Path) -> Path:
    """A path of ``kind`` in ``folder``: what a hostile user hands in as a file."""
    p = folder / f"{kind.replace(' ', '_')}.x"
    if kind == "fifo":
        os.mkfifo(p)
    elif kind == "device":
        p.symlink_to("/dev/zero")
    elif kind == "directory":
        p.mkdir()
    elif kind == "proc":
        p.symlink_to("/proc/self/status")
    elif kind == "huge":
        with open(p, "wb") as fh:
            fh.truncate(3 << 20)  # 3 MiB of zero bytes: past every limit, no memory used
    elif kind == "endless line":
        p.write_text("x_mm,y_mm,z_mm\n" + "1" * (17 << 20))
    elif kind == "endless stream":  # a FIFO fed one line that never ends
        os.mkfifo(p)
        threading.Thread(target=_feed, args=(p,), daemon=True).start()
    return p


def _feed(p: Path) -> None:
    with contextlib.suppress(OSError), open(p, "w") as fh:
        fh.write("x_mm,y_mm,z_mm\n")
        for _ in range(1 << 14):  # at most 16 GiB; the reader stops long before
            fh.write("1" * (1 << 20))


FILE_KINDS = ["fifo", "device", "directory", "proc", "huge", "endless line"]


@st.composite
def file_input(draw):
    where = draw(st.sampled_from(["--arm", "table", "--params", "--input", "closed_form"]))
    code_kinds = ["absolute", "dotdot", "symlink out", "fifo", "directory"]
    kind = draw(st.sampled_from(FILE_KINDS if where != "closed_form" else code_kinds))
    if where == "--input" and kind == "fifo":
        kind = "endless stream"  # a FIFO is a stream the batch reads: one without end
    if where == "table":
        kind = draw(st.sampled_from([*FILE_KINDS, "absolute", "dotdot", "symlink out"]))
    return where, kind


def _foreign(folder: Path) -> Path:
    """A file outside the description's folder, with content no message may quote, and a
    Python file that leaves a marker if anything runs it."""
    out = Path(tempfile.mkdtemp(prefix="hostile-foreign-"))
    (out / "secret.csv").write_text(f"link,a_mm\n{FOREIGN},1\n")
    (out / "evil.py").write_text(f"open({str(folder / MARKER)!r}, 'w').write('x')\n")
    return out


@given(case=file_input())
@examples(40)
def test_a_hostile_file_is_refused_in_one_line_and_nothing_foreign_is_read_or_run(case):
    where, kind = case
    folder = seed_folder("grabber")
    desc = folder / "arm.toml"
    foreign = _foreign(folder)
    argv = ["ik", "100", "100", "600", "--arm", str(desc)]
    named = desc.name
    if where == "--arm":
        argv[5] = str(_file_case(kind, folder))
        named = Path(argv[5]).name
    elif where == "table":
        target = {"absolute": str(foreign / "secret.csv"), "dotdot": "../secret.csv"}.get(kind)
        if kind == "symlink out":
            (folder / "t.csv").symlink_to(foreign / "secret.csv")
            target = "t.csv"
        if target is None:
            p = _file_case(kind, folder)
            (folder / "t.csv").symlink_to(p.name) if kind != "directory" else None
            target = "t.csv" if kind != "directory" else p.name
        desc.write_text(desc.read_text().replace('table = "table3.csv"', f'table = "{target}"'))
    elif where == "--params":  # the paper's arm's Table 3 (no --arm)
        p = _file_case(kind, folder)
        argv = ["ik", "100", "100", "600", "--params", str(p)]
        named = p.name
    elif where == "--input":
        p = _file_case(kind, folder)
        argv = ["ik", "--arm", str(desc), "--input", str(p), "--output", str(folder / "o.csv")]
        named = p.name
    else:  # closed_form
        target = {"absolute": str(foreign / "evil.py"), "dotdot": "../evil.py"}.get(kind)
        if kind == "symlink out":
            (folder / "cf.py").symlink_to(foreign / "evil.py")
            target = "cf.py"
        elif target is None:
            target = _file_case(kind, folder).name.replace(".x", ".py")
            (folder / target).symlink_to(folder / f"{kind}.x") if kind != "directory" else (
                (folder / target).mkdir())  # fmt: skip
        desc.write_text(desc.read_text().replace('closed_form = "grabber"',
                                                 f'closed_form = "{target}"'))  # fmt: skip
    with deadline(20, f"{where} {kind}"):
        out = cli(*argv)
    err = one_line_error(out, named if where in ("--arm", "--params", "--input") else "arm.toml")
    assert "SECRET-CONTENT-MARKER" not in err and "root:" not in err, err
    assert not (folder / MARKER).exists(), "a foreign .py file was run"


# --------------------------------------------------------------------------------------------
# 4. inputs protected
# --------------------------------------------------------------------------------------------
@st.composite
def output_onto_input(draw):
    command = draw(st.sampled_from(["stl -o", "stl --map", "urdf -o", "ik --output"]))
    victim = draw(st.sampled_from(["description", "table", "--params", "--input"]))
    how = draw(st.sampled_from(["same", "symlink", "hard link"]))
    return command, victim, how


@given(case=output_onto_input())
@examples(30)
def test_an_output_onto_an_input_is_refused_and_the_input_kept(case):
    command, victim, how = case
    folder = seed_folder("grabber")
    desc, table = folder / "arm.toml", folder / "table3.csv"
    params = folder / "p.csv"
    params.write_bytes(table.read_bytes())
    csv_in = folder / "in.csv"
    csv_in.write_text("x_mm,y_mm,z_mm\n100,100,600\n")
    target = {"description": desc, "table": table, "--params": params, "--input": csv_in}[victim]
    out_path = folder / "out.x"
    if how == "same":
        out_path = target
    elif how == "symlink":
        out_path.symlink_to(target.name)
    else:
        os.link(target, out_path)
    before = {p: p.read_bytes() for p in (desc, table, params, csv_in)}
    # --params is the paper's arm's Table 3: it takes no --arm
    arm = ["--arm", str(desc)] if victim != "--params" else []
    extra = ["--params", str(params)] if victim == "--params" else []
    if command.startswith("stl"):
        flag = command.split()[1]
        other = "--map" if flag == "-o" else "-o"
        argv = ["stl", "--dialect", "s7-300", *arm, *extra, flag, str(out_path),
                other, str(folder / "other.x")]  # fmt: skip
    elif command == "urdf -o":
        argv = ["urdf", *arm, "-o", str(out_path)]
    else:
        argv = ["ik", *arm, *extra, "--input", str(csv_in), "--output", str(out_path)]
    if victim == "--params" and command == "urdf -o":
        argv = ["stl", "--dialect", "st", "--params", str(params), "-o", str(out_path)]
    if victim == "--input" and command != "ik --output":
        return  # only the batch reads a CSV
    out = cli(*argv)
    assert out.code == 2 and "same file as input" in out.stderr, (argv, out.stderr)
    assert {p: p.read_bytes() for p in before} == before


def test_a_closed_standard_output_exits_non_zero():
    import subprocess
    import sys

    for argv in (["fk", "10", "20", "30"], ["ik", "100", "100", "600", "--json"],
                 ["urdf", "--arm", "gr1"]):  # fmt: skip
        r = subprocess.run([sys.executable, "-m", "analysis", *argv], stdout=subprocess.DEVNULL,
                           stderr=subprocess.PIPE, text=True, pass_fds=(),
                           preexec_fn=lambda: os.close(1))  # fmt: skip
        assert r.returncode == 2 and "standard output is closed" in r.stderr, (argv, r.stderr)
