MODULE MainModule
  ! Tests: a StrDigCalc operand above 4294967295 raises ERR_INT_MAXVAL.
  PROC main()
    VAR string res;
    res := StrDigCalc("4294967296", OpSub, "1");
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_INT_MAXVAL THEN
      TPWrite "ERR_INT_MAXVAL";
    ELSE
      TPWrite "other error";
    ENDIF
  ENDPROC
ENDMODULE
