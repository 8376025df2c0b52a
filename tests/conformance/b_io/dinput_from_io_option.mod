MODULE MainModule
  ! Tests: a digital input set with --io di1=1 reads 1 through DInput, TestDI and directly.
  VAR signaldi diPart;
  PROC main()
    AliasIO "di1", diPart;
    TPWrite "DInput=" \Num:=DInput(diPart);
    TPWrite "TestDI=" \Bool:=TestDI(diPart);
    IF diPart = 1 TPWrite "part present";
  ENDPROC
ENDMODULE
