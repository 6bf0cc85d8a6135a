"""The grabber's machine on the S7-200 (seed 000, Table 2), and the means to run it.

* :mod:`.networks`: the S7-200 STL networks that home, move, ramp and stop the three
  steppers after the IK (:func:`motion_networks`; MAP.json's ``machine`` section,
  :func:`machine_document`);
* :mod:`.profile`: the multi-segment PTO ramps from the joints' limits;
* :mod:`.engines`: a program scan by scan with its pulse trains in time, on the S7-200
  evaluator or on awlsim, behind one interface;
* :mod:`.drives`: the three drives as Table 2 wires them (positions from the pulses);
* :mod:`.scenarios`: the issue's scenarios, run on either engine into a trace, and the
  numbers they are held to;
* :mod:`.paper`: the paper's own listings (Figures 3-6) run through the same scenarios.

The S7-300 dialect stays the IK block alone: an S7-300 CPU has no pulse train output of its
own (stepper positioning there is an FM 353 module or a drive on PROFIBUS, whose function
blocks this project does not generate); its path here is the S7-200 program translated to AWL
and run on awlsim (:mod:`.engines`). The S7-1200/1500 machine is the SCL program of
:mod:`analysis.plc.machine` (technology objects' MC_* instructions).
"""

from analysis.plc.motion.networks import (
    CONTROL,
    MACHINE_IO,
    MOTION_MAP,
    STATUS,
    MotionPlan,
    machine_document,
    motion_networks,
    motion_plan,
    motion_uses,
    supports,
)
from analysis.plc.motion.profile import Ramp, ramp

__all__ = [
    "CONTROL",
    "MACHINE_IO",
    "MOTION_MAP",
    "MOTION_STARTUP",
    "STATUS",
    "MotionPlan",
    "Ramp",
    "machine_document",
    "motion_networks",
    "motion_plan",
    "motion_uses",
    "ramp",
    "supports",
]

MOTION_STARTUP = (
    "the first scan (SM0.1) turns Q0.0-Q0.7 off, enables PTO0/PTO1 for multi-segment profiles "
    "(SMB67 = SMB77 = 16#A0), writes the profile tables, sets the step idle, Homed, Busy, Done "
    "and Error off and Status 100 (not homed): nothing moves before Home, then Start"
)
