"""The RAPID grammar (rapid.lark), shipped as package data."""
