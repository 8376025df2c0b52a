MODULE MainModule
  ! Tests: SetDO takes a dionum value; a string is a static type error.
  VAR signaldo doA;
  PROC main()
    TPWrite "must not run";
    SetDO doA, "high";
  ENDPROC
ENDMODULE
