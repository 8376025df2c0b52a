"""A RAPID error's name appears once in what the user reads (issue 28: ``ERR_X: ERR_X: ...``).

A ``RapidError``'s text begins with its name; the texts that put the name in front
themselves (an environment routine's fault, RMC503; ``rapidmc run``'s uncaught error, RMC301;
a counterexample's headline) take only the rest (``semantics.errors.error_detail``).
"""
from __future__ import annotations

import pytest

from rapidmc.cli import main
from rapidmc.semantics.errors import error_detail, ERROR_NUMBERS

DIVIDES = """MODULE {name}
    VAR num zero := 0;
    VAR num x := 0;
    PROC {routine}()
        x := 1 / zero;
    ENDPROC
ENDMODULE
"""
COUNTS = """MODULE Counter
    VAR num n := 0;
    PROC main()
        n := n + 1;
        n := n + 1;
    ENDPROC
ENDMODULE
"""


@pytest.mark.parametrize("message, detail", [
    ("ERR_DIVZERO: division by zero", "division by zero"),
    ("ERR_DIVZERO", ""),
    ("division by zero", "division by zero"),
    ("ERR_DIVZERO_X is another text", "ERR_DIVZERO_X is another text"),
])
def test_the_detail_leaves_the_name_out(message, detail):
    assert error_detail(ERROR_NUMBERS["ERR_DIVZERO"], message) == detail


def test_an_environment_routine_that_fails_names_its_error_once(tmp_path, capsys):
    (tmp_path / "prog.mod").write_text(COUNTS)
    (tmp_path / "env.mod").write_text(DIVIDES.format(name="Plant", routine="react"))
    assert main(["check", str(tmp_path / "prog.mod"), "--env", str(tmp_path / "env.mod")]) == 2
    err = capsys.readouterr().err
    assert "[RMC503]" in err, err
    assert "stopped with ERR_DIVZERO: division by zero" in err, err
    assert err.count("ERR_DIVZERO") == 1, err


def test_an_uncaught_error_of_a_run_names_it_once(tmp_path, capsys):
    (tmp_path / "prog.mod").write_text(DIVIDES.format(name="Divide", routine="main"))
    main(["run", str(tmp_path / "prog.mod")])
    err = capsys.readouterr().err
    assert "[RMC301]" in err, err
    assert "ERR_DIVZERO (ERRNO 1001): division by zero" in err, err
    assert err.count("ERR_DIVZERO") == 1, err
