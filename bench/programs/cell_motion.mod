MODULE CellMotion
  ! Motion task of a two-task cell: takes the parts the PLC task announces through
  ! shared PERS data, counts its cycles and reports a quality input.
  PERS bool bPartReady := FALSE;
  PERS num nPartsTaken := 0;
  PERS bool bGripperOk := TRUE;
  VAR num nCycle := 0;
  VAR signaldi diQuality;
  CONST robtarget pPick := [[500,0,400],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget pPlace := [[0,500,400],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

  PROC main()
    AliasIO "DI_QUALITY", diQuality;
    WHILE TRUE DO
      WaitUntil bPartReady;
      MoveJ pPick, v1000, z10, tool0;
      IF diQuality = 1 AND bGripperOk THEN
        MoveL pPlace, v500, fine, tool0;
        nPartsTaken := (nPartsTaken + 1) MOD 4;
      ENDIF
      bPartReady := FALSE;
      nCycle := (nCycle + 1) MOD 3;
    ENDWHILE
  ENDPROC
ENDMODULE
