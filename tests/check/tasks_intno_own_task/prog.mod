MODULE Main
  ! INTNO is set in the task whose trap starts: the reader task's INTNO stays 0.
  VAR intnum irq;
  PROC main()
    CONNECT irq WITH OnSignal;
    ISignalDI di1, 1, irq;
    WHILE TRUE DO
      WaitTime 1;
    ENDWHILE
  ENDPROC
  TRAP OnSignal
    WaitTime 1;
  ENDTRAP
ENDMODULE
