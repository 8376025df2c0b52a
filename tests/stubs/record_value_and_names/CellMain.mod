MODULE CellMain
  ! Issue 28: record types of a module not given, declared with a value by the program and
  ! read by component name. The value fixes how many components there are and the type of
  ! each; the names the code reads take those places by type and order of use, so the
  ! record agrees with both (it used to get the value's c1..cN plus every name read:
  ! 8 components against a value of 4). The uses come first here: the values are declared
  ! in TeachData.mod. Names are not case-sensitive: .LABEL is .label.
  PROC main()
    VAR num nArea;
    VAR gantrygroup jgTemp;
    nArea := partA.length * partA.width;
    IF partA.stackable THEN
      TPWrite partA.label;
      TPWrite partA.LABEL;
    ENDIF
    ! a MultiMove group of three jointtargets: the nested values shape three places that
    ! hold records; .extax says they are jointtargets, and the names take them in order
    jgTemp := jgHome;
    jgTemp.Robot1 := jgHome.Robot1;
    jgTemp.Robot2 := jgHome.Robot2;
    jgTemp.Track.extax.eax_a := jgTemp.Track.extax.eax_a - 130;
    MoveAbsJ jgTemp.Robot1, v100, fine, tool0;
  ENDPROC
ENDMODULE
