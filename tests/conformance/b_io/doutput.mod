MODULE MainModule
  ! Tests: DOutput reads back the value last written to a digital output.
  VAR signaldo doA;
  VAR signaldo doB;
  PROC main()
    AliasIO "DO1", doA;
    AliasIO "DO2", doB;
    Set doA;
    TPWrite "doA=" \Num:=DOutput(doA);
    TPWrite "doB=" \Num:=DOutput(doB);
  ENDPROC
ENDMODULE
