"""Shared test configuration: deterministic Hypothesis, headless matplotlib, seeded RNG."""

import gc
import os
import sys

os.environ.setdefault("MPLBACKEND", "Agg")

import numpy as np
import pytest
from hypothesis import HealthCheck, settings

from kernel_forkserver import GC_THRESHOLD, SYMPY_SEED

# The grammar that jsonschema's optional "iri" format checker builds at import (0.8-1.4 s of CPU
# per pytest process), blocked as tests/nbval_kernel.py explains; here for the sessions that do
# not load that plugin (make test-fast, which also leaves nbval out: -p no:nbval).
sys.modules.setdefault("rfc3987_syntax", None)  # type: ignore[arg-type]

# The tests allocate millions of short-lived SymPy objects; at Python's default first threshold
# (700 allocations) the cyclic collector runs thousands of times a test run. Collected 140 times
# less often (reference counting still frees everything acyclic at once), building the four
# registers takes 3.2 s instead of 4.1 s. The same threshold (and SymPy's seed) is set for the
# notebook kernels by tests/kernel_forkserver.py, which defines both.
gc.set_threshold(*GC_THRESHOLD)


def _scratch_in_memory(min_free: int = 4 << 30) -> None:
    """Temporary files (``tmp_path``, ``tempfile``, and the subprocesses' TMPDIR) in /dev/shm
    when it is a writable tmpfs with at least ``min_free`` bytes free, and TMPDIR is not set.

    The atomic writers fsync every file and directory they write (analysis.safe_io); on
    the disk those fsyncs are most of the time of the tests that write thousands of small
    files (tests/safe_io/test_safe_io.py: 40.6 s on /tmp, 10.5 s on /dev/shm, measured on one
    machine). The semantics under test (rename, permissions, ENOSPC/EFBIG, links) are those
    of any POSIX file system; on a machine without such a tmpfs nothing changes."""
    if os.environ.get("TMPDIR"):
        return
    shm = "/dev/shm"
    try:
        with open("/proc/mounts") as fh:
            if not any(f.split()[1:3] == [shm, "tmpfs"] for f in fh if len(f.split()) > 2):
                return
        st = os.statvfs(shm)
        if st.f_bavail * st.f_frsize < min_free or not os.access(shm, os.W_OK | os.X_OK):
            return
        scratch = os.path.join(shm, f"analysis-tests-{os.getuid()}")
        os.makedirs(scratch, mode=0o700, exist_ok=True)
    except OSError:
        return
    import tempfile

    os.environ["TMPDIR"] = tempfile.tempdir = scratch


_scratch_in_memory()

# Derandomized so CI results do not depend on the run; raise the example count locally
# with HYPOTHESIS_PROFILE=thorough.
settings.register_profile(
    "ci",
    derandomize=True,
    max_examples=300,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
)
# make test-fast: the same properties on fewer examples (quick feedback; make test, which CI
# runs, keeps "ci").
settings.register_profile("fast", parent=settings.get_profile("ci"), max_examples=60)
settings.register_profile("thorough", max_examples=5000, deadline=None)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))


@pytest.fixture
def rng() -> np.random.Generator:
    """A seeded generator; every random test draws from it."""
    return np.random.default_rng(20161)


@pytest.fixture(autouse=True)
def _sympy_seeded():
    """SymPy draws random numbers inside some algorithms (multivariate factorisation picks
    random evaluation points, ``sympy.core.random``). Seeded before each test, a test takes the
    same path through SymPy in every run, whichever worker and order it runs in (the notebook
    kernels: tests/kernel_forkserver.py)."""
    from sympy.core.random import seed

    seed(SYMPY_SEED)


@pytest.fixture(scope="session")
def arm():
    from analysis.kinematics.arm import paper_arm

    return paper_arm()


@pytest.fixture(scope="session")
def engine():
    """The ST engine's sweep binary (make st-engine); the test skips, saying why, without it."""
    from analysis.plc import st_engine

    try:
        return st_engine.engine_path()
    except st_engine.EngineMissing as exc:
        pytest.skip(str(exc))


@pytest.fixture(scope="session")
def machine_engine():
    """The ST engine's machine driver (make st-engine); skips, saying why, without it."""
    from analysis.plc import st_engine

    try:
        return st_engine.machine_engine_path()
    except st_engine.EngineMissing as exc:
        pytest.skip(str(exc))


def pytest_collection_modifyitems(items):
    """Longest work first: the notebooks (nbval cells, seconds per notebook), then the tests
    marked ``slow`` (awlsim sweeps, subprocess sessions, a Sphinx build, the VB6 runs:
    ``pytestmark`` in their modules), then the rest. ``make test`` hands out whole notebooks and
    test modules in this order (``--dist loadscope --no-loadscope-reorder``), ``make test-fast``
    single tests (``--dist worksteal``: each worker starts on its own half of the collection and
    an idle one steals from the end of the other's). Either way the long work is shared out at
    the start and the run ends on short tests, not one worker finishing a long one alone."""
    items.sort(
        key=lambda item: (item.path.suffix != ".ipynb", item.get_closest_marker("slow") is None)
    )  # stable


# Building the papers' registers takes seconds of SymPy, cached per process. Under
# `--dist loadscope` (make test) the modules that build them share one work unit, so only one
# xdist worker pays for it: the audit tests and the report site (which lists every register).
_REGISTER_SCOPE = ("tests/audit/", "tests/app/test_report.py")


def shared_scope(nodeid: str) -> str | None:
    """The loadscope unit a test shares with others beyond its module, if any."""
    return "the papers' registers" if nodeid.startswith(_REGISTER_SCOPE) else None


@pytest.hookimpl(optionalhook=True)  # a hook of pytest-xdist: `-p no:xdist` must still work
def pytest_xdist_make_scheduler(config, log):
    """``--dist loadscope`` with the register-building modules as one scope (see above)."""
    if config.getoption("dist") != "loadscope":
        return None  # xdist's own scheduler
    from xdist.scheduler import LoadScopeScheduling

    class Scheduling(LoadScopeScheduling):
        def _split_scope(self, nodeid: str) -> str:
            return shared_scope(nodeid) or super()._split_scope(nodeid)

    return Scheduling(config, log)
