MODULE BgMod
  PERS num nLoops := 0;
  PERS bool bInBg := FALSE;
  PROC main()
    bInBg := TRUE;
    IF nLoops < 2 THEN
      nLoops := nLoops + 1;
    ELSE
      nLoops := 0;
    ENDIF
    ExitCycle;
  ENDPROC
ENDMODULE
