"""Kinematics: D-H and screw chains, arm descriptions, one closed form per arm, Pinocchio models,
pulses."""
