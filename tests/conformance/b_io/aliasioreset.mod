MODULE MainModule
  ! Tests: AliasIOReset unbinds a signal variable: ValidIO becomes FALSE and using it is a
  ! recoverable error (error number not asserted).
  VAR signaldo doA;
  PROC main()
    AliasIO "DO1", doA;
    Set doA;
    AliasIOReset doA;
    TPWrite "valid=" \Bool:=ValidIO(doA);
    Set doA;
    TPWrite "not reached";
  ERROR
    TPWrite "error after AliasIOReset";
  ENDPROC
ENDMODULE
