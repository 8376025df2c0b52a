MODULE undo_on_exit
  ! Tests: EXIT leaves the active routines abnormally, so their UNDO
  ! handlers run (innermost first) before the program ends (reference 4.5:
  ! UNDO runs on PP to Main, ExitCycle, EXIT and error unwinding).
  PROC leaf()
    TPWrite "leaf exits";
    EXIT;
  UNDO
    TPWrite "undo leaf";
  ENDPROC
  PROC main()
    leaf;
    TPWrite "not reached";
  UNDO
    TPWrite "undo main";
  ENDPROC
ENDMODULE
