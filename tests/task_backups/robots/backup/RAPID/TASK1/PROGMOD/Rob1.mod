MODULE Rob1
  PERS bool go := FALSE;
  PERS num done := 0;
  CONST robtarget home := [[0,600,600],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p10 := [[500,0,300],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    MoveJ home, v1000, fine, tool0;
    WaitUntil go;
    MoveL p10, v500, fine, tool0;
    MoveJ home, v1000, fine, tool0;
    done := 1;
  ENDPROC
ENDMODULE
