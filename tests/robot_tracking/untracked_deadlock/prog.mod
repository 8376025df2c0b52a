MODULE Prog
  ! A pick cycle that lowers by a fixed step from where the robot is; the third part waits
  ! for a flag nothing sets.
  VAR signaldi diPart;
  VAR bool bReady := FALSE;
  VAR num nParts := 0;
  CONST robtarget pHome := [[500, 0, 600], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    AliasIO "DI_PART", diPart;
    WHILE TRUE DO
      WaitDI diPart, 1;
      MoveL Offs(CRobT(), 0, 0, -50), v100, fine, tool0;
      nParts := nParts + 1;
      IF nParts = 3 THEN
        WaitUntil bReady;
        nParts := 0;
      ENDIF
    ENDWHILE
  ENDPROC
ENDMODULE
