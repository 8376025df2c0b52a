MODULE not_lowest_precedence
  ! Tests: NOT has the lowest priority: NOT a AND b means NOT (a AND b),
  ! which differs from (NOT a) AND b when a is TRUE and b is FALSE.
  PROC main()
    VAR bool a := TRUE;
    VAR bool b := FALSE;
    TPWrite "NOT a AND b: " \Bool:=NOT a AND b;
    TPWrite "(NOT a) AND b: " \Bool:=(NOT a) AND b;
  ENDPROC
ENDMODULE
