MODULE Watcher
  VAR intnum irq;
  PERS bool ready := FALSE;
  PERS bool hit := FALSE;
  PROC main()
    WaitUntil ready;
    CONNECT irq WITH OnSignal;
    ISignalDI di1, 1, irq;
    WHILE TRUE DO
      WaitTime 1;
    ENDWHILE
  ENDPROC
  TRAP OnSignal
    hit := TRUE;
  ENDTRAP
ENDMODULE
