MODULE record_default_init
  ! Tests: an uninitialised record variable is initialised component-wise
  ! to the defaults 0, "" and FALSE (also nested record components).
  RECORD part
    num id;
    string name;
    bool ok;
    pos where;
  ENDRECORD
  PROC main()
    VAR part p;
    TPWrite "id=" \Num:=p.id;
    TPWrite "name=[" + p.name + "]";
    TPWrite "ok=" \Bool:=p.ok;
    TPWrite "where=" \Pos:=p.where;
  ENDPROC
ENDMODULE
