MODULE set_reset_trigger_interrupts
  ! Tests: edges caused by Set, Reset and InvertDO trigger ISignalDO
  ! interrupts like SetDO does (edge trigger: every change counts).
  VAR signaldo do1;
  VAR intnum ir1;
  VAR num changes := 0;
  PROC main()
    AliasIO "DO1", do1;
    CONNECT ir1 WITH onChange;
    ISignalDO do1, 2, ir1;
    Set do1;
    Reset do1;
    InvertDO do1;
    TPWrite "changes=" \Num:=changes;
  ENDPROC
  TRAP onChange
    changes := changes + 1;
  ENDTRAP
ENDMODULE
