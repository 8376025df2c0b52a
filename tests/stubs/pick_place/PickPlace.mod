MODULE PickPlace
  ! Tests: rapidmc stubs declares what the cell's CalibData and Gripper modules held
  ! (not given): targets, tool, work object, counters, flags, a slot table, a
  ! gripper procedure with a switch, a function and a trap (issue 8, part B).
  VAR num nSlot := 1;
  VAR intnum irStop;

  PROC main()
    CONNECT irStop WITH trStopReq;
    ISignalDI diStopReq, 1, irStop;
    nCycles := 0;
    WHILE nCycles < nMaxCycles DO
      PickPart;
      PlacePart;
      nCycles := nCycles + 1;
      IF bSingleCycle THEN
        EXIT;
      ENDIF
    ENDWHILE
  ENDPROC

  PROC PickPart()
    MoveJ Offs(pPick, 0, 0, nApproachZ), vFast, z50, tGripper \WObj:=wobjConveyor;
    MoveL pPick, v200, fine, tGripper \WObj:=wobjConveyor;
    GripperClose \Wait;
    WaitTime nGripDelay;
    MoveL Offs(pPick, 0, 0, nApproachZ), v200, z10, tGripper \WObj:=wobjConveyor;
  ENDPROC

  PROC PlacePart()
    nSlot := NextFreeSlot(nSlot);
    MoveJ pSlots{nSlot}, vFast, z50, tGripper \WObj:=wobjPallet;
    GripperOpen;
    TPWrite sCellName + ": part placed in slot " \Num:=nSlot;
  ENDPROC
ENDMODULE
