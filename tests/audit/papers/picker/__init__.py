"""Tests of one paper's home (analysis.audit.papers)."""
