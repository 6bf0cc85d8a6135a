"""analysis.safe_io: atomic outputs, path checks, one-line write errors, strict CSV tables."""

from __future__ import annotations

import csv
import errno
import io
import json
import os
import re
import stat
import subprocess
import sys
import tempfile
import textwrap
import tracemalloc
from contextlib import ExitStack
from pathlib import Path
from unittest import mock

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from analysis import safe_io
from analysis.safe_io import (
    InputError,
    OutputError,
    atomic_writer,
    check_paths,
    iter_table_chunks,
    read_table,
    write_many_atomic,
    write_text_atomic,
)


def listing(directory: Path) -> dict[str, bytes]:
    """Every file in ``directory`` (hidden temporary files included) with its bytes."""
    return {p.name: p.read_bytes() for p in sorted(directory.iterdir()) if p.is_file()}


# --------------------------------------------------------------------------------------------
# atomic outputs
# --------------------------------------------------------------------------------------------


def test_atomic_writer_replaces_content_and_leaves_no_temp_file(tmp_path):
    out = tmp_path / "out.csv"
    out.write_text("old\n")
    with atomic_writer(out, newline="") as fh:
        csv.writer(fh).writerows([["a", "b"], ["1", "2"]])
        assert out.read_text() == "old\n", "the output changed before the block finished"
    assert out.read_bytes() == b"a,b\r\n1,2\r\n"
    assert listing(tmp_path) == {"out.csv": b"a,b\r\n1,2\r\n"}


def test_atomic_writer_binary_and_text_helpers(tmp_path):
    with atomic_writer(tmp_path / "b.bin", "wb") as fh:
        fh.write(b"\x00\xff")
    write_text_atomic(tmp_path / "t.txt", "grüße\n", encoding="latin-1")
    assert (tmp_path / "b.bin").read_bytes() == b"\x00\xff"
    assert (tmp_path / "t.txt").read_bytes() == "grüße\n".encode("latin-1")


def test_block_that_closes_the_file_itself_still_lands(tmp_path):
    out = tmp_path / "out.txt"
    with atomic_writer(out) as fh:
        fh.write("closed early")
        fh.close()
    assert listing(tmp_path) == {"out.txt": b"closed early"}


def test_exception_in_block_keeps_old_file_and_propagates(tmp_path):
    out = tmp_path / "out.txt"
    out.write_bytes(b"precious")
    with pytest.raises(ZeroDivisionError), atomic_writer(out) as fh:
        fh.write("half of the new conte")
        1 / 0  # noqa: B018
    assert listing(tmp_path) == {"out.txt": b"precious"}


def test_unrelated_oserror_in_block_is_not_blamed_on_the_output(tmp_path):
    out = tmp_path / "out.txt"
    with pytest.raises(FileNotFoundError), atomic_writer(out) as fh:
        fh.write("x")
        open(tmp_path / "missing-input.csv")
    assert listing(tmp_path) == {}


def test_permissions_of_an_existing_output_are_kept_new_file_follows_umask(tmp_path):
    old = tmp_path / "old.txt"
    old.write_text("a")
    old.chmod(0o640)
    write_text_atomic(old, "b")
    assert stat.S_IMODE(old.stat().st_mode) == 0o640
    mask = os.umask(0o027)
    try:
        write_text_atomic(tmp_path / "new.txt", "c")
    finally:
        os.umask(mask)
    assert stat.S_IMODE((tmp_path / "new.txt").stat().st_mode) == 0o640


def test_symlinked_output_is_written_through(tmp_path):
    real = tmp_path / "real.txt"
    real.write_text("old")
    link = tmp_path / "link.txt"
    link.symlink_to(real)
    write_text_atomic(link, "new")
    assert link.is_symlink() and real.read_text() == "new"


def test_missing_parent_is_refused_unless_requested(tmp_path):
    out = tmp_path / "a" / "b" / "out.txt"
    with pytest.raises(OutputError, match=r"cannot write .*out\.txt: directory .*b does not exist"):
        write_text_atomic(out, "x")
    assert not (tmp_path / "a").exists()
    write_text_atomic(out, "x", make_parents=True)
    assert out.read_text() == "x"


