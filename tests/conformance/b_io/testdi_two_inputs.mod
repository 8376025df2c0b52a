MODULE MainModule
  ! Tests: TestDI reports each input separately: di1 set high by --io, di2 left at 0.
  VAR signaldi diA;
  VAR signaldi diB;
  PROC main()
    AliasIO "di1", diA;
    AliasIO "di2", diB;
    TPWrite "di1=" \Bool:=TestDI(diA);
    TPWrite "di2=" \Bool:=TestDI(diB);
    TPWrite "both=" \Bool:=TestDI(diA) AND TestDI(diB);
  ENDPROC
ENDMODULE
