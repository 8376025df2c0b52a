MODULE MainModule
  ! Tests: MoveL moves linearly to ToPoint; after a sequence of moves the robot is at the last one.
  CONST robtarget p10 := [[500,100,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p20 := [[600,-100,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    MoveL p10, v100, z10, tool0;
    TPWrite "first=" \Pos:=CPos();
    MoveL p20, v100, fine, tool0;
    TPWrite "second=" \Pos:=CPos();
  ENDPROC
ENDMODULE
