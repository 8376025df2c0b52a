MODULE Main
  ! A division by zero caught by this task's handler sets this task's ERRNO only.
  VAR num zero := 0;
  VAR num q := 0;
  PROC main()
    q := 1 / zero;
    WHILE TRUE DO
      WaitTime 1;
    ENDWHILE
  ERROR
    TRYNEXT;
  ENDPROC
ENDMODULE
