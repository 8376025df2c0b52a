MODULE MainModule
  ! Tests: StrToVal returns FALSE and leaves the variable unchanged when the text does not
  ! match the type.
  PROC main()
    VAR bool ok;
    VAR num nval := 7;
    VAR pos p := [1, 2, 3];
    ok := StrToVal("abc", nval);
    TPWrite "ok=" \Bool:=ok;
    TPWrite "nval=" \Num:=nval;
    ok := StrToVal("[1,2]", p);
    TPWrite "pos ok=" \Bool:=ok;
    TPWrite "p=" \Pos:=p;
  ENDPROC
ENDMODULE
