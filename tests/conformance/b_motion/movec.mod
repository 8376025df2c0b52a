MODULE MainModule
  ! Tests: MoveC moves along a circle through CirPoint and ends at ToPoint (second argument).
  CONST robtarget pStart := [[500,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget pCir := [[600,100,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget pEnd := [[700,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    MoveL pStart, v100, fine, tool0;
    MoveC pCir, pEnd, v100, fine, tool0;
    TPWrite "end=" \Pos:=CPos();
  ENDPROC
ENDMODULE
