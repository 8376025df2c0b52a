"""Grammar rules to ``rapidmc.ast``, while the parser reduces them: construction only.

One method per grammar rule (or rule alias), named like the rule; it gets
the rule's children (shaped as Lark's tree builder would shape them, see
``reductions``) and the raw entries of the parser stack, from which the
node's ``Span`` is taken: it runs from the first token of the rule's text
(a parenthesised expression starts at its parenthesis) to the last token
the parser has shifted.  The only checks made here are lexical ones the
grammar cannot express: string escapes and length, numeric range,
identifier length, reserved words read as names.  Their diagnostics wait
until the parse has succeeded, so a syntax error anywhere in the file is
reported first, and of several such problems the first in the order of a
bottom-up walk of the tree wins.

Example::

    >>> from rapidmc.syntax.parser import parse_modules
    >>> (module,) = parse_modules("MODULE m PROC main() x := 1 + 2; ENDPROC ENDMODULE", "m.mod")
    >>> module.routines[0].body[0].value.op
    '+'
"""
from __future__ import annotations

import dataclasses
import math
import re
from typing import Optional

from lark import Token

from .. import ast
from ..diagnostics import (BAD_NUMBER, BAD_STRING, IDENTIFIER_TOO_LONG, SYNTAX, UNSUPPORTED,
                           UserError, error)
from .construct import draft_class, nodes
from .reductions import children_only
from .tokens import TOKEN_TYPES

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
# Binary operators by precedence level (terminal names in the grammar) for
# the rules that leave the grouping to the lowering.
MULTIPLYING = frozenset({"STAR", "SLASH", "DIV", "MOD"})
COMPARING = frozenset({"RELATION"})
CONJOINING = frozenset({"AND"})
DISJOINING = frozenset({"OR", "XOR"})
_STRING_ESCAPE = re.compile(r'""|\\\\|\\([0-9a-fA-F]{2})|\\')
_INTEGER_LITERAL = re.compile(r"[0-9]+|0[xX][0-9a-fA-F]+|0[oO][0-7]+|0[bB][01]+")
# The nodes the hottest rules make (one or more per identifier and literal) are
# filled in as drafts right where they are made, without a builder's call
# (``construct.draft_class``; CPython allows the class assignment that ends a draft).
_SpanDraft, _NameDraft, _NameRefDraft, _NumLiteralDraft, _ArgumentDraft = DRAFTS = tuple(
    draft_class(c) for c in (ast.Span, ast.Name, ast.NameRef, ast.NumLiteral, ast.Argument))
assert None not in DRAFTS, "this Python cannot turn a draft into its node"
_Span, _Name, _NameRef, _NumLiteral, _Argument = (
    ast.Span, ast.Name, ast.NameRef, ast.NumLiteral, ast.Argument)


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
    if text.isdecimal() and text.isascii():         # the common case: [0-9]+
        return int(text)
    if _INTEGER_LITERAL.fullmatch(text):
        return int(text, 0) if text[:2].lower() in ("0x", "0o", "0b") else int(text)
    return float(text)


