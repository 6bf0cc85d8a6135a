"""Tests of analysis.plc."""
