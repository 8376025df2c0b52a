MODULE aggregate_with_expressions
  ! Tests: in assignments and arguments an aggregate may contain non-constant
  ! expressions; its type comes from the target (pos, user record, array).
  RECORD item
    string name;
    num qty;
  ENDRECORD
  PROC show(pos p)
    TPWrite "p=" \Pos:=p;
  ENDPROC
  PROC main()
    VAR num x := 2;
    VAR pos p;
    VAR item it;
    VAR num row{3};
    p := [x, x + 1, x * x];
    it := ["bolt" + "s", x * 10];
    row := [x, -x, 0];
    TPWrite "p=" \Pos:=p;
    TPWrite it.name \Num:=it.qty;
    TPWrite "row{2}=" \Num:=row{2};
    show [x, 0, -1];
  ENDPROC
ENDMODULE
