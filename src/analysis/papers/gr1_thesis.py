"""The GR-1 thesis as printed (Chen Huihuang, Xiangtan University 2007): the module view of
``data/papers/gr1.toml`` (:mod:`analysis.papers`): ``ARM``, ``MOTOR``, ``ENCODER``,
``TABLE2_1`` .. ``TABLE5_4``, ``CUBIC``, ``MATRICES``, ``EQUATIONS``, ``LISTING`` (the VB6
listing), ``LADDER``, ``TEXT_CLAIMS``, ``LOST``, ``UNCERTAIN`` ...; ``parse(text, symbols=
"kinematics" | "cubic")``; ``CUBIC_SYMBOLS`` the symbols of section 5.4.1."""

import sympy as sp

from analysis.papers import legacy, load


def parse(text: str, symbols: str = "kinematics") -> sp.Expr:
    if symbols not in ("kinematics", "cubic"):
        raise ValueError(f"symbols must be 'kinematics' or 'cubic', not {symbols!r}")
    return load("gr1").parse(text, "main" if symbols == "kinematics" else "cubic")


_view = legacy("gr1", parse=parse)


def __getattr__(attr: str):
    if attr == "CUBIC_SYMBOLS":
        return {k: v for k, v in load("gr1").symbols("cubic").items() if isinstance(v, sp.Symbol)}
    return _view(attr)
