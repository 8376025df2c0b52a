MODULE Rob2
  PERS bool go := FALSE;
  CONST robtarget home := [[2000,600,600],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p10 := [[1500,0,300],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    MoveJ home, v1000, fine, tool0;
    MoveL p10, v500, fine, tool0;
    go := TRUE;
  ENDPROC
ENDMODULE
