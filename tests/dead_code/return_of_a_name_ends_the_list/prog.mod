MODULE Prog
  ! RETURN of a variable cannot raise: the statement after it is dead whatever the answers,
  ! handler or not.
  VAR num result := 0;
  VAR num divisor := 0;
  FUNC num Ratio(num d)
    VAR num q;
    q := 10 / d;
    RETURN q;
    RETURN -1;
  ERROR
    IF ERRNO = ERR_DIVZERO TRYNEXT;
  ENDFUNC
  PROC main()
    TPReadNum divisor, "divisor?";
    result := Ratio(divisor);
    TPWrite "result", \Num:=result;
  ENDPROC
ENDMODULE
