MODULE MainModule
  ! Tests: Offs adds the offsets to the position of a robtarget and keeps its orientation and
  ! configuration; the original is unchanged.
  CONST robtarget p10 := [[100,200,300],[0,0,1,0],[1,-1,0,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    VAR robtarget p20;
    p20 := Offs(p10, 10, -20, 30);
    TPWrite "trans=" \Pos:=p20.trans;
    TPWrite "rot=" \Orient:=p20.rot;
    TPWrite "cf4=" \Num:=p20.robconf.cf4;
    TPWrite "orig=" \Pos:=p10.trans;
  ENDPROC
ENDMODULE
