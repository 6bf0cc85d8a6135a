"""Text embedded in a generated output, escaped in one place per output kind (issue 27 item 4).

Every generator that puts a name, a title, a note or any other text from an arm description,
a closed form or a user into its output calls the function of its output kind here, and
nothing else: the PLC printers (comments and titles of every dialect, IEC 61131-3
identifiers), the URDF and PLCopen XML writers, the explorer's JavaScript inside ``<script>``
(the report site and JupyterLab), the report's HTML, and what a command prints on a terminal.
Each function makes its output *unable* to leave its context, whatever the text (line
breaks, comment terminators, markup, control characters, U+2028/U+2029): it never fails and
never needs a caller to check first.

Output kinds and their rule
---------------------------
one line (:func:`one_line`)
    Every line break (what :meth:`str.splitlines` splits on: LF, CR, VT, FF, FS, GS, RS,
    NEL, U+2028, U+2029) and every other control character (C0, DEL, C1) becomes a space;
    runs of white space become one. The base of every comment and title below.
PLC comments and titles (:func:`plc_comment`)
    One line, and the dialect's comment delimiters taken apart (a space inserted, until none
    is left): ``(*`` and ``*)`` for IEC 61131-3 ST, SCL and the ST inside PLCopen XML (CODESYS
    nests ``(* *)`` comments, so an opening one matters too), ``/*`` and ``*/`` as well
    (IEC 61131-3 3rd edition block comments). S7 ``//`` comments and ``TITLE =`` lines end at
    the line's end: one line is all they need.
IEC 61131-3 identifiers (:func:`iec_identifier`)
    IEC 61131-3 (3rd ed., 6.1.2): letters ``A-Z a-z``, digits and underscores, beginning with
    a letter or an underscore, no two underscores in a row, none at the end; case does not
    distinguish two identifiers; a keyword is no identifier. A name is mapped: any other
    character (a non-ASCII letter included) becomes ``_``, runs of ``_`` one, leading and
    trailing ``_`` dropped; a name that is then empty, begins with a digit or is a reserved
    word gets the prefix ``v_``. Callers keep the identifiers of one scope distinct
    (:meth:`analysis.plc.st.StPrinter.declare`).
XML (:func:`xml_text`, :func:`xml_attr`, :func:`xml_comment`, :func:`xml_cdata`)
    Characters XML 1.0 does not allow (C0 controls but TAB, LF, CR; U+FFFE, U+FFFF; lone
    surrogates) removed, not escaped (``&#1;`` is no XML 1.0 either); ``& < >`` as entities;
    in an attribute also ``"`` and TAB, LF, CR as character references (an attribute value's
    white space is normalised by parsers otherwise); in a comment one line and no ``--``.
JSON and JavaScript inside ``<script>`` (:func:`js_json`, :func:`js_comment`)
    JSON (strings escaped by :func:`json.dumps`), then ``<``, ``>``, ``&``, U+2028 and
    U+2029 as ``\\uXXXX`` escapes, which mean the same character in JSON and in JavaScript:
    no ``</script>``, ``<!--`` or line terminator can appear in the script's text. A
    JavaScript ``//`` comment is one line with ``<`` and ``>`` taken out.
HTML (:func:`html_text`)
    :func:`html.escape` with quotes, for text and attribute values.
TOML (:func:`toml_string`)
    A basic string: ``"`` and ``\\`` escaped, every C0 control and DEL as ``\\uXXXX`` (what
    :mod:`tomllib` reads back to the same text); the description a URDF is converted to.
Terminal (:func:`terminal`)
    Control characters (C0 but TAB and LF, DEL, C1: the escape sequences of a terminal) and
    the bidirectional overrides shown as ``\\xNN`` / ``\\uNNNN`` escapes, visible and inert.
CSV
    Structure (delimiters, quotes, line breaks inside a cell) is Python's :mod:`csv` writer's
    (:mod:`analysis.app.safe_io`). Formula cells: a cell is written as given, also one that
    begins with ``=``, ``+``, ``-`` or ``@`` (the batch output echoes every input cell byte
    for byte; a ``-5`` is a number): the CSV files are data for programs, and the README says
    to import them into a spreadsheet as text. The project's own cells are numbers and words.

Why by hand: the standard library escapes each context's syntax (:func:`json.dumps`,
:func:`html.escape`, :mod:`xml.etree.ElementTree`) but not what makes a text unable to leave
the context it is embedded in (a ``</script>`` inside JSON inside HTML, a control character
ElementTree writes as is, a PLC comment terminator); these few rules are that.
"""

