MODULE MainModule
  ! Tests: MoveJ moves the TCP to ToPoint (the robot position afterwards is the target's).
  CONST robtarget p10 := [[500,100,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    MoveJ p10, v500, fine, tool0;
    TPWrite "at=" \Pos:=CPos();
  ENDPROC
ENDMODULE
