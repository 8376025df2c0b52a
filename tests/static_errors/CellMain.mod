MODULE CellMain
  ! Tests: every static error of a program is reported at once (issue 8, part A).
  ! A cell program whose teach-point module was not given, plus real mistakes.
  VAR num nParts := 0;
  VAR gripdata gMain;
  PROC main()
    Init;
    WHILE TRUE DO
      MoveJ pApproach, v500, z50, tGripper \WObj:=wobjTable;
      MoveL pPick, v100, fine, tGripper \WObj:=wobjTable;
      GripClose;
      MoveL pApproach, v500, z50, tGripper \WObj:=wobjTable;
      nParts := nParts + "1";
      IF bStopReq THEN
        EXIT;
      ENDIF
    ENDWHILE
  ENDPROC
  PROC Init()
    gMain.force := 20;
    nParts := 0;
    Incr 5;
  ENDPROC
ENDMODULE
