MODULE MainModule
  ! Tests: StrDigCmp with a value above 4294967295 raises ERR_INT_MAXVAL.
  PROC main()
    VAR bool b;
    b := StrDigCmp("99999999999", GT, "1");
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_INT_MAXVAL THEN
      TPWrite "ERR_INT_MAXVAL";
    ELSE
      TPWrite "other error";
    ENDIF
  ENDPROC
ENDMODULE
