MODULE MainModule
  ! Tests: StrDigCalc division (OpDiv) by "0" raises ERR_CALC_DIVZERO; so does OpMod.
  PROC main()
    Calc OpDiv;
    Calc OpMod;
  ENDPROC

  PROC Calc(opcalc op)
    VAR string res;
    res := StrDigCalc("5", op, "0");
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_CALC_DIVZERO THEN
      TPWrite "ERR_CALC_DIVZERO";
    ELSE
      TPWrite "other error";
    ENDIF
  ENDPROC
ENDMODULE
