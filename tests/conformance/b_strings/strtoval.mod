MODULE MainModule
  ! Tests: StrToVal parses text as a value of the target's type, returns TRUE and stores it
  ! (manual example "3.85"); works for num, bool and pos.
  PROC main()
    VAR bool ok;
    VAR num nval;
    VAR bool flag;
    VAR pos p;
    ok := StrToVal("3.85", nval);
    TPWrite "num ok=" \Bool:=ok;
    TPWrite "nval=" \Num:=nval;
    ok := StrToVal("TRUE", flag);
    TPWrite "flag=" \Bool:=flag;
    ok := StrToVal("[600,500,225.3]", p);
    TPWrite "pos ok=" \Bool:=ok;
    TPWrite "p=" \Pos:=p;
  ENDPROC
ENDMODULE
