"""The GR-1 thesis as printed (Chen Huihuang, Xiangtan University 2007): the module view of
``data/papers/gr1.toml`` (:mod:`analysis.papers`): ``ARM``, ``MOTOR``, ``ENCODER``,
``TABLE2_1`` .. ``TABLE5_4``, ``CUBIC``, ``MATRICES``, ``EQUATIONS``, ``LISTING`` (the VB6
listing), ``LADDER``, ``TEXT_CLAIMS``, ``LOST``, ``UNCERTAIN`` ...; ``parse(text, symbols=
"kinematics" | "cubic")``; ``CUBIC_SYMBOLS`` the symbols of section 5.4.1; ``poses()`` Table
5-3's two poses (mm, rad)."""

import math

import sympy as sp

from analysis.papers import legacy, load


def parse(text: str, symbols: str = "kinematics") -> sp.Expr:
    if symbols not in ("kinematics", "cubic"):
        raise ValueError(f"symbols must be 'kinematics' or 'cubic', not {symbols!r}")
    return load("gr1").parse(text, "main" if symbols == "kinematics" else "cubic")


def poses() -> tuple[tuple[float, ...], tuple[float, ...]]:
    """Table 5-3's start and end poses, as printed: (px, py, pz) [mm] and the RPY angles
    (alpha, beta, gamma) in radians (printed in degrees; the angle headers are lost, the
    listing's input order alpha, beta, gamma is read)."""
    rows = load("gr1").record("table5_3")["rows"]
    return tuple(  # type: ignore[return-value]
        (*(float(v) for v in rows[k][:3]), *(math.radians(float(v)) for v in rows[k][3:]))
        for k in ("start", "end")
    )


_view = legacy("gr1", parse=parse, poses=poses)


def __getattr__(attr: str):
    if attr == "CUBIC_SYMBOLS":
        return {k: v for k, v in load("gr1").symbols("cubic").items() if isinstance(v, sp.Symbol)}
    return _view(attr)
