"""The command line: usage errors are diagnostics with the documented shape."""
from __future__ import annotations


def test_usage_errors_are_one_diagnostic_line_even_with_newlines_in_arguments(capsys):
    from rapidmc.cli import main
    assert main(["check", "prog.mod", "--no-such-option", "x\ny"]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and err.endswith("[RMC601]") and "x\\ny" in err
