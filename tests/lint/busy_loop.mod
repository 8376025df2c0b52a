MODULE BusyLoop
  PERS num seen := 0;

  PROC main()
    IF seen < 0 Polite;
    IF seen < 0 ThroughCall;
    IF seen < 0 Bounded;
    WHILE TRUE DO  ! expect: RMC805
      IF DInput(di_part) = 1 seen := seen + 1;
    ENDWHILE
  ENDPROC

  PROC Polite()
    WHILE TRUE DO
      IF DInput(di_part) = 1 seen := seen + 1;
      WaitTime 0.1;
    ENDWHILE
  ENDPROC

  PROC ThroughCall()
    WHILE TRUE DO
      Pause;
    ENDWHILE
  ENDPROC

  PROC Pause()
    WaitUntil DInput(di_part) = 1;
  ENDPROC

  PROC Bounded()
    WHILE seen < 10 DO
      seen := seen + 1;
    ENDWHILE
  ENDPROC
ENDMODULE
