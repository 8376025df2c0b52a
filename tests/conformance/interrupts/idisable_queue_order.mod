MODULE idisable_queue_order
  ! Tests: interrupts occurring while disabled are all queued and run after
  ! IEnable one at a time, in the order they occurred.
  VAR signaldo doA;
  VAR signaldo doB;
  VAR intnum irA;
  VAR intnum irB;
  PROC main()
    AliasIO "DOA", doA;
    AliasIO "DOB", doB;
    CONNECT irA WITH onA;
    CONNECT irB WITH onB;
    ISignalDO doA, 1, irA;
    ISignalDO doB, 1, irB;
    IDisable;
    SetDO doB, 1;
    SetDO doA, 1;
    TPWrite "disabled";
    IEnable;
    TPWrite "enabled";
  ENDPROC
  TRAP onA
    TPWrite "trap A";
  ENDTRAP
  TRAP onB
    TPWrite "trap B";
  ENDTRAP
ENDMODULE
