MODULE MainModule
  ! Tests: MoveJSync calls the procedure named by its string argument during the move
  ! (at ToPoint for a fine point), before the next instruction runs.
  CONST robtarget p10 := [[500,100,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    MoveJSync p10, v100, fine, tool0, "AtPoint";
    TPWrite "after move";
    TPWrite "at=" \Pos:=CPos();
  ENDPROC

  PROC AtPoint()
    TPWrite "AtPoint called";
  ENDPROC
ENDMODULE