class Lowering:
    """The rule methods for one file; ``lexer`` tells the last token shifted.

    A token's line is read as its ``end_line``: no token of the grammar spans lines,
    and lark_cython's tokens keep ``line`` as a C int, made into a new Python int at
    each read, but ``end_line`` as the int the scanner gave, one for all the tokens
    (and spans) of a line."""

    def __init__(self, filename: str, lexer):
        self.for_file(filename, lexer)

    def for_file(self, filename: str, lexer) -> None:
        """Ready for a parse of ``filename``, as if new (the parser keeps one lowering
        with its callbacks: parser._parsing)."""
        self.filename = filename
        self.lexer = lexer
        self.problem: Optional[UserError] = None
        # Expressions written in parentheses: id -> where the parentheses start and
        # end, and the node itself (kept alive so that its id is not reused).
        self.enclosed: dict[int, tuple] = {}
        # Identifier text -> key, for the identifiers already checked and found good
        # (a file repeats its few names thousands of times).
        self.keys: dict[str, str] = {}
        # Numeric literal text -> value, for the literals already read and in range.
        self.numbers: dict[str, int | float] = {}

    # ---------------------------------------------------------------- helpers

    def report(self, problem: UserError) -> None:
        """Keep the first problem; it is raised once the whole file has parsed."""
        if self.problem is None:
            self.problem = problem

    def too_deep(self) -> None:
        self.report(error(UNSUPPORTED, f"'{self.filename}' nests expressions or statements "
                          "too deeply to analyse"))

    def enclose(self, node, entries: list) -> None:
        """``node`` stands for all of ``entries`` (parentheses around it)."""
        last = self.lexer.previous
        self.enclosed[id(node)] = (*self.text_start(entries), last.end_line, last.end_column, node)

    def span(self, entries: list) -> ast.Span:
        first = entries[0]
        if isinstance(first, TOKEN_TYPES):
            line, column = first.end_line, first.column
        else:
            line, column = self.text_start(entries)
        last = self.lexer.previous
        span = _SpanDraft()
        span.file, span.line, span.column = self.filename, line, column
        span.end_line, span.end_column = last.end_line, last.end_column
        span.__class__ = _Span
        return span

    def text_start(self, entries) -> Optional[tuple[int, int]]:
        """Where the text of ``entries`` begins (None when they hold no token)."""
        for entry in entries:
            if isinstance(entry, TOKEN_TYPES):
                return entry.end_line, entry.column
            if isinstance(entry, (list, tuple)):
                found = self.text_start(entry)
                if found is not None:
                    return found
                continue
            span = getattr(entry, "span", None)
            if span is not None:
                enclosed = self.enclosed.get(id(entry))
                return enclosed[:2] if enclosed else (span.line, span.column)
        return None

    def text_end(self, node) -> tuple[int, int]:
        """Where the text of an expression ends (after its parentheses, if any)."""
        enclosed = self.enclosed.get(id(node))
        return enclosed[2:4] if enclosed else (node.span.end_line, node.span.end_column)

    def operation_span(self, first, last) -> ast.Span:
        """From the start of ``first`` (a token or an expression) to the end of ``last``."""
        line, column = self.text_start((first,))
        span = _SpanDraft()
        span.file, span.line, span.column = self.filename, line, column
        span.end_line, span.end_column = self.text_end(last)
        span.__class__ = _Span
        return span

    def token_span(self, token: Token) -> ast.Span:
        """The span of one token (built as ``nodes.Span`` would build it, inline: the
        front end makes one for every identifier and literal)."""
        span = _SpanDraft()
        span.file, span.line, span.column = self.filename, token.end_line, token.column
        span.end_line, span.end_column = token.end_line, token.end_column
        span.__class__ = _Span
        return span

    def name(self, token: Token) -> ast.Name:
        text = token.value
        span = _SpanDraft()         # the token's span, as ``token_span`` builds it
        span.file, span.line, span.column = self.filename, token.end_line, token.column
        span.end_line, span.end_column = token.end_line, token.end_column
        span.__class__ = _Span
        key = self.keys.get(text)
        if key is None:
            key = self.checked_key(text, span)
        name = _NameDraft()
        name.text, name.key, name.span = text, key, span
        name.__class__ = _Name
        return name

    def checked_key(self, text: str, span: ast.Span) -> str:
        """The key of an identifier not met before in this file, reported if it is bad."""
        key = text.upper()
        if len(text) > MAX_IDENTIFIER_LENGTH or key in RESERVED_WORDS:
            self.report_bad_name(text, key, span)
        else:
            self.keys[text] = key
        return key

    def report_bad_name(self, text: str, key: str, span: ast.Span) -> None:
        if len(text) > MAX_IDENTIFIER_LENGTH:
            self.report(error(IDENTIFIER_TOO_LONG,
                              f"identifier '{text}' has {len(text)} characters; "
                              f"RAPID allows at most {MAX_IDENTIFIER_LENGTH}", span))
        if key in RESERVED_WORDS:
            self.report(error(SYNTAX, f"'{text}' is a reserved word and cannot be used as a "
                              "name", span))

    # ---------------------------------------------------------------- modules

    def start(self, modules, entries):
        return tuple(modules)

    def module(self, children, entries):
        name, attributes, *items, _end = children
        return nodes.Module(
            self.name(name), attributes or (),
            tuple(i for i in items if isinstance(i, (ast.RecordDefinition, ast.AliasDefinition))),
            tuple(i for i in items if isinstance(i, ast.DataDeclaration)),
            tuple(i for i in items if isinstance(i, ast.Routine)),
            self.span(entries))

    def module_attributes(self, attributes, entries):
        return tuple(attribute.value.upper() for attribute in attributes)

    # ------------------------------------------------------- type definitions

    def record_definition(self, children, entries):
        local, name, *components = children
        return nodes.RecordDefinition(local is not None, self.name(name), tuple(components),
                                    self.span(entries))

    def record_component(self, children, entries):
        type_ref, name = children
        return nodes.RecordComponent(type_ref, self.name(name), self.span(entries))

    def alias_definition(self, children, entries):
        local, base, name = children
        return nodes.AliasDefinition(local is not None, base, self.name(name), self.span(entries))

    @children_only
    def type_ref(self, children, entries=None):
        name = self.name(children[0])
        return nodes.TypeRef(name, name.span)       # the rule's text is the name

    # ------------------------------------------------------ data declarations

    def data_declaration(self, children, entries):
        scope, storage, type_ref, name, dimensions, init = children
        return nodes.DataDeclaration(storage.value.upper(), scope.value.upper() if scope else ast.GLOBAL,
                                   type_ref, self.name(name), dimensions or (), init,
                                   self.span(entries))

    def dimensions(self, sizes, entries):
        return tuple(sizes)

    # --------------------------------------------------------------- routines

    def procedure(self, children, entries):
        local, name, parameters, (data, body), backward, handler, undo, end = children
        return nodes.Routine(ast.PROC, local is not None, self.name(name), None, parameters or (),
                           data, body, backward, handler, undo, self.span(entries),
                           self.token_span(end))

    def function(self, children, entries):
        local, return_type, name, parameters, (data, body), handler, undo, end = children
        return nodes.Routine(ast.FUNC, local is not None, self.name(name), return_type,
                           parameters or (), data, body, None, handler, undo,
                           self.span(entries), self.token_span(end))

    def trap(self, children, entries):
        local, name, (data, body), handler, undo, end = children
        return nodes.Routine(ast.TRAP, local is not None, self.name(name), None, (), data, body,
                           None, handler, undo, self.span(entries), self.token_span(end))

    def routine_body(self, items, entries):
        data = tuple(i for i in items if isinstance(i, ast.DataDeclaration))
        body = tuple(i for i in items if not isinstance(i, ast.DataDeclaration)
                     and not _declaration_hole(i))
        return data, body

    def declaration_placeholder(self, children, entries):
        """A <TDN>, <DDN> or <RDN> among a module's declarations: it declares nothing."""
        return None

    def backward_handler(self, children, entries):
        return children[0]

    def undo_handler(self, children, entries):
        return children[0]

    def error_handler(self, children, entries):
        numbers, body = children
        return nodes.ErrorHandler(numbers, body, self.span(entries))

    def error_numbers(self, numbers, entries):
        return tuple(numbers)

    def parameters(self, children, entries):
        """Flatten groups of alternatives, numbering the groups of two or more."""
        result = []
        group = 0
        for entry in children:
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

    def alternatives(self, children, entries):
        _backslash, *parameters = children
        return tuple(parameters)

    def parameter(self, children, entries):
        mode, type_ref, name, rank = children
        return nodes.Parameter(mode.value.upper() if mode else ast.IN, type_ref, self.name(name),
                             rank or 0, False, None, self.span(entries))

    def conformant_dimensions(self, stars, entries):
        return len(stars)

    # ------------------------------------------------------------- statements

    def body(self, statements, entries):
        return tuple(statements)

    def assignment(self, children, entries):
        target, value = children
        return nodes.Assignment(target, value, self.span(entries))

    def procedure_call(self, children, entries):
        name, arguments = children
        return nodes.ProcedureCall(self.name(name), arguments or (), self.span(entries))

    def late_binding_call(self, children, entries):
        name_expr, arguments = children
        return nodes.LateBindingCall(name_expr, arguments or (), self.span(entries))

    def goto(self, children, entries):
        return nodes.Goto(self.name(children[0]), self.span(entries))

    def label(self, children, entries):
        return nodes.Label(self.name(children[0]), self.span(entries))

    def return_statement(self, children, entries):
        return nodes.Return(children[0], self.span(entries))

    def raise_statement(self, children, entries):
        return nodes.Raise(children[0], self.span(entries))

    def exit(self, children, entries):
        return nodes.Exit(self.span(entries))

    def retry(self, children, entries):
        return nodes.Retry(self.span(entries))

    def trynext(self, children, entries):
        return nodes.TryNext(self.span(entries))

    def connect(self, children, entries):
        target, trap = children
        return nodes.Connect(target, self.name(trap), self.span(entries))

    def placeholder_statement(self, children, entries):
        return nodes.PlaceholderStatement(children[0].value[1:-1].upper(), self.span(entries))

    def if_statement(self, children, entries):
        condition, body, *elseifs, else_body = children
        first = nodes.IfBranch(condition, body, self.span(entries))
        branches = [split for branch in (first, *elseifs) for split in _elseif_holes(branch)]
        return nodes.If(tuple(branches), else_body, self.span(entries))

    def elseif(self, children, entries):
        condition, body = children
        return nodes.IfBranch(condition, body, self.span(entries))

    def compact_if(self, children, entries):
        condition, statement = children
        return nodes.CompactIf(condition, statement, self.span(entries))

    def for_statement(self, children, entries):
        variable, start, stop, step, body = children
        return nodes.For(self.name(variable), start, stop, step, body, self.span(entries))

    def while_statement(self, children, entries):
        condition, body = children
        return nodes.While(condition, body, self.span(entries))

    def test_statement(self, children, entries):
        subject, *cases, default = children
        cases = [split for case in cases for split in _case_holes(case)]
        return nodes.Test(subject, tuple(cases), default, self.span(entries))

    def test_case(self, children, entries):
        *values, body = children
        return nodes.TestCase(tuple(values), body, self.span(entries))

    # -------------------------------------------------------------- arguments

    def arguments(self, arguments, entries):
        return tuple(arguments)

    @children_only
    def positional_argument(self, children, entries=None):
        (value,) = children
        # The argument's text is the expression's, unless parentheses enclose it: the
        # expression's span (equal to the one ``span`` would build) serves as it is.
        argument = _ArgumentDraft()
        argument.kind, argument.name, argument.value = ast.REQUIRED, None, value
        argument.source = None
        argument.span = self.span(entries or children) if id(value) in self.enclosed else value.span
        argument.__class__ = _Argument
        return argument

    def named_argument(self, children, entries):
        name, value = children
        return nodes.Argument(ast.REQUIRED, self.name(name), value, self.span(entries))

    def optional_argument(self, children, entries):
        _backslash, name, value = children
        kind = ast.SWITCH if value is None else ast.OPTIONAL
        return nodes.Argument(kind, self.name(name), value, self.span(entries))

    def conditional_argument(self, children, entries):
        _backslash, name, source = children
        return nodes.Argument(ast.CONDITIONAL, self.name(name), None, self.span(entries),
                            self.name(source))

    # ------------------------------------------------------------ expressions

    def expression(self, children, entries):
        """Relations first, then AND, then OR and XOR, each from left to right."""
        if len(children) == 3:              # one operator (each is one of the levels')
            return self.joined(*children)
        items = children
        for operators in COMPARING, CONJOINING, DISJOINING:
            items = self.grouped(items, operators)
        return items[0]

    def term(self, children, entries):
        """Operands joined by * / DIV MOD, from left to right; a sign covers one operand."""
        if len(children) == 3:              # one operator, no sign
            return self.joined(*children)
        operands = [children[0]]
        rest = iter(children[1:])
        for operator in rest:
            operand = next(rest)
            if isinstance(operand, TOKEN_TYPES):
                operand = self.negated(operand, next(rest))
            operands += (operator, operand)
        return self.grouped(operands, MULTIPLYING)[0]

    def binary(self, children, entries):
        left, operator, right = children
        return nodes.Binary(operator.value.upper(), left, right, self.span(entries))

    def grouped(self, items: list, operators: frozenset[str]) -> list:
        """``operand (operator operand)*`` with the given operators applied, left to right."""
        result = [items[0]]
        for index in range(1, len(items), 2):
            operator, operand = items[index], items[index + 1]
            if operator.type in operators:
                result[-1] = self.joined(result[-1], operator, operand)
            else:
                result += (operator, operand)
        return result

    def joined(self, left, operator: Token, right) -> ast.Binary:
        """``left operator right``, spanning both operands (and their parentheses)."""
        return nodes.Binary(operator.value.upper(), left, right, self.operation_span(left, right))

    def negated(self, sign: Token, operand):
        return nodes.Unary(sign.value.upper(), operand, self.operation_span(sign, operand))

    def unary(self, children, entries):
        operator, operand = children
        return nodes.Unary(operator.value.upper(), operand, self.span(entries))

    @children_only
    def name_ref(self, children, entries=None):
        name = self.name(children[0])
        reference = _NameRefDraft()
        reference.name, reference.span = name, name.span
        reference.__class__ = _NameRef
        return reference

    def index(self, children, entries):
        base, *indices = children
        return nodes.Index(base, tuple(indices), self.span(entries))

    def component(self, children, entries):
        base, name = children
        return nodes.Component(base, self.name(name), self.span(entries))

    def function_call(self, children, entries):
        name, arguments = children
        return nodes.FunctionCall(self.name(name), arguments or (), self.span(entries))

    def aggregate(self, items, entries):
        return nodes.Aggregate(tuple(items), self.span(entries))

    # The literals' rules: the rule's text is the one token.

    @children_only
    def placeholder(self, children, entries=None):
        return nodes.Placeholder(children[0].value[1:-1].upper(), self.token_span(children[0]))

    @children_only
    def boolean(self, children, entries=None):
        return nodes.BoolLiteral(children[0].value.upper() == "TRUE",
                                 self.token_span(children[0]))

    @children_only
    def number(self, children, entries=None):
        token = children[0]
        text = token.value
        span = _SpanDraft()         # ``token_span`` written out
        span.file, span.line, span.column = self.filename, token.end_line, token.column
        span.end_line, span.end_column = token.end_line, token.end_column
        span.__class__ = _Span
        value = self.numbers.get(text)
        if value is None:
            value = self.checked_number(text, span)
        literal = _NumLiteralDraft()
        literal.value, literal.text, literal.span = value, text, span
        literal.__class__ = _NumLiteral
        return literal

    def checked_number(self, text: str, span: ast.Span) -> int | float:
        """The value of a numeric literal not met before in this file, reported if it is
        out of range."""
        value = number_value(text)
        if isinstance(value, float) and math.isinf(value):
            self.report(error(BAD_NUMBER, f"numeric literal {text} is out of range", span))
        else:
            self.numbers[text] = value
        return value

    @children_only
    def string(self, children, entries=None):
        text = children[0].value
        value = decode_string(text)
        span = self.token_span(children[0])
        if value is None:
            self.report(error(BAD_STRING, "bad escape in string: a backslash must be followed "
                              "by another backslash or two hex digits", span))
            value = text
        elif len(value) > MAX_STRING_LENGTH:
            self.report(error(BAD_STRING, f"string of {len(value)} characters; RAPID strings "
                              f"hold at most {MAX_STRING_LENGTH}", span))
        return nodes.StringLiteral(value, span)


