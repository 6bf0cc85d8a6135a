"""Seed 000 as printed (Li Feng et al., Food & Machinery 2016): the module view of
``data/papers/grabber.toml`` (:mod:`analysis.papers`). Each former constant is a group of
records: ``FIGURE_STL`` (Figures 3-6, reconstructed), ``MATRICES``, ``EQUATIONS``, ``TABLE2``,
``CLAIMS``, ``UNCERTAIN`` ...; ``SYMBOLS``, ``parse`` and ``matrix`` as for every paper."""

from analysis.papers import legacy, load


def _extracted() -> dict[int, str]:
    return {n: load("grabber").record(f"figure{n}")["extracted"] for n in (3, 4, 5, 6)}


__getattr__ = legacy("grabber", FIGURE_STL_EXTRACTED=_extracted)
