MODULE MainModule
  ! Tests: MoveCSync moves along the circle to ToPoint and calls the named procedure.
  CONST robtarget pStart := [[500,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget pCir := [[600,100,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget pEnd := [[700,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    MoveL pStart, v100, fine, tool0;
    MoveCSync pCir, pEnd, v100, fine, tool0, "OnCircle";
    TPWrite "end=" \Pos:=CPos();
  ENDPROC

  PROC OnCircle()
    TPWrite "OnCircle called";
  ENDPROC
ENDMODULE
