MODULE MainModule
  ! Tests: StrDigCmp with a non-digit string raises ERR_INT_NOTVAL.
  PROC main()
    VAR bool b;
    b := StrDigCmp("-1", LT, "5");
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_INT_NOTVAL THEN
      TPWrite "ERR_INT_NOTVAL";
    ELSE
      TPWrite "other error";
    ENDIF
  ENDPROC
ENDMODULE
