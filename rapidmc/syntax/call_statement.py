"""The syntax error of a call written ``Name(a, b);`` as a statement.

A RAPID statement that calls a routine is a procedure call, whose arguments
follow the name without parentheses (``MoveL p10, v100, z10, tool0;``).
``StrToVal(text, value);`` or ``NumToStr(x, 0);`` is a function called as if
it were a procedure; ``MyProc(a, b);`` is a procedure with its arguments in
parentheses.  The parser reads ``Name(a`` as a procedure call whose first
argument is the parenthesised expression ``(a``, so it fails at the comma
(``unexpected ','; expected one of: ')'``).  This module recognises that
failure from the parser's stack (the name, the ``(`` and one expression on
top) and words the diagnostic after what ``Name`` is: a predefined function
or a ``FUNC`` of the file, or else a procedure.

(A single argument, ``Abs(x);``, parses as a procedure call with the
argument ``(x)``; linking then says that a function is not a statement.)

Example::

    >>> is_function_name("StrToVal", "")
    True
    >>> is_function_name("Helper", "FUNC bool Helper(num a) ... ENDFUNC")
    True
    >>> is_function_name("MoveL", "")
    False
"""
from __future__ import annotations

import re
from typing import Optional

from lark.exceptions import UnexpectedToken
from lark.lexer import Token



def called_name(exc: UnexpectedToken) -> Optional[Token]:
    """The routine name of a statement ``Name(a, ...`` that failed at its first comma, or None."""
    if exc.token.type != "COMMA" or exc.interactive_parser is None:
        return None
    stack = exc.interactive_parser.parser_state.value_stack
    if len(stack) < 3:
        return None
    name, opening = stack[-3], stack[-2]
    if not (isinstance(name, Token) and name.type == "NAME"
            and isinstance(opening, Token) and opening.type == "LPAR"):
        return None
    return name


def is_function_name(name: str, text: str) -> bool:
    """Whether ``name`` is a predefined function or a ``FUNC`` declared in ``text``."""
    # The table of predefined routines is only read here, on this error's path.
    from ..semantics.library import registry
    key = name.upper()
    if registry.lookup_function(key) is not None and registry.lookup_procedure(key) is None:
        return True
    declared = re.compile(r"\bFUNC\s+\w+\s+%s\s*\(" % re.escape(name), re.IGNORECASE)
    return declared.search(text) is not None


def message(name: str, text: str) -> str:
    """What the statement ``name(a, ...);`` does wrong."""
    if is_function_name(name, text):
        return (f"'{name}' is a function, called here as if it were a procedure: a function "
                f"call is not a statement; use its value, e.g. `result := {name}(...);`")
    return (f"procedure call with its arguments in parentheses: write `{name} arg1, arg2;` "
            f"(a function call is not a statement)")

