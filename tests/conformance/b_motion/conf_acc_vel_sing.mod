MODULE MainModule
  ! Tests: ConfJ, ConfL, AccSet, VelSet and SingArea are accepted with their documented
  ! arguments and do not change where a move ends.
  CONST robtarget p10 := [[500,100,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    ConfJ \Off;
    ConfL \On;
    AccSet 50, 100;
    VelSet 50, 800;
    SingArea \Wrist;
    MoveL p10, v1000, fine, tool0;
    SingArea \Off;
    ConfJ \On;
    ConfL \Off;
    AccSet 100, 100;
    VelSet 100, 5000;
    TPWrite "at=" \Pos:=CPos();
  ENDPROC
ENDMODULE
