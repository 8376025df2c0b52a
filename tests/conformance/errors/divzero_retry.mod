MODULE divzero_retry
  ! Tests: RETRY re-executes the statement that caused the error, after the
  ! handler removed the cause.
  PROC main()
    VAR num d := 0;
    VAR num x;
    x := 10 / d;
    TPWrite "x=" \Num:=x;
  ERROR
    IF ERRNO = ERR_DIVZERO THEN
      TPWrite "fixing divisor";
      d := 2;
      RETRY;
    ENDIF
  ENDPROC
ENDMODULE