def test_directory_as_output_is_refused_and_left_intact(tmp_path):
    target = tmp_path / "results"
    target.mkdir()
    (target / "keep.txt").write_text("keep")
    with pytest.raises(OutputError, match=r"^cannot write .*results: it is a directory$"):
        write_text_atomic(target, "x")
    assert listing(target) == {"keep.txt": b"keep"} and listing(tmp_path) == {}


def test_invalid_mode_is_refused(tmp_path):
    with pytest.raises(ValueError, match="mode must be"), atomic_writer(tmp_path / "x", "a"):
        pass


@pytest.mark.parametrize(
    ("where", "exc", "reason"),
    [
        ("mkstemp", PermissionError(errno.EACCES, "Permission denied"), "Permission denied"),
        ("fsync", OSError(errno.ENOSPC, "No space left on device"), "No space left on device"),
        (
            "chmod",
            PermissionError(errno.EPERM, "Operation not permitted"),
            "Operation not permitted",
        ),
        ("replace", OSError(errno.EROFS, "Read-only file system"), "Read-only file system"),
    ],
)
def test_oserror_while_writing_becomes_one_line_output_error(tmp_path, where, exc, reason):
    out = tmp_path / "out.txt"
    out.write_bytes(b"old")
    target = tempfile if where == "mkstemp" else os
    with mock.patch.object(target, where, side_effect=exc):
        with pytest.raises(OutputError) as info:
            write_text_atomic(out, "new")
    assert str(info.value) == f"cannot write {out}: {reason}"
    assert "\n" not in str(info.value) and info.value.path == str(out)
    assert listing(tmp_path) == {"out.txt": b"old"}


def test_disk_full_inside_the_block_becomes_output_error(tmp_path):
    out = tmp_path / "out.txt"
    out.write_bytes(b"old")
    with pytest.raises(OutputError, match=r"cannot write .*out\.txt: No space left on device$"):
        with atomic_writer(out) as fh:
            fh.write("partial")
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
    assert listing(tmp_path) == {"out.txt": b"old"}


@pytest.mark.skipif(os.geteuid() == 0, reason="root ignores directory permissions")
def test_read_only_directory_gives_permission_denied(tmp_path):
    locked = tmp_path / "locked"
    locked.mkdir()
    (locked / "out.txt").write_bytes(b"old")
    locked.chmod(0o500)
    try:
        with pytest.raises(OutputError, match=r"out\.txt: Permission denied$"):
            write_text_atomic(locked / "out.txt", "new")
    finally:
        locked.chmod(0o700)
    assert listing(locked) == {"out.txt": b"old"}


FSIZE_SCRIPT = textwrap.dedent(
    """
    import json, resource, signal, sys
    from analysis.safe_io import OutputError, write_many_atomic, write_text_atomic

    signal.signal(signal.SIGXFSZ, signal.SIG_IGN)   # EFBIG instead of being killed
    resource.setrlimit(resource.RLIMIT_FSIZE, (4096, 4096))
    single, first, second = sys.argv[1:]
    errors = []
    try:
        write_text_atomic(single, "x" * 100_000)
    except OutputError as exc:
        errors.append(str(exc))
    try:
        write_many_atomic({first: "small", second: "y" * 100_000})
    except OutputError as exc:
        errors.append(str(exc))
    print(json.dumps(errors))
    """
)


