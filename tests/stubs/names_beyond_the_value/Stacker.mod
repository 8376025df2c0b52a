MODULE Stacker
  ! Issue 28: the uses name more components (.length, .width, .label, .stackable, .code)
  ! than the value declared has parts (4). The record keeps the value's four places, so
  ! the declaration loads; .code has no place, the comment says so, and stubs reports the
  ! error that remains with exit 2.
  PERS partdata partA := [120, 80, "box", TRUE];

  PROC main()
    VAR num nArea;
    nArea := partA.length * partA.width;
    IF partA.stackable THEN
      TPWrite partA.label;
    ENDIF
    partA.code := 7;
  ENDPROC
ENDMODULE
