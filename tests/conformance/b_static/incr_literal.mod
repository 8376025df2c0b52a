MODULE MainModule
  ! Tests: Incr needs a data reference (INOUT parameter); a literal is a static error.
  PROC main()
    TPWrite "must not run";
    Incr 5;
  ENDPROC
ENDMODULE
