"""Mutations of RAPID source text: token and line edits that keep most of a program intact.

Each mutation is a pure function ``(text, rng) -> text``; ``mutate`` applies a few of
them.  The token pattern is deliberately rough (it is not the front end's lexer): it
only has to split text into pieces worth deleting, duplicating, swapping or replacing.
"""
from __future__ import annotations

import random
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
CORPUS_GLOBS = ("tests/conformance/**/*.mod", "tests/realworld/**/*.mod",
                "tests/realworld/**/*.sys", "case_studies/**/*.mod", "tests/check/**/*.mod")

TOKEN = re.compile(r'"(?:[^"\n]|"")*"|\d+(?:\.\d*)?(?:[eE][+-]?\d+)?|[A-Za-z_]\w*'
                   r"|:=|<=|>=|<>|\S")
IDENTIFIER = re.compile(r"[A-Za-z_]\w*\Z")
NUMBER = re.compile(r"\d")

TYPES = ("num", "dnum", "bool", "string", "pos", "orient", "pose", "robtarget", "jointtarget",
         "tooldata", "wobjdata", "speeddata", "zonedata", "confdata", "extjoint", "intnum",
         "errnum", "signaldi", "signaldo", "signalai", "signalao", "signalgi", "signalgo",
         "clock", "iodev", "byte", "rawbytes", "loaddata", "triggdata", "socketdev")
KEYWORDS = ("IF", "THEN", "ELSE", "ELSEIF", "ENDIF", "WHILE", "DO", "ENDWHILE", "FOR", "FROM",
            "TO", "STEP", "ENDFOR", "TEST", "CASE", "DEFAULT", "ENDTEST", "RETURN", "RAISE",
            "RETRY", "TRYNEXT", "EXIT", "GOTO", "CONNECT", "WITH", "ERROR", "UNDO", "BACKWARD",
            "VAR", "PERS", "CONST", "LOCAL", "TASK", "INOUT", "PROC", "ENDPROC", "FUNC",
            "ENDFUNC", "TRAP", "ENDTRAP", "RECORD", "ENDRECORD", "ALIAS", "MODULE", "ENDMODULE",
            "NOT", "AND", "OR", "XOR", "DIV", "MOD", "TRUE", "FALSE", "switch")
ROUTINES = ("TPWrite", "TPReadNum", "TPReadFK", "WaitTime", "WaitUntil", "WaitDI", "Set",
            "Reset", "SetDO", "PulseDO", "Incr", "Decr", "Add", "Clear", "Stop", "EXIT",
            "ISignalDI", "ITimer", "IDelete", "ISleep", "IWatch", "IEnable", "IDisable",
            "AliasIO", "StrLen", "StrPart", "NumToStr", "StrToVal", "ValToStr", "Abs", "Sqrt",
            "Round", "Trunc", "Dim", "Present", "DInput", "DOutput", "AInput", "GInput",
            "ClkStart", "ClkRead", "ClkReset", "MoveL", "MoveJ", "CRobT", "Offs", "ErrWrite",
            "BitAnd", "BitLSh", "StrFind", "StrMap", "Exp", "Pow", "ACos", "ATan2", "Sin",
            "NOrient", "PoseMult", "OrientZYX", "EulerZYX", "CallByVar", "RaiseToUser")
NUMBERS = ("0", "1", "-1", "2", "0.5", "3.4E38", "1E39", "1E400", "1E-45", "65535", "65536",
           "2147483647", "2147483648", "4294967295", "4294967296", "8388608", "16777217",
           "-0", "1E308", "0.0000001", "100000000000000000000", "255", "256", "32", "81")
STRINGS = ('""', '"x"', '"' + "a" * 80 + '"', '"\\\\"', '"DI1"', '"DO1"', '"1.5"', '"[1,2,3]"',
           '"TRUE"', '"main"', '"%"')


def corpus_files() -> list[Path]:
    """The RAPID files mutations start from, in a fixed order."""
    found = set()
    for pattern in CORPUS_GLOBS:
        found.update(ROOT.glob(pattern))
    return sorted(found)


def _tokens(text: str) -> list[re.Match]:
    return list(TOKEN.finditer(text))


def _replace_token(text: str, rng: random.Random, choose) -> str:
    tokens = _tokens(text)
    if not tokens:
        return text
    token = rng.choice(tokens)
    return text[:token.start()] + choose(token.group(), tokens) + text[token.end():]


def delete_token(text: str, rng: random.Random) -> str:
    return _replace_token(text, rng, lambda word, tokens: "")


def duplicate_token(text: str, rng: random.Random) -> str:
    return _replace_token(text, rng, lambda word, tokens: word + " " + word)


def swap_tokens(text: str, rng: random.Random) -> str:
    tokens = _tokens(text)
    if len(tokens) < 2:
        return text
    index = rng.randrange(len(tokens) - 1)
    first, second = tokens[index], tokens[index + 1]
    return (text[:first.start()] + second.group() + text[first.end():second.start()]
            + first.group() + text[second.end():])


def change_identifier(text: str, rng: random.Random) -> str:
    """An identifier becomes another one: of the file, a keyword, a type or a routine."""
    def choose(word, tokens):
        names = [t.group() for t in tokens if IDENTIFIER.match(t.group())] or [word]
        pool = rng.choice((names, KEYWORDS, TYPES, ROUTINES))
        return rng.choice(pool)
    return _replace_token(text, rng, choose)


def change_number(text: str, rng: random.Random) -> str:
    numbers = [t for t in _tokens(text) if NUMBER.match(t.group())]
    if not numbers:
        return change_identifier(text, rng)
    token = rng.choice(numbers)
    return text[:token.start()] + rng.choice(NUMBERS) + text[token.end():]


def change_type(text: str, rng: random.Random) -> str:
    typed = [t for t in _tokens(text) if t.group() in TYPES]
    if not typed:
        return change_identifier(text, rng)
    token = rng.choice(typed)
    return text[:token.start()] + rng.choice(TYPES) + text[token.end():]


def insert_literal(text: str, rng: random.Random) -> str:
    """A literal replaces a token: a number, a string or an aggregate."""
    pool = NUMBERS + STRINGS + ("[1,2,3]", "[[1,2],[3,4]]", "[]", "TRUE", "{1}", "{0,0}")
    return _replace_token(text, rng, lambda word, tokens: rng.choice(pool))


def _lines(text: str) -> list[str]:
    return text.split("\n")


def delete_line(text: str, rng: random.Random) -> str:
    lines = _lines(text)
    del lines[rng.randrange(len(lines))]
    return "\n".join(lines)


def duplicate_line(text: str, rng: random.Random) -> str:
    lines = _lines(text)
    index = rng.randrange(len(lines))
    lines.insert(index, lines[index])
    return "\n".join(lines)


def swap_lines(text: str, rng: random.Random) -> str:
    lines = _lines(text)
    first, second = rng.randrange(len(lines)), rng.randrange(len(lines))
    lines[first], lines[second] = lines[second], lines[first]
    return "\n".join(lines)


def move_line(text: str, rng: random.Random) -> str:
    lines = _lines(text)
    line = lines.pop(rng.randrange(len(lines)))
    lines.insert(rng.randrange(len(lines) + 1), line)
    return "\n".join(lines)


MUTATIONS = (delete_token, duplicate_token, swap_tokens, change_identifier, change_number,
             change_type, insert_literal, delete_line, duplicate_line, swap_lines, move_line)


def mutate(text: str, rng: random.Random, count: int) -> str:
    """``count`` random mutations applied one after another."""
    for _ in range(count):
        text = rng.choice(MUTATIONS)(text, rng)
    return text
