MODULE Watcher
  VAR intnum irq;
  PERS num x := 0;
  PROC main()
    CONNECT irq WITH OnSignal;
    ISignalDI di1, 1, irq;
    WHILE TRUE DO
      WaitTime 1;
    ENDWHILE
  ENDPROC
  TRAP OnSignal
    x := 1;
    x := 0;
  ENDTRAP
ENDMODULE
