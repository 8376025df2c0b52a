MODULE MainModule
  ! Tests: MoveJDO sets the digital output to Value at the end of the move.
  CONST robtarget p10 := [[500,100,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR signaldo doGrip;
  PROC main()
    AliasIO "DO1", doGrip;
    TPWrite "before=" \Num:=DOutput(doGrip);
    MoveJDO p10, v100, fine, tool0, doGrip, 1;
    TPWrite "after=" \Num:=DOutput(doGrip);
    TPWrite "at=" \Pos:=CPos();
  ENDPROC
ENDMODULE
