MODULE MainModule
  ! Tests: a negative StrDigCalc result raises ERR_CALC_NEG.
  PROC main()
    VAR string res;
    res := StrDigCalc("10", OpSub, "20");
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_CALC_NEG THEN
      TPWrite "ERR_CALC_NEG";
    ELSE
      TPWrite "other error";
    ENDIF
  ENDPROC
ENDMODULE
