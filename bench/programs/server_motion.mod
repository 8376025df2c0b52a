MODULE ServerMotion
  ! Motion task of the remote-controlled cell: runs each command the socket task
  ! hands over, and a gripper check between commands.
  PERS num nCommand;
  PERS num nMoves;
  VAR num nIdle := 0;
  VAR signaldi diGripper;
  VAR signaldo doGrip;
  CONST robtarget pHome := [[400,0,600],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget pPick := [[500,0,400],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget pPlace := [[0,500,400],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

  PROC main()
    AliasIO "DI_GRIPPER", diGripper;
    AliasIO "DO_GRIP", doGrip;
    WHILE TRUE DO
      IF nCommand = 0 THEN
        nIdle := (nIdle + 1) MOD 3;
        IF diGripper = 0 THEN
          SetDO doGrip, 0;
        ENDIF
      ELSE
        TEST nCommand
        CASE 1:
          MoveJ pHome, v1000, z10, tool0;
        CASE 2:
          MoveJ pPick, v1000, z10, tool0;
          SetDO doGrip, 1;
        CASE 3:
          MoveL pPlace, v500, fine, tool0;
          SetDO doGrip, 0;
        ENDTEST
        nMoves := (nMoves + 1) MOD 4;
        nCommand := 0;
      ENDIF
    ENDWHILE
  ENDPROC
ENDMODULE
