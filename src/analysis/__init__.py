"""Audit of Li Feng et al. (2016), "Research on self-navigation system of material grabbing
robot based on the inverse kinematics analysis", Food & Machinery 32(7).

Modules: :mod:`~analysis.dh` (D-H transforms), :mod:`~analysis.params` (Table 3),
:mod:`~analysis.arm` (FK, closed-form IK, Jacobian), :mod:`~analysis.pulses` (eqs. 20-22),
:mod:`~analysis.pinocchio_model` (independent check), :mod:`~analysis.plotting`,
:mod:`~analysis.report`. Importing the package has no side effects.
"""

__version__ = "0.1.0"
