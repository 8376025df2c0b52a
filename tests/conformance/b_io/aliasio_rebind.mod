MODULE MainModule
  ! Tests: after AliasIOReset a signal variable can be bound again, to another signal.
  VAR signaldo doA;
  VAR signaldo doWatch;
  PROC main()
    AliasIO "DO5", doA;
    AliasIO "DO5", doWatch;
    Set doA;
    AliasIOReset doA;
    AliasIO "DO6", doA;
    TPWrite "DO6=" \Num:=DOutput(doA);
    Set doA;
    Reset doWatch;
    TPWrite "DO6 after Reset of DO5=" \Num:=DOutput(doA);
  ENDPROC
ENDMODULE
