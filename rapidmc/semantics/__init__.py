"""The executable semantics of RAPID: one step function for ``run`` and for ``check``.

``link`` turns an AST program into a ``Program`` (symbol tables, static
checks, instructions per routine); ``state`` is the immutable, hashable
program state; ``step`` and its fast drivers (``plain_step``, ``fused_step``,
``staged_step``) give a state's successors; ``library/`` holds the predefined
routines and data by topic, with their signatures in one registry.

May import: ``ast``, ``diagnostics``.  Nothing RAPID-independent lives here.
"""
