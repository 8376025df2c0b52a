"""The command line's subcommands: one module per ``rapidmc`` command.

Each module adds its arguments to the parser (``cli``) and turns a parsed
command line into calls to the stages below (``api`` for ``check``), then
prints the report and returns the exit code.  ``console`` drives ``rapidmc
run``: the FlexPendant as standard input and output.

May import: every stage, and ``api``; nothing imports it but ``cli``.
"""
