"""Shared test configuration: deterministic Hypothesis, headless matplotlib, seeded RNG."""

import os

os.environ.setdefault("MPLBACKEND", "Agg")

import numpy as np
import pytest
from hypothesis import HealthCheck, settings

# Derandomized so CI results do not depend on the run; raise the example count locally
# with HYPOTHESIS_PROFILE=thorough.
settings.register_profile(
    "ci",
    derandomize=True,
    max_examples=300,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
)
settings.register_profile("thorough", max_examples=5000, deadline=None)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))


@pytest.fixture
def rng() -> np.random.Generator:
    """A seeded generator; every random test draws from it."""
    return np.random.default_rng(20161)


@pytest.fixture(scope="session")
def arm():
    from analysis.kinematics.arm import paper_arm

    return paper_arm()


# Tests that take seconds each (awlsim sweeps, subprocess sessions, a Sphinx build, the
# registers): marked ``slow`` and run first. ``--dist worksteal`` hands each xdist worker a
# contiguous half of the collection and lets an idle worker steal from the end of the other's
# queue, so long tests at the front are shared out and the run ends on short ones (the
# longest-first rule), instead of one worker finishing a long test alone.
SLOW_FILES = frozenset(
    {
        "tests/plc/test_gr1_plc.py",
        "tests/plc/test_plc_awlsim.py",
        "tests/plc/test_conventions_plc.py",
        "tests/plc/test_palletizer_plc.py",
        "tests/test_nbval_kernel.py",
        "tests/test_kernel_forkserver.py",
        "tests/app/test_report.py",
        "tests/audit/test_vb6.py",
    }
)


def pytest_collection_modifyitems(config, items):
    root = config.rootpath
    for item in items:
        try:
            rel = item.path.relative_to(root).as_posix()
        except ValueError:
            continue
        if rel in SLOW_FILES:
            item.add_marker(pytest.mark.slow)
    items.sort(key=lambda item: item.get_closest_marker("slow") is None)  # stable
