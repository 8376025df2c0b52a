"""Packed states for the compiled core: a RAPID state as vectors of value ids, and the
fused steps and atoms as code for its step machine (``check/_packed.c``).

``table``: ``PackedStateTable``, the state table the native breadth-first search
runs on, and ``packed_table(system)``, which says whether a system can use it;
``bytecode``: the compiler from fused steps and atoms to the machine's code.
"""
