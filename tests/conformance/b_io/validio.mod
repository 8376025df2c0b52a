MODULE MainModule
  ! Tests: ValidIO is FALSE for a signal variable not yet bound by AliasIO and TRUE once bound;
  ! it raises no error.
  VAR signaldo doA;
  PROC main()
    TPWrite "before AliasIO=" \Bool:=ValidIO(doA);
    AliasIO "DO1", doA;
    TPWrite "after AliasIO=" \Bool:=ValidIO(doA);
  ENDPROC
ENDMODULE
