MODULE MainModule
  ! Tests: TryInt on a num integer above num's exact integer range (8388608) raises ERR_INT_MAXVAL.
  PROC main()
    VAR num n := 10000000;
    TryInt n;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_INT_MAXVAL THEN
      TPWrite "ERR_INT_MAXVAL";
    ELSE
      TPWrite "other error";
    ENDIF
  ENDPROC
ENDMODULE
