"""Loading a program: source files, controller backups, configuration, input domains, stubs.

What a check or a run reads before any RAPID executes: ``source`` reads module
files (encodings, ``.pgf`` lists), ``backup`` finds a backup's tasks (named and
configured by ``task_config`` from BACKINFO and SYS.cfg) and the signals of its EIO
configuration, ``shared_data`` names the PERS data a task checked alone reads and
never writes, ``input_domains`` derives the values a free
group or analog input may take, and ``stubs`` writes declarations for the
names a program uses and no module declares.

May import: ``ast``, ``diagnostics``, ``syntax``, ``semantics``.
"""
