MODULE duplicate_routine
  ! Tests: two routines with one name in one module are a duplicate
  ! (RMC204).
  PROC helper()
    TPWrite "one";
  ENDPROC
  PROC helper()  ! <-- error
    TPWrite "two";
  ENDPROC
  PROC main()
    helper;
  ENDPROC
ENDMODULE
