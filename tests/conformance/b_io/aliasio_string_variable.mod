MODULE MainModule
  ! Tests: AliasIO accepts the configured signal name as a string expression (variable).
  VAR signaldo doA;
  VAR signaldo doB;
  PROC main()
    VAR string name := "DO7";
    AliasIO name, doA;
    AliasIO "DO7", doB;
    Set doA;
    TPWrite "via other alias=" \Num:=DOutput(doB);
  ENDPROC
ENDMODULE
