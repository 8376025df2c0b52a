MODULE MainModule
  ! Tests: ExitCycle leaves the active routines abnormally, so their UNDO handlers run.
  ! ASSUMPTION: `rapidmc run` executes a single cycle.
  PROC main()
    Work;
    TPWrite "not reached";
  ENDPROC

  PROC Work()
    TPWrite "working";
    ExitCycle;
  UNDO
    TPWrite "undo Work";
  ENDPROC
ENDMODULE
