MODULE Prog
  ! RETURN 10 / d raises ERR_DIVZERO for the answer 0; TRYNEXT then runs RETURN -1.
  ! The check tries the answers 1 and 5 only: RETURN -1 is unreached with them, not dead.
  VAR num result := 0;
  VAR num divisor := 0;
  FUNC num Ratio(num d)
    VAR num q;
    q := 10 / (d - 1);
    RETURN 10 / d;
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
