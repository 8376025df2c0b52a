MODULE divzero_trynext
  ! Tests: division by zero raises ERR_DIVZERO, caught by the routine's ERROR
  ! handler; ERRNO holds ERR_DIVZERO; TRYNEXT continues with the statement
  ! after the failing one.
  PROC main()
    VAR num d := 0;
    VAR num x := 5;
    x := 10 / d;
    TPWrite "x=" \Num:=x;
  ERROR
    IF ERRNO = ERR_DIVZERO TPWrite "caught ERR_DIVZERO";
    TRYNEXT;
  ENDPROC
ENDMODULE
