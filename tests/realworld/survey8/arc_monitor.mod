MODULE ArcMonitor
  ! Our own program in the style of a welding-equipment background task (survey
  ! round 8): analog-output interrupts with their three limits written positionally,
  ! and a handshake wait that shows a FlexPendant message (\Visualize, RobotWare 6).
  VAR intnum intCurrent;
  VAR num nChanges := 0;

  PROC main()
    CONNECT intCurrent WITH CurrentChanged;
    ISignalAO aoWeldCurrent, AIO_BETWEEN, 400, 0, 1, intCurrent;
    WaitDI diArcEstablished, 1 \Visualize \Header:="Arc" \Message:="Waiting for the arc" \Icon:=iconInfo;
    SetDO doWeldDone, 1;
  ENDPROC

  TRAP CurrentChanged
    Incr nChanges;
  ENDTRAP
ENDMODULE
