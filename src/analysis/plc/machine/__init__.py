"""The machine program of an arm (issue 29): power, home, move to a target, grip, stop, on
PLCopen motion blocks around the IK block, in ST, SCL and PLCopen XML; its scenarios and the
checks that hold a run to numbers computed apart from the program.

- :mod:`.spec`: what the machine needs of an arm (axes, limits, homing, status codes);
- :mod:`.program`, :mod:`.program_scl`: the ST and SCL printers;
- :mod:`.generate`: the program beside the IK block (ST, SCL, PLCopen XML) and MAP.json;
- :mod:`.tags`: its signals as a TIA Portal PLC tag table and a CODESYS GVL;
- :mod:`.profile`: jerk-limited profile bounds computed independently of any engine;
- :mod:`.scenarios`, :mod:`.checks`: the scenarios and the checks over a trace (for every
  engine: the ST engine here, the S7-200 evaluator and awlsim with the same definitions);
- :mod:`.run`, :mod:`.offline`, :mod:`.xml_st`: running it on the ST engine (``stl-run``).
"""