def test_file_size_limit_efbig_becomes_output_error_and_keeps_old_files(tmp_path):
    """RLIMIT_FSIZE (SIGXFSZ ignored) makes the kernel refuse the write with EFBIG."""
    names = ["single.txt", "first.txt", "second.txt"]
    for name in names:
        (tmp_path / name).write_bytes(f"old {name}\n".encode())
    before = listing(tmp_path)
    proc = subprocess.run(
        [sys.executable, "-c", FSIZE_SCRIPT, *(str(tmp_path / n) for n in names)],
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )
    assert proc.returncode == 0, proc.stderr
    errors = json.loads(proc.stdout)
    too_large = os.strerror(errno.EFBIG)
    assert errors == [
        f"cannot write {tmp_path / 'single.txt'}: {too_large}",
        f"cannot write {tmp_path / 'second.txt'}: {too_large}",
    ]
    assert listing(tmp_path) == before


FAILURES = ["raise", "enospc", "mkstemp", "fsync", "chmod", "replace"]


@given(
    old=st.binary(max_size=300),
    new=st.lists(st.text(max_size=50), max_size=8),
    fail_after=st.integers(0, 8),
    failure=st.sampled_from(FAILURES),
)
def test_any_failure_mid_write_leaves_old_file_byte_identical(old, new, fail_after, failure):
    with tempfile.TemporaryDirectory() as tmp:
        directory = Path(tmp)
        out = directory / "out.dat"
        out.write_bytes(old)
        before = listing(directory)
        boom = OSError(errno.EIO, "Input/output error")
        with ExitStack() as stack:
            if failure in ("fsync", "chmod", "replace"):
                stack.enter_context(mock.patch.object(os, failure, side_effect=boom))
            elif failure == "mkstemp":
                stack.enter_context(mock.patch.object(tempfile, "mkstemp", side_effect=boom))
            expected = RuntimeError if failure == "raise" else OutputError
            with pytest.raises(expected), atomic_writer(out) as fh:
                for i, piece in enumerate(new):
                    if i == fail_after:
                        break
                    fh.write(piece)
                if failure == "raise":
                    raise RuntimeError("caller failed mid-write")
                if failure == "enospc":
                    raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
        assert listing(directory) == before


@given(old=st.binary(max_size=200), new=st.text(max_size=200))
def test_successful_write_leaves_exactly_the_new_content(old, new):
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "out.txt"
        out.write_bytes(old)
        write_text_atomic(out, new, newline="")
        assert listing(Path(tmp)) == {"out.txt": new.encode()}


# --------------------------------------------------------------------------------------------
# several files together
# --------------------------------------------------------------------------------------------


def test_write_many_writes_all_files(tmp_path):
    (tmp_path / "a.csv").write_text("old a")
    write_many_atomic(
        {tmp_path / "a.csv": "new a", tmp_path / "sub" / "b.bin": b"\x01"}, make_parents=True
    )
    assert (tmp_path / "a.csv").read_text() == "new a"
    assert (tmp_path / "sub" / "b.bin").read_bytes() == b"\x01"
    assert listing(tmp_path) == {"a.csv": b"new a"}


def test_write_many_refuses_two_spellings_of_one_file_before_writing(tmp_path):
    (tmp_path / "a.txt").write_text("old")
    with pytest.raises(OutputError, match="are the same file"):
        write_many_atomic({tmp_path / "a.txt": "1", f"{tmp_path}/./a.txt": "2"})
    assert listing(tmp_path) == {"a.txt": b"old"}


def _fail_nth(real, n, exc, only=lambda *a: True):
    """A side effect that calls ``real`` but raises ``exc`` on the n-th (0-based) matching call."""
    calls = []

    def side_effect(*args, **kwargs):
        if only(*args):
            calls.append(args)
            if len(calls) - 1 == n:
                raise exc
        return real(*args, **kwargs)

    return side_effect


