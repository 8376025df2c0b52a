MODULE Second
  CONST robtarget p2 := [[50,0,300],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS bool moved := FALSE;
  PERS num seen := 0;
  PROC main()
    MoveJ p2, v1000, fine, tool0;
    WaitUntil moved;
    seen := CRobT(\TaskName:="T_ROB9").trans.x;
    WHILE TRUE DO
      WaitTime 1;
    ENDWHILE
  ENDPROC
ENDMODULE