# Editor placeholders that stand for a clause or a declaration, not a statement: the parser
# reads them as placeholder statements, and the lowering puts them where they belong.
DECLARATION_HOLES = ("TDN", "DDN", "RDN")


def _declaration_hole(item) -> bool:
    return isinstance(item, ast.PlaceholderStatement) and item.kind in DECLARATION_HOLES


def _hole_at(body, kind: str):
    return next((i for i, s in enumerate(body)
                 if isinstance(s, ast.PlaceholderStatement) and s.kind == kind), None)


def _elseif_holes(branch):
    """An <EIT> in a branch's body is an ELSEIF clause of its own: its condition is the
    placeholder (reached only when the conditions before it are false), its body what follows."""
    at = _hole_at(branch.body, "EIT")
    if at is None:
        return [branch]
    hole = branch.body[at]
    rest = nodes.IfBranch(nodes.Placeholder("EIT", hole.span), branch.body[at + 1:], hole.span)
    return [nodes.IfBranch(branch.condition, branch.body[:at], branch.span)] + _elseif_holes(rest)


def _case_holes(case):
    """A <CSE> in a CASE body is a CASE clause of its own, whose value is the placeholder."""
    at = _hole_at(case.body, "CSE")
    if at is None:
        return [case]
    hole = case.body[at]
    rest = nodes.TestCase((nodes.Placeholder("CSE", hole.span),), case.body[at + 1:], hole.span)
    return [nodes.TestCase(case.values, case.body[:at], case.span)] + _case_holes(rest)
