"""Conveyor tracking: connecting to an object on the conveyor and dropping it.

The conveyor is not modelled: WaitWObj connects at once (the object is
taken to be there) and DropWObj releases it; both change nothing rapidmc
observes.
"""
from __future__ import annotations

from .arguments import no_effect
from .registry import NO_EFFECT, compiled

compiled("WaitWObj(PERS wobjdata WObj \\num RelDist \\num MaxTime)",
         "DropWObj(PERS wobjdata WObj)",
         modelled=NO_EFFECT)(no_effect)
