"""Batch I/O that loses nothing (issue 19 item 4), as a user meets it: ``python -m analysis ik
--input --output`` in a real process, killed by signals, pointed at devices and FIFOs, fed
cells of 10,000 characters and rows of 200,000 columns (peak memory measured by the kernel:
``ru_maxrss`` of the child from ``os.wait4``)."""

from __future__ import annotations

import os
import signal
import stat
import subprocess
import sys
import time
from pathlib import Path

import pytest

from analysis.app.cli import main
from analysis.safe_io import sweep_stale

pytestmark = pytest.mark.slow  # subprocesses: seconds each

PEAK_LIMIT_MB = 300


def _spawn(*argv: str, **kw) -> subprocess.Popen:
    return subprocess.Popen(
        [sys.executable, "-m", "analysis", *argv],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        **kw,
    )


PEAK = """
import os, subprocess, sys
pid = os.fork()
if pid == 0:
    os.execv(sys.executable, [sys.executable, "-m", "analysis", *sys.argv[1:]])
_, status, usage = os.wait4(pid, 0)
print(os.waitstatus_to_exitcode(status), usage.ru_maxrss / 1024)
"""


def peak_mb(*argv: str) -> tuple[int, float]:
    """(exit status, peak RSS [MB]) of ``python -m analysis ARGV``, from the kernel."""
    proc = subprocess.run(
        [sys.executable, "-c", PEAK, *argv], capture_output=True, text=True, timeout=900
    )
    code, mb = proc.stdout.split()
    return int(code), float(mb)


@pytest.fixture(scope="module")
def wide_files(tmp_path_factory) -> dict[str, Path]:
    """The issue's shapes: a 10,000-character cell in the first of 20,000 rows (read into a
    fixed-width text array, as before, one chunk of them took 800 MB), and 200,000 columns."""
    d = tmp_path_factory.mktemp("wide")
    files = {}
    for width in (10_000,):
        path = d / f"cell{width}.csv"
        with path.open("w") as fh:
            fh.write("x_mm,y_mm,z_mm,note\n")
            fh.write(f"100,100,600,{'n' * width}\n")
            fh.writelines("100,100,600,a\n" for _ in range(20_000))
        files[f"cell{width}"] = path
    path = d / "columns.csv"
    extra = 200_000
    with path.open("w") as fh:
        fh.write("x_mm,y_mm,z_mm," + ",".join(f"c{k}x" for k in range(extra)) + "\n")
        for _ in range(3):
            fh.write("100,100,600," + ",".join("1" for _ in range(extra)) + "\n")
    files["columns"] = path
    return files


@pytest.mark.parametrize("shape", ["cell10000", "columns"])
def test_memory_is_bounded_whatever_the_cell_widths(wide_files, tmp_path, shape):
    """Peak RSS under 300 MB (it was 5.0 GB for the 10,000-character cell in 100,000 rows and
    1.1 GB for 200,000 columns). Figures: printed with -s."""
    out = tmp_path / "o.csv"
    code, mb = peak_mb("ik", "--input", str(wide_files[shape]), "--output", str(out))
    print(f"\npeak RSS {shape}: {mb:.0f} MB")
    assert code == 0
    assert mb < PEAK_LIMIT_MB, f"{shape}: peak RSS {mb:.0f} MB"
    with out.open() as fh:
        header = fh.readline()
    assert header.count(",") == wide_files[shape].open().readline().count(",") + 10


def _running_batch(out: Path) -> subprocess.Popen:
    """A batch that is still running when the test signals it, whatever the machine's speed:
    it reads its targets from a pipe (``--input -``) that the test keeps open after 2,000 rows,
    so after its first chunks (``--chunk-rows 500``) are in the temporary file it waits for more.
    (A 100,000-row file could be finished before the signal came: it was, once, on a tmpfs.)"""
    proc = _spawn("ik", "--input", "-", "--output", str(out), "--branch", "all",
                  "--chunk-rows", "500", stdin=subprocess.PIPE)  # fmt: skip
    proc.stdin.write("x_mm,y_mm,z_mm\n" + "100,100,600\n" * 2_000)
    proc.stdin.flush()
    return proc


def _wait_for_tmp(directory: Path, proc: subprocess.Popen, timeout: float = 300) -> list[str]:
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        tmp = [n for n in os.listdir(directory) if n.endswith(".tmp")]
        if tmp and os.path.getsize(directory / tmp[0]) > 0:
            return tmp
        if proc.poll() is not None:
            pytest.fail(f"the batch ended before it wrote: {proc.communicate()}")
        time.sleep(0.02)
    pytest.fail("no temporary file appeared")


