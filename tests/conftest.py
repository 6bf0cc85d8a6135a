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


def pytest_collection_modifyitems(items):
    """Tests marked ``slow`` (awlsim sweeps, subprocess sessions, a Sphinx build, the VB6
    runs: ``pytestmark`` in their modules) run first. ``--dist worksteal`` hands each xdist
    worker a contiguous half of the collection and lets an idle worker steal from the end of
    the other's queue, so long tests at the front are shared out and the run ends on short
    ones (longest first), instead of one worker finishing a long test alone."""
    items.sort(key=lambda item: item.get_closest_marker("slow") is None)  # stable
