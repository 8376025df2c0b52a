MODULE isleep_discards_iwatch_resumes
  ! Tests: ISleep deactivates one interrupt and occurrences while asleep are
  ! discarded (not run later); IWatch reactivates it.
  VAR signaldo do1;
  VAR intnum ir1;
  VAR num count := 0;
  PROC main()
    AliasIO "DO1", do1;
    CONNECT ir1 WITH onRise;
    ISignalDO do1, 1, ir1;
    SetDO do1, 1;
    ISleep ir1;
    SetDO do1, 0;
    SetDO do1, 1;
    TPWrite "asleep";
    IWatch ir1;
    TPWrite "watching";
    SetDO do1, 0;
    SetDO do1, 1;
    TPWrite "count=" \Num:=count;
  ENDPROC
  TRAP onRise
    count := count + 1;
    TPWrite "trap " \Num:=count;
  ENDTRAP
ENDMODULE
