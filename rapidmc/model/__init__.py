"""The model of a program for checking: the RAPID system, properties, atoms, fairness, reductions.

``rapid_system`` presents a linked program as the ``TransitionSystem`` the
search engine explores (and rebuilds its counterexamples as RAPID steps);
``properties`` reads property files and compiles atoms over RAPID states,
``fused_atoms`` values them with one generated function; ``fairness`` gives
the tasks' weak-fairness constraints, ``waiting`` the search for a task that
waits forever while the others go on; ``reduction`` plans the verdict-keeping
reductions (sliced data, merged steps, partial-order reduction between tasks)
and expands reduced traces.

May import: ``ast``, ``diagnostics``, ``syntax``, ``semantics``, ``ltl``, the
generic search engine ``check`` (its protocol and result types) and ``load``.
"""
