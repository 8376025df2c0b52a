MODULE Reader
  ! Written for the test (issue 28): a plain read of the command the other task's wait
  ! stores depends on that wait's step.
  PERS string command := "";
  VAR num seen := 0;
  PROC main()
    IF command <> "" THEN                ! SHARED
      seen := 1;
    ENDIF
  ENDPROC
ENDMODULE
