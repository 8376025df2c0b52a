MODULE MainModule
  ! Tests: a CONST cannot be passed to the INOUT parameter of Incr (static error; which of the
  ! codes assign-const / not-a-reference applies is not asserted).
  CONST num limit := 3;
  PROC main()
    TPWrite "must not run";
    Incr limit;
  ENDPROC
ENDMODULE
