MODULE Main
  ! Two motion tasks, each with its own robot. The second reads a robot through a task
  ! name no loaded task has (a backup whose other tasks are not loaded): that reads its
  ! own robot, so each task's steps are taken alone (no step reads another task's robot);
  ! so does this task's read of its own robot by its own name.
  CONST robtarget p1 := [[500,0,400],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS bool moved := FALSE;
  PERS num mine := 0;
  PROC main()
    MoveJ p1, v1000, fine, tool0;
    moved := TRUE;
    mine := CRobT(\TaskRef:=T_ROB1Id).trans.x;
    WHILE TRUE DO
      WaitTime 1;
    ENDWHILE
  ENDPROC
ENDMODULE
