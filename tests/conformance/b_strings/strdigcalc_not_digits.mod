MODULE MainModule
  ! Tests: a StrDigCalc operand that is not a digit string raises ERR_INT_NOTVAL.
  PROC main()
    VAR string res;
    res := StrDigCalc("12a", OpAdd, "1");
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_INT_NOTVAL THEN
      TPWrite "ERR_INT_NOTVAL";
    ELSE
      TPWrite "other error";
    ENDIF
  ENDPROC
ENDMODULE
