MODULE MainModule
  ! Tests: ClkStart takes a clock; a num variable is a static type error.
  PROC main()
    VAR num c;
    TPWrite "must not run";
    ClkStart c;
  ENDPROC
ENDMODULE
