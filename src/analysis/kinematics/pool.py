"""Output buffers that are touched once and reused: a small caching allocator.

Why: a batch IK call of the compiled kernel (:mod:`analysis.kinematics.compiled`) writes
about 100 bytes per target; for 2e6 targets that is 192 MB of fresh memory. On the test
machine (a Firecracker VM) memory the process maps again after a second of idling costs about
1.5 ms per MB at its first touch (192 MB: 300-430 ms), memory the process kept costs 6 ms:
without reuse a cold call ran at a ninth of a warm one, all of it in the page faults of its
outputs (``make bench``). ``out=`` buffers avoid that for a caller who manages them; this
pool does it for everyone else, as CuPy's and PyTorch's caching allocators do for GPU memory.
NumPy has no allocator hook reachable from Python (NEP 49 handlers are C-level), so this is
written by hand: :func:`empty` returns an array whose ``base`` holds a pooled block; when the
last array or view over the block is gone, the block goes back to the pool instead of the
operating system. Nothing is shared while any view is alive, so a result never changes
under its owner.

Blocks are matched by exact size (repeated calls of one batch size, the common case) and the
pool keeps at most :data:`MAX_BYTES` (environment ``ANALYSIS_POOL_BYTES``; ``0`` turns the
pool off); arrays under :data:`MIN_BYTES` come from ``np.empty``.
"""

from __future__ import annotations

import math
import os
import threading

import numpy as np

__all__ = ["MAX_BYTES", "MIN_BYTES", "clear", "empty", "retained_bytes"]


def _max_bytes() -> int:
    text = os.environ.get("ANALYSIS_POOL_BYTES", str(1 << 30))
    try:
        value = int(text)
    except ValueError:
        raise ValueError(
            f"ANALYSIS_POOL_BYTES = {text!r}: expected a whole number of bytes"
        ) from None
    if value < 0:
        raise ValueError(f"ANALYSIS_POOL_BYTES = {value}: must be >= 0 (0 turns the pool off)")
    return value


MAX_BYTES = _max_bytes()
"""Bytes the pool may keep for reuse (default 1 GiB)."""
MIN_BYTES = 1 << 20
"""Smaller arrays are not pooled (their first touch is cheap)."""

_lock = threading.RLock()  # re-entrant: a release may run from the GC inside _take
_free: dict[int, list[np.ndarray]] = {}
_retained = 0


class _Block:
    """Owns one pooled buffer; returns it to the pool when the last array over it is gone."""

    __slots__ = ("buf",)

    def __init__(self, buf: np.ndarray) -> None:
        self.buf = buf

    def __del__(self) -> None:
        _release(self.buf)


class _Exported:
    """What NumPy wraps (``__array_interface__``): the array's ``base``, holding the block."""

    __slots__ = ("__array_interface__", "_block")

    def __init__(self, interface: dict, block: _Block) -> None:
        self.__array_interface__ = interface
        self._block = block


def _take(nbytes: int) -> np.ndarray:
    global _retained
    with _lock:
        blocks = _free.get(nbytes)
        if blocks:
            _retained -= nbytes
            return blocks.pop()
    return np.empty(nbytes, dtype=np.uint8)


def _release(buf: np.ndarray) -> None:
    global _retained
    if _free is None or _lock is None:  # pragma: no cover - interpreter shutdown
        return
    with _lock:
        if _retained + buf.nbytes <= MAX_BYTES:
            _free.setdefault(buf.nbytes, []).append(buf)
            _retained += buf.nbytes


def empty(shape: tuple[int, ...], dtype=float) -> np.ndarray:
    """``np.empty(shape, dtype)``, from the pool when large enough (C order).

    >>> a = empty((1000, 300))
    >>> a.shape, a.dtype, a.flags.c_contiguous, a.flags.writeable
    ((1000, 300), dtype('float64'), True, True)
    """
    dt = np.dtype(dtype)
    shape = tuple(int(s) for s in shape)
    nbytes = math.prod(shape) * dt.itemsize
    if MAX_BYTES == 0 or nbytes < MIN_BYTES:
        return np.empty(shape, dtype=dt)
    buf = _take(nbytes)
    interface = {
        "data": (buf.ctypes.data, False),
        "shape": shape,
        "typestr": dt.str,
        "version": 3,
    }
    return np.asarray(_Exported(interface, _Block(buf)))


def retained_bytes() -> int:
    """Bytes kept for reuse now (not held by any array)."""
    return _retained


def clear() -> None:
    """Give every kept block back to the operating system."""
    global _retained
    with _lock:
        _free.clear()
        _retained = 0
