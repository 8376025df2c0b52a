"""Tests that need an outside tool skip without it, unless CI says the tool must be there."""
from __future__ import annotations

import os

import pytest


def require_tool(present: bool, variable: str, missing: str) -> None:
    """Skip when the tool is ``missing``; fail instead when ``variable`` is set to 1 (CI)."""
    if present:
        return
    if os.environ.get(variable) == "1":
        pytest.fail(f"{missing}, but {variable}=1")
    pytest.skip(missing, allow_module_level=True)   # also called at module level
