"""One home per paper: ``analysis.audit.papers.<paper>`` holds everything that paper's audit
needs beyond the shared kinds (:mod:`analysis.audit.kinds`): ``checks.py`` (its
:class:`~analysis.audit.context.Bespoke` ``B``: the domains, matrices, values, facts and
predicates its register names) and the model of its printed method the checks compute with.

A paper needs a folder here only if its register names something of its own: the papers
themselves are found in ``data/`` (:data:`analysis.papers.PAPERS`), and a paper without a
folder is checked by the shared kinds alone (:func:`analysis.audit.context.context`).
"""
