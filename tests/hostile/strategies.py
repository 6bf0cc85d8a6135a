"""Hypothesis strategies for the classes of hostile input (issue 19)."""

from __future__ import annotations

import contextlib
import math
import signal

import numpy as np
from hypothesis import HealthCheck, settings
from hypothesis import strategies as st

from analysis import validate


@contextlib.contextmanager
def deadline(seconds: float, what: str, hint: str = "blocked on a read?"):
    """Fail (instead of hanging) when the body runs longer than ``seconds`` (SIGALRM)."""

    def expired(signum, frame):
        raise AssertionError(f"{what}: still running after {seconds} s ({hint})")

    old = signal.signal(signal.SIGALRM, expired)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)


def examples(n: int, cost: int = 1) -> settings:
    """Settings drawing ``n // cost`` examples under the "ci" profile (make test), 30 times as
    many under "thorough", a third under "fast" (make test-fast); at least 2."""
    drawn = settings().max_examples
    scale = 30 if drawn > 1000 else 1 if drawn >= 300 else 1 / 3
    return settings(
        max_examples=max(2, int(n * scale) // cost),
        deadline=None,
        suppress_health_check=[
            HealthCheck.too_slow,
            HealthCheck.data_too_large,
            HealthCheck.function_scoped_fixture,
        ],
    )


FIXED_BAD_TEXT = [
    "nan", "NaN", "-nan", "inf", "-inf", "+Infinity", "infinity", "1e400", "-1e999",
    "1,5", "0x10", "0b1", "1_000", "1__0", "_1", "1e3_0", "", " ", "\t", "1e", "e5", ".",
    "-", "+", "--1", "1.2.3", "1e5.5", "١٢٣", "１", "٣.٥", "१", "１e3", "1\u00a0", "\u20071",
    "abc", "1 2", "0x1p3", "1j", "(1+0j)", "True", "None", "1e+", "∞", "½", "²",
]  # fmt: skip
"""Texts that Python's ``float()`` (or a careless reader) would take, or that are no number."""


def _mutate(text: str, how: int, extra: str) -> str:
    if how == 0:
        return text[: len(text) // 2] + "_" + text[len(text) // 2 :]
    if how == 1:  # an ASCII digit replaced by a non-ASCII one of the same value
        for i, c in enumerate(text):
            if c.isdigit():
                return text[:i] + chr(0x0660 + int(c)) + text[i + 1 :]
        return "٠" + text
    if how == 2:
        return text.replace(".", ",") if "." in text else text + ",5"
    return text + extra


def hostile_texts():
    """Members of the class: fixed samples, and valid numbers broken by an underscore, a
    non-ASCII digit, a decimal comma or a stray character."""
    valid = st.floats(allow_nan=False, allow_infinity=False).map(repr)
    broken = st.builds(
        _mutate, valid, st.integers(0, 3), st.sampled_from(list("x,;_ﾠ\u2009#e+-"))
    )
    return st.sampled_from(FIXED_BAD_TEXT) | broken


def number_texts():
    """Texts that look like numbers, good and bad: what CLI and CSV must read alike."""
    parts = st.text(alphabet="0123456789", min_size=1, max_size=6)
    signs = st.sampled_from(["", "-", "+"])
    exps = st.sampled_from(["", "e3", "E-2", "e+10", "e400", "e-400"])
    plain = st.builds(lambda s, a, b, e: f"{s}{a}.{b}{e}", signs, parts, parts, exps)
    ints = st.builds(lambda s, a, e: f"{s}{a}{e}", signs, parts, exps)
    return plain | ints | hostile_texts() | st.floats().map(repr)


HOSTILE_API = [
    math.nan, math.inf, -math.inf, 10**400, -(10**400), 1 + 0j, complex(100, 0), 1j,
    True, False, np.bool_(True), None, "100", b"100", [100.0], {"v": 1},
    np.ma.masked_array(1.0, mask=True), np.float64("nan"), np.complex128(1),
    np.array([1.0]),
]  # fmt: skip
"""Python values the API must refuse with a ValueError (never TypeError or OverflowError)."""


def hostile_api_values():
    return st.sampled_from(HOSTILE_API) | st.floats(allow_nan=True).filter(
        lambda v: not math.isfinite(v)
    )


def beyond(kind: str):
    """Finite values outside the supported range of a slot of this kind."""
    limit = {
        "mm": validate.MAX_COORD_MM,
        "len": validate.MAX_LENGTH_MM,
        "jdeg": validate.MAX_JOINT_DEG,
        "rad": validate.MAX_ANGLE_RAD,
        "tol": validate.MAX_TOL_MM,
        "ppr": validate.MAX_PULSES_PER_REV,
    }[kind]
    big = st.floats(min_value=min(limit * (1 + 1e-9), 1.7e308), max_value=1.7e308)
    return st.builds(lambda v, s: s * v, big, st.sampled_from([1.0, -1.0]))
