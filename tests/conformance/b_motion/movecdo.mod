MODULE MainModule
  ! Tests: MoveCDO moves along the circle to ToPoint and sets the digital output.
  CONST robtarget pStart := [[500,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget pCir := [[600,100,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget pEnd := [[700,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR signaldo doGlue;
  PROC main()
    AliasIO "DO2", doGlue;
    MoveL pStart, v100, fine, tool0;
    MoveCDO pCir, pEnd, v100, fine, tool0, doGlue, 1;
    TPWrite "glue=" \Num:=DOutput(doGlue);
    TPWrite "end=" \Pos:=CPos();
  ENDPROC
ENDMODULE
