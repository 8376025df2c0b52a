MODULE MainModule
  ! Tests: two signal variables aliased to the same signal see the same value; a variable
  ! aliased to another signal does not.
  VAR signaldo doA;
  VAR signaldo doB;
  VAR signaldo doOther;
  PROC main()
    AliasIO "DO3", doA;
    AliasIO "DO3", doB;
    AliasIO "DO4", doOther;
    Set doA;
    TPWrite "doB=" \Num:=DOutput(doB);
    TPWrite "doOther=" \Num:=DOutput(doOther);
    Reset doB;
    TPWrite "doA=" \Num:=DOutput(doA);
  ENDPROC
ENDMODULE
