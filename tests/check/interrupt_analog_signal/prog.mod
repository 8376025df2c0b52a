MODULE prog
  ! ISignalAI orders an interrupt when the analog input rises above 5. With the input free
  ! over {0, 10}, a real controller runs OnHigh once the pressure reads 10, so 'hits'
  ! becomes 1. rapidmc models ISignalAI with no effect: OnHigh never runs, 'quiet' came out
  ! HOLDS and the TRAP was reported 'never reached under any input' (RMC701).
  VAR signalai ai_press;
  VAR intnum irq;
  VAR num hits := 0;
  PROC main()
    AliasIO "AI_PRESS", ai_press;
    CONNECT irq WITH OnHigh;
    ISignalAI ai_press, AIO_ABOVE_HIGH, 5, 0, 0, irq;
    WHILE TRUE DO
      WaitTime 1;
    ENDWHILE
  ENDPROC
  TRAP OnHigh
    hits := hits + 1;
    IF hits > 3 hits := 0;
  ENDTRAP
ENDMODULE
