"""``rapidmc ltl``: HOA on stdout, diagnostics and exit codes on bad input."""
from __future__ import annotations

import pytest

from rapidmc.cli import main
from rapidmc.diagnostics import EXIT_INPUT_ERROR, EXIT_OK
from rapidmc.ltl import read_hoa
from rapidmc.ltl.lasso import accepts_lasso

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py


def test_prints_hoa_of_the_formula(capsys):
    assert main(["ltl", "--backend", "builtin", 'G("x = 1" -> F b)']) == EXIT_OK
    automaton = read_hoa(capsys.readouterr().out)
    assert automaton.atoms == ("x = 1", "b")
    assert accepts_lasso(automaton, [], [{"x = 1"}, {"b"}])
    assert not accepts_lasso(automaton, [{"x = 1"}], [set()])


def test_negate_translates_the_negation(capsys):
    assert main(["ltl", "--backend", "builtin", "--negate", "G p"]) == EXIT_OK
    out = capsys.readouterr().out
    assert 'name: "!G p"' in out
    automaton = read_hoa(out)
    assert accepts_lasso(automaton, [{"p"}], [set()])
    assert not accepts_lasso(automaton, [], [{"p"}])


def test_malformed_formula_is_a_diagnostic_with_caret(capsys):
    assert main(["ltl", "G (a | )"]) == EXIT_INPUT_ERROR
    err = capsys.readouterr().err
    assert err.startswith("<command-line>:1:8: error: expected a formula, found ')' [RMC401]")
    assert "    G (a | )\n           ^" in err


def test_spot_backend_without_spot_is_a_usage_error(capsys, monkeypatch):
    monkeypatch.setattr("rapidmc.ltl.spot_available", lambda: False)
    assert main(["ltl", "--backend", "spot", "p"]) == EXIT_INPUT_ERROR
    assert "[RMC601]" in capsys.readouterr().err


def test_default_backend_works_without_spot(capsys, monkeypatch):
    monkeypatch.setattr("rapidmc.ltl.spot_available", lambda: False)
    assert main(["ltl", "F p"]) == EXIT_OK
    assert read_hoa(capsys.readouterr().out).atoms == ("p",)


def test_a_pattern_prints_the_automaton_of_its_translation(capsys):
    assert main(["ltl", "--backend", "builtin", "response(req, ack) before(stop)"]) == EXIT_OK
    out = capsys.readouterr().out
    assert 'name: "F stop -> (req -> !stop U (ack & !stop)) U stop"' in out
    automaton = read_hoa(out)
    assert accepts_lasso(automaton, [{"req"}, {"ack"}, {"stop"}], [set()])
    assert not accepts_lasso(automaton, [{"req"}, {"stop"}], [{"ack"}])


def test_a_malformed_pattern_is_a_diagnostic_with_caret(capsys):
    assert main(["ltl", "response(req)"]) == EXIT_INPUT_ERROR
    err = capsys.readouterr().err
    assert err.startswith("<command-line>:1:1: error: response takes 2 conditions (P, S), "
                          "found 1 [RMC860]")
