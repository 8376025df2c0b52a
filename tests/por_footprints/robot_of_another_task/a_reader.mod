MODULE Reader
  ! A reading of another motion task's robot conflicts with that task's moves; the
  ! reader's own robot and a task that never moves are its own; a move of a robot no
  ! other task reads is its task's own.
  CONST robtarget pHome := [[500,0,500],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR robtarget here;
  VAR tooldata held;
  PROC main()
    MoveJ pHome, v100, fine, tool0;      ! LOCAL
    here := CRobT(\TaskName:="task 2 (b_mover)"); ! SHARED
    held := CTool(\TaskName:="task 3 (c_still)"); ! LOCAL
    here := CRobT(\TaskName:="T_ROB1");  ! LOCAL
  ENDPROC
ENDMODULE
