MODULE MainModule
  ! Tests: ReadAnyBin loads with its signature (iodev, VAR anytype, optional \Time) and
  ! reaching it stops the run with RMC305 (exit 2): reading data of any type in binary
  ! form is not modelled.
  VAR iodev channel;
  VAR robtarget pReceived;
  PROC main()
    Open "HOME:" \File:="data.bin", channel \Bin;
    ReadAnyBin channel, pReceived \Time:=5;
  ENDPROC
ENDMODULE