from __future__ import annotations

import html
import json
import re

__all__ = [
    "LINE_BREAKS",
    "html_text",
    "iec_identifier",
    "js_comment",
    "js_json",
    "one_line",
    "plc_comment",
    "terminal",
    "toml_string",
    "xml_attr",
    "xml_cdata",
    "xml_chars",
    "xml_comment",
    "xml_text",
]

LINE_BREAKS = "\n\r\v\f\x1c\x1d\x1e\x85\u2028\u2029"
"""The characters :meth:`str.splitlines` breaks a line at."""

_CONTROL = re.compile("[\x00-\x1f\x7f-\x9f\u2028\u2029]")
_SPACES = re.compile(r"\s+")


def one_line(text) -> str:
    """``text`` on one line: line breaks and control characters as spaces, white space
    collapsed, no leading or trailing space.

    >>> one_line("a\\nORGANIZATION_BLOCK OB 100\\r\\n\\tb\\u2028c")
    'a ORGANIZATION_BLOCK OB 100 b c'
    """
    return _SPACES.sub(" ", _CONTROL.sub(" ", str(text))).strip()


_PLC_DELIMITERS = ("(*", "*)", "/*", "*/")


def plc_comment(text, delimiters=_PLC_DELIMITERS) -> str:
    """``text`` as the body of a PLC comment or title: one line, no comment delimiter
    (each taken apart by a space until none is left).

    >>> plc_comment("x *) y := 1; (* z")
    'x * ) y := 1; ( * z'
    >>> plc_comment("(*)")
    '( * )'
    """
    out = one_line(text)
    while any(d in out for d in delimiters):
        for d in delimiters:
            out = out.replace(d, f"{d[0]} {d[1]}")
    return out


IEC_RESERVED = frozenset(
    """ABS ACOS ACTION AND ANY ARRAY AT ATAN BOOL BY BYTE CASE CONFIGURATION CONSTANT CONTINUE
    COS D DATE DATE_AND_TIME DINT DO DT DWORD ELSE ELSIF END_ACTION END_CASE END_CONFIGURATION
    END_FOR END_FUNCTION END_FUNCTION_BLOCK END_IF END_PROGRAM END_REPEAT END_RESOURCE
    END_STEP END_STRUCT END_TRANSITION END_TYPE END_VAR END_WHILE EXIT EXP F_EDGE FALSE FOR
    FROM FUNCTION FUNCTION_BLOCK IF INITIAL_STEP INT INTERVAL L LD LINT LN LOG LREAL LT LTOD
    LWORD MOD NOT OF ON OR PRIORITY PROGRAM R_EDGE READ_ONLY READ_WRITE REAL REPEAT RESOURCE
    RETAIN RETURN S SIN SINGLE SINT SQRT STEP STRING STRUCT T TAN TASK THEN TIME TIME_OF_DAY TO
    TOD TRANSITION TRUE TYPE UDINT UINT ULINT UNTIL USINT VAR VAR_ACCESS VAR_EXTERNAL
    VAR_GLOBAL VAR_INPUT VAR_IN_OUT VAR_OUTPUT VAR_TEMP VOID WHILE WITH WORD XOR""".split()
)
"""Words no generated identifier may be: the keywords of IEC 61131-3 ST and SCL, the
elementary type names, the standard functions the generated code calls, and the one- and
two-letter literal prefixes and units the short names of the closed forms could collide with
(``D``, ``DT``, ``L``, ``LD``, ``LT``, ``S``, ``T``)."""


def iec_identifier(name, reserved=IEC_RESERVED) -> str:
    """An IEC 61131-3 identifier for ``name`` (the module docstring's rule).

    >>> [iec_identifier(n) for n in ("px", "d", "θ1", "a__b_", "1st", "TO", "x\\n(*y")]
    ['px', 'v_d', 'v_1', 'a_b', 'v_1st', 'v_TO', 'x_y']
    """
    out = re.sub(r"_+", "_", re.sub(r"[^A-Za-z0-9_]", "_", str(name))).strip("_")
    if not out or out[0].isdigit() or out.upper() in reserved:
        out = "v_" + out
    return out


