"""Findings beyond verdicts: what a complete search shows besides HOLDS or VIOLATED.

``explored`` gathers them while the run-time error search walks every state:
``coverage`` (statements no input reaches), ``vacuity`` (properties whose
trigger never happens); ``fixed_readings`` names the controller readings a
check took as fixed.  Each finding is a ``Diagnostic`` for the report.

For editors (``rapidmc lsp``): ``editor`` gives the diagnostics of the
documents open in an editor (syntax, static, lint), ``declarations`` the
declaration a name at a place refers to.

May import: everything below it (``ast``, ``diagnostics``, ``semantics``,
``ltl``, ``check``, ``model``).
"""
