MODULE Partner
  PERS num code := 0;
  VAR bool early := FALSE;
  PROC main()
    TEST 0                               ! SHARED
    CASE code:
      early := TRUE;
    ENDTEST
  ENDPROC
ENDMODULE
