"""Going on after a syntax error: blank out the statement that failed.

RAPID statements and declarations end with ``;``.  When the parser fails
inside one, the text from the end of the previous statement (a ``;``, a
``THEN``/``DO``/``ELSE``/``END...`` keyword, a label or CASE ``:``, a
routine header or ``MODULE name``) to the next ``;`` is replaced by spaces
(line breaks kept, so positions stay true) and the file is parsed again.
Errors at a block keyword, or whose statement would take a block keyword
with it, are not recovered from: blanking them would change the block
structure and report errors that are not there.

Example::

    >>> text = "MODULE m\\nPROC p()\\n  x := ;\\n  y := 2;\\nENDPROC\\nENDMODULE"
    >>> blank_statement(text, text.index(";")).splitlines()[2].strip()
    ''
"""
from __future__ import annotations

import re
from typing import Optional

from lark.exceptions import UnexpectedCharacters, UnexpectedInput, UnexpectedToken

MAX_SYNTAX_ERRORS = 50

_NOT_CODE = re.compile(r'"(?:[^"\n]|"")*"?|![^\n]*')
_STATEMENT_END = re.compile(
    r";|\b(?:THEN|DO|ELSE|ENDIF|ENDWHILE|ENDFOR|ENDTEST|ERROR|UNDO|BACKWARD)\b|:(?!=)"
    r"|\)[ \t]*(?=\r?\n)|\bMODULE[ \t]+\w+(?:[ \t]*\([^)\n]*\))?", re.IGNORECASE)
_BLOCK_WORDS = re.compile(
    r"\b(?:MODULE|ENDMODULE|PROC|FUNC|TRAP|ENDPROC|ENDFUNC|ENDTRAP|RECORD|ENDRECORD|IF|THEN|"
    r"ELSEIF|ELSE|ENDIF|WHILE|DO|ENDWHILE|FOR|ENDFOR|TEST|CASE|DEFAULT|ENDTEST|ERROR|UNDO|"
    r"BACKWARD)\b", re.IGNORECASE)


def offset(failure: UnexpectedInput) -> int:
    """Where in the text the parser failed."""
    if isinstance(failure, UnexpectedToken) and failure.token.start_pos is not None:
        return failure.token.start_pos
    return failure.pos_in_stream or 0


def code_only(text: str) -> str:
    """``text`` with strings and comments replaced by spaces (same length)."""
    return _NOT_CODE.sub(lambda match: " " * len(match.group(0)), text)


def without_failed_statement(text: str, failure: UnexpectedInput) -> Optional[str]:
    """``text`` with the failed statement blanked, or None when that is not safe."""
    if isinstance(failure, UnexpectedToken):
        if failure.token.type == "$END" or _BLOCK_WORDS.fullmatch(str(failure.token)):
            return None
    elif not isinstance(failure, UnexpectedCharacters):
        return None
    return blank_statement(text, offset(failure))


def blank_statement(text: str, at: int) -> Optional[str]:
    """``text`` with the statement around position ``at`` turned into spaces."""
    code = code_only(text)
    start = 0
    for match in _STATEMENT_END.finditer(code, 0, at):
        start = match.end()
    end = code.find(";", at)
    if end < 0 or _BLOCK_WORDS.search(code, start, end + 1):
        return None
    blanked = re.sub(r"[^\r\n]", " ", text[start:end + 1])
    return text[:start] + blanked + text[end + 1:]
