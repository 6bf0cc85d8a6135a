"""Tests of analysis.studies."""
