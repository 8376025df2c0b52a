MODULE MainModule
  ! Tests: SetDO \SDelay changes the output only after the delay; execution continues at once.
  VAR signaldo doValve;
  PROC main()
    AliasIO "DO1", doValve;
    SetDO \SDelay:=0.5, doValve, 1;
    TPWrite "at once=" \Num:=DOutput(doValve);
    WaitTime 1;
    TPWrite "after delay=" \Num:=DOutput(doValve);
  ENDPROC
ENDMODULE
