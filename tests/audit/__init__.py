"""Tests of analysis.audit."""
