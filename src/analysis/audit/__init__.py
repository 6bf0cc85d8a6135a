"""The audit: every printed item checked against its derivation, one register schema per paper."""
