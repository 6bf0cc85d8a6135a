"""Tests of analysis.app."""
