MODULE MainModule
  ! Tests: TryInt on 1.5 raises ERR_INT_NOTVAL, which the ERROR handler sees in ERRNO.
  PROC main()
    VAR num n := 1.5;
    TryInt n;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_INT_NOTVAL THEN
      TPWrite "ERR_INT_NOTVAL";
    ELSE
      TPWrite "other error";
    ENDIF
  ENDPROC
ENDMODULE
