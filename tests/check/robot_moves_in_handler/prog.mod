MODULE Rob1
  CONST robtarget pNear := [[300,0,400],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    MoveJ pNear, v100, fine, tool0;
  ENDPROC
ENDMODULE