@given(
    n_files=st.integers(1, 5),
    existing=st.lists(st.booleans(), min_size=5, max_size=5),
    phase=st.sampled_from(["stage", "rename"]),
    fail_at=st.integers(0, 4),
)
def test_write_many_is_all_or_nothing(n_files, existing, phase, fail_at):
    fail_at %= n_files
    with tempfile.TemporaryDirectory() as tmp:
        directory = Path(tmp)
        paths = [directory / f"f{i}.txt" for i in range(n_files)]
        for path, exists in zip(paths, existing, strict=False):
            if exists:
                path.write_text(f"old {path.name}")
        before = listing(directory)
        boom = OSError(errno.EIO, "Input/output error")
        if phase == "stage":  # the fsync of the fail_at-th temporary file fails
            patch = mock.patch.object(os, "fsync", side_effect=_fail_nth(os.fsync, fail_at, boom))
        else:  # the fail_at-th rename of a temporary file over its output fails
            only = lambda src, dst: str(src).endswith(".tmp")  # noqa: E731
            patch = mock.patch.object(
                os, "replace", side_effect=_fail_nth(os.replace, fail_at, boom, only)
            )
        with patch, pytest.raises(OutputError, match=r"^cannot write .*Input/output error$"):
            write_many_atomic({path: f"new {path.name}" for path in paths})
        assert listing(directory) == before


def test_write_many_reports_a_failed_restore_and_keeps_its_backup(tmp_path):
    a, b = tmp_path / "a.txt", tmp_path / "b.txt"
    a.write_text("old a")
    b.write_text("old b")
    real = os.replace
    state = {"renames": 0}

    def flaky(src, dst):
        if str(src).endswith(".tmp"):
            state["renames"] += 1
            if state["renames"] == 2:
                raise OSError(errno.EIO, "Input/output error")
        elif str(src).endswith(".bak"):
            raise OSError(errno.EIO, "Input/output error")  # the restore fails too
        return real(src, dst)

    with mock.patch.object(os, "replace", side_effect=flaky):
        with pytest.raises(OutputError, match=r"could not all be restored: .*a\.txt \(old content"):
            write_many_atomic({a: "new a", b: "new b"})
    backups = [p for p in tmp_path.iterdir() if p.name.endswith(".bak")]
    assert len(backups) == 1 and backups[0].read_text() == "old a"
    assert b.read_text() == "old b"


# --------------------------------------------------------------------------------------------
# check_paths
# --------------------------------------------------------------------------------------------


@pytest.fixture
def files(tmp_path):
    (tmp_path / "in.csv").write_text("x\n")
    (tmp_path / "other.csv").write_text("y\n")
    (tmp_path / "dir").mkdir()
    os.link(tmp_path / "in.csv", tmp_path / "hard.csv")
    (tmp_path / "soft.csv").symlink_to(tmp_path / "in.csv")
    return tmp_path


@pytest.mark.parametrize(
    ("inputs", "outputs", "message"),
    [
        (["in.csv"], ["in.csv"], r"output {d}/in\.csv is the same file as input {d}/in\.csv;"),
        (["in.csv"], ["dir/../in.csv"], r"output .*dir/\.\./in\.csv is the same file as input"),
        (["in.csv"], ["soft.csv"], r"output .*soft\.csv is the same file as input .*\(through"),
        (["in.csv"], ["hard.csv"], r"output .*hard\.csv is the same file as input .*\(hard link\)"),
        ([], ["a.csv", "hard.csv", "in.csv"], r"outputs .*hard\.csv and .*in\.csv are the same"),
        ([], ["dir"], r"^output .*dir is a directory; give a file name$"),
        ([], ["nowhere/out.csv"], r"^output .*out\.csv: directory .*nowhere does not exist$"),
        ([], ["in.csv/out.csv"], r"directory .*in\.csv is not a directory$"),
    ],
)
def test_check_paths_refuses(files, inputs, outputs, message):
    with pytest.raises(OutputError, match=message.format(d=re.escape(str(files)))) as info:
        check_paths(inputs=[files / p for p in inputs], outputs=[files / p for p in outputs])
    assert "\n" not in str(info.value)


def test_check_paths_accepts_distinct_files_and_parents_to_be_made(files):
    check_paths(inputs=[files / "in.csv"], outputs=[files / "out.csv", files / "other.csv"])
    check_paths(outputs=[files / "new" / "out.csv"], make_parents=True)


# --------------------------------------------------------------------------------------------
# strict CSV tables
# --------------------------------------------------------------------------------------------

