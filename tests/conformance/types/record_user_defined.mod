MODULE record_user_defined
  ! Tests: a user RECORD is initialised from an aggregate in component
  ! order, and its components are read and written with dot notation.
  RECORD part
    num id;
    string name;
    bool ok;
  ENDRECORD
  VAR part p := [7, "gear", TRUE];
  PROC main()
    TPWrite "id=" \Num:=p.id;
    TPWrite "name=" + p.name;
    TPWrite "ok=" \Bool:=p.ok;
    p.name := "pinion";
    p.id := p.id + 1;
    TPWrite p.name \Num:=p.id;
  ENDPROC
ENDMODULE
