MODULE MainModule
  ! Tests: SetGO with a value outside 0..2^n-1 (here negative) raises ERR_GO_LIM.
  VAR signalgo goCode;
  PROC main()
    AliasIO "GO1", goCode;
    SetGO goCode, -1;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_GO_LIM THEN
      TPWrite "ERR_GO_LIM";
    ELSE
      TPWrite "other error";
    ENDIF
  ENDPROC
ENDMODULE