XYZ = ("x_mm", "y_mm", "z_mm")


def table(tmp_path, text: str, name: str = "t.csv") -> Path:
    path = tmp_path / name
    path.write_bytes(text.encode())
    return path


def test_read_table_types_order_blank_lines_bom_crlf(tmp_path):
    path = table(
        tmp_path,
        '\ufeffsource,x_mm,y_mm,z_mm\r\n"a, ""b""\nc",1,2.5, 3e2 \r\n\r\nrow2,-1,0,1e-3\r\n\r\n',
    )
    got = read_table(path, required=XYZ, optional=("source", "branch"), numeric=XYZ)
    assert list(got) == ["source", "x_mm", "y_mm", "z_mm"]
    assert got["source"].tolist() == ['a, "b"\nc', "row2"]
    assert got["x_mm"].dtype == np.float64
    np.testing.assert_array_equal(
        np.c_[got["x_mm"], got["y_mm"], got["z_mm"]], [[1, 2.5, 300], [-1, 0, 1e-3]]
    )


def test_header_only_gives_empty_columns(tmp_path):
    got = read_table(table(tmp_path, "x_mm,y_mm,z_mm\n"), required=XYZ, numeric=("x_mm",))
    assert {k: (v.dtype.kind, v.shape) for k, v in got.items()} == {
        "x_mm": ("f", (0,)),
        "y_mm": ("U", (0,)),
        "z_mm": ("U", (0,)),
    }


@pytest.mark.parametrize(
    ("text", "message", "line", "column"),
    [
        ("", r"t\.csv: no header line; expected the columns x_mm, y_mm, z_mm", None, None),
        ("\n\n", r"t\.csv: no header line", None, None),
        (
            "x_mm,y_mm,x_mm,z_mm\n",
            r"t\.csv line 1 column x_mm: column 'x_mm' appears twice in the header \(fields 1 and",
            1,
            "x_mm",
        ),
        ("\nx_mm,,z_mm\n", r"t\.csv line 2: header field 2 is empty", 2, None),
        (
            "x_mm,z_mm\n1,2\n",
            r"line 1: missing required column\(s\) y_mm \(the header has: x_mm, z_mm",
            1,
            None,
        ),
        (
            "x_mm,y_mm,z_mm,w\n",
            r"line 1: unknown column\(s\) w; expected x_mm, y_mm, z_mm",
            1,
            None,
        ),
        (
            'x_mm,y_mm,z_mm\n1,2,3\n"4\n",5,6\n\n7,8,9,10\n',
            r"t\.csv line 6: 4 field\(s\) where the header \(line 1\) has 3 \(x_mm, y_mm, z_mm\)$",
            6,
            None,
        ),
        (
            'x_mm,y_mm,z_mm\n1,2,3\n\n4,"5\n\n"\n',
            r"t\.csv line 4: 2 field\(s\) .*\(the record spans lines 4-6\)$",
            4,
            None,
        ),
        (
            "x_mm,y_mm,z_mm\n1,2,3\n4,,6\n",
            r"t\.csv line 3 column y_mm: empty cell; a number is required",
            3,
            "y_mm",
        ),
        ("x_mm,y_mm,z_mm\n1,2,3\n4, ,6\n", r"line 3 column y_mm: empty cell", 3, "y_mm"),
        (
            "x_mm,y_mm,z_mm\n1,2,abc\n",
            r"t\.csv line 2 column z_mm: 'abc' is not a number$",
            2,
            "z_mm",
        ),
        ("x_mm,y_mm,z_mm\n1,2,1_000\n", r"line 2 column z_mm: '1_000' is not a number", 2, "z_mm"),
        (
            "x_mm,y_mm,z_mm\n1,nan,3\n",
            r"line 2 column y_mm: 'nan' is not a finite number",
            2,
            "y_mm",
        ),
        (
            "x_mm,y_mm,z_mm\n-inf,2,3\n",
            r"line 2 column x_mm: '-inf' is not a finite number",
            2,
            "x_mm",
        ),
        ("x_mm,y_mm,z_mm\n1,2,1e999\n", r"line 2 column z_mm: '1e999' is beyond", 2, "z_mm"),
        (
            'x_mm,y_mm,z_mm\n1,2,3\n4,5,"6\n7,8,9\n',
            r"line 3: quoted field not closed before the end",
            3,
            None,
        ),
        ('x_mm,y_mm,z_mm\n1,"2"x,3\n', r"t\.csv line 2: malformed CSV", 2, None),
        (
            'x_mm,y_mm,z_mm\n1,2,3\n\n\n4,5,"6\n7\n',
            r"t\.csv line 5: quoted field not closed",
            5,
            None,
        ),
        (
            b"x_mm,y_mm,z_mm\n1,2,3\n4,5,\xff6\n",
            r"line 3: not valid utf-8 text \(byte\(s\) b'\\xff6",
            3,
            None,
        ),
    ],
)
def test_read_table_errors_name_file_line_and_column(tmp_path, text, message, line, column):
    path = tmp_path / "t.csv"
    path.write_bytes(text if isinstance(text, bytes) else text.encode())
    with pytest.raises(InputError, match=message) as info:
        read_table(path, required=XYZ, numeric=XYZ)
    assert (info.value.line, info.value.column, info.value.path) == (line, column, str(path))
    assert "\n" not in str(info.value)


