MODULE MainModule
  ! Tests: a robtarget read with CRobT can be used as a move target to return to that point.
  CONST robtarget p10 := [[500,100,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p20 := [[600,-100,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    VAR robtarget saved;
    MoveL p10, v100, fine, tool0;
    saved := CRobT();
    MoveL p20, v100, fine, tool0;
    MoveL saved, v100, fine, tool0;
    TPWrite "back=" \Pos:=CPos();
  ENDPROC
ENDMODULE
