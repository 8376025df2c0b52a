MODULE record_value_semantics
  ! Tests: record assignment copies the value: changing the copy leaves the
  ! original unchanged; = compares records component-wise.
  RECORD part
    num id;
    string name;
  ENDRECORD
  PROC main()
    VAR part a := [1, "a"];
    VAR part b;
    b := a;
    TPWrite "equal after copy " \Bool:=a = b;
    b.id := 9;
    TPWrite "a.id=" \Num:=a.id;
    TPWrite "equal after change " \Bool:=a = b;
  ENDPROC
ENDMODULE
