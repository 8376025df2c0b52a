MODULE record_and_string_equality
  ! Tests: = and <> apply to any value type: pos records compare
  ! component-wise, strings character by character, bools by value.
  PROC main()
    VAR pos p := [1, 2, 3];
    VAR pos q := [1, 2, 3];
    TPWrite "p=q " \Bool:=p = q;
    q.z := 4;
    TPWrite "p<>q " \Bool:=p <> q;
    TPWrite "strings " \Bool:="ab" = "a" + "b";
    TPWrite "bools " \Bool:=(1 < 2) = TRUE;
  ENDPROC
ENDMODULE
