"""Seed 004 (Chen Huihuang, Xiangtan University thesis 2007): its checks (:mod:`.checks`), the
thesis recomputed (:mod:`.thesis`), its VB6 listing run (:mod:`.listing`) and the figures of
notebook 10 (:mod:`.plots`)."""
