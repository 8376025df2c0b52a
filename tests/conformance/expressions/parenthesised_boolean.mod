MODULE parenthesised_boolean
  ! Tests: parentheses group boolean sub-expressions: NOT (a OR b), and
  ! (a OR b) AND c differs from a OR b AND c.
  PROC main()
    VAR bool a := TRUE;
    VAR bool b := FALSE;
    VAR bool c := FALSE;
    TPWrite "NOT (a OR b): " \Bool:=NOT (a OR b);
    TPWrite "(a OR b) AND c: " \Bool:=(a OR b) AND c;
    TPWrite "a OR b AND c: " \Bool:=a OR b AND c;
  ENDPROC
ENDMODULE
