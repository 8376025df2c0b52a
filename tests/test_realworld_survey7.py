"""Survey round 7 (docs/realworld-survey.md): programs of ours in the styles of the public
RAPID code surveyed, one per cause of a program that did not load.

* ``effector_setup.mod``: a component of a record of a module not given is turned through
  its own components (``ee.grip.tframe.rot := ...``) before it is copied into a tooldata;
  ``rapidmc stubs`` declares the component a tooldata instead of the records it invented
  for ``.tframe`` while nothing else was known.
* ``clamp_library.mod``: types of a module not given take their shape from declared values
  (an aggregate of atomic parts: a RECORD; one number: an ALIAS of num).
* ``lap_clocks.mod``: the elements of a clock array start as stopped clocks.
* ``diagnose_codes.mod``: data of a module not given read only by components
  (``cmdCodes.READ_TIME``) gets a RECORD of the stubs, as arrays of records did.
* ``sync_release.mod``: a procedure named by a string given to MoveLSync is declared by
  the stubs when no module declares it.
"""
from __future__ import annotations

from pathlib import Path

from tests.test_realworld_survey4 import cli, verdicts

HERE = Path(__file__).resolve().parent / "realworld" / "survey7"


def stubs_text(program: Path, tmp_path: Path) -> str:
    """The module ``rapidmc stubs`` writes for ``program`` (it must succeed)."""
    output = tmp_path / "Missing.mod"
    code, _, err = cli("stubs", program, "-o", output)
    assert code == 0, err
    return output.read_text()


def assert_holds(*files, formula: str) -> None:
    """``check`` of ``files`` with ``formula`` (``name: LTL``): every property holds."""
    code, out, err = cli("check", *files, "--quiet", "--formula", formula)
    assert code == 0, err
    assert set(verdicts(out).values()) == {"HOLDS"}, out


def test_a_known_type_from_a_later_use_replaces_invented_component_records(tmp_path):
    program = HERE / "effector_setup.mod"
    text = stubs_text(program, tmp_path)
    assert "tooldata grip;" in text
    assert "effector_t_grip" not in text          # no invented record left behind
    assert_holds(program, tmp_path / "Missing.mod",
                 formula='turned: G ("Ended()" -> "nTurned = 1")')


def test_missing_types_take_their_shape_from_declared_values(tmp_path):
    program = HERE / "clamp_library.mod"
    text = stubs_text(program, tmp_path)
    assert "RECORD jawdata\n    string c1;\n    num c2;\n    bool c3;\n    bool c4;\n  ENDRECORD" \
        in text
    assert "ALIAS num stationno;" in text
    assert 'PERS jawdata jawActive := ["",0,FALSE,FALSE];' in text
    assert_holds(program, tmp_path / "Missing.mod",
                 formula='station: G ("Ended()" -> "nSelected = 4")')


def test_the_elements_of_a_clock_array_start_as_stopped_clocks():
    program = HERE / "lap_clocks.mod"
    code, out, err = cli("run", program)
    assert code == 0, err                      # was an internal error (no value to reset)
    assert_holds(program, formula='unused_lap_reads_zero: G ("Ended()" -> "nLapTime = 0")')


def test_data_read_by_components_gets_a_record_of_the_stubs(tmp_path):
    program = HERE / "diagnose_codes.mod"
    text = stubs_text(program, tmp_path)       # cmdCodes was left to the user
    assert "RECORD cmdCodes_rec\n    num READ_TIME;\n    num READ_PART;\n  ENDRECORD" in text
    assert "PERS cmdCodes_rec cmdCodes := [0,0]; ! type from: has components .READ_TIME" in text
    assert_holds(program, tmp_path / "Missing.mod", formula='both: G ("Ended()" -> "nAsked = 2")')


def test_stubs_declare_a_procedure_named_by_a_sync_move(tmp_path):
    program = HERE / "sync_release.mod"
    code, out, _ = cli("check", program, "--quiet")
    assert code == 1 and "ERR_REFUNKPRC" in out        # the procedure is not in the program
    text = stubs_text(program, tmp_path)
    assert "PROC ReleaseClamp()\n  ENDPROC" in text
    assert "CountDrop" not in text
    assert_holds(program, tmp_path / "Missing.mod",
                 formula='counted: G ("Ended()" -> "nReleased = 1")')
