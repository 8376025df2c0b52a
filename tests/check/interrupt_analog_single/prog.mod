MODULE prog
  ! ISignalAI \Single: the first time the pressure passes 5 runs OnHigh, then the interrupt
  ! is off. Over {0, 7, 10} the value may differ from the reference twice above 5 (7, then
  ! 10), which without \Single would run OnHigh twice.
  VAR signalai ai_press;
  VAR intnum irq;
  VAR num hits := 0;
  PROC main()
    AliasIO "AI_PRESS", ai_press;
    CONNECT irq WITH OnHigh;
    ISignalAI \Single, ai_press, AIO_ABOVE_HIGH, 5, 0, 0, irq;
    WHILE TRUE DO
      WaitTime 1;
    ENDWHILE
  ENDPROC
  TRAP OnHigh
    hits := hits + 1;
  ENDTRAP
ENDMODULE
