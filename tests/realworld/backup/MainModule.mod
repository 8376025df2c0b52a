MODULE MainModule
  ! Configured I/O (EIO.cfg) is not part of the backup's RAPID code:
  ! diPartPresent, doGripClose and goCellState are used without declarations.

  PROC main()
    MoveAbsJ jSafe, v1000, fine, tool0;
    Reset doGripClose;
    SetGO goCellState, 1;
    WHILE nPartsTotal < MAX_PARTS DO
      WaitDI diPartPresent, 1;
      PickAndPlace;
    ENDWHILE
    SetGO goCellState, 2;
    TPWrite "Cell done, parts: " \Num:=nPartsTotal;
  ENDPROC

  PROC PickAndPlace()
    MoveJ Offs(pPick,0,0,100), v1000, z50, tGripper \WObj:=wConveyor;
    MoveL pPick, v200, fine, tGripper \WObj:=wConveyor;
    SetDO doGripClose, 1;
    WaitTime 0.3;
    TriggL Offs(pPick,0,0,100), v500, trigGrip, z10, tGripper \WObj:=wConveyor;
    MoveL pPlace, v500, fine, tGripper \WObj:=wConveyor;
    SetDO doGripClose, 0;
    nPartsTotal := nPartsTotal + 1;
    LogLine "placed part ";
  ENDPROC

  VAR triggdata trigGrip;
ENDMODULE
