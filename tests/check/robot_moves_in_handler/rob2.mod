MODULE Rob2
  CONST robtarget pFar := [[900,0,400],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR num zero := 0;
  VAR num x := 0;
  PROC main()
    x := 1 / zero;
  ERROR
    MoveJ pFar, v100, fine, tool0;
    TRYNEXT;
  ENDPROC
ENDMODULE
