MODULE exit_terminates_program
  ! Tests: EXIT terminates the whole program, even from a called routine;
  ! the caller does not continue; the run ends normally (exit code 0).
  PROC finish()
    TPWrite "finishing";
    EXIT;
    TPWrite "not reached in finish";
  ENDPROC
  PROC main()
    TPWrite "start";
    finish;
    TPWrite "not reached in main";
  ENDPROC
ENDMODULE
