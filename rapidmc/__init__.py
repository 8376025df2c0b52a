"""rapidmc: an explicit-state LTL model checker and reference interpreter for ABB RAPID."""

__version__ = "0.1.0"
