MODULE MainModule
  ! Tests: ExitCycle ends the current cycle; a run executes one cycle, so the program stops
  ! there with exit code 0 (manual: in cycle mode execution stops at the start of main).
  ! ASSUMPTION: `rapidmc run` executes a single cycle.
  PROC main()
    TPWrite "cycle start";
    Sub;
    TPWrite "not reached";
  ENDPROC

  PROC Sub()
    ExitCycle;
    TPWrite "not reached in Sub";
  ENDPROC
ENDMODULE
