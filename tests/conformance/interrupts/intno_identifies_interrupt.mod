MODULE intno_identifies_interrupt
  ! Tests: several intnums may be connected to one TRAP; inside it INTNO
  ! equals the intnum of the interrupt that started it.
  VAR signaldo doA;
  VAR signaldo doB;
  VAR intnum irA;
  VAR intnum irB;
  PROC main()
    AliasIO "DOA", doA;
    AliasIO "DOB", doB;
    CONNECT irA WITH onAny;
    CONNECT irB WITH onAny;
    ISignalDO doA, 1, irA;
    ISignalDO doB, 1, irB;
    SetDO doB, 1;
    SetDO doA, 1;
    TPWrite "end";
  ENDPROC
  TRAP onAny
    IF INTNO = irA TPWrite "A";
    IF INTNO = irB TPWrite "B";
  ENDTRAP
ENDMODULE
