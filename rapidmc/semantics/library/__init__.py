"""The predefined RAPID library: every predefined routine and data object, by topic.

Each routine is one registry entry: its signature (parsed from a RAPID-like
declaration) beside its behaviour, either a pure Python function over
values (``@function``, ``@procedure``, ``@numeric``) or a factory that
compiles each call against the program state (``@compiled``); see
``registry``.  ``data`` holds the predefined data objects.  Adding a name is
adding an entry to the module of its topic (``TOPICS``); docs/predefined.md
is generated from the registry (``python -m rapidmc.semantics.library.documentation``).
"""
from .registry import (  # noqa: F401
    FUNCTION,
    PROCEDURE,
    ParameterSpec,
    RoutineEntry,
    Signature,
    all_entries,
    lookup_function,
    lookup_procedure,
    parse_signature,
)

# The modules that register routines, in the order docs/predefined.md shows them.
TOPICS = (
    "math", "numeric_instructions", "bits", "strings", "stringdig", "conversion", "geometry",
    "system", "data_access", "position", "signals", "clocks", "flexpendant", "flexpendant_ui",
    "waits", "motion", "arc_welding", "search", "motion_settings", "process_support", "path_recovery", "world_zones", "conveyor",
    "interrupts", "program_control", "error_recovery", "controller", "calibration", "tasks", "sockets", "files",
    "file_system", "raw_data", "message_queues", "vision", "smart_gripper", "environment_model",
)
