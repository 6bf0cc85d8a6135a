"""Browser tests of the report site (Playwright + Debian Chromium)."""
