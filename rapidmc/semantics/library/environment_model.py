"""Model-only routines of environment modules (--env, docs/environment.md)."""
from __future__ import annotations

from ..errors import RapidError
from ..expressions import Compiled
from ..types import BOOL, NUM
from .arguments import Arguments
from .registry import CHOICE, compiled

ENVIRONMENT_ONLY = {"ANYBOOL", "ANYNUM", "SETDI", "SETAI", "SETGI"}

def where(span) -> str:
    from pathlib import Path
    return f"{Path(span.file).name}:{span.line}:{span.column}"


def site_domain(m, span, given, derived: str, default: tuple) -> tuple:
    """Check mode: what the environment may deliver to the reading site at ``span``: the
    domain an option gave (``config.<given>``) when there is one, else the site's domain
    derived from the program (``config.<derived>``, ``load.message_domains``), else
    ``default``."""
    return configured_site_domain(getattr(m.chooser, "config", None), span, given, derived,
                                  default)


def configured_site_domain(config, span, given, derived: str, default: tuple) -> tuple:
    """``site_domain`` under the check configuration ``config``."""
    explicit = tuple(getattr(config, given, ())) if given else ()
    if explicit:
        return explicit
    per_site = getattr(config, derived, {})
    return tuple(per_site.get((span.file, span.line, span.column), ())) or default


@compiled("bool AnyBool()",
          modelled=CHOICE)
def _any_bool(calls, compiler, call, entry) -> Compiled:
    Arguments(calls, compiler, call, entry)
    name = f"AnyBool at {where(call.span)}"
    return Compiled(lambda m: m.choose(name, (False, True)), BOOL)


@compiled("num AnyNum(num Low, num High)",
          modelled=CHOICE)
def _any_num(calls, compiler, call, entry) -> Compiled:
    arguments = Arguments(calls, compiler, call, entry)
    low = arguments.value("Low")
    high = arguments.value("High")
    name = f"AnyNum at {where(call.span)}"

    def any_num(m):
        lo, hi = low(m), high(m)
        if lo != int(lo) or hi != int(hi) or hi < lo or hi - lo > 1000:
            raise RapidError("ERR_ARGVALERR", "AnyNum needs integer bounds Low <= High "
                             "(at most 1001 values)")
        return m.choose(name, tuple(float(v) for v in range(int(lo), int(hi) + 1)))
    return Compiled(any_num, NUM)


