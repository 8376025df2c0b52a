MODULE raise_user_errnum_constant
  ! Tests: the documented convention CONST errnum name := n; RAISE name;
  ! the handler compares ERRNO with the constant.
  CONST errnum ERR_EMPTY := 10;
  CONST errnum ERR_FULL := 11;
  PROC take(num stock)
    IF stock = 0 RAISE ERR_EMPTY;
    IF stock > 99 RAISE ERR_FULL;
  ENDPROC
  PROC main()
    take 0;
    take 100;
    take 5;
    TPWrite "done";
  ERROR
    IF ERRNO = ERR_EMPTY TPWrite "empty";
    IF ERRNO = ERR_FULL TPWrite "full";
    TRYNEXT;
  ENDPROC
ENDMODULE
