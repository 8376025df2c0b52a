"""Lark parse tree to ``rapidmc.ast``: construction only, no meaning.

One method per grammar rule (or rule alias), named like the rule.  Every node
gets the ``Span`` of the text it came from.  The only checks made here are
lexical ones the grammar cannot express: string escapes and length, numeric
range, identifier length.

Example::

    >>> from rapidmc.syntax.parser import parse_tree
    >>> tree = parse_tree("MODULE m PROC main() x := 1 + 2; ENDPROC ENDMODULE", "m.mod")
    >>> lower(tree, "m.mod")[0].routines[0].body[0].value.op
    '+'
"""
from __future__ import annotations

import dataclasses
import math
import re
from typing import Optional

from lark import Token, Transformer, v_args
from lark.exceptions import VisitError
from lark.tree import Meta

from .. import ast
from ..diagnostics import (BAD_NUMBER, BAD_STRING, IDENTIFIER_TOO_LONG, SYNTAX, UNSUPPORTED,
                           UserError, error)

MAX_IDENTIFIER_LENGTH = 32
# Reference 1.4.  The contextual lexer reads a reserved word as an identifier
# where no keyword fits, so the check is made here.
RESERVED_WORDS = frozenset("""
    ALIAS AND BACKWARD CASE CONNECT CONST DEFAULT DIV DO ELSE ELSEIF ENDFOR ENDFUNC ENDIF
    ENDMODULE ENDPROC ENDRECORD ENDTEST ENDTRAP ENDWHILE ERROR EXIT FALSE FOR FROM FUNC GOTO
    IF INOUT LOCAL MOD MODULE NOSTEPIN NOT NOVIEW OR PERS PROC RAISE READONLY RECORD RETRY
    RETURN STEP SYSMODULE TASK TEST THEN TO TRAP TRUE TRYNEXT UNDO VAR VIEWONLY WHILE WITH
    XOR""".split())
MAX_STRING_LENGTH = 80
_STRING_ESCAPE = re.compile(r'""|\\\\|\\([0-9a-fA-F]{2})|\\')
_INTEGER_LITERAL = re.compile(r"[0-9]+|0[xX][0-9a-fA-F]+|0[oO][0-7]+|0[bB][01]+")


def lower(tree, filename: str) -> tuple[ast.Module, ...]:
    """The modules of a parsed file."""
    try:
        return Lowering(filename).transform(tree)
    except VisitError as exc:
        if isinstance(exc.orig_exc, UserError):
            raise exc.orig_exc from None
        raise
    except RecursionError:
        raise error(UNSUPPORTED, f"'{filename}' nests expressions or statements too deeply "
                    "to analyse") from None


def decode_string(token_text: str) -> Optional[str]:
    """The value of a string literal as written (with quotes); None if an escape is bad.

    >>> decode_string('"say ""hi"" \\\\41"')
    'say "hi" A'
    """
    body = token_text[1:-1]
    bad = False

    def replace(match: re.Match) -> str:
        nonlocal bad
        text = match.group(0)
        if text == '""':
            return '"'
        if text == "\\\\":
            return "\\"
        if match.group(1):
            return chr(int(match.group(1), 16))
        bad = True
        return text

    value = _STRING_ESCAPE.sub(replace, body)
    return None if bad else value


def number_value(text: str) -> int | float:
    """The value of a numeric literal: an exact int for integer literals."""
    if _INTEGER_LITERAL.fullmatch(text):
        return int(text, 0) if text[:2].lower() in ("0x", "0o", "0b") else int(text)
    return float(text)


