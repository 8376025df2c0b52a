MODULE MainModule
  ! Tests: SetDO sets a digital output to the given value 1 or 0 (also from a variable or high/low).
  VAR signaldo doValve;
  PROC main()
    VAR dionum value := 1;
    AliasIO "DO1", doValve;
    SetDO doValve, 1;
    TPWrite "one=" \Num:=DOutput(doValve);
    SetDO doValve, 0;
    TPWrite "zero=" \Num:=DOutput(doValve);
    SetDO doValve, value;
    TPWrite "var=" \Num:=DOutput(doValve);
    SetDO doValve, low;
    TPWrite "low=" \Num:=DOutput(doValve);
    SetDO doValve, high;
    TPWrite "high=" \Num:=DOutput(doValve);
  ENDPROC
ENDMODULE
