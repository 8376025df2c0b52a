MODULE MainModule
  ! Tests: StrDigCmp compares digit strings as numbers (so "1000" > "999", unlike text order)
  ! with each relation LT, LTEQ, EQ, NOTEQ, GTEQ, GT.
  PROC main()
    TPWrite "gt=" \Bool:=StrDigCmp("1000", GT, "999");
    TPWrite "lt=" \Bool:=StrDigCmp("1000", LT, "999");
    TPWrite "eq=" \Bool:=StrDigCmp("42", EQ, "42");
    TPWrite "noteq=" \Bool:=StrDigCmp("42", NOTEQ, "42");
    TPWrite "lteq=" \Bool:=StrDigCmp("5", LTEQ, "5");
    TPWrite "gteq=" \Bool:=StrDigCmp("4", GTEQ, "5");
    TPWrite "max=" \Bool:=StrDigCmp("4294967295", GT, "4294967294");
  ENDPROC
ENDMODULE
