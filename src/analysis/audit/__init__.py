"""The audit: every paper's errata register as data, decided by shared check kinds.

:func:`manifestations` is the audit API (a contract, used by outside checks): every
manifestation of every paper's register, each with ``id``, ``cause``, ``status``, ``printed``,
``corrected`` and ``verify(text) -> bool``, True only when the text states what the paper
should have printed, decided by computation (:mod:`analysis.audit.kinds`).
"""

from __future__ import annotations

__all__ = ["manifestations"]


def manifestations():
    """Every manifestation of every paper's register (``data/registers/``), in order."""
    from analysis.audit.register import manifestations as _all

    yield from _all()
