"""Studies built on the kinematics: workspace, quantization, trajectories, companion systems."""
