"""Sockets, files and other controller I/O routines (registered with special_routines)."""
from __future__ import annotations
