MODULE idisable_queues_ienable_runs
  ! Tests: IDisable disables all interrupts but occurrences are queued;
  ! after IEnable the queued trap runs (before the next statement).
  VAR signaldo do1;
  VAR intnum ir1;
  PROC main()
    AliasIO "DO1", do1;
    CONNECT ir1 WITH onRise;
    ISignalDO do1, 1, ir1;
    IDisable;
    SetDO do1, 1;
    TPWrite "disabled";
    IEnable;
    TPWrite "enabled";
  ENDPROC
  TRAP onRise
    TPWrite "trap";
  ENDTRAP
ENDMODULE
