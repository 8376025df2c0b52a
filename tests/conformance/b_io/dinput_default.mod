MODULE MainModule
  ! Tests: in a run, a digital input not set with --io reads 0 (DInput, TestDI, direct read).
  VAR signaldi diPart;
  PROC main()
    AliasIO "di1", diPart;
    TPWrite "DInput=" \Num:=DInput(diPart);
    TPWrite "TestDI=" \Bool:=TestDI(diPart);
    TPWrite "direct=" \Num:=diPart;
  ENDPROC
ENDMODULE
