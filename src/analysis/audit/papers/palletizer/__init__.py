"""Seed 001 (Li Zhaoxiang, Hu Jie 2021): its checks (:mod:`.checks`) and its printed method as
a model (:mod:`.method`: the IK chain, the D-H table read off the printed matrices)."""