@v_args(meta=True)
class Lowering(Transformer):
    """The transformer from Lark tree to AST; one instance per file."""

    def __init__(self, filename: str):
        super().__init__(visit_tokens=False)
        self.filename = filename

    # ---------------------------------------------------------------- helpers

    def span(self, meta: Meta) -> ast.Span:
        return ast.Span(self.filename, meta.line, meta.column, meta.end_line, meta.end_column)

    def token_span(self, token: Token) -> ast.Span:
        return ast.Span(self.filename, token.line, token.column, token.end_line, token.end_column)

    def name(self, token: Token) -> ast.Name:
        span = self.token_span(token)
        if len(token) > MAX_IDENTIFIER_LENGTH:
            raise error(IDENTIFIER_TOO_LONG,
                        f"identifier '{token}' has {len(token)} characters; "
                        f"RAPID allows at most {MAX_IDENTIFIER_LENGTH}", span)
        key = token.upper()
        if key in RESERVED_WORDS:
            raise error(SYNTAX, f"'{token}' is a reserved word and cannot be used as a name", span)
        return ast.Name(str(token), key, span)

    # ---------------------------------------------------------------- modules

    def start(self, meta, modules):
        return tuple(modules)

    def module(self, meta, children):
        name, attributes, *items, _end = children
        return ast.Module(
            self.name(name), attributes or (),
            tuple(i for i in items if isinstance(i, (ast.RecordDefinition, ast.AliasDefinition))),
            tuple(i for i in items if isinstance(i, ast.DataDeclaration)),
            tuple(i for i in items if isinstance(i, ast.Routine)),
            self.span(meta))

    def module_attributes(self, meta, attributes):
        return tuple(attribute.upper() for attribute in attributes)

    # ------------------------------------------------------- type definitions

    def record_definition(self, meta, children):
        local, name, *components = children
        return ast.RecordDefinition(local is not None, self.name(name), tuple(components),
                                    self.span(meta))

    def record_component(self, meta, children):
        type_ref, name = children
        return ast.RecordComponent(type_ref, self.name(name), self.span(meta))

    def alias_definition(self, meta, children):
        local, base, name = children
        return ast.AliasDefinition(local is not None, base, self.name(name), self.span(meta))

    def type_ref(self, meta, children):
        (name,) = children
        return ast.TypeRef(self.name(name), self.span(meta))

    # ------------------------------------------------------ data declarations

    def data_declaration(self, meta, children):
        scope, storage, type_ref, name, dimensions, init = children
        return ast.DataDeclaration(storage.upper(), scope.upper() if scope else ast.GLOBAL,
                                   type_ref, self.name(name), dimensions or (), init,
                                   self.span(meta))

    def dimensions(self, meta, sizes):
        return tuple(sizes)

    # --------------------------------------------------------------- routines

    def procedure(self, meta, children):
        local, name, parameters, (data, body), backward, handler, undo, end = children
        return ast.Routine(ast.PROC, local is not None, self.name(name), None, parameters or (),
                           data, body, backward, handler, undo, self.span(meta),
                           self.token_span(end))

    def function(self, meta, children):
        local, return_type, name, parameters, (data, body), handler, undo, end = children
        return ast.Routine(ast.FUNC, local is not None, self.name(name), return_type,
                           parameters or (), data, body, None, handler, undo,
                           self.span(meta), self.token_span(end))

    def trap(self, meta, children):
        local, name, (data, body), handler, undo, end = children
        return ast.Routine(ast.TRAP, local is not None, self.name(name), None, (), data, body,
                           None, handler, undo, self.span(meta), self.token_span(end))

    def routine_body(self, meta, items):
        data = tuple(i for i in items if isinstance(i, ast.DataDeclaration))
        body = tuple(i for i in items if not isinstance(i, ast.DataDeclaration))
        return data, body

    def backward_handler(self, meta, children):
        return children[0]

    def undo_handler(self, meta, children):
        return children[0]

    def error_handler(self, meta, children):
        numbers, body = children
        return ast.ErrorHandler(numbers, body, self.span(meta))

    def error_numbers(self, meta, numbers):
        return tuple(numbers)

    def parameters(self, meta, entries):
        """Flatten groups of alternatives, numbering the groups of two or more."""
        result = []
        group = 0
        for entry in entries:
            if isinstance(entry, ast.Parameter):
                result.append(entry)
                continue
            number = None
            if len(entry) > 1:
                group += 1
                number = group
            result.extend(dataclasses.replace(p, optional=True, alternative_group=number)
                          for p in entry)
        return tuple(result)

    def alternatives(self, meta, children):
        _backslash, *parameters = children
        return tuple(parameters)

    def parameter(self, meta, children):
        mode, type_ref, name, rank = children
        return ast.Parameter(mode.upper() if mode else ast.IN, type_ref, self.name(name),
                             rank or 0, False, None, self.span(meta))

    def conformant_dimensions(self, meta, stars):
        return len(stars)

    # ------------------------------------------------------------- statements

    def body(self, meta, statements):
        return tuple(statements)

    def assignment(self, meta, children):
        target, value = children
        return ast.Assignment(target, value, self.span(meta))

    def procedure_call(self, meta, children):
        name, arguments = children
        return ast.ProcedureCall(self.name(name), arguments or (), self.span(meta))

    def late_binding_call(self, meta, children):
        name_expr, arguments = children
        return ast.LateBindingCall(name_expr, arguments or (), self.span(meta))

    def goto(self, meta, children):
        return ast.Goto(self.name(children[0]), self.span(meta))

    def label(self, meta, children):
        return ast.Label(self.name(children[0]), self.span(meta))

    def return_statement(self, meta, children):
        return ast.Return(children[0], self.span(meta))

    def raise_statement(self, meta, children):
        return ast.Raise(children[0], self.span(meta))

    def exit(self, meta, children):
        return ast.Exit(self.span(meta))

    def retry(self, meta, children):
        return ast.Retry(self.span(meta))

    def trynext(self, meta, children):
        return ast.TryNext(self.span(meta))

    def connect(self, meta, children):
        target, trap = children
        return ast.Connect(target, self.name(trap), self.span(meta))

    def placeholder_statement(self, meta, children):
        return ast.PlaceholderStatement(children[0][1:-1].upper(), self.span(meta))

    def if_statement(self, meta, children):
        condition, body, *elseifs, else_body = children
        first = ast.IfBranch(condition, body, self.span(meta))
        return ast.If((first, *elseifs), else_body, self.span(meta))

    def elseif(self, meta, children):
        condition, body = children
        return ast.IfBranch(condition, body, self.span(meta))

    def compact_if(self, meta, children):
        condition, statement = children
        return ast.CompactIf(condition, statement, self.span(meta))

    def for_statement(self, meta, children):
        variable, start, stop, step, body = children
        return ast.For(self.name(variable), start, stop, step, body, self.span(meta))

    def while_statement(self, meta, children):
        condition, body = children
        return ast.While(condition, body, self.span(meta))

    def test_statement(self, meta, children):
        subject, *cases, default = children
        return ast.Test(subject, tuple(cases), default, self.span(meta))

    def test_case(self, meta, children):
        *values, body = children
        return ast.TestCase(tuple(values), body, self.span(meta))

    # -------------------------------------------------------------- arguments

    def arguments(self, meta, arguments):
        return tuple(arguments)

    def positional_argument(self, meta, children):
        return ast.Argument(ast.REQUIRED, None, children[0], self.span(meta))

    def named_argument(self, meta, children):
        name, value = children
        return ast.Argument(ast.REQUIRED, self.name(name), value, self.span(meta))

    def optional_argument(self, meta, children):
        _backslash, name, value = children
        kind = ast.SWITCH if value is None else ast.OPTIONAL
        return ast.Argument(kind, self.name(name), value, self.span(meta))

    def conditional_argument(self, meta, children):
        _backslash, name, source = children
        return ast.Argument(ast.CONDITIONAL, self.name(name), None, self.span(meta),
                            self.name(source))

    # ------------------------------------------------------------ expressions

    def binary(self, meta, children):
        left, operator, right = children
        return ast.Binary(operator.upper(), left, right, self.span(meta))

    def unary(self, meta, children):
        operator, operand = children
        return ast.Unary(operator.upper(), operand, self.span(meta))

    def name_ref(self, meta, children):
        name = self.name(children[0])
        return ast.NameRef(name, name.span)

    def index(self, meta, children):
        base, *indices = children
        return ast.Index(base, tuple(indices), self.span(meta))

    def component(self, meta, children):
        base, name = children
        return ast.Component(base, self.name(name), self.span(meta))

    def function_call(self, meta, children):
        name, arguments = children
        return ast.FunctionCall(self.name(name), arguments or (), self.span(meta))

    def aggregate(self, meta, items):
        return ast.Aggregate(tuple(items), self.span(meta))

    def placeholder(self, meta, children):
        return ast.Placeholder(children[0][1:-1].upper(), self.span(meta))

    def boolean(self, meta, children):
        return ast.BoolLiteral(children[0].upper() == "TRUE", self.span(meta))

    def number(self, meta, children):
        text = str(children[0])
        value = number_value(text)
        if isinstance(value, float) and math.isinf(value):
            raise error(BAD_NUMBER, f"numeric literal {text} is out of range", self.span(meta))
        return ast.NumLiteral(value, text, self.span(meta))

    def string(self, meta, children):
        text = str(children[0])
        value = decode_string(text)
        span = self.span(meta)
        if value is None:
            raise error(BAD_STRING, "bad escape in string: a backslash must be followed by "
                        "another backslash or two hex digits", span)
        if len(value) > MAX_STRING_LENGTH:
            raise error(BAD_STRING, f"string of {len(value)} characters; RAPID strings hold "
                        f"at most {MAX_STRING_LENGTH}", span)
        return ast.StringLiteral(value, span)
