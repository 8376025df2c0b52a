MODULE reraise_to_caller
  ! Tests: RAISE without argument in an ERROR handler propagates the same
  ! ERRNO to the caller's handler; the rest of the callee does not run.
  PROC divide(num d)
    VAR num x;
    x := 1 / d;
    TPWrite "not reached";
  ERROR
    TPWrite "divide handler";
    RAISE;
  ENDPROC
  PROC main()
    divide 0;
    TPWrite "after call";
  ERROR
    IF ERRNO = ERR_DIVZERO TPWrite "main handler: divzero";
    TRYNEXT;
  ENDPROC
ENDMODULE