_XML_INVALID = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ufffe\uffff\ud800-\udfff]")


def xml_chars(text) -> str:
    """``text`` with the characters XML 1.0 does not allow removed (for a writer that
    escapes the markup itself, :mod:`xml.etree.ElementTree`)."""
    return _XML_INVALID.sub("", str(text))


def xml_text(text) -> str:
    """``text`` as XML character data.

    >>> xml_text("a < b && c\\x00 ]]> d")
    'a &lt; b &amp;&amp; c ]]&gt; d'
    """
    s = _XML_INVALID.sub("", str(text))
    return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def xml_cdata(text) -> str:
    """``text`` as the content of a CDATA section (``<![CDATA[`` ... ``]]>``): characters
    XML forbids removed, and a ``]]>`` inside split across two sections.

    >>> xml_cdata("a ]]> b")
    'a ]]]]><![CDATA[> b'
    """
    return _XML_INVALID.sub("", str(text)).replace("]]>", "]]]]><![CDATA[>")


def xml_attr(text) -> str:
    """``text`` as an XML attribute value (to go between double quotes)."""
    s = xml_text(text).replace('"', "&quot;")
    return s.replace("\t", "&#9;").replace("\n", "&#10;").replace("\r", "&#13;")


def xml_comment(text) -> str:
    """``text`` as the body of an XML comment: one line, XML characters only, no ``--``
    and no ``-`` at either end (``<!-- -->`` around it stays a comment).

    >>> xml_comment("title --> <robot> ---")
    'title - -> <robot> - -'
    """
    s = one_line(_XML_INVALID.sub("", str(text)))
    while "--" in s:
        s = s.replace("--", "- -")
    return s.strip("-").strip()


_JS_UNSAFE = {"<": "\\u003c", ">": "\\u003e", "&": "\\u0026", "\u2028": "\\u2028",
              "\u2029": "\\u2029"}  # fmt: skip
_JS_UNSAFE_RE = re.compile("[<>&\u2028\u2029]")


def js_json(value, **kwargs) -> str:
    """``value`` as JSON that is also a JavaScript expression safe inside an HTML
    ``<script>`` (no ``<``, ``>``, ``&``, U+2028, U+2029 in its text).

    >>> js_json({"title": "</script><script>alert(1)//"})
    '{"title": "\\\\u003c/script\\\\u003e\\\\u003cscript\\\\u003ealert(1)//"}'
    """
    text = json.dumps(value, ensure_ascii=False, allow_nan=False, **kwargs)
    return _JS_UNSAFE_RE.sub(lambda m: _JS_UNSAFE[m.group(0)], text)


def js_comment(text) -> str:
    """``text`` as the body of a JavaScript ``//`` comment inside ``<script>``: one line,
    no ``<`` or ``>``."""
    return one_line(text).replace("<", " ").replace(">", " ")


def html_text(text) -> str:
    """``text`` as HTML text or a (quoted) attribute value."""
    return html.escape(str(text), quote=True)


_TERMINAL = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u200e\u200f\u202a-\u202e\u2066-\u2069]")


def terminal(text) -> str:
    """``text`` safe to print on a terminal: control characters (escape sequences, a
    carriage return that overwrites the line) and bidirectional overrides as visible
    escapes.

    >>> terminal("grabber\\x1b[2J\\rX")
    'grabber\\\\x1b[2J\\\\rX'
    """

    def show(m: re.Match) -> str:
        c = m.group(0)
        return repr(c)[1:-1] if ord(c) < 0x100 else f"\\u{ord(c):04x}"

    return _TERMINAL.sub(show, str(text))


def toml_string(text) -> str:
    r"""``text`` as a TOML basic string (module docstring).

    >>> print(toml_string('say "hi"\tthen\\'))
    "say \"hi\"\u0009then\\"
    """
    out = []
    for ch in str(text):
        if ch in '"\\':
            out.append("\\" + ch)
        elif ord(ch) < 0x20 or ord(ch) == 0x7F:
            out.append(f"\\u{ord(ch):04x}")
        else:
            out.append(ch)
    return '"' + "".join(out) + '"'
