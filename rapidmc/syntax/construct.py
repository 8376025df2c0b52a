"""AST nodes built without their dataclass ``__init__``, for the parser's hot path.

The nodes of ``rapidmc.ast`` are frozen dataclasses with slots: their
generated ``__init__`` sets each field through ``object.__setattr__``, which
costs about a microsecond per node, and the front end builds several nodes
per line.  ``constructor(cls)`` gives a function with the same parameters
(names, order, defaults) that fills the slots directly through their
descriptors: the node is the same object an ordinary call would build.

Example::

    >>> from rapidmc import ast
    >>> constructor(ast.Span)("m.mod", 1, 2) == ast.Span("m.mod", 1, 2)
    True
"""
from __future__ import annotations

import dataclasses
from types import SimpleNamespace
from typing import Callable

from .. import ast


def constructor(cls: type) -> Callable:
    """A fast equivalent of calling ``cls``; ``cls`` itself when its ``__init__``
    does more than set fields (a ``__post_init__``, a default factory, no slots)."""
    fields = dataclasses.fields(cls)
    if (hasattr(cls, "__post_init__") or "__slots__" not in cls.__dict__
            or any(not f.init or f.default_factory is not dataclasses.MISSING for f in fields)):
        return cls
    namespace: dict = {"__new": object.__new__, "__cls": cls}
    parameters, lines = [], []
    for number, field in enumerate(fields):
        namespace[f"__set{number}"] = cls.__dict__[field.name].__set__
        if field.default is dataclasses.MISSING:
            parameters.append(field.name)
        else:
            namespace[f"__default{number}"] = field.default
            parameters.append(f"{field.name}=__default{number}")
        lines.append(f"    __set{number}(node, {field.name})")
    source = (f"def build({', '.join(parameters)}):\n    node = __new(__cls)\n"
              + "\n".join(lines) + "\n    return node\n")
    exec(source, namespace)
    build = namespace["build"]
    build.__qualname__ = build.__name__ = cls.__name__
    return build


def _node_classes() -> dict[str, type]:
    return {name: value for name, value in vars(ast).items()
            if isinstance(value, type) and dataclasses.is_dataclass(value)
            and value.__module__ == ast.__name__}


# ``nodes.Binary(...)`` builds an ``ast.Binary``; isinstance checks use ``ast``.
NODE_CLASSES = _node_classes()
nodes = SimpleNamespace(**{name: constructor(cls) for name, cls in NODE_CLASSES.items()})
