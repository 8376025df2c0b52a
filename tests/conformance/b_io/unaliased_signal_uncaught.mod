MODULE MainModule
  ! Tests: Set on a signal variable never bound with AliasIO is a run-time error; uncaught it
  ! stops the program (error number not asserted).
  VAR signaldo doA;
  PROC main()
    TPWrite "before";
    Set doA;
    TPWrite "not reached";
  ENDPROC
ENDMODULE
