MODULE stop_ends_run
  ! Tests: Stop halts program execution; in `rapidmc run` this ends the run
  ! normally (exit code 0) and the following statements do not run.
  PROC main()
    TPWrite "before";
    Stop;
    TPWrite "after";
  ENDPROC
ENDMODULE
