MODULE error_in_handler_propagates
  ! Tests: an error raised inside an ERROR handler goes to the caller's
  ! handler (here ERR_DIVZERO in the handler of a user error).
  PROC inner()
    VAR num z := 0;
    RAISE 8;
  ERROR
    TPWrite "inner handler";
    z := 1 / z;
    TPWrite "not reached";
  ENDPROC
  PROC main()
    inner;
    TPWrite "after";
  ERROR
    IF ERRNO = ERR_DIVZERO TPWrite "main got divzero";
    TRYNEXT;
  ENDPROC
ENDMODULE
