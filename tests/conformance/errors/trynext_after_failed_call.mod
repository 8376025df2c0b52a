MODULE trynext_after_failed_call
  ! Tests: when the error comes from a called routine, "the statement that
  ! caused the error" is the call: TRYNEXT in the caller continues after it.
  PROC fail()
    RAISE 7;
  ENDPROC
  PROC main()
    TPWrite "one";
    fail;
    TPWrite "two";
  ERROR
    TPWrite "handled " \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
ENDMODULE
