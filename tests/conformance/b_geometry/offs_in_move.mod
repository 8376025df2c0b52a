MODULE MainModule
  ! Tests: Offs can be used directly as the ToPoint of a move; the robot ends at the offset point.
  CONST robtarget p10 := [[400,0,500],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    MoveL Offs(p10, 0, 50, -100), v100, fine, tool0;
    TPWrite "at=" \Pos:=CPos();
  ENDPROC
ENDMODULE
