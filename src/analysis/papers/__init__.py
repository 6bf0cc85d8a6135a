"""The papers as printed, transcribed as data: nothing here imports other analysis code."""
