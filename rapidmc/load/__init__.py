"""Loading a program: source files, controller backups, configuration, input domains, stubs.

What a check or a run reads before any RAPID executes: ``source`` reads module
files (encodings, ``.pgf`` lists), ``backup`` finds a backup's tasks and the
signals of its EIO configuration, ``input_domains`` derives the values a free
group or analog input may take, and ``stubs`` writes declarations for the
names a program uses and no module declares.

May import: ``ast``, ``diagnostics``, ``syntax``, ``semantics``.
"""
