"""The machine program of an arm (issue 29): power, home, move to a target, grip, stop, on
PLCopen motion blocks around the IK block, in ST, SCL and PLCopen XML; its scenarios and the
checks that hold a run to numbers computed apart from the program.

- :mod:`.spec`: what the machine needs of an arm (axes, limits, homing, status codes);
- :mod:`.program`: the ST and SCL printers;
- :mod:`.generate`: the program text beside the IK block, PLCopen XML, MAP.json;
- :mod:`.profile`: jerk-limited profile bounds computed independently of any engine;
- :mod:`.scenarios`: the scenarios (power up, home, move, ...) and the checks over a trace.
"""
