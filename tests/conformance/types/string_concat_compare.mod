MODULE string_concat_compare
  ! Tests: + concatenates strings; = and <> compare strings and are case
  ! sensitive ("abc" <> "ABC").
  PROC main()
    VAR string s := "ab";
    s := s + "cd";
    TPWrite s;
    TPWrite "equal " \Bool:=s = "abcd";
    TPWrite "case differs " \Bool:="abc" <> "ABC";
    TPWrite s + "-" + s;
  ENDPROC
ENDMODULE
