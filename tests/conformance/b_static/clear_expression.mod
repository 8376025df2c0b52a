MODULE MainModule
  ! Tests: Clear needs a variable; an expression is a static not-a-reference error.
  PROC main()
    VAR num a := 1;
    TPWrite "must not run";
    Clear a + 1;
  ENDPROC
ENDMODULE
