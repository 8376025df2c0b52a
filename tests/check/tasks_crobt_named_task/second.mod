MODULE Second
  CONST robtarget p2 := [[50,0,300],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS bool moved := FALSE;
  PERS num seen := 0;
  PERS num seen_ref := 0;
  VAR robtarget other;
  PROC main()
    MoveJ p2, v1000, fine, tool0;
    WaitUntil moved;
    other := CRobT(\TaskName:="T_ROB1");
    seen := other.trans.x;
    seen_ref := CRobT(\TaskRef:=T_ROB1Id).trans.x;
    WHILE TRUE DO
      WaitTime 1;
    ENDWHILE
  ENDPROC
ENDMODULE
