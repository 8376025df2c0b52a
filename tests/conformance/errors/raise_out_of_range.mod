MODULE raise_out_of_range
  ! Tests: RAISE with a number outside 1..90 is itself an error: ERRNO
  ! becomes ERR_ILLRAISE, which the handler can catch.
  PROC main()
    RAISE 100;
    TPWrite "after";
  ERROR
    IF ERRNO = ERR_ILLRAISE TPWrite "illegal raise";
    TRYNEXT;
  ENDPROC
ENDMODULE
