"""``rapidmc COMMAND`` loads the modules of that command only.

Start-up is part of every check's time to verdict: the graph command's
networkx, the run command's console or the stubs writer have no business in
``rapidmc check``.  Each test runs a fresh interpreter (the test session has
loaded everything already).
"""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

PROGRAM = """MODULE Tiny
  VAR num x := 0;
  PROC main()
    x := 1;
  ENDPROC
ENDMODULE
"""
OTHER_COMMANDS = ["rapidmc.commands.graph", "rapidmc.commands.run", "rapidmc.commands.stubs",
                  "rapidmc.commands.replay", "rapidmc.commands.parse", "networkx"]


def modules_after(argv: list[str], folder: Path) -> tuple[int, set]:
    """Exit code of ``rapidmc ARGV`` in a fresh interpreter, and the modules it loaded."""
    script = ("import contextlib, io, json, sys\n"
              "from rapidmc.cli import main\n"
              "with contextlib.redirect_stdout(io.StringIO()):\n"
              f"    code = main({argv!r})\n"
              "print(json.dumps([code, sorted(sys.modules)]))\n")
    done = subprocess.run([sys.executable, "-c", script], cwd=folder, capture_output=True,
                          text=True, check=True)
    code, modules = json.loads(done.stdout.splitlines()[-1])
    return code, set(modules)


def test_check_loads_no_other_commands_module(tmp_path):
    (tmp_path / "tiny.mod").write_text(PROGRAM)
    code, modules = modules_after(["check", "tiny.mod", "--formula", 'P: F "x = 1"',
                                   "--quiet"], tmp_path)
    assert code == 0
    assert "rapidmc.commands.check" in modules
    assert not modules & set(OTHER_COMMANDS)
    # the report writers load when asked for
    assert not modules & {"rapidmc.report.html", "rapidmc.report.junit", "rapidmc.report.sarif"}


@pytest.mark.parametrize("report", [["--format", "sarif"], ["--junit", "out.xml"],
                                    ["--html", "out.html"]], ids=["sarif", "junit", "html"])
def test_a_report_writer_loads_when_asked_for(report, tmp_path):
    (tmp_path / "tiny.mod").write_text(PROGRAM)
    code, _ = modules_after(["check", "tiny.mod", "--formula", 'P: F "x = 1"', "--quiet",
                             *report], tmp_path)
    assert code == 0
    if report[0] != "--format":
        assert (tmp_path / report[1]).stat().st_size > 0


def test_the_command_list_still_names_every_command(tmp_path):
    from rapidmc.cli import SUBCOMMANDS, build_parser
    help_text = build_parser("check").format_help()
    assert all(name in help_text for name in SUBCOMMANDS)


def _last_json_line(script: str, folder):
    """What a fresh interpreter running ``script`` in ``folder`` prints last, read as JSON."""
    done = subprocess.run([sys.executable, "-c", script], cwd=folder, capture_output=True,
                          text=True, check=True)
    return json.loads(done.stdout.splitlines()[-1])


def test_check_parses_the_signatures_of_the_routines_it_looks_up_only(tmp_path):
    (tmp_path / "tiny.mod").write_text(PROGRAM.replace("x := 1;", "x := Abs(-1);"))
    script = ("import contextlib, io, json\n"
              "from rapidmc.cli import main\n"
              "from rapidmc.semantics.library import registry\n"
              "with contextlib.redirect_stdout(io.StringIO()):\n"
              "    code = main(['check', 'tiny.mod', '--formula', 'P: F \"x = 1\"', '--quiet'])\n"
              "parsed = [key for table in (registry.FUNCTIONS, registry.PROCEDURES)\n"
              "          for key, entry in table.items() if type(entry) is registry.RoutineEntry]\n"
              "print(json.dumps([code, parsed, len(registry.FUNCTIONS) + len(registry.PROCEDURES)]))\n")
    code, parsed, registered = _last_json_line(script, tmp_path)
    assert code == 0 and "ABS" in parsed
    assert registered > 500 and len(parsed) < 20


def test_the_console_script_writes_everything_and_exits_with_the_code(tmp_path):
    """``console_main`` freezes the collector before the interpreter exits (its last pass
    is work for nothing): every report is still complete."""
    (tmp_path / "tiny.mod").write_text(PROGRAM)
    done = subprocess.run([sys.executable, "-m", "rapidmc", "check", "tiny.mod", "--formula",
                           'P: G "x = 0"', "--quiet", "--format", "json", "--junit", "out.xml"],
                          cwd=tmp_path, capture_output=True, text=True)
    assert done.returncode == 1
    assert json.loads(done.stdout)["properties"][-1]["verdict"] == "VIOLATED"
    assert (tmp_path / "out.xml").read_text().rstrip().endswith("</testsuites>")


def test_the_console_script_freezes_the_collector_before_exiting(monkeypatch):
    import gc
    from rapidmc import cli
    frozen = []
    monkeypatch.setattr(cli, "main", lambda: 3)
    monkeypatch.setattr(gc, "freeze", lambda: frozen.append(True))
    with pytest.raises(SystemExit) as exited:
        cli.console_main()
    assert exited.value.code == 3 and frozen == [True]


def test_the_command_module_is_imported_without_collections_and_the_collector_runs_after(
        tmp_path):
    (tmp_path / "tiny.mod").write_text(PROGRAM)
    script = ("import contextlib, gc, io, json\n"
              "from rapidmc import cli\n"
              "passes = []\n"
              "gc.callbacks.append(lambda phase, info: passes.append(phase))\n"
              "cli._command_module('check')\n"
              "during = len(passes)\n"
              "with contextlib.redirect_stdout(io.StringIO()):\n"
              "    code = cli.main(['check', 'tiny.mod', '--quiet'])\n"
              "print(json.dumps([code, during, gc.isenabled()]))\n")
    assert _last_json_line(script, tmp_path) == [0, 0, True]