@pytest.mark.parametrize(
    ("sig", "status", "word"),
    [(signal.SIGINT, 130, "interrupted (SIGINT)"), (signal.SIGTERM, 143, "terminated (SIGTERM)"),
     (signal.SIGHUP, 129, "terminated (SIGHUP)")],
)
def test_a_signal_removes_the_temporary_file_and_ends_in_one_line(tmp_path, sig, status, word):
    out = tmp_path / "out.csv"
    out.write_text("old\n")
    proc = _running_batch(out)
    _wait_for_tmp(tmp_path, proc)
    proc.send_signal(sig)
    proc.stdin.close()
    err = proc.stderr.read()
    assert proc.wait(timeout=120) == status, err
    assert err.strip().splitlines() == [f"python -m analysis ik: {word}"], err
    assert sorted(os.listdir(tmp_path)) == ["out.csv"]
    assert out.read_text() == "old\n"  # the old output stays


def test_a_sigkill_leaves_a_file_that_the_next_run_sweeps(tmp_path):
    out = tmp_path / "out.csv"
    proc = _running_batch(out)
    (left,) = _wait_for_tmp(tmp_path, proc)
    proc.kill()
    proc.stdin.close()
    proc.wait()
    assert (tmp_path / left).exists()  # nothing can run on SIGKILL
    small = tmp_path / "small.csv"
    small.write_text("x_mm,y_mm,z_mm\n100,100,600\n")
    assert main(["ik", "--input", str(small), "--output", str(out)]) == 0
    assert sorted(os.listdir(tmp_path)) == ["out.csv", "small.csv"]
    assert sweep_stale(out) == []


def test_a_running_writers_file_is_not_swept(tmp_path):
    out = tmp_path / "out.csv"
    mine = tmp_path / f".out.csv.{os.getppid()}.abcd1234.tmp"  # a live process: the parent
    mine.write_text("partial")
    assert sweep_stale(out) == [] and mine.exists()


def test_outputs_that_are_not_regular_files_are_refused_and_kept(tmp_path, capsys):
    """A FIFO and a character device (a private one: mknod, as root) are refused, never
    replaced by a file; a reader of the FIFO is not left blocking."""
    src = tmp_path / "in.csv"
    src.write_text("x_mm,y_mm,z_mm\n100,100,600\n")
    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)
    nodes = [fifo]
    if os.geteuid() == 0:
        null = tmp_path / "null"
        os.mknod(null, stat.S_IFCHR | 0o666, os.makedev(1, 3))
        nodes.append(null)
        link = tmp_path / "link-to-null"
        link.symlink_to(null)
        nodes.append(link)
    for node in nodes:
        for argv in (
            ["ik", "--input", str(src), "--output", str(node)],
            ["stl", "--dialect", "s7-300", "-o", str(node)],
            ["stl", "--dialect", "s7-300", "-o", str(tmp_path / "p.awl"), "--map", str(node)],
        ):
            assert main(argv) == 2
            err = capsys.readouterr().err
            assert "not a regular file" in err and err.count("\n") == 1, err
        assert not stat.S_ISREG(os.stat(node).st_mode)
    assert stat.S_ISFIFO(os.stat(fifo).st_mode)
    assert not (tmp_path / "p.awl").exists()


def test_dash_is_standard_input_and_output(tmp_path):
    proc = subprocess.run(
        [sys.executable, "-m", "analysis", "ik", "--input", "-", "--output", "-"],
        input="x_mm,y_mm,z_mm,keep\n100,100,600,é\n",
        capture_output=True,
        text=True,
        check=False,
    )
    assert proc.returncode == 0, proc.stderr
    lines = proc.stdout.splitlines()
    assert lines[0].startswith("x_mm,y_mm,z_mm,keep,branch")
    assert lines[1].startswith("100,100,600,é,front-up,true,45.0,")
    assert "1 targets, 1 solved" in proc.stderr
    assert not (tmp_path / "-").exists() and not Path("-").exists()


def test_no_directory_is_made_unless_asked_and_none_is_left_on_failure(tmp_path, capsys):
    src = tmp_path / "in.csv"
    src.write_text("x_mm,y_mm,z_mm\n100,100,600\n")
    out = tmp_path / "new" / "x" / "o.csv"
    assert main(["ik", "--input", str(src), "--output", str(out)]) == 2
    err = capsys.readouterr().err
    assert "does not exist (--mkdir creates it)" in err
    assert not (tmp_path / "new").exists()
    bad = tmp_path / "bad.csv"
    bad.write_text("x_mm,y_mm,z_mm\n1,2,3\n4,5\n")  # a ragged row: a structural error
    assert main(["ik", "--input", str(bad), "--output", str(out), "--mkdir"]) == 2
    assert not (tmp_path / "new").exists(), "directories left behind by a failed batch"
    assert main(["ik", "--input", str(src), "--output", str(out), "--mkdir"]) == 0
    assert out.exists()
