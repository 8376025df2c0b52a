MODULE MainModule
  ! Tests: WaitUntil with a condition on a digital input set by --io continues at once.
  VAR signaldi diStart;
  PROC main()
    AliasIO "di1", diStart;
    WaitUntil TestDI(diStart) \MaxTime:=1;
    TPWrite "input high";
  ENDPROC
ENDMODULE