def test_long_bad_value_is_shortened_in_the_message(tmp_path):
    path = table(tmp_path, "x_mm,y_mm,z_mm\n1,2," + "q" * 10_000 + "\n")
    with pytest.raises(InputError) as info:
        read_table(path, required=XYZ, numeric=XYZ)
    assert len(str(info.value)) < 200


def test_extra_columns_only_when_allowed_and_returned_as_text(tmp_path):
    path = table(tmp_path, "x_mm,note,y_mm,z_mm\n1,hi,2,3\n")
    with pytest.raises(InputError, match=r"unknown column\(s\) note"):
        read_table(path, required=XYZ, numeric=XYZ)
    got = read_table(path, required=XYZ, numeric=XYZ, allow_extra=True)
    assert list(got) == ["x_mm", "note", "y_mm", "z_mm"] and got["note"].tolist() == ["hi"]


def test_missing_file_and_directory_are_input_errors(tmp_path):
    with pytest.raises(InputError, match=r"nope\.csv: cannot read: No such file or directory$"):
        read_table(tmp_path / "nope.csv", required=XYZ)
    with pytest.raises(InputError, match=r"is a directory, not a file of rows$"):
        read_table(tmp_path, required=XYZ)


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"required": ("a",), "numeric": ("b",)}, "numeric column.* b are neither required"),
        ({"required": ("a",), "optional": ("a",)}, r"column\(s\) a both required and optional"),
        ({"required": "abc"}, "required must be a sequence of distinct column names"),
        ({"encoding": "utf-16"}, "not ASCII-compatible"),
        ({"chunk_rows": 0}, "chunk_rows must be a positive integer"),
    ],
)
def test_contradictory_arguments_are_refused_at_the_call(tmp_path, kwargs, message):
    with pytest.raises(ValueError, match=message):
        iter_table_chunks(tmp_path / "not-opened.csv", **kwargs)


def test_chunks_carry_first_line_numbers_and_concatenate_to_the_whole(tmp_path):
    rows = ["x_mm,y_mm,z_mm,label"]
    for i in range(10):
        rows.append(f'{i},{i * 2},{i * 3},"l{i}' + ('\nmore"' if i == 3 else '"'))
        if i == 6:
            rows.append("")
    path = table(tmp_path, "\n".join(rows) + "\n")
    kw = {"required": XYZ, "optional": ("label",), "numeric": XYZ}
    chunks = list(iter_table_chunks(path, chunk_rows=4, **kw))
    # records at lines 2,3,4,5-6 | 7,8,9,11 (line 10 blank) | 12,13
    assert [first for first, _ in chunks] == [2, 7, 12]
    assert [len(c["x_mm"]) for _, c in chunks] == [4, 4, 2]
    whole = read_table(path, **kw)
    for name, values in whole.items():
        np.testing.assert_array_equal(np.concatenate([c[name] for _, c in chunks]), values)


