"""Which reads of a name in a routine only index arrays (``ExpressionCompiler._outside_index``).

A read of PERS data no loaded code writes takes values of a domain the check builds, some of
them invented (one beyond each compared constant); where such a read is an array's index,
the writer (a PC's step number) is taken to write an index.  Only where the routine reads the
data for nothing else: a routine that also tests it (``IF n <> 0 x := t{n};``) reads it twice,
and the writer may change it between the reads, a race the code has, so there its reads keep
the whole domain.
"""
from __future__ import annotations

from typing import Iterator

from .. import ast


def datum_reads(routine_ast, key: str) -> Iterator[tuple]:
    """(the read, its parent node) for each occurrence of the name ``key`` in the routine,
    the read being the outermost expression built on the name by components and elements."""
    for node, above in ast.walk(routine_ast):
        if not isinstance(node, ast.NameRef) or node.name.key != key:
            continue
        top, chain = node, list(above)
        while chain and isinstance(chain[-1], (ast.Component, ast.Index)) and \
                chain[-1].base is top:
            top = chain.pop()
        yield top, (chain[-1] if chain else None)


def is_whole_index(read, parent) -> bool:
    return isinstance(parent, ast.Index) and any(index is read for index in parent.indices)


def reads_only_index(routine_ast, key: str, copies: bool = True) -> bool:
    """Whether every read of ``key`` in the routine is an array's whole index, a write of it,
    or (``copies``) the whole value assigned to a name whose every read is a whole index."""
    for read, parent in datum_reads(routine_ast, key):
        if is_whole_index(read, parent):
            continue
        if isinstance(parent, ast.Assignment) and parent.target is read:
            continue
        if copies and isinstance(parent, ast.Assignment) and parent.value is read and \
                isinstance(parent.target, ast.NameRef) and parent.target.name.key != key and \
                reads_only_index(routine_ast, parent.target.name.key, copies=False):
            continue
        return False
    return True
