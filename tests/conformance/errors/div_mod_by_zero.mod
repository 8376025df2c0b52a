MODULE div_mod_by_zero
  ! Tests: DIV and MOD by zero also raise ERR_DIVZERO.
  VAR num caught := 0;
  PROC main()
    VAR num z := 0;
    VAR num r;
    r := 7 DIV z;
    r := 7 MOD z;
    TPWrite "caught=" \Num:=caught;
  ERROR
    IF ERRNO = ERR_DIVZERO caught := caught + 1;
    TRYNEXT;
  ENDPROC
ENDMODULE
