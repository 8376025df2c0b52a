MODULE Main
  ! reg1 is data of the USER system module, which every task has its own copy of: the
  ! other task's writes to its reg1 never change this task's.
  VAR bool bad := FALSE;
  PROC main()
    reg1 := 1;
    WaitTime 1;
    IF reg1 <> 1 THEN
      bad := TRUE;
    ENDIF
  ENDPROC
ENDMODULE
