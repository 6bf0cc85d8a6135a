"""Seed 002 (Yang, Li, Gao 2016): its checks (:mod:`.checks`), runs of the reconstructed
mechanism (:mod:`.method`) and the product of exponentials held against other routes
(:mod:`.poe_checks`)."""
