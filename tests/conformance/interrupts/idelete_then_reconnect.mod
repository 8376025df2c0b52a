MODULE idelete_then_reconnect
  ! Tests: after IDelete the intnum is free and can be CONNECTed again, here
  ! to a different TRAP.
  VAR signaldo do1;
  VAR intnum ir1;
  PROC main()
    AliasIO "DO1", do1;
    CONNECT ir1 WITH first;
    ISignalDO do1, 1, ir1;
    SetDO do1, 1;
    IDelete ir1;
    CONNECT ir1 WITH second;
    ISignalDO do1, 0, ir1;
    SetDO do1, 0;
    TPWrite "end";
  ENDPROC
  TRAP first
    TPWrite "first";
  ENDTRAP
  TRAP second
    TPWrite "second";
  ENDTRAP
ENDMODULE
