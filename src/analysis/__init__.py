"""Audit of Li Feng et al. (2016), "Research on self-navigation system of material grabbing
robot based on the inverse kinematics analysis", Food & Machinery 32(7).

Modules: :mod:`~analysis.kinematics.dh` (D-H transforms), :mod:`~analysis.kinematics.params` (Table
3),
:mod:`~analysis.kinematics.arm` (FK, closed-form IK, Jacobian), :mod:`~analysis.kinematics.pulses`
(eqs. 20-22),
:mod:`~analysis.kinematics.pinocchio_model` (independent check), :mod:`~analysis.app.plotting`,
:mod:`~analysis.app.report`. Importing the package has no side effects.
"""

__version__ = "0.1.0"
