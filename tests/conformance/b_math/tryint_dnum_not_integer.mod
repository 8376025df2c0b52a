MODULE MainModule
  ! Tests: TryInt on a non-integer dnum raises ERR_INT_NOTVAL; TRYNEXT continues after it.
  PROC main()
    VAR dnum d := 2.25;
    TryInt d;
    TPWrite "after TryInt";
  ERROR
    IF ERRNO = ERR_INT_NOTVAL TPWrite "ERR_INT_NOTVAL";
    TRYNEXT;
  ENDPROC
ENDMODULE
