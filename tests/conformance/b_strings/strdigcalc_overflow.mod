MODULE MainModule
  ! Tests: a StrDigCalc result above 4294967295 raises ERR_CALC_OVERFLOW.
  PROC main()
    VAR string res;
    res := StrDigCalc("4294967295", OpAdd, "1");
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_CALC_OVERFLOW THEN
      TPWrite "ERR_CALC_OVERFLOW";
    ELSE
      TPWrite "other error";
    ENDIF
  ENDPROC
ENDMODULE
