MODULE prog
  ! ISignalAI orders an interrupt above 50, and the pressure reads only 0 or 10: no value
  ! meets the condition, so OnHigh never runs under any input of the domain.
  VAR signalai ai_press;
  VAR intnum irq;
  VAR num hits := 0;
  PROC main()
    AliasIO "AI_PRESS", ai_press;
    CONNECT irq WITH OnHigh;
    ISignalAI ai_press, AIO_ABOVE_HIGH, 50, 0, 0, irq;
    WHILE TRUE DO
      WaitTime 1;
    ENDWHILE
  ENDPROC
  TRAP OnHigh
    hits := hits + 1;
  ENDTRAP
ENDMODULE
