MODULE Main
  ! Two motion tasks, each with its own robot: the second reads this task's robot with
  ! CRobT(\TaskName:="T_ROB1") and CRobT(\TaskRef:=T_ROB1Id).
  CONST robtarget p1 := [[500,0,400],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS bool moved := FALSE;
  PROC main()
    MoveJ p1, v1000, fine, tool0;
    moved := TRUE;
    WHILE TRUE DO
      WaitTime 1;
    ENDWHILE
  ENDPROC
ENDMODULE
