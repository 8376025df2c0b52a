MODULE prog
  ! ISignalAI orders an interrupt when the analog input rises above 5. With the input free
  ! over {0, 10}, a real controller runs OnHigh once the pressure reads 10, so 'hits'
  ! becomes 1 ('quiet' is violated). ABB's rule keeps a reference value: the interrupt comes
  ! when the condition holds and the value differs from the reference (DeltaValue 0), and the
  ! reference then becomes that value; back at 0 (condition unmet, reference stays 10) and up
  ! to 10 again is no difference, so OnHigh runs once only ('once' holds).
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
