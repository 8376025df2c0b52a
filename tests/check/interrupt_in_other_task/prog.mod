MODULE Main
  ! The second task orders the interrupt: the input is kept in the state for it too.
  VAR num n := 0;
  PROC main()
    WHILE TRUE DO
      WaitTime 1;
    ENDWHILE
  ENDPROC
ENDMODULE