def test_error_in_a_later_chunk_is_raised_after_the_earlier_chunks(tmp_path):
    path = table(tmp_path, "x_mm,y_mm,z_mm\n" + "1,2,3\n" * 5 + "1,2\n")
    it = iter_table_chunks(path, required=XYZ, numeric=XYZ, chunk_rows=2)
    assert [first for first, _ in (next(it), next(it))] == [2, 4]
    with pytest.raises(InputError, match=r"line 7: 2 field\(s\)"):
        list(it)


def test_streaming_memory_does_not_grow_with_the_file(tmp_path):
    n = 40_000
    path = tmp_path / "big.csv"
    with open(path, "w") as fh:
        fh.write("x_mm,y_mm,z_mm\n")
        fh.writelines(f"{i % 997}.25,{i % 13}.5,600\n" for i in range(n))

    def peak(fn) -> int:
        tracemalloc.start()
        try:
            fn()
            return tracemalloc.get_traced_memory()[1]
        finally:
            tracemalloc.stop()

    def stream() -> None:
        total = 0
        for _, cols in iter_table_chunks(path, required=XYZ, numeric=XYZ, chunk_rows=1_000):
            total += len(cols["x_mm"])
        assert total == n

    streamed = peak(stream)
    whole = peak(lambda: read_table(path, required=XYZ, numeric=XYZ))
    assert streamed < 1_000_000, f"streaming peak {streamed} bytes"
    assert streamed * 10 < whole, (streamed, whole)


# Property tests: random tables written with csv.writer, physical lines counted while writing.

cell_text = st.text(alphabet=st.sampled_from(list("ab ,\"'\n\r;x1é")), max_size=8)
numbers = st.floats(allow_nan=False, allow_infinity=False, width=64)


@st.composite
def tables(draw):
    n_num = draw(st.integers(1, 3))
    n_txt = draw(st.integers(0, 2))
    header = [f"n{i}" for i in range(n_num)] + [f"t{i}" for i in range(n_txt)]
    n_rows = draw(st.integers(1, 12))
    rows = [
        [repr(draw(numbers)) for _ in range(n_num)] + [draw(cell_text) for _ in range(n_txt)]
        for _ in range(n_rows)
    ]
    blanks = draw(st.lists(st.booleans(), min_size=n_rows, max_size=n_rows))
    return header, rows, blanks


def render(header, rows, blanks, eol="\n"):
    """CSV text and the physical first line of every record.

    csv.writer quotes a field holding "\r" only when "\r" is in its lineterminator (with
    lineterminator="\n" it writes a bare "\r" that no strict reader accepts), so records are
    written with "\r\n" and the terminator is then swapped for ``eol``.
    """

    def record(fields):
        buf = io.StringIO(newline="")
        csv.writer(buf, lineterminator="\r\n").writerow(fields)
        return buf.getvalue()[:-2] + eol

    parts = [record(header)]
    first_lines = []
    line = 2
    for row, blank in zip(rows, blanks, strict=True):
        if blank:
            parts.append(eol)
            line += 1
        text = record(row)
        parts.append(text)
        first_lines.append(line)
        line += text.count("\n")
    return "".join(parts), first_lines


@given(data=tables(), eol=st.sampled_from(["\n", "\r\n"]))
def test_random_valid_tables_round_trip(data, eol):
    header, rows, blanks = data
    text, _ = render(header, rows, blanks, eol)
    numeric = [h for h in header if h.startswith("n")]
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "t.csv"
        path.write_bytes(text.encode())
        got = read_table(path, required=header, numeric=numeric)
    for j, name in enumerate(header):
        expected = [row[j] for row in rows]
        if name in numeric:
            np.testing.assert_array_equal(got[name], np.array(expected, dtype=float))
        else:
            assert got[name].tolist() == expected


