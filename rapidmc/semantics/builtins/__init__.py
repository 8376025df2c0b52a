"""Predefined RAPID routines and data, one topic per module.

``registry`` holds the signatures and implementations (look routines up
with ``lookup_function`` / ``lookup_procedure``); ``data`` the predefined
constants.  The topic modules (math, bits, strings, stringdig, conversion,
numeric_instructions, geometry, specials) register themselves when the
registry is first queried.
"""
from .registry import (  # noqa: F401
    FUNCTION, PROCEDURE, ParameterSpec, RoutineEntry, Signature, all_entries,
    lookup_function, lookup_procedure, parse_signature,
)
