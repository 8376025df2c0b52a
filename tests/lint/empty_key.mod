MODULE EmptyKey
  PROC main()
    VAR num key;
    TPReadFK key, "Choose", "Run", "", stEmpty, "Stop", stEmpty;  ! expect: RMC810, RMC810
    IF key = 2 THEN
      TPWrite "never";
    ENDIF
    TEST key
      CASE 1:
        TPWrite "run";
      CASE 4, 5:
        TPWrite "stop";
    ENDTEST
  ENDPROC
ENDMODULE