@given(
    data=tables(),
    pick=st.integers(0, 11),
    change=st.sampled_from(["extra", "missing"]),
    eol=st.sampled_from(["\n", "\r\n"]),
)
def test_random_table_with_wrong_field_count_names_its_physical_line(data, pick, change, eol):
    header, rows, blanks = data
    bad = pick % len(rows)
    if change == "extra":
        rows[bad] = [*rows[bad], "surplus"]
    elif len(header) == 1:  # no field at all would be a blank line, which is skipped
        rows[bad] = ["1", "2"]
    else:
        rows[bad] = rows[bad][:-1]
    text, first_lines = render(header, rows, blanks, eol)
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "t.csv"
        path.write_bytes(text.encode())
        with pytest.raises(InputError) as info:
            read_table(path, required=header)
    assert info.value.line == first_lines[bad], (text, str(info.value))
    assert f"line {first_lines[bad]}: " in str(info.value)


@given(data=tables(), pick=st.integers(0, 11), junk=st.sampled_from(["", " ", "x", "nan", "inf"]))
def test_random_bad_number_names_line_and_column(data, pick, junk):
    header, rows, blanks = data
    bad = pick % len(rows)
    rows[bad][0] = junk
    text, first_lines = render(header, rows, blanks)
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "t.csv"
        path.write_bytes(text.encode())
        with pytest.raises(InputError) as info:
            read_table(path, required=header, numeric=[h for h in header if h.startswith("n")])
    assert (info.value.line, info.value.column) == (first_lines[bad], "n0")


def test_module_exports():
    assert set(safe_io.__all__) == {
        "InputError",
        "OutputError",
        "Records",
        "atomic_writer",
        "check_paths",
        "iter_record_chunks",
        "iter_table_chunks",
        "output_stream",
        "read_bytes",
        "read_table",
        "read_text",
        "sweep_stale",
        "write_many_atomic",
        "write_text_atomic",
    }


# --- bounded reads of whole files ----------------------------------------------------------
def test_read_bytes_takes_a_regular_file_up_to_its_limit(tmp_path):
    from analysis.safe_io import InputError, read_bytes, read_text

    f = tmp_path / "a.toml"
    f.write_bytes(b"\xef\xbb\xbfname = 'x'\n")
    assert read_text(f, 100) == "name = 'x'\n"
    assert read_bytes(f, 14) == f.read_bytes()
    with pytest.raises(InputError, match=r"larger than 13 bytes"):
        read_bytes(f, 13, "arm description")
    f.write_bytes(b"name = '\xff'")
    with pytest.raises(InputError, match=r"not utf-8 text \(byte 8 does not decode\)"):
        read_text(f, 100)


@pytest.mark.parametrize(
    ("make", "kind"),
    [
        (lambda p: os.mkfifo(p), r"a FIFO \(named pipe\)"),
        (lambda p: p.mkdir(), "a directory"),
        (lambda p: p.symlink_to("/dev/zero"), "a character device"),
    ],
)
def test_read_bytes_refuses_special_files_without_blocking(tmp_path, make, kind):
    """A FIFO with no writer (open would block), a directory, a device behind a symlink."""
    from analysis.safe_io import InputError, read_bytes

    p = tmp_path / "x"
    make(p)
    with pytest.raises(InputError, match=f"the table is {kind}; only a regular file is read"):
        read_bytes(p, 1 << 20, "table")


def test_read_bytes_bounds_a_file_that_reports_no_size(tmp_path):
    """/proc files report st_size 0: the limit is enforced while reading, not from stat."""
    from analysis.safe_io import InputError, read_bytes

    with pytest.raises(InputError, match="larger than 10 bytes"):
        read_bytes("/proc/self/status", 10)
    with pytest.raises(InputError, match="cannot read the file: No such file"):
        read_bytes(tmp_path / "none", 10)
