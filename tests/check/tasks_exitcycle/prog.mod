MODULE MainMod
  PERS num nLoops := 0;
  PERS bool bInBg := FALSE;
  PROC main()
    WHILE TRUE DO
      WaitTime 1;
    ENDWHILE
  ENDPROC
ENDMODULE
