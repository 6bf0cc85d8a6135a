"""Seed 000 (Li Feng et al., Food & Machinery 2016): its checks (:mod:`.checks`), its printed
STL listings executed (:mod:`.listings`) and Table 4 recomputed (:mod:`.table4`)."""
