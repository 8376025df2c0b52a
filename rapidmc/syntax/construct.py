"""AST nodes built without their dataclass ``__init__``, for the parser's hot path.

The nodes of ``rapidmc.ast`` are frozen dataclasses with slots: their
generated ``__init__`` sets each field through ``object.__setattr__``, which
costs about a microsecond per node, and the front end builds several nodes
per line.  ``constructor(cls)`` gives a function with the same parameters
(names, order, defaults) that fills the slots directly (see ``draft_class``):
the node is the same object an ordinary call would build.

Example::

    >>> from rapidmc import ast
    >>> constructor(ast.Span)("m.mod", 1, 2) == ast.Span("m.mod", 1, 2)
    True
"""
from __future__ import annotations

import dataclasses
from types import SimpleNamespace
from typing import Callable, Optional

from .. import ast


def constructor(cls: type) -> Callable:
    """A fast equivalent of calling ``cls``; ``cls`` itself when its ``__init__``
    does more than set fields (a ``__post_init__``, a default factory, no slots)."""
    fields = dataclasses.fields(cls)
    if (hasattr(cls, "__post_init__") or "__slots__" not in cls.__dict__
            or any(not f.init or f.default_factory is not dataclasses.MISSING for f in fields)):
        return cls
    draft = draft_class(cls)
    namespace: dict = {"__new": object.__new__, "__cls": cls, "__draft": draft}
    parameters, lines = [], []
    for number, field in enumerate(fields):
        if field.default is dataclasses.MISSING:
            parameters.append(field.name)
        else:
            namespace[f"__default{number}"] = field.default
            parameters.append(f"{field.name}=__default{number}")
        if draft is None:
            namespace[f"__set{number}"] = cls.__dict__[field.name].__set__
            lines.append(f"    __set{number}(node, {field.name})")
        else:
            lines.append(f"    node.{field.name} = {field.name}")
    made = "__new(__cls)" if draft is None else "__draft()"   # a call: cheaper than __new__
    finish = "" if draft is None else "    node.__class__ = __cls\n"
    source = (f"def build({', '.join(parameters)}):\n    node = {made}\n"
              + "\n".join(lines) + f"\n{finish}    return node\n")
    exec(source, namespace)
    build = namespace["build"]
    build.__qualname__ = build.__name__ = cls.__name__
    return build


def draft_class(cls: type) -> Optional[type]:
    """A class with the slots of ``cls`` and nothing else, so not frozen: a node is
    filled in as one of these by plain attribute stores (several times faster than
    the slots' ``__set__``), then turned into a ``cls`` by assigning its class, which
    Python allows between classes of the same layout.  None where it does not."""
    draft = type(f"{cls.__name__}Draft", (), {"__slots__": cls.__dict__["__slots__"],
                                                 "__module__": __name__})
    try:
        object.__new__(draft).__class__ = cls
    except TypeError:                   # pragma: no cover - another layout, another Python
        return None
    return draft


def _node_classes() -> dict[str, type]:
    return {name: value for name, value in vars(ast).items()
            if isinstance(value, type) and dataclasses.is_dataclass(value)
            and value.__module__ == ast.__name__}


# ``nodes.Binary(...)`` builds an ``ast.Binary``; isinstance checks use ``ast``.
NODE_CLASSES = _node_classes()
nodes = SimpleNamespace(**{name: constructor(cls) for name, cls in NODE_CLASSES.items()})
