"""A compact one-line notation for AST expressions and statements.

Used by the data-driven parser tests (tests/syntax/*.txt) and handy when
debugging: it shows the tree's shape and nothing else (no spans).

Example::

    >>> from rapidmc.ast import Binary, NameRef, Name, NO_SPAN
    >>> a, b = (NameRef(Name.of(x), NO_SPAN) for x in "ab")
    >>> sexpr(Binary("AND", a, b, NO_SPAN))
    '(AND a b)'
"""
from __future__ import annotations

from typing import Callable

from .. import ast


def sexpr(node) -> str:
    """The notation of an expression, argument or statement."""
    return _WRITERS[type(node)](node)


def _items(nodes) -> str:
    return "".join(" " + sexpr(node) for node in nodes)


def _body(keyword: str, statements) -> str:
    return f"({keyword}{_items(statements)})"


def _argument(node: ast.Argument) -> str:
    if node.kind == ast.REQUIRED:
        value = sexpr(node.value)
        return value if node.name is None else f"{node.name}:={value}"
    if node.kind == ast.SWITCH:
        return f"\\{node.name}"
    if node.kind == ast.CONDITIONAL:
        return f"\\{node.name}?{node.source}"
    return f"\\{node.name}:={sexpr(node.value)}"


def _if(node: ast.If) -> str:
    branches = "".join(f" ({sexpr(b.condition)}{_items(b.body)})" for b in node.branches)
    otherwise = "" if node.else_body is None else " " + _body("ELSE", node.else_body)
    return f"(IF{branches}{otherwise})"


def _for(node: ast.For) -> str:
    step = "" if node.step is None else f" STEP {sexpr(node.step)}"
    return f"(FOR {node.variable} {sexpr(node.start)} {sexpr(node.stop)}{step}{_items(node.body)})"


def _test(node: ast.Test) -> str:
    cases = "".join(f" (CASE ({sexpr(c.values[0])}{_items(c.values[1:])}){_items(c.body)})"
                    for c in node.cases)
    default = "" if node.default is None else " " + _body("DEFAULT", node.default)
    return f"(TEST {sexpr(node.subject)}{cases}{default})"


def _optional(node) -> str:
    return "" if node is None else " " + sexpr(node)


_WRITERS: dict[type, Callable] = {
    ast.NumLiteral: lambda n: repr(n.value),
    ast.StringLiteral: lambda n: '"' + n.value.replace('"', '""') + '"',
    ast.BoolLiteral: lambda n: "TRUE" if n.value else "FALSE",
    ast.NameRef: lambda n: n.name.text,
    ast.Index: lambda n: f"(index {sexpr(n.base)}{_items(n.indices)})",
    ast.Component: lambda n: f"(. {sexpr(n.base)} {n.name})",
    ast.FunctionCall: lambda n: f"(call {n.name}{_items(n.args)})",
    ast.Unary: lambda n: f"({n.op} {sexpr(n.operand)})",
    ast.Binary: lambda n: f"({n.op} {sexpr(n.left)} {sexpr(n.right)})",
    ast.Aggregate: lambda n: f"[{' '.join(sexpr(i) for i in n.items)}]",
    ast.Placeholder: lambda n: f"<{n.kind}>",
    ast.Argument: _argument,
    ast.Assignment: lambda n: f"(:= {sexpr(n.target)} {sexpr(n.value)})",
    ast.ProcedureCall: lambda n: f"(proc {n.name}{_items(n.args)})",
    ast.LateBindingCall: lambda n: f"(late {sexpr(n.name_expr)}{_items(n.args)})",
    ast.Goto: lambda n: f"(GOTO {n.label})",
    ast.Label: lambda n: f"(label {n.name})",
    ast.Return: lambda n: f"(RETURN{_optional(n.value)})",
    ast.Raise: lambda n: f"(RAISE{_optional(n.value)})",
    ast.Exit: lambda n: "(EXIT)",
    ast.Retry: lambda n: "(RETRY)",
    ast.TryNext: lambda n: "(TRYNEXT)",
    ast.Connect: lambda n: f"(CONNECT {sexpr(n.target)} {n.trap})",
    ast.If: _if,
    ast.CompactIf: lambda n: f"(IF1 {sexpr(n.condition)} {sexpr(n.statement)})",
    ast.For: _for,
    ast.While: lambda n: f"(WHILE {sexpr(n.condition)}{_items(n.body)})",
    ast.Test: _test,
    ast.PlaceholderStatement: lambda n: f"<{n.kind}>",
}
