MODULE prog
  ! IError orders an interrupt for errors of the controller's event log, which rapidmc
  ! does not model (no effect): the TRAP never runs in the check, and every verdict says so.
  VAR intnum errIrq;
  VAR num logged := 0;
  PROC main()
    CONNECT errIrq WITH OnError;
    IError COMMON_ERR, TYPE_ALL, errIrq;
    WaitTime 1;
  ENDPROC
  TRAP OnError
    logged := logged + 1;
  ENDTRAP
ENDMODULE
