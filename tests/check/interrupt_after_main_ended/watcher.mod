MODULE Watcher
  PERS bool main_done := FALSE;
  VAR intnum irq;
  VAR bool fired := FALSE;
  PROC main()
    WaitUntil main_done;
    CONNECT irq WITH OnSignal;
    ISignalDI di1, 1, irq;
    WHILE TRUE DO
      WaitTime 1;
    ENDWHILE
  ENDPROC
  TRAP OnSignal
    fired := TRUE;
  ENDTRAP
ENDMODULE
