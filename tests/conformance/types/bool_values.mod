MODULE bool_values
  ! Tests: bool default is FALSE; TRUE/FALSE print as TRUE/FALSE; NOT, AND,
  ! OR and XOR on bools; bools compare with =.
  PROC main()
    VAR bool b;
    TPWrite "default " \Bool:=b;
    b := NOT b;
    TPWrite "not " \Bool:=b;
    TPWrite "xor " \Bool:=b XOR TRUE;
    TPWrite "or " \Bool:=b OR FALSE;
    TPWrite "and " \Bool:=b AND FALSE;
    TPWrite "eq " \Bool:=b = TRUE;
  ENDPROC
ENDMODULE
