MODULE Cell
  ! The interrupt is ordered in an ERROR handler: the input it watches is kept in
  ! the state all the same, so its edge can fire OnSignal.
  VAR intnum irq;
  VAR bool fired := FALSE;
  VAR num zero := 0;
  VAR num x := 0;
  PROC main()
    x := 1 / zero;
    WHILE TRUE DO
      WaitTime 1;
    ENDWHILE
  ERROR
    CONNECT irq WITH OnSignal;
    ISignalDI di1, 1, irq;
    TRYNEXT;
  ENDPROC
  TRAP OnSignal
    fired := TRUE;
  ENDTRAP
ENDMODULE
