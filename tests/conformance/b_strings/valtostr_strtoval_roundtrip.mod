MODULE MainModule
  ! Tests: StrToVal reads back what ValToStr wrote for a robtarget.
  CONST robtarget p10 := [[500,100,400],[0,0,1,0],[1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    VAR robtarget copy;
    VAR bool ok;
    ok := StrToVal(ValToStr(p10.trans), copy.trans);
    TPWrite "ok=" \Bool:=ok;
    TPWrite "trans=" \Pos:=copy.trans;
    ok := StrToVal(ValToStr(p10.robconf), copy.robconf);
    TPWrite "cf6=" \Num:=copy.robconf.cf6;
  ENDPROC
ENDMODULE
