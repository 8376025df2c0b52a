MODULE MainModule
  ! Tests: BitAnd requires two arguments; one is a static argument error.
  PROC main()
    VAR byte b;
    TPWrite "must not run";
    b := BitAnd(3);
  ENDPROC
ENDMODULE
