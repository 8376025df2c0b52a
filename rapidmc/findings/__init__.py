"""Findings beyond verdicts: what a complete search shows besides HOLDS or VIOLATED.

``explored`` gathers them while the run-time error search walks every state:
``coverage`` (statements no input reaches), ``vacuity`` (properties whose
trigger never happens); ``fixed_readings`` names the controller readings a
check took as fixed.  Each finding is a ``Diagnostic`` for the report.

``lint`` finds what needs no search at all: the rules of ``rapidmc lint`` over the
syntax tree, the taint analysis of unchecked input flows, and the taint marks that let
``check --flows`` verify those flows on the state graph.
For editors (``rapidmc lsp``): ``editor`` gives the diagnostics of the
documents open in an editor (syntax, static, lint), ``declarations`` the
declaration a name at a place refers to.

May import: everything below it (``ast``, ``diagnostics``, ``semantics``,
``ltl``, ``check``, ``model``).
"""
