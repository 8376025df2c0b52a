MODULE TaskLists
  ! Our own program in the style of a multi-robot welding task (survey round 8): the task
  ! list of a module not given is assigned whole, as an aggregate of task names.
  VAR string sSecond := "";

  PROC main()
    tlCurrent := [["T_ROB1"],["T_ROB2"],["T_POS1"]];
    sSecond := tlCurrent{2}.taskname;
  ENDPROC
ENDMODULE
