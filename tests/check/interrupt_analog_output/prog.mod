MODULE prog
  ! ISignalAO on an output the program sets: ordered at 0 (the reference), 3 is below the
  ! limit, 8 is above it and differs from the reference by more than 1: OnHigh runs once.
  ! Setting 8.5 then differs from the reference (8) by 0.5 only: no second interrupt.
  VAR signalao ao_speed;
  VAR intnum irq;
  VAR num hits := 0;
  PROC main()
    AliasIO "AO_SPEED", ao_speed;
    CONNECT irq WITH OnHigh;
    ISignalAO ao_speed, AIO_ABOVE_HIGH, 5, 0, 1, irq;
    SetAO ao_speed, 3;
    SetAO ao_speed, 8;
    SetAO ao_speed, 8.5;
    WHILE TRUE DO
      WaitTime 1;
    ENDWHILE
  ENDPROC
  TRAP OnHigh
    hits := hits + 1;
  ENDTRAP
ENDMODULE
